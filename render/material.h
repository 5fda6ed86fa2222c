// How a surface looks: one type for the surfaces of a plain scene and for every node of an SDF
// scene tree, read from the same scene-file keys (render/detail/surface_keys.h) and shaded by
// one Blinn–Phong core (render/blinn_phong.h).
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "render/footprint.h"
#include "render/vec3.h"

namespace locus::render {

// Blinn–Phong, two-sided: the side where f > 0 (`color`, the side ∇f points to) and the side
// where f < 0 (`inside`) have their own colours, as in surf and SURFER; closed solids never show
// their inside. The defaults are the two-sided look of algebraic surfaces, orange and blue.
//
// `checker`, when set, alternates `color` (and `inside`) with it on cubes of `checker_size`;
// at() resolves the pattern at a point, box-filtered over a sample's footprint, and shaders
// only ever see resolved materials.
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
    //
    // With a footprint (in the same coordinates), the checker is the exact average of the
    // pattern over the box of widths |dx| + |dy| per axis about p (Quilez's filtered checker):
    // the pattern is ±1 = (−1)^(cell x + cell y + cell z), a product of one square wave per
    // axis, so its box average is the product of the waves' averages, each a difference of
    // the wave's integral (a triangle wave). Where a footprint spans many cells the colour
    // tends to the mean of the two instead of aliasing into moiré.
    Material at(const Vec3& p, const Footprint& footprint = {}) const {
        Material resolved = *this;
        resolved.checker.reset();
        if (checker) {
            const Vec3 q = p / checker_size;
            const Vec3 width = (glm::abs(footprint.dx) + glm::abs(footprint.dy)) / checker_size;
            double wave = 1.0;
            for (int axis = 0; axis < 3; ++axis) {
                wave *= square_wave_mean(q[axis], width[axis]);
            }
            const double share = 0.5 * (1.0 - wave);  // of the checker colour
            resolved.color = color + share * (*checker - color);
            resolved.inside = inside + share * (*checker - inside);
        }
        return resolved;
    }

  private:
    // The mean over [x − w/2, x + w/2] of the wave that is +1 on cells with an even floor(x)
    // and −1 on the others; its integral is the triangle wave 1 − |2·fract(x/2) − 1|.
    static double square_wave_mean(double x, double w) {
        if (!(w > 1e-9)) {
            return std::fmod(std::floor(x), 2.0) == 0.0 ? 1.0 : -1.0;
        }
        const auto integral = [](double v) {
            const double half = v * 0.5;
            return 1.0 - std::abs(2.0 * (half - std::floor(half)) - 1.0);
        };
        return std::clamp((integral(x + 0.5 * w) - integral(x - 0.5 * w)) / w, -1.0, 1.0);
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
