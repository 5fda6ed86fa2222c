// Clip regions: the interval of a ray inside a sphere, at every scale the doubles hold.
#include "render/clip_region.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace locus::render {
namespace {

// Random rays against random spheres, the oracle being the definition: the ends' points lie on
// the sphere (to the rounding of a unit-scale computation), and scaling the sphere and the ray's
// origin by s scales the ends by s. Below 1e-154 and past 1e154 the squares of the coordinates
// leave the doubles; the interval must not (its ends were NaN past 1e154: every ray missed).
TEST(ClipRegion, SphereIntervalsAreTheSameAtEveryScale) {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int crossing = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec3 centre{unit(random), unit(random), unit(random)};
        const double radius = 0.2 + std::abs(unit(random));
        // Aimed near the sphere (most cross it, some pass by).
        const Vec3 origin{3 * unit(random), 3 * unit(random), 3 * unit(random)};
        const Vec3 aim = centre + 1.5 * radius * Vec3{unit(random), unit(random), unit(random)};
        const Ray ray{origin, (aim - origin) * (0.5 + std::abs(unit(random)))};
        const Interval at_one = clip(ClipSphere{centre, radius}, ray, {-INFINITY, INFINITY});
        if (!(at_one.hi >= at_one.lo)) {
            for (const double s : {1e-300, 1e-200, 1e200, 1e300}) {
                const Interval scaled =
                    clip(ClipSphere{centre * s, radius * s}, {ray.origin * s, ray.direction},
                         {-INFINITY, INFINITY});
                EXPECT_FALSE(scaled.hi >= scaled.lo) << i << " at " << s;
            }
            continue;
        }
        ++crossing;
        for (const double t : {at_one.lo, at_one.hi}) {
            EXPECT_NEAR(glm::length(ray.at(t) - centre), radius, 1e-12) << i;
        }
        for (const double s : {1e-300, 1e-200, 1e-100, 1e100, 1e200, 1e300}) {
            const Interval scaled = clip(ClipSphere{centre * s, radius * s},
                                         {ray.origin * s, ray.direction}, {-INFINITY, INFINITY});
            EXPECT_NEAR(scaled.lo / s, at_one.lo, 1e-12 * (1 + std::abs(at_one.lo))) << i << s;
            EXPECT_NEAR(scaled.hi / s, at_one.hi, 1e-12 * (1 + std::abs(at_one.hi))) << i << s;
        }
    }
    EXPECT_GT(crossing, 500);  // 893 with this seed
}

}  // namespace
}  // namespace locus::render
