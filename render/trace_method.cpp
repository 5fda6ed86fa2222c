#include "render/trace_method.h"

#include <array>
#include <string>

#include "algebra/error.h"

namespace locus::render {

namespace {
constexpr std::array<TraceMethod, 8> kMethods = {
    TraceMethod::certified,        TraceMethod::sturm, TraceMethod::bernstein,
    TraceMethod::laguerre,         TraceMethod::eigen, TraceMethod::sphere_gradient,
    TraceMethod::sphere_lipschitz, TraceMethod::exact};
}  // namespace

std::span<const TraceMethod> all_trace_methods() {
    return kMethods;
}

std::string_view to_string(TraceMethod method) {
    switch (method) {
    case TraceMethod::certified:
        return "certified";
    case TraceMethod::sturm:
        return "sturm";
    case TraceMethod::bernstein:
        return "bernstein";
    case TraceMethod::laguerre:
        return "laguerre";
    case TraceMethod::eigen:
        return "eigen";
    case TraceMethod::sphere_gradient:
        return "sphere-gradient";
    case TraceMethod::sphere_lipschitz:
        return "sphere-lipschitz";
    case TraceMethod::exact:
        return "exact";
    }
    return "?";
}

TraceMethod parse_trace_method(std::string_view name) {
    std::string valid;
    for (TraceMethod method : kMethods) {
        if (to_string(method) == name) {
            return method;
        }
        valid += valid.empty() ? "" : ", ";
        valid += to_string(method);
    }
    throw InputError("method '" + std::string(name) + "'",
                     "unknown method; expected one of " + valid);
}

}  // namespace locus::render
