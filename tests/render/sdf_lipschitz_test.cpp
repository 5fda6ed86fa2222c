// The honest-bounds property: every node type is sampled on random point pairs, near
// and far apart, and |f(p) − f(q)| ≤ L·|p − q| must hold with the L the node reports. A node
// that understated L would let the tracer step through its surface.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sdf_test_nodes.h"

namespace locus::render::sdf {
namespace {

TEST(SdfLipschitz, EveryNodeTypeRespectsItsConstant) {
    std::mt19937_64 random(20261123);
    std::uniform_real_distribution<double> coordinate(-2.5, 2.5);
    std::uniform_real_distribution<double> scale_of_offset(-8.0, 0.0);  // log2 of |p − q|
    for (const auto& [name, node] : testing::every_node_type()) {
        const double lipschitz = node->lipschitz();
        double worst = 0.0;
        for (int i = 0; i < 20000; ++i) {
            const Vec3 p{coordinate(random), coordinate(random), coordinate(random)};
            Vec3 offset{coordinate(random), coordinate(random), coordinate(random)};
            offset *= std::exp2(scale_of_offset(random)) / glm::length(offset);
            const Vec3 q = p + offset;
            const double ratio = std::abs(node->value(p) - node->value(q)) / glm::length(p - q);
            worst = std::max(worst, ratio);
        }
        EXPECT_LE(worst, lipschitz * (1.0 + 1e-9))
            << name << " (kind " << to_string(node->kind()) << ")";
        // And the constant is not absurdly loose (which would make tracing crawl).
        EXPECT_GE(worst, 0.2 * lipschitz) << name;
    }
}

// Noise: values within the stated amplitude and slopes within 3 per octave (Hart), checked
// densely on one octave since every octave is the same function scaled.
TEST(SdfLipschitz, NoiseOctaveStaysWithinThreePerUnitFrequency) {
    const Noise noise(1.0, 1.0, 1, 42);
    EXPECT_DOUBLE_EQ(noise.lipschitz(), 3.0);
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> coordinate(-20.0, 20.0);
    double largest_value = 0.0, steepest = 0.0;
    const double h = 1e-4;
    for (int i = 0; i < 200000; ++i) {
        const Vec3 p{coordinate(random), coordinate(random), coordinate(random)};
        const double v = noise.value(p);
        largest_value = std::max(largest_value, std::abs(v));
        const Vec3 g{(noise.value(p + Vec3(h, 0, 0)) - noise.value(p - Vec3(h, 0, 0))) / (2 * h),
                     (noise.value(p + Vec3(0, h, 0)) - noise.value(p - Vec3(0, h, 0))) / (2 * h),
                     (noise.value(p + Vec3(0, 0, h)) - noise.value(p - Vec3(0, 0, h))) / (2 * h)};
        steepest = std::max(steepest, glm::length(g));
    }
    EXPECT_LE(largest_value, noise.max_amplitude());
    EXPECT_LE(steepest, 3.0);
    EXPECT_GE(steepest, 1.5);  // not a trivially flat field
    std::printf("noise octave: max |value| %.3f, max |gradient| %.3f\n", largest_value, steepest);
}

TEST(SdfLipschitz, WyvillSlopeIsTheMaximumOfTheFalloffDerivative) {
    // C(s) = 1 − 4/9 s⁶ + 17/9 s⁴ − 22/9 s², sampled finely on [0, 1].
    double steepest = 0.0;
    for (int i = 0; i <= 100000; ++i) {
        const double s = i / 100000.0;
        const double slope =
            std::abs(-24.0 / 9 * std::pow(s, 5) + 68.0 / 9 * std::pow(s, 3) - 44.0 / 9 * s);
        steepest = std::max(steepest, slope);
    }
    EXPECT_NEAR(kWyvillSlope, steepest, 1e-8);
    EXPECT_GT(kWyvillSlope, 1.5);  // Hart's 3/(2R) would understate it
}

}  // namespace
}  // namespace locus::render::sdf
