// Clip regions: the interval of a ray inside a sphere, at every scale the doubles hold.
#include "render/clip_region.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
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

// The same against an oracle that shares no code with clip(): the definition evaluated in long
// double (x87's 15-bit exponent holds the squares of 1e300), on near-tangent rays whose closest
// approach to the centre is r·(1 + δ) for |δ| from 1e-9 to 1e-3: a ray crosses exactly when
// δ < 0, and both ends of its interval lie on the sphere.
TEST(ClipRegion, NearTangentRaysAgreeWithTheDefinitionInLongDouble) {
    static_assert(std::numeric_limits<long double>::max_exponent10 > 600);
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const auto random_unit = [&] {
        const Vec3 v{unit(random), unit(random), unit(random)};
        return v / glm::length(v);
    };
    int crossing = 0, passing = 0;
    for (int i = 0; i < 1000; ++i) {
        const Vec3 d = random_unit();
        const Vec3 w = glm::normalize(glm::cross(d, random_unit()));  // perpendicular to d
        const double delta = (i % 2 == 0 ? -1.0 : 1.0) * std::pow(10.0, -9.0 + 6.0 * (i % 7) / 6.0);
        for (const double s : {1e-300, 1e-150, 1e-20, 1.0, 1e20, 1e150, 1e300}) {
            const Vec3 centre = s * Vec3{unit(random), unit(random), unit(random)};
            const double radius = s * (0.5 + std::abs(unit(random)));
            const Vec3 origin = centre + (-3.0 * radius) * d + (radius * (1.0 + delta)) * w;
            const Vec3 direction = d * (0.25 + std::abs(unit(random)));
            const Interval in =
                clip(ClipSphere{centre, radius}, {origin, direction}, {-INFINITY, INFINITY});
            if (delta > 0.0) {
                EXPECT_TRUE(in.is_empty()) << i << " at " << s;
                ++passing;
                continue;
            }
            ASSERT_FALSE(in.is_empty()) << i << " at " << s;
            ++crossing;
            for (const double t : {in.lo, in.hi}) {
                long double squared = 0.0L;
                for (int k = 0; k < 3; ++k) {
                    const long double q = static_cast<long double>(origin[k]) +
                                          static_cast<long double>(t) * direction[k] - centre[k];
                    squared += q * q;
                }
                const long double relative = std::sqrt(squared) / radius - 1.0L;
                EXPECT_LT(std::abs(static_cast<double>(relative)), 1e-9)
                    << i << " at " << s << ", delta " << delta;
            }
        }
    }
    EXPECT_GT(crossing, 3000);
    EXPECT_GT(passing, 3000);
}

}  // namespace
}  // namespace locus::render
