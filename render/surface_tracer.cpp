#include "render/surface_tracer.h"

#include <algorithm>
#include <cmath>

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

SurfaceTracer::SurfaceTracer(const algebra::CompiledPolynomial& f, TraceMethod method, double scale)
    : f_(&f), restrictor_(f.terms()), method_(method), finder_(finder_for(method)), scale_(scale) {}

RootResult SurfaceTracer::first_hit(const Ray& ray, Interval interval,
                                    const RayPolynomial* restriction,
                                    double restriction_origin) const {
    if (interval.is_empty()) {
        return {};
    }
    switch (method_) {
    case TraceMethod::exact: {
        const algebra::ExactRoot root = algebra::exact_first_root(
            *f_, to_point(ray.origin), to_point(ray.direction), interval.lo, interval.hi);
        RootResult result;
        result.work = 1;
        if (root.status == algebra::ExactRoot::Status::miss) {
            result.status = RootStatus::miss;
        } else {
            // A ray inside the surface meets it at once.
            result.status = RootStatus::hit;
            result.t = root.t;
        }
        return result;
    }
    case TraceMethod::sphere_gradient:
        return sphere_trace_gradient(*f_, ray, interval, 1e-7 * scale_);
    default:
        break;
    }
    if (restriction != nullptr) {
        return on_restriction(*restriction, restriction_origin, interval, ray);
    }
    const double middle = 0.5 * (interval.lo + interval.hi);
    const RayPolynomial computed = restrictor_.restrict_to(ray.at(middle), ray.direction);
    return on_restriction(computed, middle, interval, ray);
}

RootResult SurfaceTracer::on_restriction(const RayPolynomial& restriction, double origin,
                                         Interval interval, const Ray& ray) const {
    const Interval shifted{interval.lo - origin, interval.hi - origin};
    RootResult found;
    if (method_ == TraceMethod::sphere_lipschitz) {
        found = sphere_trace_lipschitz(restriction, shifted,
                                       1e-9 * scale_ / glm::length(ray.direction));
    } else {
        found = first_root(finder_, restriction, shifted.lo, shifted.hi);
        if (found.status == RootStatus::unknown && method_ != TraceMethod::bernstein) {
            // The method could not decide (an inconsistent Sturm chain, an iteration cap):
            // Bernstein subdivision answers the same question from the same coefficients.
            const int work = found.work;
            found = BernsteinRootFinder{}.first_root(restriction, shifted.lo, shifted.hi);
            found.work += work;
        }
    }
    found.t = std::clamp(found.t + origin, interval.lo, interval.hi);
    return found;
}

}  // namespace locus::render
