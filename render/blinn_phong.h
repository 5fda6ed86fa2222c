// The shading core both renderers share: which side of a surface the viewer sees, and the
// Blinn–Phong sum over the lights. What differs between them is only how they decide that a
// light is visible (exact shadow rays through the surface tracers, or sphere-traced
// transmittance through a scene tree) and how they estimate ambient occlusion; those come in
// as arguments.
#pragma once

#include <algorithm>
#include <cmath>
#include <span>

#include "render/material.h"
#include "render/scene.h"

namespace locus::render {

// The unit normal towards the viewer, and whether the viewer sees the side where f > 0.
struct FacingSide {
    Vec3 normal;
    bool outside = true;
};

// `gradient`: ∇f at the hit; `view`: unit vector from the hit towards the eye. Where ∇f
// vanishes or is not finite (a singular point, hit exactly), the normal faces the viewer and
// the outside is seen, so no pixel is ever NaN.
inline FacingSide facing_side(Vec3 gradient, const Vec3& view) {
    const double length = glm::length(gradient);
    if (!(length > 0.0) || !std::isfinite(length)) {
        return {view, true};
    }
    gradient *= 1.0 / length;  // one division instead of three
    if (glm::dot(gradient, view) < 0.0) {
        return {-gradient, false};
    }
    return {gradient, true};
}

// Whether specular_power takes x^e by squaring (a whole exponent up to 1024).
inline bool squares_for_power(double e) {
    return e >= 0.0 && e <= 1024.0 && e == std::floor(e);
}

// x^e, by squaring when the exponent is a whole number (the default 48 is): std::pow was 3 %
// of a degree-6 frame, two calls per hit.
inline double specular_power(double x, double e) {
    if (squares_for_power(e)) {
        auto n = static_cast<unsigned>(e);
        double result = 1.0;
        double square = x;
        while (n != 0) {
            if ((n & 1u) != 0) {
                result *= square;
            }
            square *= square;
            n >>= 1u;
        }
        return result;
    }
    return std::pow(x, e);
}

// The colour of a hit: ambient (scaled by `ambient_factor`, the caller's occlusion estimate)
// plus, for each light on the side the normal faces, diffuse and a white specular highlight,
// scaled by `visibility(light, to_light, distance)`, the fraction of the light that reaches
// the point (`to_light` is unit; `distance` is infinite for directional lights).
// Precondition: `material` is resolved (Material::at), `side.normal` and `view` are unit.
template <class Visibility>
Vec3 blinn_phong(const Material& material, const FacingSide& side, const Vec3& point,
                 const Vec3& view, std::span<const Light> lights, double ambient_factor,
                 Visibility&& visibility) {
    const Vec3 base = side.outside ? material.color : material.inside;
    const Vec3& n = side.normal;
    Vec3 color = (material.ambient * ambient_factor) * base;
    for (const Light& light : lights) {
        Vec3 to_light = light.direction;
        double distance = INFINITY;
        if (light.kind == Light::Kind::point) {
            to_light = light.position - point;
            distance = scaled_length(to_light);  // a light 1e200 away is not at infinity
            to_light /= distance;
        }
        const double cosine = glm::dot(n, to_light);
        if (cosine <= 0.0) {
            continue;
        }
        const double visible = visibility(light, to_light, distance);
        if (visible <= 0.0) {
            continue;
        }
        const Vec3 half = glm::normalize(to_light + view);
        const double highlight =
            specular_power(std::max(0.0, glm::dot(n, half)), material.shininess);
        color += (visible * light.intensity) * light.color *
                 (material.diffuse * cosine * base + material.specular * highlight * Vec3(1.0));
    }
    return color;
}

}  // namespace locus::render
