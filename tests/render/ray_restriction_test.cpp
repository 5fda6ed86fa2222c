// The restriction of a surface to a line, by the general LineRestrictor and by the per-frame
// RayFamily, against direct evaluation of f along the ray.
#include "render/ray_restriction.h"

#include <gtest/gtest.h>

#include <flint/fmpq_mpoly.h>
#include <flint/fmpq_poly.h>

#include <array>
#include <cmath>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "algebra/compiled.h"
#include "algebra/flint_convert.h"
#include "algebra/parse.h"
#include "algebra/poly_ring.h"
#include "algebra/rational.h"
#include "algebra/real_roots.h"
#include "render/ray_family.h"
#include "tests/support/chmutov.h"
#include "tests/support/test_data.h"

namespace locus::render {
namespace {

// A random dense-ish polynomial of the given degree as text (x^degree added when every term
// of that degree drew a zero coefficient: at LOCUS_TEST_MULTIPLIER=400 one seed drew a
// constant, which defines no surface).
std::string random_equation(std::mt19937_64& rng, int degree) {
    std::uniform_int_distribution<int> coefficient(-5, 5);
    std::string text = "1";
    bool top = false;
    for (int a = 0; a <= degree; ++a) {
        for (int b = 0; a + b <= degree; ++b) {
            for (int c = 0; a + b + c <= degree; ++c) {
                const int k = coefficient(rng);
                if (k != 0 && (rng() % 3 == 0 || a + b + c == degree)) {
                    top = top || a + b + c == degree;
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
    if (!top) {
        text += "+x^";
        text += std::to_string(degree);
    }
    return text;
}

// |F(t) − f(o + t·d)| relative to the size of the terms of f expanded along the line,
// Σ|c|·Π(|o_i| + |t|·|d_i|)^e_i: what the restriction's roundings scale with. (The terms' size
// at the point itself, which cancellation can make far smaller, was too tight a scale: seed
// 469 of LOCUS_TEST_MULTIPLIER=20 failed by 1.5 times, before and after the Taylor shift.)
void expect_restriction_matches(const algebra::CompiledPolynomial& f, const RayPolynomial& F,
                                const Vec3& o, const Vec3& d, double relative = 1e-11) {
    for (double t : {-1.0, -0.3, 0.0, 0.4, 1.0, 2.5}) {
        const Vec3 p = o + t * d;
        const Vec3 reach = glm::abs(o) + std::abs(t) * glm::abs(d);
        double magnitude = 0.0;
        for (const algebra::CompiledTerm& term : f.terms()) {
            magnitude += std::abs(term.coefficient) * std::pow(reach.x, term.ex) *
                         std::pow(reach.y, term.ey) * std::pow(reach.z, term.ez);
        }
        EXPECT_NEAR(F(t), f.value(to_point(p)), relative * (1.0 + magnitude)) << "t = " << t;
    }
}

// The exact coefficients of f(m + x·h) over Q for a double-double line (hi + lo read
// exactly), by FLINT's composition: the oracle of the double-double restriction.
struct ExactCoefficient {
    algebra::Rational exact;
    double value = 0.0;  // near exact, for messages
    // |exact − c| ≤ r, decided in rationals.
    bool within(double c, double r) const {
        algebra::Rational difference, bound;
        algebra::set_exact_double(difference.get(), c);
        fmpq_sub(difference.get(), difference.get(), exact.get());
        fmpq_abs(difference.get(), difference.get());
        algebra::set_exact_double(bound.get(), r);
        return fmpq_cmp(difference.get(), bound.get()) <= 0;
    }
};

using RingPtrForTest = algebra::RingPtr;
RingPtrForTest xyz_ring_for_test() {
    return algebra::PolyRing::make({"x", "y", "z"}, algebra::MonomialOrder::grevlex(3));
}

std::vector<ExactCoefficient> exact_restriction(const std::string& equation,
                                                const DoubleDoubleLine& line) {
    const algebra::RingPtr ring = xyz_ring_for_test();
    const algebra::Polynomial f = algebra::parse_polynomial(equation, ring);
    algebra::FlintContext context(ring);
    const algebra::FlintPolynomial flint_f = algebra::to_fmpq_mpoly(f, context);
    std::array<fmpq_poly_t, 3> coordinates;
    std::array<fmpq_poly_struct*, 3> pointers;
    algebra::Rational part, sum;
    for (int i = 0; i < 3; ++i) {
        fmpq_poly_init(coordinates[i]);
        for (const auto& [hi, lo, power] :
             {std::tuple{line.origin_hi[i], line.origin_lo[i], 0},
              std::tuple{line.direction_hi[i], line.direction_lo[i], 1}}) {
            algebra::set_exact_double(sum.get(), hi);
            algebra::set_exact_double(part.get(), lo);
            fmpq_add(sum.get(), sum.get(), part.get());
            fmpq_poly_set_coeff_fmpq(coordinates[i], power, sum.get());
        }
        pointers[i] = coordinates[i];
    }
    fmpq_poly_t composed;
    fmpq_poly_init(composed);
    fmpq_mpoly_compose_fmpq_poly(composed, flint_f.get(), pointers.data(), context.get());
    std::vector<ExactCoefficient> result(static_cast<std::size_t>(fmpq_poly_length(composed)));
    for (std::size_t k = 0; k < result.size(); ++k) {
        fmpq_poly_get_coeff_fmpq(result[k].exact.get(), composed, static_cast<slong>(k));
        result[k].value = fmpq_get_d(result[k].exact.get());
    }
    fmpq_poly_clear(composed);
    for (auto& c : coordinates) {
        fmpq_poly_clear(c);
    }
    return result;
}

// Σ|c|·(|m| + |h|)^|α| over f's terms for the line m + x·h: what any rounding of a
// restriction is measured against.
double terms_magnitude(const algebra::CompiledPolynomial& f, const DoubleDoubleLine& line) {
    double magnitude = 0.0;
    for (const algebra::CompiledTerm& term : f.terms()) {
        magnitude += std::abs(term.coefficient) *
                     std::pow(std::abs(line.origin_hi.x) + std::abs(line.direction_hi.x), term.ex) *
                     std::pow(std::abs(line.origin_hi.y) + std::abs(line.direction_hi.y), term.ey) *
                     std::pow(std::abs(line.origin_hi.z) + std::abs(line.direction_hi.z), term.ez);
    }
    return magnitude;
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

// The double-double restriction's balls against the exact restriction over Q (FLINT's
// composition, which shares no code with it): for random surfaces with coefficients that are
// not doubles (twenty digits, thirds: their low words matter), random double-double lines and a
// degree-30 surface, every exact coefficient of f(m + x·h) lies within its radius — and each
// radius is the coefficient's own rounding to a double plus at most 1e-24 of the terms'
// magnitudes, where a restriction in doubles gives about 1e-16 of them.
TEST(LineRestrictor, DoubleDoubleBallsHoldTheExactRestriction) {
    const RingPtrForTest ring = xyz_ring_for_test();
    std::mt19937_64 rng(30);
    std::uniform_real_distribution<double> coordinate(-1.5, 1.5), tiny(-1e-17, 1e-17);
    int checked = 0;
    for (int trial = 0; trial < 60; ++trial) {
        std::string equation;
        if (trial % 10 == 9) {
            equation = test::chmutov_equation(30);
        } else {
            equation = random_equation(rng, 2 + trial % 9) +
                       "+12345678901234567891*x*y-98765432109876543211/3*z^2";
        }
        const algebra::CompiledPolynomial f = algebra::compile_surface(equation);
        const LineRestrictor restrictor(f.terms(), f.low_words());
        DoubleDoubleLine line;
        for (int i = 0; i < 3; ++i) {
            line.origin_hi[i] = coordinate(rng);
            line.origin_lo[i] = tiny(rng) * std::abs(line.origin_hi[i]);
            line.direction_hi[i] = 0.01 * coordinate(rng);
            line.direction_lo[i] = tiny(rng) * std::abs(line.direction_hi[i]);
        }
        const RestrictionBall ball = restrictor.restrict_with_double_double_bounds(
            line, LineError{}, f.double_double_coefficient_error());
        ASSERT_TRUE(ball.certified);
        const std::vector<ExactCoefficient> exact = exact_restriction(f.equation(), line);
        const double magnitude = terms_magnitude(f, line);
        for (int k = 0; k <= ball.polynomial.degree; ++k) {
            const auto at = static_cast<std::size_t>(k);
            const double exact_value = at < exact.size() ? exact[at].value : 0.0;
            const bool within = at < exact.size()
                                    ? exact[at].within(ball.polynomial.c[k], ball.radius[k])
                                    : std::abs(ball.polynomial.c[k]) <= ball.radius[k];
            EXPECT_TRUE(within) << equation << ": coefficient " << k << " " << ball.polynomial.c[k]
                                << " ± " << ball.radius[k] << ", exact " << exact_value;
            // The rounding to a double (about u·|c_k|) and double-double's own radius (u² of the
            // terms' magnitudes): in doubles the radius would be about u·magnitude instead.
            EXPECT_LT(ball.radius[k],
                      2.5 * 0x1.0p-53 * std::abs(ball.polynomial.c[k]) + 1e-24 * magnitude)
                << equation << ": coefficient " << k;
            ++checked;
        }
    }
    EXPECT_GT(checked, 300);
}

// The restriction's balls in doubles against the exact restriction over Q, on the surfaces
// whose pure powers go through Horner's rule (an axis' pure powers above its other exponents:
// Chmutov's T_n, and random surfaces with their top pure powers) and on ones that keep the power
// tables (every pure power matched by a mixed term as high): every exact coefficient lies within
// its radius, and the radius stays near u of the terms' magnitudes.
TEST(LineRestrictor, BallsHoldTheExactRestrictionWithAndWithoutHorner) {
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> coordinate(-1.5, 1.5);
    int checked = 0;
    for (int trial = 0; trial < 40; ++trial) {
        std::string equation;
        switch (trial % 4) {
        case 0:
            equation = test::chmutov_equation(4 + 2 * (trial % 13));
            break;
        case 1:
            equation = random_equation(rng, 2 + trial % 9) + "-1/3*x^12+7*z^11";
            break;
        case 2:  // pure powers no higher than the mixed terms: power tables only
            equation = random_equation(rng, 2 + trial % 7) + "+x^9*y+y^9*z+z^9*x-2*x^9+y^9/5";
            break;
        default:
            equation = random_equation(rng, 2 + trial % 9);
            break;
        }
        const algebra::CompiledPolynomial f = algebra::compile_surface(equation);
        const LineRestrictor restrictor(f.terms());
        DoubleDoubleLine line;
        for (int i = 0; i < 3; ++i) {
            line.origin_hi[i] = coordinate(rng);
            line.direction_hi[i] = 0.5 * coordinate(rng);
        }
        const RestrictionBall ball = restrictor.restrict_with_bounds(
            line.origin_hi, line.direction_hi, LineError{}, f.coefficient_error());
        ASSERT_TRUE(ball.certified) << equation;
        const std::vector<ExactCoefficient> exact = exact_restriction(f.equation(), line);
        const double magnitude = terms_magnitude(f, line);
        for (int k = 0; k <= ball.polynomial.degree; ++k) {
            const auto at = static_cast<std::size_t>(k);
            const bool within = at < exact.size()
                                    ? exact[at].within(ball.polynomial.c[k], ball.radius[k])
                                    : std::abs(ball.polynomial.c[k]) <= ball.radius[k];
            EXPECT_TRUE(within) << equation << ": coefficient " << k << " " << ball.polynomial.c[k]
                                << " ± " << ball.radius[k];
            EXPECT_LT(ball.radius[k], 1e-12 * magnitude) << equation << ": coefficient " << k;
            ++checked;
        }
    }
    EXPECT_GT(checked, 300);
}

// Mixed terms at the largest exponents the tables hold (degree 64, an axis' power 63 among its
// mixed terms): the expansion's tables are packed by row (row k from k(k + 1)/2), and these
// reach their last rows. Every exact coefficient lies within its ball, in doubles and in
// double-double, and the plain restriction agrees with the exact one.
TEST(LineRestrictor, BallsHoldTheExactRestrictionAtTheLargestExponents) {
    std::mt19937_64 rng(64);
    std::uniform_real_distribution<double> coordinate(-1.1, 1.1);
    const std::vector<std::string> equations = {
        "x^63*y-3*y^61*z^3+z^62*x^2/7+x^2*y*z-1",
        "x^32*y^32+y^40*z^24/5-z^50*x^14+x^63*z-2*y^63*x+x^64+y^64-z^64+1/3",
        "x^60*y*z^3-x*y^60*z^3+x^3*y*z^60-12345678901234567891*x*y*z-2"};
    int checked = 0;
    for (const std::string& equation : equations) {
        const algebra::CompiledPolynomial f = algebra::compile_surface(equation);
        ASSERT_EQ(f.degree(), 64) << equation;
        const LineRestrictor restrictor(f.terms(), f.low_words());
        for (int trial = 0; trial < 4; ++trial) {
            DoubleDoubleLine line;
            for (int i = 0; i < 3; ++i) {
                line.origin_hi[i] = coordinate(rng);
                line.direction_hi[i] = 0.05 * coordinate(rng);
            }
            const std::vector<ExactCoefficient> exact = exact_restriction(f.equation(), line);
            for (const bool double_double : {false, true}) {
                const RestrictionBall ball =
                    double_double
                        ? restrictor.restrict_with_double_double_bounds(
                              line, LineError{}, f.double_double_coefficient_error())
                        : restrictor.restrict_with_bounds(line.origin_hi, line.direction_hi,
                                                          LineError{}, f.coefficient_error());
                ASSERT_TRUE(ball.certified) << equation;
                for (int k = 0; k <= ball.polynomial.degree; ++k) {
                    const auto at = static_cast<std::size_t>(k);
                    const bool within = at < exact.size()
                                            ? exact[at].within(ball.polynomial.c[k], ball.radius[k])
                                            : std::abs(ball.polynomial.c[k]) <= ball.radius[k];
                    EXPECT_TRUE(within)
                        << equation << (double_double ? " (double-double)" : "") << ": coefficient "
                        << k << " " << ball.polynomial.c[k] << " ± " << ball.radius[k];
                    ++checked;
                }
            }
            expect_restriction_matches(f, restrictor.restrict_to(line.origin_hi, line.direction_hi),
                                       line.origin_hi, line.direction_hi, 1e-11);
        }
    }
    EXPECT_GT(checked, 1000);
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
                // The family interpolates through n + 1 rays (and evaluates the interpolant in
                // powers of x): ten times the direct restriction's allowance (seed 35 of
                // LOCUS_TEST_MULTIPLIER=5 needed 1.3 times the direct one).
                expect_restriction_matches(f, from_family, ray.at(family.origin_t()), ray.direction,
                                           1e-10);
            }
        }
    }
}

}  // namespace
}  // namespace locus::render
