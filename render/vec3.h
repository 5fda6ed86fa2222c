// Small vector helpers over GLM for the renderer: world-space points and directions are
// glm::dvec3 (double, since the root finders and the exact reference work in double).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

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

// The largest |component|, and the length computed on v scaled by it: glm::length squares the
// components, which overflows past 1e154 and underflows to 0 below 1e-154 where the length
// itself is an ordinary double (a clip sphere of radius 1e200 had NaN ends, a camera 1e-300
// from its target was "at" it).
inline double largest_component(const Vec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}
inline double scaled_length(const Vec3& v) {
    const double largest = largest_component(v);
    return largest > 0.0 && std::isfinite(largest) ? largest * glm::length(v / largest) : largest;
}
// v / |v| the same way; the zero vector for a zero or non-finite v.
inline Vec3 scaled_normalize(const Vec3& v) {
    const double largest = largest_component(v);
    if (!(largest > 0.0) || !std::isfinite(largest)) {
        return Vec3(0.0);
    }
    return glm::normalize(v / largest);
}

// "(x, y, z)" with `digits` significant digits (%g: 1e-300 prints as itself, not 0.000000).
inline std::string format_point(const Vec3& p, int digits = 4) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.*g, %.*g, %.*g)", digits, p.x, digits, p.y, digits, p.z);
    return text;
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
