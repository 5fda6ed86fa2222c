// How a surface looks: one type for the surfaces of a plain scene and for every node of an SDF
// scene tree, read from the same scene-file keys (render/detail/surface_keys.h) and shaded by
// one Blinn–Phong core (render/blinn_phong.h).
#pragma once

#include <cmath>
#include <optional>

#include "render/vec3.h"

namespace locus::render {

// Blinn–Phong, two-sided: the side where f > 0 (`color`, the side ∇f points to) and the side
// where f < 0 (`inside`) have their own colours, as in surf and SURFER; closed solids never show
// their inside. The defaults are the two-sided look of algebraic surfaces, orange and blue.
//
// `checker`, when set, alternates `color` (and `inside`) with it on cubes of `checker_size`;
// at() resolves the pattern at a point, and shaders only ever see resolved materials.
struct Material {
    Vec3 color{0.95, 0.62, 0.22};
    Vec3 inside{0.30, 0.52, 0.90};
    double ambient = 0.15;
    double diffuse = 0.75;
    double specular = 0.35;
    double shininess = 48.0;
    std::optional<Vec3> checker;
    double checker_size = 1.0;

    // One colour on both sides, everything else at its default.
    static Material plain(const Vec3& color) {
        Material m;
        m.color = m.inside = color;
        return m;
    }

    // The material at `p`, in the coordinates the pattern lives in (a leaf's own coordinates
    // in a scene tree, world coordinates for a plain surface), without its pattern. Callers
    // ask just inside the surface, so that a floor lying on a cell boundary (y = 0) gets one
    // layer of cells, not a rounding-dependent mix of two.
    Material at(const Vec3& p) const {
        Material resolved = *this;
        resolved.checker.reset();
        if (checker) {
            const Vec3 cell = glm::floor(p / checker_size);
            if (static_cast<long long>(cell.x + cell.y + cell.z) % 2 != 0) {
                resolved.color = resolved.inside = *checker;
            }
        }
        return resolved;
    }
};

// Every parameter mixed linearly (smooth blends mix their children's resolved materials).
inline Material mix(const Material& a, const Material& b, double weight_of_b) {
    const double w = weight_of_b;
    Material m;
    m.color = a.color + w * (b.color - a.color);
    m.inside = a.inside + w * (b.inside - a.inside);
    m.ambient = a.ambient + w * (b.ambient - a.ambient);
    m.diffuse = a.diffuse + w * (b.diffuse - a.diffuse);
    m.specular = a.specular + w * (b.specular - a.specular);
    m.shininess = a.shininess + w * (b.shininess - a.shininess);
    return m;
}

}  // namespace locus::render
