#include "view/http_server.h"

#ifdef LOCUS_HTTP_LINKED
// Sanitizer builds link the server in (view/CMakeLists.txt says why).
extern "C" locus::view::HttpServer* locus_make_http_server(
    const locus::view::HttpServerSettings* settings);
#else
#include "render/loadable_module.h"
#endif

namespace locus::view {

std::unique_ptr<HttpServer> make_http_server(const HttpServerSettings& settings) {
    using Make = HttpServer* (*)(const HttpServerSettings*);
#ifdef LOCUS_HTTP_LINKED
    const Make make = &locus_make_http_server;
#else
    static const Make make = reinterpret_cast<Make>(render::module_symbol(
        "liblocus_http.so", "view", LOCUS_HTTP_MODULE, "locus_make_http_server", "HTTP server"));
#endif
    return std::unique_ptr<HttpServer>(make(&settings));
}

}  // namespace locus::view
