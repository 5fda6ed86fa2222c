// The compile step (algebra/compiled.h) and the exact first root it offers the renderer: exact
// root isolation (algebra/real_roots.h) against roots known in closed form.
#include "algebra/compiled.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "algebra/error.h"
#include "algebra/parse.h"
#include "algebra/print.h"
#include "algebra/real_roots.h"
#include "tests/support/chmutov.h"
#include "tests/support/exact_ray_oracle.h"
#include "tests/support/test_data.h"

namespace locus::algebra {
namespace {

using Status = ExactRoot::Status;

TEST(CompileSurface, RejectsEquationsWithoutASurface) {
    EXPECT_THROW(compile_surface("0"), InputError);
    EXPECT_THROW(compile_surface("x - x + 3"), InputError);
    try {
        compile_surface("x^2 + w");
        FAIL() << "an unknown variable must be a parse error";
    } catch (const ParseError& e) {
        EXPECT_EQ(e.line(), 1u);
        EXPECT_EQ(e.column(), 7u);
    }
}

TEST(CompileSurface, ReplacesNonReducedEquationsByTheirSquareFreePart) {
    const CompiledPolynomial squared = compile_surface("(x^2+y^2+z^2-1)^2");
    EXPECT_TRUE(squared.made_square_free());
    EXPECT_EQ(squared.degree(), 2);
    EXPECT_EQ(squared.equation(), "x^2+y^2+z^2-1");
    const CompiledPolynomial plain = compile_surface("x^2+y^2+z^2-1");
    EXPECT_FALSE(plain.made_square_free());
    const CompiledPolynomial mixed = compile_surface("x^3*(y-1)^2*(z+x)");
    EXPECT_TRUE(mixed.made_square_free());
    EXPECT_EQ(mixed.degree(), 3);
}

// The compiled polynomial has the sign of the equation as written, so that its sides (a
// two-sided material's colours, an SDF leaf's inside f < 0) are the ones the user wrote:
// the square-free part's normalisation (a positive leading coefficient) made 1 − x² − y² − z²
// render exactly as x² + y² + z² − 1, its outside in the colour of f > 0. The oracle is the
// exact value of the written polynomial over Q at random rational points.
TEST(CompileSurface, KeepsTheSignOfTheEquation) {
    const CompiledPolynomial ball = compile_surface("1-x^2-y^2-z^2");
    EXPECT_GT(ball.value({0.0, 0.0, 0.0}), 0.0);
    EXPECT_LT(ball.value({2.0, 0.0, 0.0}), 0.0);
    const CompiledPolynomial sphere = compile_surface("x^2+y^2+z^2-1");
    EXPECT_LT(sphere.value({0.0, 0.0, 0.0}), 0.0);
    // A repeated factor: the signs agree wherever it is positive (outside the sphere here).
    const CompiledPolynomial repeated = compile_surface("-(x^2+y^2+z^2-1)^2*(z-5)");
    EXPECT_TRUE(repeated.made_square_free());
    EXPECT_GT(repeated.value({2.0, 0.0, 0.0}), 0.0);  // the equation: −9·(−5) > 0
    EXPECT_LT(repeated.value({2.0, 0.0, 6.0}), 0.0);  // −(39)²·1 < 0
    const RingPtr ring = PolyRing::make({"x", "y", "z"}, MonomialOrder::grevlex(3));
    int compared = 0;
    for (int seed = 0; seed < test::seed_count(40); ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        std::mt19937_64 rng(static_cast<std::uint64_t>(seed) + 1000);
        Polynomial f = test::random_polynomial(ring, rng, 6, 4);
        if (seed % 2 == 1) {
            f = -f;
        }
        if (f.is_constant()) {
            continue;
        }
        const CompiledPolynomial compiled = compile_surface(f);
        if (compiled.made_square_free()) {
            continue;
        }
        std::uniform_int_distribution<int> numerator(-20, 20);
        for (int k = 0; k < 8; ++k) {
            const std::array<Rational, 3> point = {Rational(numerator(rng), 8),
                                                   Rational(numerator(rng), 8),
                                                   Rational(numerator(rng), 8)};
            const Rational exact = f.evaluate(point);
            const double value =
                compiled.value({fmpq_get_d(point[0].get()), fmpq_get_d(point[1].get()),
                                fmpq_get_d(point[2].get())});
            if (exact.sign() == 0 || std::abs(value) < 1e-9 * (1.0 + std::abs(value))) {
                continue;
            }
            ++compared;
            EXPECT_EQ(value > 0.0, exact.sign() > 0) << to_string(f);
        }
    }
    EXPECT_GT(compared, 100);
}

TEST(CompiledPolynomial, ValueAndGradientAgreeWithExactEvaluation) {
    const RingPtr ring = PolyRing::make({"x", "y", "z"}, MonomialOrder::grevlex(3));
    for (int seed = 0; seed < test::seed_count(20); ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        std::mt19937_64 rng(static_cast<std::uint64_t>(seed));
        const Polynomial f = test::random_polynomial(ring, rng, 8, 4);
        if (f.is_constant()) {
            continue;
        }
        const CompiledPolynomial compiled = compile_surface(f);
        // Compare against the square-free polynomial the compile step kept.
        const Polynomial kept = parse_polynomial(compiled.equation(), ring);
        std::uniform_int_distribution<int> numerator(-20, 20);
        const std::array<Rational, 3> point = {
            Rational(numerator(rng), 8), Rational(numerator(rng), 8), Rational(numerator(rng), 8)};
        const Point3 p = {fmpq_get_d(point[0].get()), fmpq_get_d(point[1].get()),
                          fmpq_get_d(point[2].get())};
        const double expected = fmpq_get_d(kept.evaluate(point).get());
        const ValueGradient vg = compiled.value_gradient(p);
        const double scale = 1e-12 * (1.0 + std::abs(expected)) * 1e3;
        EXPECT_NEAR(compiled.value(p), expected, scale);
        EXPECT_NEAR(vg.value, expected, scale);
        for (std::size_t axis = 0; axis < 3; ++axis) {
            const double partial = fmpq_get_d(kept.derivative(axis).evaluate(point).get());
            EXPECT_NEAR(vg.gradient[axis], partial, 1e-9 * (1.0 + std::abs(partial)));
            // The gradient alone sums the same terms in another order.
            EXPECT_NEAR(compiled.gradient(p)[axis], partial, 1e-9 * (1.0 + std::abs(partial)));
        }
    }
}

// enclose_on_line's enclosures hold the exact value of the exact f at the exact point o + t·d,
// in doubles and in double-double — the exact value from FLINT's own parser and composition
// (tests/support/exact_ray_oracle.h), which share no code with the compile step. On random
// polynomials, and on ones whose pure powers it takes by Horner's rule (chains: Chmutov's T_n,
// odd and even; pure powers above and below an axis's other exponents; a z chain beside low z
// powers and the constant); at random points of random lines and at points next to a root
// along them, where the terms cancel most.
TEST(CompiledPolynomial, EnclosuresOnALineHoldTheExactValue) {
    const RingPtr ring = PolyRing::make({"x", "y", "z"}, MonomialOrder::grevlex(3));
    std::vector<std::string> equations = {test::chmutov_equation(6),
                                          test::chmutov_equation(9),
                                          test::chmutov_equation(30),
                                          "x^7-3*x^5*y+2*x^9+y^4-z^3*y+z^11-2*z^4+z+1/3",
                                          "x^12+x^6*y*z-y^10+y^2+z^2*x-7/5*z^8+z^5-1",
                                          "x^2+y^2+z^2-1"};
    std::mt19937_64 rng(2026);
    for (int i = 0; i < 6; ++i) {
        equations.push_back(to_string(test::random_polynomial(ring, rng, 9, 6)));
    }
    std::uniform_real_distribution<double> unit(-1.0, 1.0), scale(0.05, 1.6);
    int checked = 0, near_roots = 0;
    for (const std::string& equation : equations) {
        SCOPED_TRACE(equation);
        const Polynomial parsed = parse_polynomial(equation, ring);
        if (parsed.is_constant()) {
            continue;
        }
        const CompiledPolynomial compiled = compile_surface(parsed);
        const test::ExactRayOracle oracle(compiled.equation());
        for (int trial = 0; trial < 40; ++trial) {
            const double size = scale(rng);
            const Point3 origin = {size * unit(rng), size * unit(rng), size * unit(rng)};
            const Point3 direction = {unit(rng), unit(rng), unit(rng)};
            const auto value_at = [&](double t) {
                return compiled.value({origin[0] + t * direction[0], origin[1] + t * direction[1],
                                       origin[2] + t * direction[2]});
            };
            std::vector<double> ts = {0.5 * unit(rng)};
            // A root along the line, by bisection in doubles on a sign change of f, and the
            // doubles either side of it.
            for (int k = 0; k < 64; ++k) {
                double lo = -1.0 + k / 32.0, hi = lo + 1.0 / 32.0;
                if ((value_at(lo) > 0.0) == (value_at(hi) > 0.0)) {
                    continue;
                }
                for (int step = 0; step < 80; ++step) {
                    const double middle = 0.5 * (lo + hi);
                    ((value_at(middle) > 0.0) == (value_at(lo) > 0.0) ? lo : hi) = middle;
                }
                ts.insert(ts.end(), {lo, hi, std::nextafter(lo, -1.0), std::nextafter(hi, 1.0)});
                ++near_roots;
                break;
            }
            for (const double t : ts) {
                Rational exact;
                oracle.value_on_line(origin, direction, t, exact.get());
                for (const auto precision : {CompiledPolynomial::Precision::double_precision,
                                             CompiledPolynomial::Precision::double_double}) {
                    const ValueEnclosure e =
                        compiled.enclose_on_line(origin, direction, t, precision);
                    ASSERT_TRUE(std::isfinite(e.radius));
                    // |exact − (value + value_low)| ≤ radius, in rationals.
                    Rational difference, part;
                    set_exact_double(part.get(), e.value);
                    fmpq_sub(difference.get(), exact.get(), part.get());
                    set_exact_double(part.get(), e.value_low);
                    fmpq_sub(difference.get(), difference.get(), part.get());
                    fmpq_abs(difference.get(), difference.get());
                    set_exact_double(part.get(), e.radius);
                    EXPECT_LE(fmpq_cmp(difference.get(), part.get()), 0)
                        << "t " << t << ", double-double "
                        << (precision == CompiledPolynomial::Precision::double_double) << ": value "
                        << e.value << " radius " << e.radius << ", exact "
                        << fmpq_get_d(exact.get());
                    ++checked;
                }
            }
        }
    }
    EXPECT_GT(checked, 1500);
    EXPECT_GT(near_roots, 100);
}

TEST(ExactFirstRoot, SphereAlongAnAxisIsExact) {
    const CompiledPolynomial sphere = compile_surface("x^2+y^2+z^2-1");
    ExactRoot r = exact_first_root(sphere, {0, 0, 5}, {0, 0, -1}, 0, 100);
    ASSERT_EQ(r.status, Status::hit);
    EXPECT_EQ(r.t, 4.0);  // rational roots are found exactly
    r = exact_first_root(sphere, {0, 0, 0}, {1, 0, 0}, 0, 100);
    EXPECT_EQ(r.t, 1.0);
    r = exact_first_root(sphere, {3, 3, 3}, {1, 0, 0}, 0, 100);
    EXPECT_EQ(r.status, Status::miss);
    // Tangent ray: a double root counts.
    r = exact_first_root(sphere, {1, 0, 5}, {0, 0, -1}, 0, 100);
    ASSERT_EQ(r.status, Status::hit);
    EXPECT_EQ(r.t, 5.0);
    // Irrational root 5 − √(1 − 0.25): within one ulp.
    r = exact_first_root(sphere, {0.5, 0, 5}, {0, 0, -1}, 0, 100);
    EXPECT_NEAR(r.t, 5.0 - std::sqrt(0.75), 1e-15);
}

TEST(ExactFirstRoot, IntervalEndsAndOpenLowerEnd) {
    const CompiledPolynomial sphere = compile_surface("x^2+y^2+z^2-1");
    // Origin on the surface: t = 0 is a root; with lo_open the next root is t = 2.
    EXPECT_EQ(exact_first_root(sphere, {-1, 0, 0}, {1, 0, 0}, 0, 10).t, 0.0);
    const ExactRoot open = exact_first_root(sphere, {-1, 0, 0}, {1, 0, 0}, 0, 10, true);
    ASSERT_EQ(open.status, Status::hit);
    EXPECT_EQ(open.t, 2.0);
    // Root exactly at the upper end, and just beyond it.
    EXPECT_EQ(exact_first_root(sphere, {0, 0, 5}, {0, 0, -1}, 0, 4).t, 4.0);
    EXPECT_EQ(exact_first_root(sphere, {0, 0, 5}, {0, 0, -1}, 0, 3.999).status, Status::miss);
}

TEST(ExactFirstRoot, RayInsideTheSurfaceIsReported) {
    const CompiledPolynomial plane = compile_surface("z");
    EXPECT_EQ(exact_first_root(plane, {0, 0, 0}, {1, 1, 0}, 0.5, 2).status,
              Status::identically_zero);
}

// Exact isolation on polynomials with known roots, including clustered ones 2^-40 apart.
TEST(FirstRealRoot, KnownRootsAndClusters) {
    fmpz_poly_t p;
    fmpz_poly_init(p);
    fmpq_t lo, hi;
    fmpq_init(lo);
    fmpq_init(hi);
    // (2t − 1)(2^41 t − 2^40 − 1): roots 1/2 and 1/2 + 2^-41.
    fmpz_poly_t a, b;
    fmpz_poly_init(a);
    fmpz_poly_init(b);
    fmpz_poly_set_coeff_si(a, 1, 2);
    fmpz_poly_set_coeff_si(a, 0, -1);
    fmpz_t c;
    fmpz_init(c);
    fmpz_one(c);
    fmpz_mul_2exp(c, c, 41);
    fmpz_poly_set_coeff_fmpz(b, 1, c);
    fmpz_one(c);
    fmpz_mul_2exp(c, c, 40);
    fmpz_add_ui(c, c, 1);
    fmpz_neg(c, c);
    fmpz_poly_set_coeff_fmpz(b, 0, c);
    fmpz_poly_mul(p, a, b);
    fmpq_set_si(lo, 0, 1);
    fmpq_set_si(hi, 1, 1);
    EXPECT_EQ(first_real_root(p, lo, hi, false), 0.5);
    fmpq_set_si(lo, 1, 2);
    EXPECT_EQ(first_real_root(p, lo, hi, true), 0.5 + std::ldexp(1.0, -41));
    // t² − 2 on [0, 2]: √2 to the nearest double.
    fmpz_poly_zero(p);
    fmpz_poly_set_coeff_si(p, 2, 1);
    fmpz_poly_set_coeff_si(p, 0, -2);
    fmpq_set_si(lo, 0, 1);
    fmpq_set_si(hi, 2, 1);
    EXPECT_EQ(first_real_root(p, lo, hi, false), std::sqrt(2.0));
    // No root in [−1, 1].
    fmpq_set_si(lo, -1, 1);
    fmpq_set_si(hi, 1, 1);
    EXPECT_FALSE(first_real_root(p, lo, hi, false).has_value());
    fmpz_clear(c);
    fmpz_poly_clear(a);
    fmpz_poly_clear(b);
    fmpz_poly_clear(p);
    fmpq_clear(lo);
    fmpq_clear(hi);
}

// Wilkinson's polynomial Π (t − k), k = 1..20: every first root after a half-integer is exact.
TEST(FirstRealRoot, Wilkinson) {
    fmpz_poly_t p, factor;
    fmpz_poly_init(p);
    fmpz_poly_init(factor);
    fmpz_poly_one(p);
    for (int k = 1; k <= 20; ++k) {
        fmpz_poly_zero(factor);
        fmpz_poly_set_coeff_si(factor, 1, 1);
        fmpz_poly_set_coeff_si(factor, 0, -k);
        fmpz_poly_mul(p, p, factor);
    }
    fmpq_t lo, hi;
    fmpq_init(lo);
    fmpq_init(hi);
    fmpq_set_si(hi, 100, 1);
    for (int k = 0; k < 20; ++k) {
        fmpq_set_si(lo, 2 * k + 1, 2);
        EXPECT_EQ(first_real_root(p, lo, hi, false), k + 1.0) << "after " << k + 0.5;
    }
    fmpq_clear(lo);
    fmpq_clear(hi);
    fmpz_poly_clear(p);
    fmpz_poly_clear(factor);
}

// Roots at the edges of the doubles: exactly halfway between the two smallest subnormals (a
// rounding boundary where a quarter ulp is no double: the enclosure must still end), near 2^1000,
// and on intervals as wide as the doubles go. Either neighbour of a boundary root is right.
TEST(FirstRealRoot, RootsAtTheEdgesOfTheDoubles) {
    fmpz_poly_t p;
    fmpz_poly_init(p);
    fmpq_t lo, hi;
    fmpq_init(lo);
    fmpq_init(hi);
    fmpz_t c;
    fmpz_init(c);
    // 2^1075·t − 3: the root 1.5·2^-1074.
    fmpz_one(c);
    fmpz_mul_2exp(c, c, 1075);
    fmpz_poly_set_coeff_fmpz(p, 1, c);
    fmpz_poly_set_coeff_si(p, 0, -3);
    set_exact_double(lo, 0.0);
    set_exact_double(hi, 1.0);
    const std::optional<double> tiny = first_real_root(p, lo, hi, true);
    ASSERT_TRUE(tiny.has_value());
    EXPECT_TRUE(*tiny == std::ldexp(1.0, -1074) || *tiny == std::ldexp(1.0, -1073)) << *tiny;
    // t − (2^1000 + 2^950): a double itself, found from an interval of width 2^1023.
    fmpz_poly_zero(p);
    fmpz_one(c);
    fmpz_mul_2exp(c, c, 1000);
    fmpz_t small;
    fmpz_init(small);
    fmpz_one(small);
    fmpz_mul_2exp(small, small, 950);
    fmpz_add(c, c, small);
    fmpz_neg(c, c);
    fmpz_poly_set_coeff_fmpz(p, 0, c);
    fmpz_poly_set_coeff_si(p, 1, 1);
    set_exact_double(lo, -std::ldexp(1.0, 1022));
    set_exact_double(hi, std::ldexp(1.0, 1023));
    EXPECT_EQ(first_real_root(p, lo, hi, false), std::ldexp(1.0, 1000) + std::ldexp(1.0, 950));
    // 3t² − 1 over [−1e300, 1e300]: −1/√3 first, to the nearest double.
    fmpz_poly_zero(p);
    fmpz_poly_set_coeff_si(p, 2, 3);
    fmpz_poly_set_coeff_si(p, 0, -1);
    set_exact_double(lo, -1e300);
    set_exact_double(hi, 1e300);
    const std::optional<double> third = first_real_root(p, lo, hi, false);
    ASSERT_TRUE(third.has_value());
    EXPECT_NEAR(*third, -1.0 / std::sqrt(3.0), 2.3e-16);
    fmpz_clear(small);
    fmpz_clear(c);
    fmpq_clear(lo);
    fmpq_clear(hi);
    fmpz_poly_clear(p);
}

// The refinement (regula falsi with bisection, exact signs at dyadic points) on roots nobody
// placed: random products of linear factors b·t − a and of t² − m, at every scale from 2^-40 to
// 2^40. The first root in [lo, hi] is known exactly — a rational a/b, whose nearest double
// nearest_double computes, or ±√m·2^e, which IEEE's correctly rounded square root gives — and
// the answer must be that double (a root on a rounding boundary may give either neighbour).
TEST(FirstRealRoot, RandomRootsAreFoundToTheNearestDouble) {
    std::mt19937_64 random(1127);
    std::uniform_int_distribution<long> numerator(-100000, 100000), denominator(1, 5000);
    std::uniform_int_distribution<int> scale_exponent(-40, 40), count(1, 7);
    int exact = 0, trials = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const int e = scale_exponent(random);
        fmpz_poly_t p, factor;
        fmpz_poly_init(p);
        fmpz_poly_init(factor);
        fmpz_poly_one(p);
        std::vector<double> roots;  // as doubles, nearest to the exact roots
        Rational root, scale;
        // Roots r·2^e: the factor (b·t − a·2^e) for e ≥ 0, (2^−e·b·t − a) otherwise.
        fmpz_t a, b;
        fmpz_init(a);
        fmpz_init(b);
        for (int k = count(random); k > 0; --k) {
            fmpz_set_si(a, numerator(random));
            fmpz_set_si(b, denominator(random));
            if (e >= 0) {
                fmpz_mul_2exp(a, a, static_cast<ulong>(e));
            } else {
                fmpz_mul_2exp(b, b, static_cast<ulong>(-e));
            }
            fmpz_poly_zero(factor);
            fmpz_poly_set_coeff_fmpz(factor, 1, b);
            fmpz_neg(a, a);
            fmpz_poly_set_coeff_fmpz(factor, 0, a);
            fmpz_neg(a, a);
            fmpq_set_fmpz_frac(root.get(), a, b);
            roots.push_back(nearest_double(root.get()));
            fmpz_poly_mul(p, p, factor);
        }
        // t² − m·4^e', roots ±√m·2^e' (m = 2, 3, 5, ... not a square).
        const long m = std::array<long, 5>{2, 3, 5, 7, 11}[static_cast<std::size_t>(trial % 5)];
        const int half = e / 2;
        fmpz_poly_zero(factor);
        if (half >= 0) {
            fmpz_poly_set_coeff_si(factor, 2, 1);
            fmpz_set_si(a, -m);
            fmpz_mul_2exp(a, a, static_cast<ulong>(2 * half));
            fmpz_poly_set_coeff_fmpz(factor, 0, a);
        } else {
            fmpz_one(a);
            fmpz_mul_2exp(a, a, static_cast<ulong>(-2 * half));
            fmpz_poly_set_coeff_fmpz(factor, 2, a);
            fmpz_poly_set_coeff_si(factor, 0, -m);
        }
        fmpz_poly_mul(p, p, factor);
        roots.push_back(std::ldexp(std::sqrt(static_cast<double>(m)), half));
        roots.push_back(-roots.back());
        // Square-free: equal random linear roots would repeat.
        fmpz_poly_t derivative, common;
        fmpz_poly_init(derivative);
        fmpz_poly_init(common);
        fmpz_poly_derivative(derivative, p);
        fmpz_poly_gcd(common, p, derivative);
        fmpz_poly_div(p, p, common);
        fmpz_poly_clear(derivative);
        fmpz_poly_clear(common);
        std::sort(roots.begin(), roots.end());
        roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
        // An interval from a random point below the smallest root to past the largest.
        const double low = std::ldexp(-2.0e5, std::max(e, 0)) * (1.0 + 0.001 * (trial % 7));
        const double high = std::ldexp(2.0e5, std::max(e, 0)) + 1.0;
        const std::size_t skip = static_cast<std::size_t>(trial) % roots.size();
        const double from = skip == 0 ? low : 0.5 * (roots[skip - 1] + roots[skip]);
        fmpq_t lo, hi;
        fmpq_init(lo);
        fmpq_init(hi);
        set_exact_double(lo, from);
        set_exact_double(hi, high);
        const std::optional<double> found = first_real_root(p, lo, hi, false);
        ASSERT_TRUE(found.has_value()) << "trial " << trial;
        const double expected = roots[skip];
        const double gap = std::nextafter(std::abs(expected), INFINITY) - std::abs(expected);
        EXPECT_LE(std::abs(*found - expected), gap)
            << "trial " << trial << ": " << *found << " for " << expected;
        exact += *found == expected ? 1 : 0;
        ++trials;
        fmpq_clear(lo);
        fmpq_clear(hi);
        fmpz_clear(a);
        fmpz_clear(b);
        fmpz_poly_clear(p);
        fmpz_poly_clear(factor);
    }
    // Boundary cases are rare: nearly every answer is the nearest double itself.
    EXPECT_GE(exact, trials - 3);
}

}  // namespace
}  // namespace locus::algebra

#include <mpfr.h>

namespace locus::algebra {
namespace {

// nearest_double against MPFR's correctly rounded conversion (a library that shares no code with
// it): small quotients (the direct division), quotients at the 53-bit edge, and large ones (the
// search around fmpq_get_d).
TEST(NearestDouble, AgreesWithMpfrRoundingToNearest) {
    std::mt19937_64 random(53);
    mpfr_t rounded;
    mpfr_init2(rounded, 53);
    mpq_t exact;
    mpq_init(exact);
    fmpq_t t;
    fmpq_init(t);
    const auto check = [&](const fmpz_t numerator, const fmpz_t denominator) {
        if (fmpz_is_zero(denominator)) {
            return;
        }
        fmpq_set_fmpz_frac(t, numerator, denominator);
        fmpq_get_mpq(exact, t);
        mpfr_set_q(rounded, exact, MPFR_RNDN);
        ASSERT_EQ(nearest_double(t), mpfr_get_d(rounded, MPFR_RNDN))
            << fmpq_get_str(nullptr, 10, t);
    };
    fmpz_t numerator, denominator;
    fmpz_init(numerator);
    fmpz_init(denominator);
    for (int i = 0; i < 20000; ++i) {
        const int bits = 1 + static_cast<int>(random() % 70);  // across the 53-bit edge
        const int denominator_bits = 1 + static_cast<int>(random() % 70);
        fmpz_set_ui(numerator, random());
        fmpz_mul_2exp(numerator, numerator, 64);
        fmpz_add_ui(numerator, numerator, random());
        fmpz_fdiv_r_2exp(numerator, numerator, static_cast<ulong>(bits));
        fmpz_set_ui(denominator, random());
        fmpz_mul_2exp(denominator, denominator, 64);
        fmpz_add_ui(denominator, denominator, random());
        fmpz_fdiv_r_2exp(denominator, denominator, static_cast<ulong>(denominator_bits));
        if (i % 2 == 1) {
            fmpz_neg(numerator, numerator);
        }
        check(numerator, denominator);
    }
    // The ends of the direct division: ±2^53 and 2^53 − 1 over 2^53, 3, 2^53 − 1.
    for (const slong n : {slong{1} << 53, -(slong{1} << 53), (slong{1} << 53) - 1, slong{1}}) {
        for (const slong d : {slong{1} << 53, slong{3}, (slong{1} << 53) - 1, slong{1}}) {
            fmpz_set_si(numerator, n);
            fmpz_set_si(denominator, d);
            check(numerator, denominator);
        }
    }
    fmpz_clear(numerator);
    fmpz_clear(denominator);
    fmpq_clear(t);
    mpq_clear(exact);
    mpfr_clear(rounded);
}

}  // namespace
}  // namespace locus::algebra
