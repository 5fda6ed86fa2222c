#include "render/clip_region.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace locus::render {

namespace {

Interval clip_sphere(const ClipSphere& sphere, const Ray& ray) {
    // |o + t·d − c|² = r²: a t² + 2 b t + c = 0, solved without cancellation.
    const Vec3 offset = ray.origin - sphere.center;
    const double a = glm::dot(ray.direction, ray.direction);
    const double b = glm::dot(offset, ray.direction);
    const double c = glm::dot(offset, offset) - sphere.radius * sphere.radius;
    const double discriminant = b * b - a * c;
    if (!(a > 0.0) || discriminant < 0.0) {
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
    return {(box.min + box.max) * 0.5, glm::length(box.max - box.min) * 0.5};
}

}  // namespace locus::render
