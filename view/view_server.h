// `locus view`: a local web server (cpp-httplib) that renders algebraic surfaces for a page in
// the browser as the user turns, zooms and edits them. The page (view/assets/, compiled into
// the binary) asks for frames over HTTP; each frame is rendered by the same renderer as
// `locus render` and sent as PNG.
//
// Endpoints (all answers are JSON except frames, which are image/png):
//   GET  /, /app.js, /style.css   the page
//   GET  /api/startup             what the command line named, the methods, the limits
//   POST /api/parse               an equation's parameters (names other than x, y, z) or its
//                                 parse error with line and column
//   POST /api/render              a frame (PNG); the frame's figures in X-Locus-* headers
//   POST /api/check               the frame's rays compared with the certified method's
//   POST /api/pick                the surface point under a pixel (double-click re-centring)
//   POST /api/implicitize         a parametrization's verified implicit equation
// Requests are form-encoded (application/x-www-form-urlencoded). A newer /api/render of the
// same `client` cancels the one in flight (render::ExecutionSettings::cancel); at most a few
// renders run at once and a bounded number wait, the rest get 503.
//
// Safety: the page cannot name files (only the command line can); bodies, equations, images and
// parameter counts are bounded; every request is answered, malformed or hostile ones with an
// error, and the server keeps serving.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "algebra/compiled.h"
#include "render/scene.h"

namespace locus::view {

struct ViewLimits {
    std::size_t max_body_bytes = 64 * 1024;
    std::size_t max_equation_chars = 4000;
    std::size_t max_parameters = 8;
    int max_image_side = 2048;
    double frame_seconds = 20.0;  // a frame that takes longer is stopped (a Timeout answer)
    double fit_seconds = 5.0;     // fitting a new surface's clip region (a Timeout answer)
    int concurrent_renders = 2;
    int waiting_renders = 8;
};

// What the command line named. An equation (or a parametrization's untrimmed implicit
// equation) goes to the page, which renders it like one typed there; a scene file, patches or a
// trimmed parametrization is compiled here, and the page renders it as source=startup until
// the user types an equation.
struct Startup {
    std::string label;     // for the page's title: the equation or the file's name
    std::string equation;  // the equation for the page, or empty
    render::Scene scene;   // for source=startup (nothing compiled: an equation)
    std::vector<algebra::CompiledPolynomial> compiled;
};

struct ViewOptions {
    std::string host = "127.0.0.1";
    int port = 8765;         // 0: any free port
    int render_threads = 0;  // 0: every core
    ViewLimits limits;
    std::optional<Startup> startup;
};

class ViewServer {
  public:
    explicit ViewServer(ViewOptions options);
    ~ViewServer();
    ViewServer(const ViewServer&) = delete;
    ViewServer& operator=(const ViewServer&) = delete;

    // Binds the socket; returns the port (the chosen one for port 0). Throws Error when the
    // address cannot be bound.
    int bind();
    // Serves until stop() (from another thread or a signal handler's thread).
    void run();
    void stop();

  private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace locus::view
