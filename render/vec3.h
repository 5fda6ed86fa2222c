// Small vector helpers over GLM for the renderer: world-space points and directions are
// glm::dvec3 (double, since the root finders and the exact reference work in double).
#pragma once

#include <array>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace locus::render {

using Vec3 = glm::dvec3;

// To and from algebra::Point3 (the same std::array type), without including algebra/ here.
inline std::array<double, 3> to_point(const Vec3& v) {
    return {v.x, v.y, v.z};
}
inline Vec3 to_vec(const std::array<double, 3>& p) {
    return {p[0], p[1], p[2]};
}

struct Ray {
    Vec3 origin;
    Vec3 direction;  // not necessarily unit length; t is measured in multiples of it
    Vec3 at(double t) const { return origin + t * direction; }
};

// A parameter interval [lo, hi] along a ray; empty when lo > hi.
struct Interval {
    double lo = 0.0;
    double hi = 0.0;
    bool is_empty() const { return !(lo <= hi); }
};

}  // namespace locus::render
