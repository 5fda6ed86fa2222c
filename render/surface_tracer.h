// First hit of a ray with one compiled surface by any TraceMethod: the one code path shared by
// the renderer (primary, shadow and occlusion rays) and `locus trace`.
//
// Methods that work on the restriction F(t) accept it precomputed (primary rays come from the
// per-frame RayFamily) or compute it with the LineRestrictor. Their root is then polished by
// one Newton step on f itself, evaluated directly at the point, which removes the rounding the
// restriction's coefficients carry. The step is taken only when it is small against the
// interval, so a double root (where ∇f·d ≈ 0) is left as found. When a univariate method cannot
// decide (RootStatus::unknown: an inconsistent floating-point Sturm chain, an iteration cap),
// Bernstein subdivision answers from the same coefficients; the work of both is counted.
#pragma once

#include "algebra/compiled.h"
#include "render/ray_restriction.h"
#include "render/root_finder.h"
#include "render/trace_method.h"
#include "render/vec3.h"

namespace locus::render {

class SurfaceTracer {
  public:
    // `scale`: the size of the scene (a clip radius), which sets the sphere-tracing tolerances.
    // The polynomial must outlive the tracer.
    SurfaceTracer(const algebra::CompiledPolynomial& f, TraceMethod method, double scale);

    TraceMethod method() const { return method_; }
    const algebra::CompiledPolynomial& polynomial() const { return *f_; }

    // The smallest t in `interval` with f(ray.at(t)) = 0. `restriction`, when given, must be
    // F(restriction_origin + s) = f(ray.at(restriction_origin + s)) as a polynomial in s;
    // otherwise it is computed about the interval's midpoint, where the terms of f have the
    // size of f near the surface rather than at the ray's origin.
    RootResult first_hit(const Ray& ray, Interval interval,
                         const RayPolynomial* restriction = nullptr,
                         double restriction_origin = 0.0) const;

  private:
    RootResult polished(const Ray& ray, Interval interval, RootResult found) const;
    RootResult on_restriction(const RayPolynomial& restriction, double origin, Interval interval,
                              double speed) const;

    const algebra::CompiledPolynomial* f_;
    LineRestrictor restrictor_;
    TraceMethod method_;
    AnyRootFinder finder_;
    double scale_;
};

}  // namespace locus::render
