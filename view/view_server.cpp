#include "view/view_server.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <map>
#include <mutex>
#include <set>
#include <thread>

#include "algebra/error.h"
#include "algebra/flint_threads.h"
#include "algebra/print.h"
#include "implicit/implicitize.h"
#include "implicit/parametrization.h"
#include "implicit/verify.h"
#include "render/camera.h"
#include "render/image_output.h"
#include "render/renderer.h"
#include "render/sdf/sdf_renderer.h"
#include "render/trace_method.h"
#include "view/assets.h"
#include "view/frame_builder.h"
#include "view/http_server.h"

namespace locus::view {
namespace {

using Clock = std::chrono::steady_clock;

std::string json_string(const std::string& text) {
    std::string out = "\"";
    for (const char c : text) {
        switch (c) {
        case '"':
            out += "\\\"";
            break;
        case '\\':
            out += "\\\\";
            break;
        case '\n':
            out += "\\n";
            break;
        case '\t':
            out += "\\t";
            break;
        default:
            if (static_cast<unsigned char>(c) < 0x20) {
                char escaped[8];
                std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
                out += escaped;
            } else {
                out += c;
            }
        }
    }
    return out + "\"";
}

std::string number(double v, int digits = 9) {
    char text[40];
    std::snprintf(text, sizeof text, "%.*g", digits, v);
    return text;
}

void send_json(HttpResponse& response, int status, const std::string& body) {
    response.status = status;
    response.set_header("Cache-Control", "no-store");
    response.set_content(body, "application/json");
}

void send_error(HttpResponse& response, int status, const std::string& message,
                const std::string& field = {}, std::size_t line = 0, std::size_t column = 0) {
    std::string body = "{\"error\":" + json_string(message);
    if (!field.empty()) {
        body += ",\"field\":" + json_string(field);
    }
    if (line > 0) {
        body += ",\"line\":" + std::to_string(line) + ",\"column\":" + std::to_string(column);
    }
    send_json(response, status, body + "}");
}

Fields fields_of(const HttpRequest& request) {
    Fields fields;
    for (const auto& [name, value] : request.params) {
        fields.emplace(name, value);
    }
    return fields;
}

// Every double to 17 digits, which read back give the same double: the page sends the camera
// back with its next frame, and the same camera must give the same picture. (At 9 digits it
// moved by 1e-9, and hits placed to the renderer's 1e-7 could then round a pixel the other way.)
std::string camera_text(const render::CameraSpec& c) {
    const auto exact = [](double v) { return number(v, 17); };
    return exact(c.eye.x) + "," + exact(c.eye.y) + "," + exact(c.eye.z) + "," + exact(c.target.x) +
           "," + exact(c.target.y) + "," + exact(c.target.z) + "," + exact(c.up.x) + "," +
           exact(c.up.y) + "," + exact(c.up.z) + "," + exact(c.fov_degrees);
}

// Runs `work`, turning every error into an answer: a page's request never stops the server.
template <class Work>
void answer(HttpResponse& response, Work&& work) {
    try {
        work();
    } catch (const RequestError& e) {
        send_error(response, 400, e.message, e.field, e.line, e.column);
    } catch (const ParseError& e) {
        send_error(response, 400, e.what(), "equation", e.line(), e.column());
    } catch (const Cancelled& e) {
        send_error(response, 409, e.what());
    } catch (const Timeout& e) {
        send_error(response, 504, e.what());
    } catch (const ResourceLimit& e) {
        send_error(response, 413, e.what());
    } catch (const Error& e) {
        send_error(response, 400, e.what());
    } catch (const std::bad_alloc&) {
        send_error(response, 507, "out of memory");
    } catch (const std::exception& e) {
        send_error(response, 500, std::string("internal error: ") + e.what());
    }
}

}  // namespace

struct ViewServer::State {
    explicit State(ViewOptions o) : options(std::move(o)), builder(options) {}

    ViewOptions options;
    FrameBuilder builder;
    std::unique_ptr<HttpServer> server;
    int port = 0;

    // One render at a time per client: a newer request cancels the one in flight.
    struct Client {
        std::mutex busy;
        std::shared_ptr<std::atomic<bool>> current;
    };
    std::mutex clients_mutex;
    std::map<std::string, std::shared_ptr<Client>> clients;
    std::set<std::shared_ptr<std::atomic<bool>>> active;  // the flags of the work in flight
    bool stopping = false;                                // guarded by clients_mutex
    // run() and stop() (httplib's stop() does nothing before the server listens).
    std::atomic<bool> stop_requested{false}, run_started{false}, run_done{false};

    // At most `concurrent_renders` at once, `waiting_renders` in line.
    std::mutex slots_mutex;
    std::condition_variable slot_freed;
    int running = 0, waiting = 0;

    render::RenderedImage render_frame(const Frame& frame, const std::atomic<bool>* cancel,
                                       render::RenderStats* stats, bool aovs) {
        render::ExecutionSettings execution;
        execution.threads = frame.scene.options.threads;
        execution.deadline =
            Clock::now() + std::chrono::duration_cast<Clock::duration>(
                               std::chrono::duration<double>(options.limits.frame_seconds));
        execution.cancel = cancel;
        execution.aovs = aovs;
        return frame.scene.objects.empty()
                   ? render::render(frame.scene, frame.compiled, execution, stats)
                   : render::render_sdf_scene(frame.scene, frame.compiled, execution, stats);
    }

    // Waits for a render slot; false when the line is full.
    bool acquire_slot() {
        std::unique_lock<std::mutex> lock(slots_mutex);
        if (running >= options.limits.concurrent_renders &&
            waiting >= options.limits.waiting_renders) {
            return false;
        }
        ++waiting;
        slot_freed.wait(lock, [&] {
            return running < options.limits.concurrent_renders || stop_requested.load();
        });
        --waiting;
        if (stop_requested.load()) {
            return false;
        }
        ++running;
        return true;
    }
    void release_slot() {
        {
            const std::lock_guard<std::mutex> lock(slots_mutex);
            --running;
        }
        slot_freed.notify_one();
    }

    // answer() within a render slot; 503 when the line is full.
    template <class Work>
    void answer_in_slot(HttpResponse& response, Work&& work) {
        if (!acquire_slot()) {
            send_error(response, 503, "busy: too many requests waiting");
            return;
        }
        struct SlotGuard {
            State* state;
            ~SlotGuard() { state->release_slot(); }
        } guard{this};
        answer(response, std::forward<Work>(work));
    }

    // One piece of rendering work for a client: a newer one from the same client (the same
    // `client` field) cancels it, the server's stop cancels every one, and it waits for its
    // client's previous work to end and for a render slot. `work` gets the cancellation flag.
    template <class Work>
    void client_work(const Fields& fields, HttpResponse& response, Work&& work) {
        const std::string client_id = field(fields, "client").value_or("");
        std::shared_ptr<Client> client;
        auto cancel = std::make_shared<std::atomic<bool>>(false);
        {
            const std::lock_guard<std::mutex> lock(clients_mutex);
            if (stopping) {
                send_error(response, 503, "stopping");
                return;
            }
            active.insert(cancel);
            if (!client_id.empty()) {
                if (clients.size() > 1000) {
                    clients.clear();  // forget idle clients; bounded memory
                }
                auto& entry = clients[client_id.substr(0, 64)];
                if (!entry) {
                    entry = std::make_shared<Client>();
                }
                client = entry;
                if (client->current) {
                    client->current->store(true);  // the work in flight is no longer wanted
                }
                client->current = cancel;
            }
        }
        struct Unregister {
            State* state;
            std::shared_ptr<std::atomic<bool>> flag;
            ~Unregister() {
                const std::lock_guard<std::mutex> lock(state->clients_mutex);
                state->active.erase(flag);
            }
        } unregister{this, cancel};
        std::unique_lock<std::mutex> own_turn;
        if (client) {
            own_turn = std::unique_lock<std::mutex>(client->busy);
        }
        if (cancel->load()) {
            send_error(response, 409, "cancelled: newer work was asked for");
            return;
        }
        answer_in_slot(response, [&] { work(cancel.get()); });
    }

    // Cancels every render and refuses new ones (the server is stopping).
    void cancel_everything() {
        {
            const std::lock_guard<std::mutex> lock(clients_mutex);
            stopping = true;
            for (const auto& flag : active) {
                flag->store(true);
            }
        }
        const std::lock_guard<std::mutex> lock(slots_mutex);
        slot_freed.notify_all();
    }

    void handle_render(const HttpRequest& request, HttpResponse& response) {
        const Fields fields = fields_of(request);
        client_work(fields, response, [&](const std::atomic<bool>* cancel) {
            const Frame frame = builder.build(fields);
            render::RenderStats stats;
            const render::RenderedImage image = render_frame(frame, cancel, &stats, false);
            response.set_header("X-Locus-Seconds", number(stats.seconds));
            response.set_header("X-Locus-Hits", std::to_string(stats.hits));
            response.set_header("X-Locus-Undecided", std::to_string(stats.unknown));
            response.set_header("X-Locus-Camera", camera_text(frame.camera));
            response.set_header("X-Locus-Method",
                                std::string(render::to_string(frame.scene.options.method)));
            response.set_header("Cache-Control", "no-store");
            response.set_content(render::png_bytes(image), "image/png");
        });
    }

    // The frame's rays by the requested method against the certified one: pixels that one hits
    // and the other misses, or whose distances differ by more than 1e-6 relative.
    void handle_check(const HttpRequest& request, HttpResponse& response) {
        const Fields fields = fields_of(request);
        client_work(fields, response, [&](const std::atomic<bool>* cancel) {
            Frame frame = builder.build(fields);
            frame.scene.options.shadows = false;
            render::RenderStats stats, reference_stats;
            const auto start = Clock::now();
            const render::RenderedImage mine = render_frame(frame, cancel, &stats, true);
            frame.scene.options.method = render::TraceMethod::certified;
            const render::RenderedImage reference =
                render_frame(frame, cancel, &reference_stats, true);
            long wrong = 0;
            for (std::size_t i = 0; i < mine.depth.size(); ++i) {
                const double a = mine.depth[i], b = reference.depth[i];
                const bool hit_a = std::isfinite(a), hit_b = std::isfinite(b);
                if (hit_a != hit_b || (hit_a && std::abs(a - b) > 1e-6 * std::max(1.0, b))) {
                    ++wrong;
                }
            }
            send_json(
                response, 200,
                "{\"rays\":" + std::to_string(mine.depth.size()) + ",\"wrong\":" +
                    std::to_string(wrong) + ",\"undecided\":" + std::to_string(stats.unknown) +
                    ",\"reference_undecided\":" + std::to_string(reference_stats.unknown) +
                    ",\"seconds\":" +
                    number(std::chrono::duration<double>(Clock::now() - start).count()) + "}");
        });
    }

    // The point under pixel (x, y): the frame's depth there along the pixel's ray.
    void handle_pick(const HttpRequest& request, HttpResponse& response) {
        const Fields fields = fields_of(request);
        client_work(fields, response, [&](const std::atomic<bool>* cancel) {
            Frame frame = builder.build(fields);
            frame.scene.options.shadows = false;
            const auto coordinate = [&](const char* name) {
                const std::string text = field(fields, name).value_or("");
                char* end = nullptr;
                const double v = std::strtod(text.c_str(), &end);
                return end != text.c_str() && *end == '\0' ? v : -1.0;
            };
            const double x = coordinate("x"), y = coordinate("y");
            if (!(x >= 0 && x < frame.scene.width && y >= 0 && y < frame.scene.height)) {
                throw RequestError{"x, y: expected a pixel of the image", "x"};
            }
            const render::RenderedImage image = render_frame(frame, cancel, nullptr, true);
            const auto px = static_cast<std::size_t>(x), py = static_cast<std::size_t>(y);
            const double depth = image.depth[py * static_cast<std::size_t>(image.width) + px];
            if (!std::isfinite(depth)) {
                send_json(response, 200, "{\"hit\":false}");
                return;
            }
            const render::Camera camera(frame.camera, frame.scene.width, frame.scene.height);
            const render::Ray ray = camera.ray(px + 0.5, py + 0.5);
            const double length =
                std::sqrt(ray.direction.x * ray.direction.x + ray.direction.y * ray.direction.y +
                          ray.direction.z * ray.direction.z);
            const render::Vec3 point = ray.at(depth / length);
            send_json(response, 200,
                      "{\"hit\":true,\"point\":[" + number(point.x) + "," + number(point.y) + "," +
                          number(point.z) + "]}");
        });
    }

    void handle_parse(const HttpRequest& request, HttpResponse& response) {
        answer(response, [&] {
            const std::string equation = request.param("equation");
            if (equation.size() > options.limits.max_equation_chars) {
                throw RequestError{"equation: longer than " +
                                       std::to_string(options.limits.max_equation_chars) +
                                       " characters",
                                   "equation"};
            }
            std::string names;
            for (const std::string& name : equation_parameters(equation)) {
                if (!names.empty()) {
                    names += ',';
                }
                names += json_string(name);
            }
            send_json(response, 200, "{\"parameters\":[" + names + "]}");
        });
    }

    void handle_implicitize(const HttpRequest& request, HttpResponse& response) {
        answer_in_slot(response, [&] {
            const std::string text = request.param("param");
            const implicit::Parametrization map = implicit::parse_parametrization(text);
            if (map.coordinates.size() != 3 || map.parameter_ring->num_vars() != 2) {
                throw RequestError{"param: a surface needs two parameters and x, y, z", "param"};
            }
            algebra::GroebnerOptions groebner;
            groebner.deadline = Clock::now() + std::chrono::seconds(10);
            const implicit::ImplicitResult result = implicit::implicitize_auto(map, groebner);
            if (!result.equation) {
                throw RequestError{"param: " + implicit::describe_image(result.image, 2, 3),
                                   "param"};
            }
            if (implicit::first_not_vanishing(result, map)) {
                throw RequestError{"param: the equation failed its verification", "param"};
            }
            send_json(response, 200,
                      "{\"equation\":" + json_string(algebra::to_string(*result.equation)) +
                          ",\"method\":" + json_string(result.method) + "}");
        });
    }

    void handle_startup(HttpResponse& response) {
        std::string methods;
        for (const render::TraceMethod m : render::all_trace_methods()) {
            if (!methods.empty()) {
                methods += ',';
            }
            methods += json_string(std::string(render::to_string(m)));
        }
        std::string body = "{\"methods\":[" + methods + "]";
        if (options.startup) {
            body +=
                ",\"label\":" + json_string(options.startup->label) +
                ",\"equation\":" + json_string(options.startup->equation) + ",\"scene\":" +
                (options.startup->compiled.empty() || !options.startup->equation.empty() ? "false"
                                                                                         : "true");
        }
        body += ",\"max_equation\":" + std::to_string(options.limits.max_equation_chars) +
                ",\"max_side\":" + std::to_string(options.limits.max_image_side) + "}";
        send_json(response, 200, body);
    }

    void routes() {
        HttpServerSettings settings;
        settings.max_body_bytes = options.limits.max_body_bytes;
        // Threads for every render and waiting render and some to spare, so that the page and
        // the 503 answers are never stuck behind renders (httplib's default was 8 here).
        settings.threads = options.limits.concurrent_renders + options.limits.waiting_renders + 6;
        server = make_http_server(settings);
        server->get("/", [](const HttpRequest&, HttpResponse& r) {
            r.set_content(std::string(assets::index_html), "text/html; charset=utf-8");
        });
        server->get("/app.js", [](const HttpRequest&, HttpResponse& r) {
            r.set_content(std::string(assets::app_js), "text/javascript; charset=utf-8");
        });
        server->get("/style.css", [](const HttpRequest&, HttpResponse& r) {
            r.set_content(std::string(assets::style_css), "text/css; charset=utf-8");
        });
        server->get("/api/startup",
                    [this](const HttpRequest&, HttpResponse& r) { handle_startup(r); });
        // The API's handlers parse, compile and implicitize with FLINT on the HTTP server's
        // threads, which end when the server stops: each frees FLINT's caches then.
        using Handler = void (State::*)(const HttpRequest&, HttpResponse&);
        const auto api = [this](Handler handler) {
            return [this, handler](const HttpRequest& q, HttpResponse& r) {
                algebra::release_flint_caches_at_thread_exit();
                (this->*handler)(q, r);
            };
        };
        server->post("/api/parse", api(&State::handle_parse));
        server->post("/api/render", api(&State::handle_render));
        server->post("/api/check", api(&State::handle_check));
        server->post("/api/pick", api(&State::handle_pick));
        server->post("/api/implicitize", api(&State::handle_implicitize));
        // Anything else, and errors httplib answers itself (413 for a body past the limit).
        server->on_error([](const HttpRequest&, HttpResponse& r) {
            if (r.body.empty()) {
                send_error(r, r.status,
                           r.status == 413 ? "request too large" : "no such page or method");
            }
        });
        server->on_exception(
            [](const HttpRequest&, HttpResponse& r) { send_error(r, 500, "internal error"); });
    }
};

ViewServer::ViewServer(ViewOptions options) : state_(std::make_unique<State>(std::move(options))) {
    state_->routes();
}

ViewServer::~ViewServer() {
    stop();
}

int ViewServer::bind() {
    State& s = *state_;
    s.port = s.server->bind(s.options.host, s.options.port);
    if (s.port <= 0) {
        throw Error("cannot listen on " + s.options.host + ":" + std::to_string(s.options.port) +
                    " (in use, or not an address of this machine)");
    }
    return s.port;
}

void ViewServer::run() {
    State& s = *state_;
    s.run_started = true;
    if (!s.stop_requested) {
        s.server->listen_after_bind();
    }
    s.run_done = true;
}

void ViewServer::stop() {
    State& s = *state_;
    s.stop_requested = true;
    s.cancel_everything();
    // httplib's stop() only acts once the server listens: wait for that (or for run() to end,
    // or never to be called) rather than lose a stop that came early.
    for (int i = 0; i < 5000; ++i) {
        if (s.server->is_running()) {
            s.server->stop();
            return;
        }
        if (!s.run_started || s.run_done) {
            return;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
}

}  // namespace locus::view
