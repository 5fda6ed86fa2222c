// End-to-end images with closed-form answers (STYLE.md P13): a sphere's silhouette radius in
// pixels and the shading of its centre pixel.
#include "render/renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <random>

#include "algebra/error.h"
#include "render/shading.h"
#include "render/trace_method.h"
#include "tests/support/trace_method_name.h"

namespace locus::render {
namespace {

Scene sphere_scene(TraceMethod method) {
    Scene scene;
    scene.width = scene.height = 101;  // odd: the centre pixel's centre is on the axis
    scene.camera = CameraSpec{{0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 30.0};
    Light light;
    light.direction = glm::normalize(Vec3{0.3, 0.4, 1.0});
    scene.lights = {light};
    scene.surfaces.push_back({"x^2+y^2+z^2-1", "", ClipSphere{}, Material{}, ""});
    scene.options.method = method;
    scene.options.shadows = false;
    scene.options.threads = 2;
    return scene;
}

class SphereImage : public ::testing::TestWithParam<TraceMethod> {};

TEST_P(SphereImage, SilhouetteRadiusAndCentreShadingMatchTheFormulas) {
    const Scene scene = sphere_scene(GetParam());
    const std::vector<algebra::CompiledPolynomial> surfaces = {
        algebra::compile_surface(scene.surfaces[0].equation)};
    RenderStats stats;
    const RenderedImage image = render(scene, surfaces, {}, &stats);
    long covered = 0;
    for (float depth : image.depth) {
        covered += std::isfinite(depth) ? 1 : 0;
    }
    // Angular radius asin(1/5); the image half-height is tan(15°) at unit distance.
    const double expected_radius =
        std::tan(std::asin(0.2)) / std::tan(15.0 * std::numbers::pi / 180.0) * (scene.height / 2.0);
    EXPECT_NEAR(std::sqrt(covered / std::numbers::pi), expected_radius, 0.5);
    EXPECT_EQ(stats.hits, covered);
    EXPECT_EQ(stats.unknown, 0);

    // Centre pixel: hit at (0, 0, 1), normal +z, view +z. Gradient sphere tracing stops within
    // its step tolerance (1e-7 × the clip radius); every other method refines to 1e-9 or better.
    const std::size_t centre = 50 * 101 + 50;
    const double depth_tolerance = GetParam() == TraceMethod::sphere_gradient ? 1e-6 : 1e-9;
    EXPECT_NEAR(image.depth[centre], 4.0, depth_tolerance);
    const Material m;
    const Vec3 l = scene.lights[0].direction;
    const Vec3 h = glm::normalize(l + Vec3(0, 0, 1));
    const Vec3 expected =
        m.ambient * m.color + m.diffuse * l.z * m.color + m.specular * std::pow(h.z, m.shininess);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(image.color[3 * centre + c], expected[c], 1e-5) << "channel " << c;
    }
    EXPECT_NEAR(image.normal[3 * centre + 2], 1.0, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Methods, SphereImage, ::testing::ValuesIn(all_trace_methods()),
                         test::trace_method_name);

TEST(Render, NoPixelIsNanAtSingularPoints) {
    // The Cayley cubic's nodes and the Whitney umbrella's handle, with shadows and AO on.
    for (const char* equation : {"4*(x^2+y^2+z^2)+16*x*y*z-1", "x^2-y^2*z"}) {
        Scene scene;
        scene.width = scene.height = 48;
        scene.surfaces.push_back({equation, "", ClipSphere{}, Material{}, ""});
        scene.options.ambient_occlusion = true;
        scene.options.ambient_occlusion_samples = 4;
        scene.options.samples = 2;
        const std::vector<algebra::CompiledPolynomial> surfaces = {
            algebra::compile_surface(equation)};
        const RenderedImage image = render(scene, surfaces, {});
        for (float c : image.color) {
            ASSERT_TRUE(std::isfinite(c)) << equation;
        }
    }
}

// A sphere of radius R seen from 5R with a clip sphere of 2R is the same picture at every scale
// the doubles hold: its silhouette covers the same pixels, and the depth scales with R. At
// R = 1e200 the clip sphere's squares overflowed (NaN ends) and every ray was decided a miss, an
// empty picture with no undecided ray; at 1e-200 they underflowed. The equation's constant
// (1e400, 1e-400) is beyond the doubles itself: the exact arithmetic decides there.
TEST(Render, ASphereIsTheSamePictureAtEveryScale) {
    const auto hits_at = [](const char* r, const char* r_squared, double scale,
                            TraceMethod method) {
        Scene scene;
        scene.width = scene.height = 24;
        scene.camera = CameraSpec{{0, 0, 5 * scale}, {0, 0, 0}, {0, 1, 0}, 30.0};
        const std::string equation = std::string("x^2+y^2+z^2-") + r_squared;
        scene.surfaces.push_back({equation, "", ClipSphere{{0, 0, 0}, 2 * scale}, Material{}, ""});
        scene.options.method = method;
        scene.options.shadows = false;
        scene.options.threads = 2;
        const std::vector<algebra::CompiledPolynomial> surfaces = {
            algebra::compile_surface(equation)};
        RenderStats stats;
        const RenderedImage image = render(scene, surfaces, {}, &stats);
        EXPECT_EQ(stats.unknown, 0) << r;
        // A hit has a unit normal, a miss a zero one (the depth AOV is a float: 4e200 is
        // infinite there).
        std::vector<bool> hit;
        for (std::size_t p = 0; p < image.normal.size(); p += 3) {
            const double z = image.normal[p + 2];
            hit.push_back(z != 0.0);
            if (hit.back()) {
                EXPECT_GT(z, 0.0) << r;  // the near side faces the eye
            }
        }
        return hit;
    };
    // The oracle: exact isolation over Q at the unit scale, which the certified method at unit
    // scale must match too.
    const std::vector<bool> exact_unit = hits_at("1", "1", 1.0, TraceMethod::exact);
    EXPECT_EQ(hits_at("1", "1", 1.0, TraceMethod::certified), exact_unit);
    for (const TraceMethod method : {TraceMethod::certified, TraceMethod::exact}) {
        const std::vector<bool>& unit = exact_unit;
        EXPECT_GT(std::count(unit.begin(), unit.end(), true), 24 * 24 / 20);
        EXPECT_EQ(hits_at("1e200", "1e400", 1e200, method), unit);
        EXPECT_EQ(hits_at("1e100", "1e200", 1e100, method), unit);
        EXPECT_EQ(hits_at("1e-100", "1e-200", 1e-100, method), unit);
        EXPECT_EQ(hits_at("1e-200", "1e-400", 1e-200, method), unit);
    }
}

TEST(Render, WithoutAovsTheColourIsTheSameAndTheAovsStayEmpty) {
    const Scene scene = sphere_scene(TraceMethod::sturm);
    const std::vector<algebra::CompiledPolynomial> surfaces = {
        algebra::compile_surface("x^2+y^2+z^2-1")};
    ExecutionSettings colour_only;
    colour_only.aovs = false;
    const RenderedImage image = render(scene, surfaces, colour_only);
    const RenderedImage full = render(scene, surfaces, {});
    EXPECT_EQ(image.color, full.color);
    EXPECT_TRUE(image.depth.empty() && image.normal.empty() && image.work.empty());
    EXPECT_EQ(full.depth.size(), static_cast<std::size_t>(scene.width) * scene.height);
}

TEST(Render, DeadlineStopsTheFrameWithATimeout) {
    const Scene scene = sphere_scene(TraceMethod::sturm);
    const std::vector<algebra::CompiledPolynomial> surfaces = {
        algebra::compile_surface("x^2+y^2+z^2-1")};
    ExecutionSettings execution;
    execution.threads = 2;
    execution.deadline = std::chrono::steady_clock::now();  // already passed
    try {
        render(scene, surfaces, execution);
        ADD_FAILURE() << "a passed deadline rendered the frame";
    } catch (const Timeout& e) {
        EXPECT_STREQ(e.what(), "timeout: rendering stopped with 0 of 101 rows done");
    }
    // A deadline far ahead changes nothing.
    execution.deadline = std::chrono::steady_clock::now() + std::chrono::hours(1);
    const RenderedImage image = render(scene, surfaces, execution);
    const RenderedImage reference = render(scene, surfaces, {});
    EXPECT_EQ(image.color, reference.color);
}

}  // namespace
}  // namespace locus::render

namespace locus::render {
namespace {

// The sRGB transfer function as IEC 61966-2-1 states it, rounded to 8 bits: the oracle of the
// threshold table behind to_srgb8.
int srgb8_reference(double c) {
    c = std::clamp(c, 0.0, 1.0);
    const double encoded = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
    return static_cast<int>(std::lround(encoded * 255.0));
}

TEST(Srgb8, TheTableEncodesAsTheTransferFunction) {
    std::mt19937_64 random(42);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 200000; ++i) {
        const double c = i % 2 == 0 ? unit(random) : std::pow(unit(random), 6.0);  // dark too
        ASSERT_EQ(to_srgb8(c), srgb8_reference(c)) << c;
    }
    // Around every step of the output, to the last bit.
    for (int k = 1; k <= 255; ++k) {
        double lo = 0.0, hi = 1.0;
        while (std::nextafter(lo, 1.0) < hi) {
            const double middle = lo + 0.5 * (hi - lo);
            (srgb8_reference(middle) >= k ? hi : lo) = middle;
        }
        EXPECT_EQ(to_srgb8(lo), k - 1) << lo;
        EXPECT_EQ(to_srgb8(hi), k) << hi;
    }
    EXPECT_EQ(to_srgb8(-1.0), 0);
    EXPECT_EQ(to_srgb8(2.0), 255);
    EXPECT_EQ(to_srgb8(std::nan("")), 0);
}

TEST(Srgb8, ARowEncodesAsItsChannels) {
    std::mt19937_64 random(11);
    std::uniform_real_distribution<float> wide(-0.5f, 1.5f);
    std::vector<float> linear(3001);
    for (float& c : linear) {
        c = wide(random);
    }
    linear[7] = std::nanf("");
    linear[8] = INFINITY;
    linear[9] = -INFINITY;
    std::vector<std::uint8_t> codes(linear.size());
    to_srgb8(linear.data(), codes.data(), linear.size());
    for (std::size_t i = 0; i < linear.size(); ++i) {
        ASSERT_EQ(codes[i], srgb8_reference(std::isnan(linear[i]) ? 0.0 : linear[i])) << i;
    }
}

}  // namespace
}  // namespace locus::render

namespace locus::render {
namespace {

TEST(Render, ACertifiedFamilyOverPartOfTheImageAgreesWithExactArithmetic) {
    // A torus clipped to a small sphere off the image's centre: the certified ray family spans
    // only the clip region's footprint (PrimaryTracer), and its balls must still hold for every
    // pixel there. Exact arithmetic on each ray (the `exact` method) is the oracle.
    Scene scene;
    scene.width = 64;
    scene.height = 48;
    scene.camera = CameraSpec{{2.4, -3.2, 2.0}, {0.3, 0.0, 0.0}, {0.0, 0.0, 1.0}, 30.0};
    scene.options.shadows = false;
    scene.options.threads = 2;
    scene.surfaces.push_back(
        {"(x^2+y^2+z^2+3/4)^2-4*(x^2+y^2)", "", ClipSphere{{0.9, 0.3, 0.1}, 0.7}, Material{}, ""});
    const std::vector<algebra::CompiledPolynomial> f = {
        algebra::compile_surface(scene.surfaces[0].equation)};
    ExecutionSettings execution;
    execution.aovs = true;
    RenderStats certified_stats, exact_stats;
    const RenderedImage certified = render(scene, f, execution, &certified_stats);
    scene.options.method = TraceMethod::exact;
    const RenderedImage exact = render(scene, f, execution, &exact_stats);
    EXPECT_GT(exact_stats.hits, 64 * 48 / 20);
    EXPECT_LT(exact_stats.hits, 64 * 48 / 2);  // a part of the picture
    EXPECT_EQ(certified_stats.unknown, 0);
    for (std::size_t i = 0; i < exact.depth.size(); ++i) {
        ASSERT_EQ(std::isfinite(certified.depth[i]), std::isfinite(exact.depth[i]))
            << "pixel " << i;
        if (std::isfinite(exact.depth[i])) {
            EXPECT_NEAR(certified.depth[i], exact.depth[i], 1e-6 * exact.depth[i]) << "pixel " << i;
        }
    }
}

}  // namespace
}  // namespace locus::render
