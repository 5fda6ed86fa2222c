// The restriction of a surface to a line, by the general LineRestrictor and by the per-frame
// RayFamily, against direct evaluation of f along the ray.
#include "render/ray_restriction.h"

#include <gtest/gtest.h>

#include <random>

#include "algebra/compiled.h"
#include "render/ray_family.h"
#include "tests/support/test_data.h"

namespace locus::render {
namespace {

// A random dense-ish polynomial of the given degree as text.
std::string random_equation(std::mt19937_64& rng, int degree) {
    std::uniform_int_distribution<int> coefficient(-5, 5);
    std::string text = "1";
    for (int a = 0; a <= degree; ++a) {
        for (int b = 0; a + b <= degree; ++b) {
            for (int c = 0; a + b + c <= degree; ++c) {
                const int k = coefficient(rng);
                if (k != 0 && (rng() % 3 == 0 || a + b + c == degree)) {
                    // Appended piece by piece: GCC 12 warns (-Wrestrict) on "lit" + to_string.
                    if (k > 0) {
                        text += '+';
                    }
                    text += std::to_string(k);
                    text += "*x^";
                    text += std::to_string(a);
                    text += "*y^";
                    text += std::to_string(b);
                    text += "*z^";
                    text += std::to_string(c);
                }
            }
        }
    }
    return text;
}

// |F(t) − f(o + t·d)| relative to the size of the terms of f at that point.
void expect_restriction_matches(const algebra::CompiledPolynomial& f, const RayPolynomial& F,
                                const Vec3& o, const Vec3& d) {
    for (double t : {-1.0, -0.3, 0.0, 0.4, 1.0, 2.5}) {
        const Vec3 p = o + t * d;
        double magnitude = 0.0;
        for (const algebra::CompiledTerm& term : f.terms()) {
            magnitude += std::abs(term.coefficient) * std::pow(std::abs(p.x), term.ex) *
                         std::pow(std::abs(p.y), term.ey) * std::pow(std::abs(p.z), term.ez);
        }
        EXPECT_NEAR(F(t), f.value(to_point(p)), 1e-11 * (1.0 + magnitude)) << "t = " << t;
    }
}

TEST(LineRestrictor, MatchesDirectEvaluation) {
    for (int seed = 0; seed < test::seed_count(30); ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        std::mt19937_64 rng(static_cast<std::uint64_t>(seed));
        const int degree = 1 + seed % 10;
        const algebra::CompiledPolynomial f =
            algebra::compile_surface(random_equation(rng, degree));
        const LineRestrictor restrictor(f.terms());
        EXPECT_EQ(restrictor.degree(), f.degree());
        std::uniform_real_distribution<double> coordinate(-1.5, 1.5);
        const Vec3 o{coordinate(rng), coordinate(rng), coordinate(rng)};
        const Vec3 d{coordinate(rng), coordinate(rng), coordinate(rng)};
        expect_restriction_matches(f, restrictor.restrict_to(o, d), o, d);
    }
}

TEST(RayFamily, MatchesTheGeneralRestrictionOfEachPrimaryRay) {
    for (int seed = 0; seed < test::seed_count(12); ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        std::mt19937_64 rng(static_cast<std::uint64_t>(seed) + 1000);
        const algebra::CompiledPolynomial f =
            algebra::compile_surface(random_equation(rng, 2 + seed % 9));
        const Camera camera({{1.0, 2.0, 5.0}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 40.0}, 64, 48);
        const RayFamily family(f, camera, {0.1, -0.2, 0.3}, 64, 48);
        const LineRestrictor restrictor(f.terms());
        RowExpansion row;
        for (double y : {0.5, 17.25, 47.5}) {
            family.expand_row(y, row);
            for (double x : {0.5, 31.0, 63.5}) {
                const Ray ray = camera.ray(x, y);
                const RayPolynomial from_family = RayFamily::restriction(row, x);
                ASSERT_EQ(from_family.degree, restrictor.degree());
                expect_restriction_matches(f, from_family, ray.at(family.origin_t()),
                                           ray.direction);
            }
        }
    }
}

}  // namespace
}  // namespace locus::render
