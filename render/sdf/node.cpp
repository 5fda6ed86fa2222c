#include "render/sdf/node.h"

#include <algorithm>
#include <stdexcept>

namespace locus::render::sdf {

std::string_view to_string(DistanceKind kind) {
    switch (kind) {
    case DistanceKind::exact:
        return "exact";
    case DistanceKind::bound:
        return "bound";
    case DistanceKind::estimate:
        return "estimate";
    }
    return "?";
}

bool Bounds::is_finite() const {
    for (int i = 0; i < 3; ++i) {
        if (!std::isfinite(min[i]) || !std::isfinite(max[i])) {
            return false;
        }
    }
    return true;
}

double Bounds::distance(const Vec3& p) const {
    const Vec3 outside = glm::max(glm::max(min - p, p - max), Vec3(0.0));
    return glm::length(outside);
}

Interval Bounds::clip(const Ray& ray, Interval limits) const {
    for (int i = 0; i < 3; ++i) {
        if (ray.direction[i] == 0.0) {
            if (ray.origin[i] < min[i] || ray.origin[i] > max[i]) {
                return {1.0, 0.0};
            }
            continue;
        }
        const double inverse = 1.0 / ray.direction[i];
        double a = (min[i] - ray.origin[i]) * inverse;
        double b = (max[i] - ray.origin[i]) * inverse;
        if (a > b) {
            std::swap(a, b);
        }
        // NaN from ∞·0 cannot occur: the direction component is non-zero.
        limits.lo = std::max(limits.lo, a);
        limits.hi = std::min(limits.hi, b);
    }
    return limits;
}

Bounds Bounds::united(const Bounds& other) const {
    return {glm::min(min, other.min), glm::max(max, other.max)};
}

Bounds Bounds::intersected(const Bounds& other) const {
    return {glm::max(min, other.min), glm::min(max, other.max)};
}

Bounds Bounds::grown(double margin) const {
    return {min - Vec3(margin), max + Vec3(margin)};
}

Vec3 Node::gradient(const Vec3& p, double h) const {
    // Four samples on a tetrahedron (one fewer than central differences on the axes).
    const Vec3 a{1, -1, -1}, b{-1, -1, 1}, c{-1, 1, -1}, d{1, 1, 1};
    return (a * value(p + h * a) + b * value(p + h * b) + c * value(p + h * c) +
            d * value(p + h * d)) /
           (4.0 * h);
}

RootResult Node::first_hit(const Ray&, Interval) const {
    throw std::logic_error("Node::first_hit on a node that does not trace exactly");
}

}  // namespace locus::render::sdf
