// Implicitization as `locus._locus` exposes it: a parametrization's text in, the verified
// equation (or the generators of a non-principal elimination ideal) out.
#include <pybind11/stl.h>

#include <string>

#include "algebra/error.h"
#include "algebra/print.h"
#include "implicit/implicitize.h"
#include "implicit/parametrization.h"
#include "implicit/verify.h"
#include "python/src/bindings.h"

namespace locus::python {
namespace {

const char* image_name(implicit::ImageKind kind) {
    switch (kind) {
    case implicit::ImageKind::hypersurface:
        return "hypersurface";
    case implicit::ImageKind::point:
        return "point";
    case implicit::ImageKind::lower_dimensional:
        return "lower-dimensional";
    case implicit::ImageKind::dense:
        return "dense";
    }
    return "?";
}

// Parses, implicitizes by `method` and verifies by substitution on the map as written (as
// `locus implicitize` does); a result that fails verification is a VerificationError.
py::dict implicitize_text(const std::string& text, const std::string& method,
                          std::optional<double> timeout, int threads) {
    const implicit::Parametrization map = implicit::parse_parametrization(text);
    const auto route = implicit::parse_implicit_method(method);
    if (!route) {
        throw_input_error("method '" + method +
                          "': expected auto, groebner, resultant, interpolate or dixon");
    }
    algebra::GroebnerOptions options;
    options.deadline = deadline_after(timeout);
    options.threads = std::max(1, threads);
    struct Outcome {
        implicit::ImplicitResult result;
        std::string fallback_reason;
        std::optional<algebra::Polynomial> wrong;
    };
    const Outcome outcome = run_interruptible([&] {
        Outcome o;
        o.result = implicit::implicitize_by(map, *route, options, &o.fallback_reason);
        o.wrong = implicit::first_not_vanishing(o.result, map);
        return o;
    });
    const implicit::ImplicitResult& r = outcome.result;
    if (outcome.wrong) {
        throw_verification_error(
            "implicitize: verification FAILED: " + algebra::to_string(*outcome.wrong) +
            " does not vanish on the parametrization");
    }
    py::dict out;
    out["ring"] = Ring{r.ring};
    out["equation"] = r.equation ? py::cast(*r.equation) : py::none();
    out["generators"] = r.generators;
    out["image"] = image_name(r.image);
    out["description"] =
        implicit::describe_image(r.image, map.parameter_ring->num_vars(), map.coordinates.size());
    out["method"] = r.method;
    out["fallback_reason"] = outcome.fallback_reason;
    std::vector<std::string> angles;
    for (const std::size_t v : map.half_angle) {
        angles.push_back(map.parameter_ring->variable_name(v));
    }
    out["angles"] = angles;
    return out;
}

}  // namespace

void bind_implicit(py::module_& m) {
    m.def("_implicitize", &implicitize_text, py::arg("text"), py::arg("method"), py::arg("timeout"),
          py::arg("threads"));
}

}  // namespace locus::python
