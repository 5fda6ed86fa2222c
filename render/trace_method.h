// The ways the renderer and `locus trace` find the first hit of a ray with a surface. All share
// one definition of the answer: the smallest t in the search interval with f(o + t·d) = 0,
// roots of even multiplicity included (render/root_finder.h).
#pragma once

#include <span>
#include <string_view>

namespace locus::render {

enum class TraceMethod {
    certified,         // the default: rigorous error bounds in doubles, then double-double, then
                       // exact arithmetic (render/certified_tracer.h)
    sturm,             // Sturm isolation on F(t), then bracketed Halley
    bernstein,         // Descartes/Bernstein subdivision on F(t)
    laguerre,          // Laguerre with deflation on F(t), polished
    eigen,             // companion-matrix eigenvalues of F(t), polished
    sphere_gradient,   // sphere tracing with the estimate |f|/|∇f| (may overshoot)
    sphere_lipschitz,  // sphere tracing with a Lipschitz bound of F on the segment (never does)
    exact,             // certified: exact F over Q, Descartes isolation, exact bisection
};

// "certified", "sturm", "bernstein", "laguerre", "eigen", "sphere-gradient", "sphere-lipschitz",
// "exact"; anything else is an InputError that lists the valid names.
TraceMethod parse_trace_method(std::string_view name);
std::string_view to_string(TraceMethod method);
std::span<const TraceMethod> all_trace_methods();

}  // namespace locus::render
