// Small vector helpers over GLM for the renderer: world-space points and directions are
// glm::dvec3 (double, since the root finders and the exact reference work in double).
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "algebra/compiled.h"

namespace locus::render {

using Vec3 = glm::dvec3;

inline algebra::Point3 to_point(const Vec3& v) {
    return {v.x, v.y, v.z};
}
inline Vec3 to_vec(const algebra::Point3& p) {
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
