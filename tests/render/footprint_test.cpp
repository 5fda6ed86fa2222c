// Patterns filtered over a sample's footprint (render/footprint.h, Material::at): the filtered
// checker against a brute-force average of point samples computed here from the cell parity,
// the footprint of a plane against its closed form, and a checkered floor toward the horizon
// that must fade to the mean colour instead of aliasing into moiré.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "render/camera.h"
#include "render/footprint.h"
#include "render/material.h"
#include "render/scene_file.h"
#include "render/sdf/sdf_renderer.h"

namespace locus::render {
namespace {

// 1 where the cell of p (cubes of `size`) has an odd coordinate sum, else 0.
double parity(const Vec3& p, double size) {
    const double sum = std::floor(p.x / size) + std::floor(p.y / size) + std::floor(p.z / size);
    return std::fmod(std::abs(sum), 2.0);
}

TEST(Footprint, TheFilteredCheckerIsTheAverageOverTheBox) {
    Material m = Material::plain({1.0, 1.0, 1.0});
    m.checker = Vec3(0.0);
    m.checker_size = 0.7;
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> position(-5.0, 5.0), width(0.0, 3.0);
    for (int trial = 0; trial < 40; ++trial) {
        const Vec3 p{position(random), position(random), position(random)};
        Footprint footprint;
        footprint.dx = {width(random), 0.0, 0.0};
        footprint.dy = {0.0, width(random), width(random) * (trial % 2)};
        const Vec3 w = glm::abs(footprint.dx) + glm::abs(footprint.dy);
        // The share of checker colour by a midpoint rule on a 60³ grid over the box.
        const int n = 60;
        double odd = 0.0;
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) {
                for (int k = 0; k < n; ++k) {
                    const Vec3 offset = Vec3((i + 0.5) / n, (j + 0.5) / n, (k + 0.5) / n) - 0.5;
                    odd += parity(p + offset * w, m.checker_size);
                }
            }
        }
        const double expected = 1.0 - odd / (n * n * n);  // white where the parity is even
        EXPECT_NEAR(m.at(p, footprint).color.x, expected, 0.02)
            << "p " << p.x << "," << p.y << "," << p.z << " w " << w.x << "," << w.y << "," << w.z;
    }
    // A point sample keeps the hard pattern.
    EXPECT_EQ(m.at({0.1, 0.1, 0.1}).color, Vec3(1.0));
    EXPECT_EQ(m.at({0.8, 0.1, 0.1}).color, Vec3(0.0));
}

TEST(Footprint, OnAPlaneItIsTheNeighbouringRaysHits) {
    // Eye 2 above the floor y = 0 looking down at 45°: a neighbouring ray's hit is where it
    // meets the plane, in closed form.
    const Vec3 eye{0.0, 2.0, 0.0};
    const SampleDirections sample{{0.0, -1.0, 1.0}, {0.01, 0.0, 0.0}, {0.0, -0.01, 0.0}};
    const Vec3 point{0.0, 0.0, 2.0};
    const Footprint f = surface_footprint(eye, sample, point, {0.0, 1.0, 0.0}, 1e6);
    EXPECT_NEAR(f.dx.x, 0.02, 1e-12);
    EXPECT_NEAR(f.dx.z, 0.0, 1e-12);
    EXPECT_NEAR(f.dy.z, 2.0 / 1.01 - 2.0, 1e-12);
    EXPECT_NEAR(f.dy.y, 0.0, 1e-12);
    // A neighbour that runs above the horizon never meets the plane: the limit, along it.
    const SampleDirections grazing{{0.0, -0.001, 1.0}, {0.0, 0.0, 0.0}, {0.0, 0.01, 0.0}};
    const Footprint g = surface_footprint(eye, grazing, {0.0, 0.0, 2000.0}, {0.0, 1.0, 0.0}, 1e6);
    EXPECT_NEAR(glm::length(g.dy), 1e6, 1e-3);
    EXPECT_NEAR(g.dy.y, 0.0, 1e-9);
}

TEST(Footprint, ACheckeredFloorFadesToItsMeanTowardTheHorizon) {
    const Scene scene = parse_scene(R"(
[image]
width = 96
height = 48
background = [0, 0, 0]
[camera]
eye = [0, 1, 0]
target = [0, 0.9, 10]
fov = 30
[render]
shadows = false
[materials.floor]
color = [1, 1, 1]
checker = [0, 0, 0]
checker_size = 0.5
ambient = 1
diffuse = 0
specular = 0
[[object]]
type = "plane"
material = "floor"
)");
    ExecutionSettings execution;
    execution.threads = 1;
    const RenderedImage image = render_sdf_scene(scene, {}, execution);
    // The rows just below the horizon see hundreds of cells per pixel: every pixel there is
    // close to the mean grey 0.5, where point samples scatter over 0 and 1.
    int far_pixels = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const std::size_t p = static_cast<std::size_t>(y) * image.width + x;
            if (!std::isfinite(image.depth[p]) || image.depth[p] < 60.0) {
                continue;
            }
            ++far_pixels;
            EXPECT_NEAR(image.color[3 * p], 0.5, 0.12) << "pixel " << x << "," << y;
        }
    }
    EXPECT_GT(far_pixels, 96);
}

}  // namespace
}  // namespace locus::render
