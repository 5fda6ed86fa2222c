// Blinn–Phong shading of a hit with several lights, hard or soft shadows traced through the
// same SurfaceTracer as the primary rays, and normal-sampled ambient occlusion.
//
// The normal is ∇f/|∇f| turned towards the viewer; the side the viewer sees selects the
// material colour (outside where f > 0). Where ∇f vanishes or is not finite (a singular point
// of the surface, hit exactly), the rule is: the normal faces the viewer (n = −d/|d|) and the
// outside colour is used, so no pixel is ever NaN.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "render/patch_trim.h"
#include "render/scene.h"
#include "render/surface_tracer.h"

namespace locus::render {

// One surface as the shader sees it.
struct ShadedSurface {
    const SurfaceTracer* tracer;
    ClipRegion clip;
    Material material;
    const PatchTrim* trim = nullptr;  // a patch's surface: shadows only from the patch
};

struct ShadingResult {
    Vec3 color;
    Vec3 normal;   // unit, towards the viewer
    int work = 0;  // root-finder work spent on shadow and occlusion rays
};

// A hit as Shader::shade takes it, for shading many at once (Shader::shade_hits).
struct HitToShade {
    Ray ray;
    std::size_t surface = 0;
    double t = 0.0;
    std::uint64_t seed = 0;
};

class Shader {
  public:
    // `scale`: scene size (largest clip radius), for ray offsets and occlusion distance.
    Shader(std::span<const ShadedSurface> surfaces, std::span<const Light> lights,
           const RenderOptions& options, double scale);

    // Shades the hit of `ray` with surface `index` at parameter t; `seed` decorrelates the
    // stochastic directions of soft shadows and occlusion between pixels. `sample` (the ray's
    // direction and its steps to the neighbouring samples) sets the footprint over which a
    // pattern is filtered.
    ShadingResult shade(const Ray& ray, std::size_t index, double t, std::uint64_t seed,
                        const SampleDirections& sample) const;

    // out[i] = shade(hits[i].ray, hits[i].surface, hits[i].t, hits[i].seed, {hits[i].ray.direction,
    // step_x, step_y}) for every i, bit for bit, in the same order of shadow rays. Where the
    // processor has AVX-512 and the scene's lights are directional, with neither ambient
    // occlusion nor patterns nor a fractional shininess, the normals and the Blinn–Phong sums
    // are computed eight hits at a time: a hit's shading is a chain of square roots and
    // divisions (its view and normal, each light's half vector) that one hit at a time leaves
    // waiting on their latency (17 % of the Whitney umbrella's frame, the gradient included).
    void shade_hits(std::span<const HitToShade> hits, const Vec3& step_x, const Vec3& step_y,
                    std::span<ShadingResult> out) const;

  private:
    // Fraction of `light` visible from `point` (1 unlit by nothing, 0 fully in shadow).
    double visibility(const Vec3& point, const Vec3& normal, const Light& light, std::uint64_t seed,
                      int& work) const;
    double ambient_occlusion(const Vec3& point, const Vec3& normal, std::uint64_t seed,
                             int& work) const;
    bool is_occluded(const Ray& ray, double t_max, int& work) const;

    std::span<const ShadedSurface> surfaces_;
    std::span<const Light> lights_;
    RenderOptions options_;
    double scale_;
    bool batched_ = false;  // shade_hits' conditions for its vector kernel hold
};

// Linear radiance to an 8-bit sRGB channel value.
std::uint8_t to_srgb8(double linear);
// The same for n channels at once: codes[i] = to_srgb8(linear[i]).
void to_srgb8(const float* linear, std::uint8_t* codes, std::size_t n);

}  // namespace locus::render
