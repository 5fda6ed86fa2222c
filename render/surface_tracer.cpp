#include "render/surface_tracer.h"

#include <algorithm>
#include <cmath>
#include <string_view>

#include "render/root_finders/detail/univariate.h"
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
                                    const RayPolynomial* restriction, double restriction_origin,
                                    double hint) const {
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
        return on_restriction(*restriction, restriction_origin, interval, ray, hint);
    }
    const double middle = 0.5 * (interval.lo + interval.hi);
    const RayPolynomial computed = restrictor_.restrict_to(ray.at(middle), ray.direction);
    return on_restriction(computed, middle, interval, ray, hint);
}

RootResult SurfaceTracer::on_restriction(const RayPolynomial& restriction, double origin,
                                         Interval interval, const Ray& ray, double hint) const {
    const Interval shifted{interval.lo - origin, interval.hi - origin};
    RootResult found;
    if (method_ == TraceMethod::sphere_lipschitz) {
        found = sphere_trace_lipschitz(restriction, shifted,
                                       1e-9 * scale_ / glm::length(ray.direction));
        found.t = std::clamp(found.t + origin, interval.lo, interval.hi);
        return found;
    }
    found = first_root(finder_, restriction, shifted.lo, shifted.hi, hint - origin);
    // Reasons are compared as text: two uses of one string literal need not share an address
    // (they did not in the debug build, and every second opinion was silently skipped). Most
    // answers carry no reason, and measuring one (strlen) was 1 % of a sextic frame.
    const std::string_view reason =
        found.reason != nullptr && found.reason[0] != '\0' ? found.reason : std::string_view{};
    const bool near_multiple = reason == kNearCommonFactor;
    if (found.status != RootStatus::unknown && (near_multiple || reason == kSecondOpinion)) {
        // Multiple or very close roots: Laguerre with deflation separates what the Sturm
        // chain merged (the stability atlas' near-double roots); the earlier hit wins.
        const RootResult second =
            LaguerreRootFinder{}.first_root(restriction, shifted.lo, shifted.hi);
        found.work += second.work;
        // "Earlier" beyond the accuracy of multiple roots (Laguerre has a triple root only
        // to about 1e-6 of the interval), so a triple point keeps the better of the two.
        const double reach = 1e-4 * (shifted.hi - shifted.lo);
        auto magnitude_at = [&](double t) {
            return std::abs(detail::horner(restriction.c.data(), restriction.degree, t));
        };
        if (second.status == RootStatus::hit &&
            (found.status == RootStatus::miss || second.t < found.t - reach ||
             // The same multiple root: keep the one where F is smaller (Sturm's bracketed
             // refinement stops 2e-6 short of a triple point that Laguerre lands on).
             (std::abs(second.t - found.t) <= reach &&
              magnitude_at(second.t) < magnitude_at(found.t)))) {
            found.status = RootStatus::hit;
            found.t = second.t;
        }
    }
    if (found.status == RootStatus::unknown && method_ != TraceMethod::bernstein) {
        // The method could not decide (an inconsistent Sturm chain, an iteration cap):
        // Bernstein subdivision answers the same question from the same coefficients.
        const int work = found.work;
        found = BernsteinRootFinder{}.first_root(restriction, shifted.lo, shifted.hi);
        found.work += work;
    }
    if (near_multiple && found.status == RootStatus::miss) {
        // A near-double root that both floating methods call a miss: a near-tangent ray whose
        // two roots may lie closer than doubles resolve (two spheres 1e-8 apart, at their
        // silhouette; stability atlas twin_spheres_1e-8). The certified method decides.
        const algebra::ExactRoot root = algebra::exact_first_root(
            *f_, to_point(ray.origin), to_point(ray.direction), interval.lo, interval.hi);
        ++found.work;
        if (root.status != algebra::ExactRoot::Status::miss) {
            found.status = RootStatus::hit;
            found.t = root.t;
        }
        return found;
    }
    found.t = std::clamp(found.t + origin, interval.lo, interval.hi);
    return found;
}

}  // namespace locus::render
