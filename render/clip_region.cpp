#include "render/clip_region.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace locus::render {

namespace {

// The roots of a t² + 2 b t + c = 0 (a > 0), solved without cancellation; empty when none.
Interval quadratic_interval(double a, double b, double c) {
    const double discriminant = b * b - a * c;
    if (!(a > 0.0) || !(discriminant >= 0.0)) {
        return {1.0, 0.0};
    }
    const double q = -(b + std::copysign(std::sqrt(discriminant), b));
    double t0 = q / a;
    double t1 = q != 0.0 ? c / q : t0;
    if (t0 > t1) {
        std::swap(t0, t1);
    }
    return {t0, t1};
}

Interval clip_sphere(const ClipSphere& sphere, const Ray& ray) {
    // |o + t·d − c|² = r². Its squares of coordinates overflowed past 1e154 (a clip sphere of
    // radius 1e200 gave NaN ends, and every ray missed) and underflowed below 1e-154. Between
    // 1e-100 and 1e100 they cannot, and the equation is solved as it stands (every primary ray
    // comes here); outside, in units where the offset o − c and the radius are at most 1 and d
    // at most 1 long: t = τ·s/s_d for the root τ of |u + τ·e|² = ρ² (u = (o − c)/s,
    // ρ = r/s, e = d/s_d).
    const Vec3 offset = ray.origin - sphere.center;
    const double s = std::max(largest_component(offset), sphere.radius);
    const double s_d = largest_component(ray.direction);
    if (s < 1e100 && s > 1e-100 && s_d < 1e100 && s_d > 1e-100) {
        return quadratic_interval(glm::dot(ray.direction, ray.direction),
                                  glm::dot(offset, ray.direction),
                                  glm::dot(offset, offset) - sphere.radius * sphere.radius);
    }
    if (!(s > 0.0) || !(s_d > 0.0) || !std::isfinite(s) || !std::isfinite(s_d)) {
        return {1.0, 0.0};
    }
    const Vec3 u = offset / s, e = ray.direction / s_d;
    const double rho = sphere.radius / s;
    const Interval tau =
        quadratic_interval(glm::dot(e, e), glm::dot(u, e), glm::dot(u, u) - rho * rho);
    const double to_t = s / s_d;
    return {tau.lo * to_t, tau.hi * to_t};
}

Interval clip_box(const ClipBox& box, const Ray& ray) {
    Interval result{-INFINITY, INFINITY};
    for (int axis = 0; axis < 3; ++axis) {
        const double o = ray.origin[axis], d = ray.direction[axis];
        if (d == 0.0) {
            if (o < box.min[axis] || o > box.max[axis]) {
                return {1.0, 0.0};
            }
            continue;
        }
        double t0 = (box.min[axis] - o) / d;
        double t1 = (box.max[axis] - o) / d;
        if (t0 > t1) {
            std::swap(t0, t1);
        }
        result.lo = std::max(result.lo, t0);
        result.hi = std::min(result.hi, t1);
    }
    return result;
}

}  // namespace

Interval clip(const ClipRegion& region, const Ray& ray, Interval limits) {
    const Interval inside = std::visit(
        [&](const auto& r) {
            if constexpr (std::is_same_v<std::decay_t<decltype(r)>, ClipSphere>) {
                return clip_sphere(r, ray);
            } else {
                return clip_box(r, ray);
            }
        },
        region);
    return {std::max(inside.lo, limits.lo), std::min(inside.hi, limits.hi)};
}

ClipSphere bounding_sphere(const ClipRegion& region) {
    if (const auto* sphere = std::get_if<ClipSphere>(&region)) {
        return *sphere;
    }
    const auto& box = std::get<ClipBox>(region);
    return {(box.min + box.max) * 0.5, scaled_length(box.max - box.min) * 0.5};
}

}  // namespace locus::render
