// A surface's own coordinates. An equation far from the origin is badly conditioned in the
// monomial basis at the origin: the teapot's spout patch (degree 18, at x ≈ 3) has terms 10^10
// times larger than its values near the surface, so rigorous double bounds cannot decide a
// ray and the certified tracer falls back to exact arithmetic on almost every ray. Written in
// coordinates centred on the patch and scaled to it, x' = (x − origin) / scale, the same surface
// has terms of the size of its values, and doubles decide (128² of the spout: 25 s → 0.2 s).
//
// The frame moves rays, not the surface: a ray o + t·d becomes o' + t·d' with the same t, where
// d' = d / scale exactly (scale is a power of two) and o' = fl(o − origin) / scale, the origin
// rounded once. So a framed surface's certified answers are exact for the ray o' + t·d' — a ray
// within 2⁻⁵³·|o − origin| of the given one, the size of the rounding that computed it — and
// Camera::in_frame gives the camera whose rays are exactly these (the certified ray family's
// premise).
#pragma once

#include <cmath>

#include "render/root_finder.h"
#include "render/vec3.h"

namespace locus::render {

struct SurfaceFrame {
    Vec3 origin{0.0};
    double scale = 1.0;  // a power of two

    bool is_identity() const { return origin == Vec3(0.0) && scale == 1.0; }
    Vec3 to_local(const Vec3& p) const { return (p - origin) * (1.0 / scale); }
    Vec3 to_world(const Vec3& p) const { return origin + p * scale; }
    Ray to_local(const Ray& ray) const {
        return {(ray.origin - origin) * (1.0 / scale), ray.direction * (1.0 / scale)};
    }
};

// A power of two for SurfaceFrame::scale: the smallest at least `size` (1 for sizes that are not
// positive and finite).
inline double power_of_two_at_least(double size) {
    if (!(size > 0.0) || !std::isfinite(size)) {
        return 1.0;
    }
    int exponent = 0;
    std::frexp(size, &exponent);  // size = m·2^exponent, m in [0.5, 1)
    return std::ldexp(1.0, exponent);
}

}  // namespace locus::render
