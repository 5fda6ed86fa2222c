// First hit of a ray with one compiled surface by any TraceMethod: the one code path shared by
// the renderer (primary, shadow and occlusion rays) and `locus trace`.
//
// Methods that work on the restriction F(t) accept it precomputed (primary rays come from the
// per-frame RayFamily) or compute it with the LineRestrictor about the middle of the interval.
// Their roots are not polished on f afterwards: with the restriction expanded near the surface
// the suite's largest distance error is 2.4e-9 (against the 1e-6 × radius the benchmark
// demands), and the Newton step on f that brought it to 1e-12 cost 15–25 % of the frame at
// degree 8–12. When a univariate method cannot decide (RootStatus::unknown: an inconsistent
// floating-point Sturm chain, an iteration cap), Bernstein subdivision answers from the same
// coefficients; the work of both is counted.
#pragma once

#include <limits>
#include <optional>

#include "algebra/compiled.h"
#include "render/certified_tracer.h"
#include "render/ray_restriction.h"
#include "render/root_finder.h"
#include "render/surface_frame.h"
#include "render/trace_method.h"
#include "render/vec3.h"

namespace locus::render {

// f along a ray about one of its points: F(s) = f(ray.at(origin + s)) as a polynomial in s.
struct RayRestriction {
    RayPolynomial polynomial;
    double origin = 0.0;
};

class SurfaceTracer {
  public:
    // `scale`: the size of the scene (a clip radius), which sets the sphere-tracing tolerances.
    // `tolerance`: the relative accuracy of a certified hit (CertifiedTracer).
    // `frame`: the coordinates f is written in (render/surface_frame.h); rays are given in
    // the world's and moved into the frame, with the same t. The polynomial must outlive the
    // tracer.
    SurfaceTracer(const algebra::CompiledPolynomial& f, TraceMethod method, double scale,
                  double tolerance = kTraceTolerance, const SurfaceFrame& frame = {});

    TraceMethod method() const { return method_; }
    const algebra::CompiledPolynomial& polynomial() const { return *f_; }
    const SurfaceFrame& frame() const { return frame_; }
    // The gradient of f at a point of the world, in the frame's units (its direction is the
    // surface normal's in the world: the frame scales uniformly).
    Vec3 gradient(const Vec3& world_point) const;

    // The smallest t in `interval` with f(ray.at(t)) = 0. The methods that need the
    // restriction of f to the ray compute it about the interval's midpoint, where the terms of
    // f have the size of f near the surface rather than at the ray's origin.
    // `hint`: a t near which the hit probably is (the neighbouring pixel's), or NaN; methods
    // that use one (SturmRootFinder) are faster with it, and the answer is the same.
    RootResult first_hit(const Ray& ray, Interval interval,
                         double hint = std::numeric_limits<double>::quiet_NaN()) const;
    // The same, for the certified method guided by the previous ray of an image row
    // (CertifiedTracer::first_hit's hint, which it updates); the other methods ignore it.
    RootResult first_hit(const Ray& ray, Interval interval, NeighbourHint& hint) const;
    // Whether f has a root in `interval`, for shadow and occlusion rays: the answer of
    // first_hit, except that a hit's t is only known to lie in the closed interval — the
    // certified method stops once a root is isolated, without placing it to the tolerance.
    RootResult occluded(const Ray& ray, Interval interval) const;
    // The same with the restriction of f to this ray already known (a RayFamily's row); the
    // methods that do not work on a restriction ignore it.
    RootResult first_hit(const Ray& ray, Interval interval, const RayRestriction& restriction,
                         double hint = std::numeric_limits<double>::quiet_NaN()) const;

    // For the certified method: the ray's ball from a CertifiedRayFamily, the restriction to
    // [t_start, t_start + t_width] (CertifiedTracer::first_hit_from).
    RootResult first_hit_from(const BernsteinBall& ball, double t_start, double t_width,
                              const Ray& ray, const Interval& interval,
                              NeighbourHint* hint = nullptr) const {
        return certified_.first_hit_from(ball, t_start, t_width, frame_.to_local(ray), interval,
                                         tolerance_, hint);
    }

  private:
    // The answer of the methods that need no restriction (certified, exact, sphere_gradient),
    // or nothing; moves a closed interval's lower end 0 to the next double, as the
    // restriction methods expect.
    std::optional<RootResult> without_restriction(const Ray& ray, Interval& interval) const;
    RootResult on_restriction(const RayRestriction& restriction, Interval interval, const Ray& ray,
                              double hint) const;

    const algebra::CompiledPolynomial* f_;
    LineRestrictor restrictor_;
    CertifiedTracer certified_;
    TraceMethod method_;
    AnyRootFinder finder_;
    double scale_;  // in the frame's units
    double tolerance_;
    SurfaceFrame frame_;
};

}  // namespace locus::render
