// The server of `locus view` over real HTTP (cpp-httplib's client against a server on a free
// port): the page and frames, every kind of bad request answered with an error that names the
// field (and the column for equations), bodies past the limit, hostile equations after which
// the server still serves, concurrent clients, and a newer frame cancelling the one in flight.
#include "view/view_server.h"

#include <gtest/gtest.h>
#include <httplib.h>

#include <atomic>
#include <chrono>
#include <future>
#include <thread>

namespace locus::view {
namespace {

class ViewServerTest : public ::testing::Test {
  protected:
    void SetUp() override {
        ViewOptions options;
        options.port = 0;
        options.render_threads = 2;
        server_ = std::make_unique<ViewServer>(std::move(options));
        port_ = server_->bind();
        thread_ = std::thread([this] { server_->run(); });
    }
    void TearDown() override {
        server_->stop();
        thread_.join();
    }
    httplib::Client client() const {
        httplib::Client c("127.0.0.1", port_);
        c.set_read_timeout(60, 0);
        return c;
    }
    httplib::Result frame(const httplib::Params& extra) const {
        httplib::Params params = {
            {"equation", "x^2+y^2+z^2-1"}, {"width", "64"}, {"height", "64"}, {"client", "test"}};
        for (const auto& [k, v] : extra) {
            params.erase(k);
            params.emplace(k, v);
        }
        return client().Post("/api/render", params);
    }

    std::unique_ptr<ViewServer> server_;
    int port_ = 0;
    std::thread thread_;
};

TEST_F(ViewServerTest, ServesThePageAndFrames) {
    const auto page = client().Get("/");
    ASSERT_TRUE(page);
    EXPECT_EQ(page->status, 200);
    EXPECT_NE(page->body.find("<title>locus view</title>"), std::string::npos);
    EXPECT_EQ(client().Get("/app.js")->status, 200);
    EXPECT_EQ(client().Get("/style.css")->status, 200);
    const auto startup = client().Get("/api/startup");
    EXPECT_NE(startup->body.find("\"certified\""), std::string::npos);
    const auto f = frame({});
    ASSERT_TRUE(f);
    ASSERT_EQ(f->status, 200) << f->body;
    EXPECT_EQ(f->get_header_value("Content-Type"), "image/png");
    EXPECT_EQ(f->body.substr(1, 3), "PNG");
    EXPECT_GT(std::stol(f->get_header_value("X-Locus-Hits")), 300);
    EXPECT_EQ(f->get_header_value("X-Locus-Undecided"), "0");
    // The camera the server framed, sent back, gives the same picture.
    const auto again = frame({{"camera", f->get_header_value("X-Locus-Camera")}});
    EXPECT_EQ(again->body, f->body);
}

TEST_F(ViewServerTest, ParametersAreSubstituted) {
    const auto parsed =
        client().Post("/api/parse", httplib::Params{{"equation", "x^2+a*y^2+z^2-r"}});
    EXPECT_EQ(parsed->body, "{\"parameters\":[\"a\",\"r\"]}");
    const auto small = frame(
        {{"equation", "x^2+y^2+z^2-r"}, {"params", "r=0.5"}, {"camera", "0,0,6,0,0,0,0,1,0,30"}});
    const auto large = frame(
        {{"equation", "x^2+y^2+z^2-r"}, {"params", "r=2"}, {"camera", "0,0,6,0,0,0,0,1,0,30"}});
    ASSERT_EQ(small->status, 200);
    ASSERT_EQ(large->status, 200);
    EXPECT_LT(std::stol(small->get_header_value("X-Locus-Hits")),
              std::stol(large->get_header_value("X-Locus-Hits")));
}

TEST_F(ViewServerTest, BadRequestsNameTheField) {
    const auto expect_error = [&](const httplib::Params& extra, int status,
                                  const std::string& fragment) {
        const auto r = frame(extra);
        ASSERT_TRUE(r);
        EXPECT_EQ(r->status, status) << r->body;
        EXPECT_NE(r->body.find(fragment), std::string::npos) << r->body;
        EXPECT_EQ(r->get_header_value("Content-Type"), "application/json");
    };
    expect_error({{"width", "0"}}, 400, "\"field\":\"width\"");
    expect_error({{"width", "100000"}}, 400, "\"field\":\"width\"");
    expect_error({{"height", "abc"}}, 400, "\"field\":\"height\"");
    expect_error({{"camera", "1,2,3"}}, 400, "\"field\":\"camera\"");
    expect_error({{"camera", "0,0,0,0,0,0,0,1,0,35"}}, 400, "\"error\"");
    expect_error({{"method", "guess"}}, 400, "\"field\":\"method\"");
    expect_error({{"front", "2,0,0"}}, 400, "\"field\":\"front\"");
    expect_error({{"params", "a=1e1000"}}, 400, "\"field\":\"params\"");  // 1e999 is exact
    expect_error({{"params", "a=0x10"}}, 400, "\"field\":\"params\"");
    expect_error({{"equation", "x^2 + * y"}}, 400, "\"column\":7");
    expect_error({{"equation", "3"}}, 400, "constant");
    expect_error({{"equation", std::string(5000, 'x')}}, 400, "longer than");
    expect_error({{"source", "/etc/passwd"}}, 400, "\"field\":\"source\"");
    expect_error({{"source", "startup"}}, 400, "no scene");
    const auto missing = client().Post("/api/render", httplib::Params{{"width", "8"}});
    EXPECT_EQ(missing->status, 400);
    EXPECT_EQ(client().Get("/etc/passwd")->status, 404);
    EXPECT_EQ(client().Get("/api/render")->status, 404);
}

TEST_F(ViewServerTest, HostileInputGetsAnErrorAndTheServerKeepsServing) {
    const std::string huge_body(200 * 1024, 'x');
    const auto big = client().Post("/api/render", huge_body, "application/x-www-form-urlencoded");
    ASSERT_TRUE(big);
    EXPECT_EQ(big->status, 413);
    for (const std::string& equation :
         {std::string("x^100000"), std::string("(x+y+z)^400-1"), std::string("x^65-1"),
          std::string(3000, '(') + "x", std::string("\xff\xfe") + "x"}) {
        const auto r = frame({{"equation", equation}});
        ASSERT_TRUE(r) << equation.substr(0, 20);
        EXPECT_GE(r->status, 400) << equation.substr(0, 20);
    }
    EXPECT_EQ(frame({})->status, 200);
}

TEST_F(ViewServerTest, ConcurrentClientsEachGetTheirFrame) {
    std::vector<std::future<int>> answers;
    for (int i = 0; i < 4; ++i) {
        std::string id = "c";
        id += std::to_string(i);
        answers.push_back(std::async(std::launch::async, [this, id] {
            const auto r = frame({{"client", id}, {"width", "96"}});
            return r ? r->status : -1;
        }));
    }
    for (auto& a : answers) {
        EXPECT_EQ(a.get(), 200);
    }
}

// A newer frame from the same client cancels the one in flight: the first answers 409 long
// before its render could have finished.
TEST_F(ViewServerTest, ANewerFrameCancelsTheOneInFlight) {
    const httplib::Params slow = {{"equation", "x^12+y^12+z^12-(x*y*z)^3-1"},
                                  {"width", "2048"},
                                  {"height", "2048"},
                                  {"method", "exact"},
                                  {"client", "same"}};
    const auto start = std::chrono::steady_clock::now();
    auto first = std::async(std::launch::async, [&] { return frame(slow); });
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    const auto second = frame({{"client", "same"}});
    const auto cancelled = first.get();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_TRUE(cancelled);
    EXPECT_EQ(cancelled->status, 409) << cancelled->body.substr(0, 200);
    EXPECT_EQ(second->status, 200);
    EXPECT_LT(seconds, 5.0);
}

TEST_F(ViewServerTest, MalformedPickCoordinatesAreBadRequests) {
    for (const char* x : {"abc", "1e999", "", "-3"}) {
        const auto r = client().Post("/api/pick", httplib::Params{{"equation", "x^2+y^2+z^2-1"},
                                                                  {"width", "16"},
                                                                  {"height", "16"},
                                                                  {"x", x},
                                                                  {"y", "3"}});
        ASSERT_TRUE(r);
        EXPECT_EQ(r->status, 400) << x << " " << r->body;
    }
}

// A stop that comes before the server listens (--timeout 0.00001, an early Ctrl-C) is kept:
// run() returns at once instead of serving on.
TEST(ViewServerStop, AStopBeforeRunIsNotLost) {
    ViewOptions options;
    options.port = 0;
    ViewServer server(options);
    server.bind();
    server.stop();
    const auto start = std::chrono::steady_clock::now();
    server.run();
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
}

TEST_F(ViewServerTest, ImplicitizeAndPick) {
    const auto r = client().Post(
        "/api/implicitize", httplib::Params{{"param", "params: s,t\nx = s\ny = t\nz = s^2+t^2\n"}});
    ASSERT_EQ(r->status, 200) << r->body;
    EXPECT_NE(r->body.find("\"equation\":\"x^2+y^2-z\""), std::string::npos) << r->body;
    const auto bad =
        client().Post("/api/implicitize", httplib::Params{{"param", "params: s\nx = s +\n"}});
    EXPECT_EQ(bad->status, 400);
    EXPECT_NE(bad->body.find("\"line\":"), std::string::npos) << bad->body;
    const httplib::Params pick = {{"equation", "x^2+y^2+z^2-1"},
                                  {"width", "64"},
                                  {"height", "64"},
                                  {"x", "32"},
                                  {"y", "32"},
                                  {"camera", "0,0,5,0,0,0,0,1,0,30"}};
    const auto hit = client().Post("/api/pick", pick);
    ASSERT_EQ(hit->status, 200) << hit->body;
    EXPECT_NE(hit->body.find("\"hit\":true"), std::string::npos);
    // The sphere's front, (0, 0, 1) up to the pixel's offset from the centre.
    const double z = std::stod(hit->body.substr(hit->body.rfind(',') + 1));
    EXPECT_NEAR(z, 1.0, 1e-3) << hit->body;
}

}  // namespace
}  // namespace locus::view
