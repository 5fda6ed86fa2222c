// Surfaces written in a frame of their own (render/surface_frame.h): the camera moved into the
// frame computes exactly the rays moved into it, and a surface renders the same whether its
// equation is written in the world's coordinates or in a frame centred on it.
#include "render/surface_frame.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "render/camera.h"
#include "render/renderer.h"
#include "render/trace_method.h"
#include "tests/support/trace_method_name.h"

namespace locus::render {
namespace {

TEST(SurfaceFrame, TheCameraInAFrameComputesTheFramedRaysExactly) {
    // The premise of the ray families in a frame: bit for bit, for random cameras, frames and
    // pixels.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> coordinate(-50.0, 50.0), pixel(0.0, 640.0);
    std::uniform_int_distribution<int> exponent(-8, 8);
    for (int k = 0; k < 200; ++k) {
        const CameraSpec spec{{coordinate(rng), coordinate(rng), coordinate(rng)},
                              {coordinate(rng), coordinate(rng), coordinate(rng)},
                              {0.0, 0.0, 1.0},
                              10.0 + std::abs(coordinate(rng))};
        const Camera camera(spec, 640, 480);
        const SurfaceFrame frame{{coordinate(rng), coordinate(rng), coordinate(rng)},
                                 std::ldexp(1.0, exponent(rng))};
        const Camera local = camera.in_frame(frame);
        for (int p = 0; p < 20; ++p) {
            const double x = pixel(rng), y = 0.75 * pixel(rng);
            const Ray expected = frame.to_local(camera.ray(x, y));
            const Ray computed = local.ray(x, y);
            for (int i = 0; i < 3; ++i) {
                ASSERT_EQ(computed.origin[i], expected.origin[i]);
                ASSERT_EQ(computed.direction[i], expected.direction[i]);
            }
            EXPECT_NEAR(glm::dot(computed.direction, local.forward()), 1.0, 1e-12);
        }
    }
}

TEST(SurfaceFrame, PowersOfTwo) {
    EXPECT_EQ(power_of_two_at_least(0.3), 0.5);
    EXPECT_EQ(power_of_two_at_least(0.5), 1.0);  // at least: the next one up is also fine
    EXPECT_EQ(power_of_two_at_least(3.0), 4.0);
    EXPECT_EQ(power_of_two_at_least(0.0), 1.0);
    EXPECT_EQ(power_of_two_at_least(INFINITY), 1.0);
}

class FramedSurface : public ::testing::TestWithParam<TraceMethod> {};

TEST_P(FramedSurface, RendersAsTheSameSurfaceWrittenInTheWorld) {
    // A sphere of radius 0.3 about c = (3.125, −0.25, 2.375): in the world's coordinates, and
    // in the frame x = c + x'/2, where it is 25x'² + 25y'² + 25z'² − 9 = 0.
    const Vec3 centre(3.125, -0.25, 2.375);
    Scene world;
    world.width = world.height = 48;
    world.camera = CameraSpec{centre + Vec3(1.5, -2.0, 1.0), centre, {0.0, 0.0, 1.0}, 30.0};
    world.options.method = GetParam();
    world.options.shadows = false;
    world.options.threads = 2;
    world.surfaces.push_back(
        {"(x-3.125)^2+(y+0.25)^2+(z-2.375)^2-0.09", "", ClipSphere{centre, 0.5}, Material{}, ""});
    const std::vector<algebra::CompiledPolynomial> f = {
        algebra::compile_surface(world.surfaces[0].equation)};
    RenderStats world_stats;
    ExecutionSettings execution;
    execution.aovs = true;
    const RenderedImage a = render(world, f, execution, &world_stats);
    ASSERT_EQ(a.depth.size(), 48u * 48u);
    EXPECT_GT(world_stats.hits, 48 * 48 / 10);
    // A frame smaller than the sphere's clip region and one larger: x = c + x'/2 and x = c + 4x'.
    for (const auto& [scale, equation] : {std::pair{0.5, "25*x^2+25*y^2+25*z^2-9"},
                                          std::pair{4.0, "1600*x^2+1600*y^2+1600*z^2-9"}}) {
        SCOPED_TRACE(equation);
        Scene framed = world;
        framed.surfaces[0].equation = equation;
        framed.surfaces[0].frame = SurfaceFrame{centre, scale};
        const std::vector<algebra::CompiledPolynomial> g = {algebra::compile_surface(equation)};
        RenderStats framed_stats;
        const RenderedImage b = render(framed, g, execution, &framed_stats);
        EXPECT_EQ(world_stats.hits, framed_stats.hits);
        EXPECT_EQ(framed_stats.unknown, 0);
        for (std::size_t i = 0; i < a.depth.size(); ++i) {
            ASSERT_EQ(std::isfinite(a.depth[i]), std::isfinite(b.depth[i])) << "pixel " << i;
            if (std::isfinite(a.depth[i])) {
                EXPECT_NEAR(a.depth[i], b.depth[i], 1e-5 * a.depth[i]) << "pixel " << i;
            }
        }
        // The normals (shading) agree too: the frame scales uniformly.
        for (std::size_t i = 0; i < a.color.size(); ++i) {
            EXPECT_NEAR(a.color[i], b.color[i], 1e-4) << "channel " << i;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Methods, FramedSurface,
                         ::testing::Values(TraceMethod::certified, TraceMethod::sturm,
                                           TraceMethod::bernstein, TraceMethod::exact,
                                           TraceMethod::sphere_gradient),
                         test::trace_method_name);

}  // namespace
}  // namespace locus::render
