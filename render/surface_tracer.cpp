#include "render/surface_tracer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string_view>

#include "render/sphere_tracing.h"

namespace locus::render {

namespace {
AnyRootFinder finder_for(TraceMethod method) {
    switch (method) {
    case TraceMethod::bernstein:
        return BernsteinRootFinder{};
    case TraceMethod::laguerre:
        return LaguerreRootFinder{};
    case TraceMethod::eigen:
        return CompanionRootFinder{};
    default:
        return SturmRootFinder{};
    }
}
}  // namespace

SurfaceTracer::SurfaceTracer(const algebra::CompiledPolynomial& f, TraceMethod method, double scale,
                             double tolerance, const SurfaceFrame& frame)
    : f_(&f),
      restrictor_(f.terms()),
      certified_(f),
      method_(method),
      finder_(finder_for(method)),
      scale_(scale / frame.scale),
      tolerance_(tolerance),
      frame_(frame) {}

Vec3 SurfaceTracer::gradient(const Vec3& world_point) const {
    return to_vec(f_->gradient(to_point(frame_.to_local(world_point))));
}

std::optional<RootResult> SurfaceTracer::without_restriction(const Ray& ray,
                                                             Interval& interval) const {
    if (interval.is_empty()) {
        return RootResult{};
    }
    switch (method_) {
    case TraceMethod::certified:
        return certified_.first_hit(ray, interval, tolerance_);
    case TraceMethod::exact: {
        const algebra::ExactRoot root = algebra::exact_first_root(
            *f_, to_point(ray.origin), to_point(ray.direction), interval.lo, interval.hi, true);
        RootResult result;
        result.work = 1;
        result.decided_by = Decision::exact;
        if (root.status == algebra::ExactRoot::Status::miss) {
            result.status = RootStatus::miss;
        } else {
            // A ray lying in the surface meets it at once.
            result.status = RootStatus::hit;
            result.t = root.t;
        }
        return result;
    }
    default:
        break;
    }
    // The search interval is (lo, hi]: the floating-point methods, which take closed intervals,
    // start at the next double after lo = 0 (a ray starting on the surface is not hit at 0).
    if (interval.lo == 0.0) {
        interval.lo = std::numeric_limits<double>::denorm_min();
    }
    if (method_ == TraceMethod::sphere_gradient) {
        return sphere_trace_gradient(*f_, ray, interval, 1e-7 * scale_);
    }
    return std::nullopt;
}

RootResult SurfaceTracer::first_hit(const Ray& world_ray, Interval interval, double hint) const {
    const Ray ray = frame_.to_local(world_ray);
    if (const std::optional<RootResult> answer = without_restriction(ray, interval)) {
        return *answer;
    }
    const double middle = 0.5 * (interval.lo + interval.hi);
    const RayRestriction computed{restrictor_.restrict_to(ray.at(middle), ray.direction), middle};
    return on_restriction(computed, interval, ray, hint);
}

RootResult SurfaceTracer::first_hit(const Ray& world_ray, Interval interval,
                                    NeighbourHint& hint) const {
    if (method_ != TraceMethod::certified || interval.is_empty()) {
        return first_hit(world_ray, interval);
    }
    return certified_.first_hit(frame_.to_local(world_ray), interval, tolerance_, &hint);
}

RootResult SurfaceTracer::occluded(const Ray& world_ray, Interval interval) const {
    if (method_ != TraceMethod::certified) {
        return first_hit(world_ray, interval);
    }
    if (interval.is_empty()) {
        return RootResult{};
    }
    // An unbounded tolerance: the isolating piece's bracket is answer enough.
    return certified_.first_hit(frame_.to_local(world_ray), interval, INFINITY);
}

RootResult SurfaceTracer::first_hit(const Ray& world_ray, Interval interval,
                                    const RayRestriction& restriction, double hint) const {
    const Ray ray = frame_.to_local(world_ray);
    if (const std::optional<RootResult> answer = without_restriction(ray, interval)) {
        return *answer;
    }
    return on_restriction(restriction, interval, ray, hint);
}

RootResult SurfaceTracer::on_restriction(const RayRestriction& restriction, Interval interval,
                                         const Ray& ray, double hint) const {
    const double origin = restriction.origin;
    const Interval shifted{interval.lo - origin, interval.hi - origin};
    RootResult found;
    if (method_ == TraceMethod::sphere_lipschitz) {
        found = sphere_trace_lipschitz(restriction.polynomial, shifted,
                                       1e-9 * scale_ / glm::length(ray.direction));
        found.t = std::clamp(found.t + origin, interval.lo, interval.hi);
        return found;
    }
    // The floating-point methods answer from the rounded restriction alone: no error bound
    // backs their decisions, so they are compared against `certified` and `exact`, not trusted
    // (docs/stability.md). Only an undecided answer is passed on, to Bernstein subdivision on
    // the same coefficients.
    found = first_root(finder_, restriction.polynomial, shifted.lo, shifted.hi, hint - origin);
    if (found.status == RootStatus::unknown && method_ != TraceMethod::bernstein) {
        const int work = found.work;
        found = BernsteinRootFinder{}.first_root(restriction.polynomial, shifted.lo, shifted.hi);
        found.work += work;
    }
    found.t = std::clamp(found.t + origin, interval.lo, interval.hi);
    return found;
}

}  // namespace locus::render
