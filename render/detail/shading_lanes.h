// Internal to render/: Shader::shade_hits' arrays and its AVX-512 kernels, which compute what
// facing_side and blinn_phong (render/blinn_phong.h) compute for one hit, eight hits at a time,
// with the same operations in the same order on each lane, so that the results are those of
// Shader::shade bit for bit: glm's dot is (a.x·b.x + a.y·b.y) + a.z·b.z, its normalize
// v·(1/√(v·v)), and no multiply-add is fused (the build keeps them out of the scalar code as
// well: -ffp-contract=off). Callers check that the processor runs AVX-512F first.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "render/scene.h"
#include "render/shading.h"

namespace locus::render::detail {

// One entry a hit (a thread's, kept between rows).
struct HitLanes {
    std::vector<double> dx, dy, dz;     // the ray's direction
    std::vector<double> gx, gy, gz;     // ∇f there
    std::vector<double> nx, ny, nz;     // the unit normal towards the viewer (facing_sides_avx512)
    std::vector<double> vx, vy, vz;     // the unit vector towards the eye (facing_sides_avx512)
    std::vector<std::uint8_t> outside;  // the viewer sees the side where f > 0
    // The seen side's material: its colour and the Blinn–Phong weights and (whole) exponent.
    std::vector<double> bx, by, bz, ambient, diffuse, specular;
    std::vector<std::uint64_t> shininess;
    std::vector<double> visible;  // light l's visibility of hit i at [l·n + i], with shadows

    void resize(std::size_t n, std::size_t lights);
};

// From the directions and gradients of hits [0, n): the view vectors, the normals and which
// side is seen, as facing_side(∇f, −normalize(d)).
void facing_sides_avx512(HitLanes& h, std::size_t n);

// blinn_phong of hits [0, n) with an ambient factor of 1 and directional `lights` (their
// visibility from h.visible when `shadows`, else 1), into out[i].color, and the normals into
// out[i].normal.
void blinn_phong_avx512(const HitLanes& h, std::size_t n, std::span<const Light> lights,
                        bool shadows, ShadingResult* out);

}  // namespace locus::render::detail
