// Shader::shade_hits against Shader::shade, its reference: the same colours, normals and shadow
// work bit for bit, on hits of two surfaces with different materials, hits at singular points
// (∇f = 0), on a light's terminator and along grazing rays, rays of very different lengths, every
// batch size up to 37 (the vector kernel's masked tail), with and without shadows, and in the
// scenes the kernel leaves to shade() (a point light, ambient occlusion, a checker, a fractional
// exponent).
#include "render/shading.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "algebra/compiled.h"
#include "render/scene.h"
#include "render/surface_tracer.h"

namespace locus::render {
namespace {

struct LightingSetup {
    std::string name;
    std::vector<Light> lights;
    RenderOptions options;
    Material second;  // the Whitney umbrella's material (the sphere keeps the default)
};

Material custom_material(double shininess) {
    Material m;
    m.color = {0.2, 0.9, 0.35};
    m.inside = {0.7, 0.1, 0.6};
    m.ambient = 0.05;
    m.diffuse = 0.9;
    m.specular = 0.6;
    m.shininess = shininess;
    return m;
}

std::vector<LightingSetup> setups() {
    std::vector<LightingSetup> out;
    RenderOptions plain;
    plain.shadows = false;
    RenderOptions shadowed;  // hard shadows (radius 0): one shadow ray a light
    out.push_back({"default lights, no shadows", default_lights(), plain, custom_material(7)});
    out.push_back({"default lights, shadows", default_lights(), shadowed, custom_material(1)});
    std::vector<Light> three = default_lights();
    Light back;
    back.direction = glm::normalize(Vec3{0.1, -0.3, -0.95});
    back.color = {0.4, 0.5, 0.6};
    back.intensity = 0.7;
    three.push_back(back);
    out.push_back({"three lights, exponent 1024", three, plain, custom_material(1024)});
    out.push_back({"three lights, exponent 0, shadows", three, shadowed, custom_material(0)});
    // Left to shade() one hit at a time.
    std::vector<Light> point = default_lights();
    Light bulb;
    bulb.kind = Light::Kind::point;
    bulb.position = {1.5, 2.5, 3.0};
    point.push_back(bulb);
    out.push_back({"a point light", point, plain, custom_material(48)});
    RenderOptions occlusion = plain;
    occlusion.ambient_occlusion = true;
    occlusion.ambient_occlusion_samples = 4;
    out.push_back({"ambient occlusion", default_lights(), occlusion, custom_material(48)});
    Material checkered = custom_material(48);
    checkered.checker = Vec3{0.0, 0.0, 0.0};
    checkered.checker_size = 0.25;
    out.push_back({"a checker", default_lights(), plain, checkered});
    out.push_back({"a fractional exponent", default_lights(), plain, custom_material(12.5)});
    return out;
}

TEST(ShadeHits, AgreeWithShadeBitForBit) {
    if (__builtin_cpu_supports("avx512f") == 0) {
        GTEST_SKIP() << "no AVX-512 here: shade_hits is shade() one hit at a time";
    }
    const algebra::CompiledPolynomial sphere = algebra::compile_surface("x^2+y^2+z^2-1");
    const algebra::CompiledPolynomial whitney = algebra::compile_surface("x^2-y^2*z");
    const SurfaceTracer sphere_tracer(sphere, TraceMethod::certified, 2.0);
    const SurfaceTracer whitney_tracer(whitney, TraceMethod::certified, 2.0);
    std::mt19937_64 random(2026);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_int_distribution<int> exponent(-6, 6);
    const Vec3 step_x{0.002, 0.0, 0.0}, step_y{0.0, -0.002, 0.0};
    for (const LightingSetup& setup : setups()) {
        SCOPED_TRACE(setup.name);
        const std::vector<ShadedSurface> surfaces = {
            {&sphere_tracer, ClipSphere{{0.0, 0.0, 0.0}, 2.0}, Material{}, nullptr},
            {&whitney_tracer, ClipSphere{{0.0, 0.0, 0.0}, 2.0}, setup.second, nullptr}};
        const Shader shader(surfaces, setup.lights, setup.options, 2.0);
        for (std::size_t n = 1; n <= 37; ++n) {
            std::vector<HitToShade> hits;
            for (std::size_t i = 0; i < n; ++i) {
                HitToShade hit;
                hit.ray.origin = {3.0 * unit(random), 3.0 * unit(random), 3.0 + unit(random)};
                hit.ray.direction = std::ldexp(1.0, exponent(random)) *
                                    Vec3{unit(random), unit(random), -1.0 + 0.2 * unit(random)};
                hit.surface = i % 3 == 0 ? 0 : 1;
                hit.t = 0.5 + std::abs(unit(random));
                hit.seed = random();
                if (i % 7 == 3) {
                    // On the Whitney umbrella's singular line x = y = 0: ∇f = 0 there.
                    hit.surface = 1;
                    hit.ray.origin = {0.0, 0.0, 2.0 + unit(random)};
                    hit.ray.direction = {0.0, 0.0, -1.0};
                }
                if (i % 7 == 5 || i % 7 == 6) {
                    // Near-degenerate on the sphere, where the normal is the point p: p on the
                    // first light's terminator (n·L ≈ 0, whether the light counts is decided by
                    // the last bits), or a grazing ray (d ⊥ p: n·view ≈ 0, which side is seen).
                    const Vec3 across{unit(random), unit(random), unit(random)};
                    const Vec3 p = glm::normalize(glm::cross(setup.lights[0].direction, across));
                    const Vec3 d =
                        i % 7 == 5 ? Vec3{0.3, -0.4, -1.0} : glm::normalize(glm::cross(p, across));
                    hit.surface = 0;
                    hit.t = 1.0 + std::abs(unit(random));
                    hit.ray.origin = p - hit.t * d;
                    hit.ray.direction = d;
                }
                hits.push_back(hit);
            }
            std::vector<ShadingResult> batch(n);
            shader.shade_hits(hits, step_x, step_y, batch);
            for (std::size_t i = 0; i < n; ++i) {
                const HitToShade& hit = hits[i];
                const ShadingResult one = shader.shade(hit.ray, hit.surface, hit.t, hit.seed,
                                                       {hit.ray.direction, step_x, step_y});
                ASSERT_EQ(batch[i].color, one.color) << "hit " << i << " of " << n;
                ASSERT_EQ(batch[i].normal, one.normal) << "hit " << i << " of " << n;
                ASSERT_EQ(batch[i].work, one.work) << "hit " << i << " of " << n;
            }
        }
    }
}

}  // namespace
}  // namespace locus::render
