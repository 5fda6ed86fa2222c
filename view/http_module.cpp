// cpp-httplib behind view/http_server.h, built as the module `locus view` loads on first use.
#include <httplib.h>

#include "view/http_server.h"

namespace locus::view {
namespace {

HttpRequest request_of(const httplib::Request& request) {
    HttpRequest out;
    out.params.insert(request.params.begin(), request.params.end());
    return out;
}

void answer(const HttpResponse& from, httplib::Response& to) {
    to.status = from.status;
    for (const auto& [name, value] : from.headers) {
        to.set_header(name, value);
    }
    if (!from.content_type.empty() || !from.body.empty()) {
        to.set_content(from.body, from.content_type);
    }
}

httplib::Server::Handler adapt(HttpHandler handler) {
    return [handler = std::move(handler)](const httplib::Request& request,
                                          httplib::Response& response) {
        HttpResponse out;
        handler(request_of(request), out);
        answer(out, response);
    };
}

class HttplibServer final : public HttpServer {
  public:
    explicit HttplibServer(const HttpServerSettings& settings) {
        server_.set_payload_max_length(settings.max_body_bytes);
        // Frames are small and interactive: no Nagle delay on the answers.
        server_.set_tcp_nodelay(true);
        const auto threads = static_cast<std::size_t>(std::max(1, settings.threads));
        server_.new_task_queue = [threads] { return new httplib::ThreadPool(threads); };
    }
    void get(const std::string& path, HttpHandler handler) override {
        server_.Get(path, adapt(std::move(handler)));
    }
    void post(const std::string& path, HttpHandler handler) override {
        server_.Post(path, adapt(std::move(handler)));
    }
    void on_error(HttpHandler handler) override {
        server_.set_error_handler([handler = std::move(handler)](const httplib::Request& request,
                                                                 httplib::Response& response) {
            HttpResponse out;
            out.status = response.status;
            out.body = response.body;
            handler(request_of(request), out);
            if (out.body != response.body || out.status != response.status) {
                answer(out, response);
            }
        });
    }
    void on_exception(HttpHandler handler) override {
        server_.set_exception_handler(
            [handler = std::move(handler)](const httplib::Request& request,
                                           httplib::Response& response, std::exception_ptr) {
                HttpResponse out;
                handler(request_of(request), out);
                answer(out, response);
            });
    }
    int bind(const std::string& host, int port) override {
        if (port == 0) {
            return server_.bind_to_any_port(host);
        }
        return server_.bind_to_port(host, port) ? port : -1;
    }
    void listen_after_bind() override { server_.listen_after_bind(); }
    bool is_running() const override { return server_.is_running(); }
    void stop() override { server_.stop(); }

  private:
    httplib::Server server_;
};

}  // namespace
}  // namespace locus::view

extern "C" locus::view::HttpServer* locus_make_http_server(
    const locus::view::HttpServerSettings* settings) {
    return new locus::view::HttplibServer(*settings);
}
