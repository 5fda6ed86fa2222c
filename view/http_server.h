// The HTTP side of `locus view`, behind an interface: cpp-httplib as Debian builds it brings
// OpenSSL and Brotli with it (five shared libraries, 2.3 ms at every start of the executable),
// so it lives in a module (view/http_module.cpp) that only `locus view` loads — the same way the
// image writer keeps OpenImageIO out of every other command (render/loadable_module.h).
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace locus::view {

struct HttpRequest {
    // The form fields (application/x-www-form-urlencoded body or query string), in order.
    std::multimap<std::string, std::string> params;
    // The first value of the field `name`, or "" when there is none.
    std::string param(const std::string& name) const {
        const auto found = params.lower_bound(name);  // the first of equal keys, in order
        return found == params.end() || found->first != name ? std::string() : found->second;
    }
};

struct HttpResponse {
    int status = 200;
    std::string body;
    std::string content_type;
    std::vector<std::pair<std::string, std::string>> headers;

    void set_header(std::string name, std::string value) {
        headers.emplace_back(std::move(name), std::move(value));
    }
    void set_content(std::string content, std::string type) {
        body = std::move(content);
        content_type = std::move(type);
    }
};

using HttpHandler = std::function<void(const HttpRequest&, HttpResponse&)>;

struct HttpServerSettings {
    std::size_t max_body_bytes = 64 * 1024;  // larger requests get 413
    int threads = 8;                         // requests served at once
};

class HttpServer {
  public:
    virtual ~HttpServer() = default;
    virtual void get(const std::string& path, HttpHandler handler) = 0;
    virtual void post(const std::string& path, HttpHandler handler) = 0;
    // For requests no route takes and the errors the server answers itself (413 for a body past
    // the limit): the response comes with that status and the server's body, if any.
    virtual void on_error(HttpHandler handler) = 0;
    // For an exception a handler let through.
    virtual void on_exception(HttpHandler handler) = 0;
    // The port bound (for `port` 0, the one chosen), or −1 when the address cannot be bound.
    virtual int bind(const std::string& host, int port) = 0;
    // Serves until stop(); returns at once when stop() came first.
    virtual void listen_after_bind() = 0;
    virtual bool is_running() const = 0;
    virtual void stop() = 0;
};

// A server from the module (linked in under the sanitizers: view/CMakeLists.txt). Throws Error
// when the module cannot be loaded.
std::unique_ptr<HttpServer> make_http_server(const HttpServerSettings& settings);

}  // namespace locus::view
