// Polynomial arithmetic against FLINT's fmpq_mpoly as an independent oracle, and identities.
#include "algebra/polynomial.h"

#include <gtest/gtest.h>

#include <random>

#include "algebra/error.h"
#include "algebra/flint_convert.h"
#include "algebra/parse.h"
#include "algebra/print.h"
#include "tests/support/test_data.h"

namespace locus::algebra {
namespace {

RingPtr ring_for_seed(int seed) {
    const char* orders[] = {"lex",     "grlex",
                            "grevlex", "weights(2,1,3)",
                            "elim(y)", "matrix((1,1,1),(0,0,-1),(0,-1,0))"};
    const std::vector<std::string> names = {"x", "y", "z"};
    return PolyRing::make(names, parse_monomial_order(orders[seed % 6], names));
}

TEST(Polynomial, ArithmeticAgreesWithFlint) {
    for (int seed = 0; seed < test::seed_count(200); ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        std::mt19937_64 rng(seed);
        const RingPtr ring = ring_for_seed(seed);
        const Polynomial f = test::random_polynomial(ring, rng, 1 + seed % 7, 4);
        const Polynomial g = test::random_polynomial(ring, rng, 1 + seed % 5, 3);
        FlintContext ctx(ring);
        FlintPolynomial ff = to_fmpq_mpoly(f, ctx), fg = to_fmpq_mpoly(g, ctx), r(ctx);

        fmpq_mpoly_add(r.get(), ff.get(), fg.get(), ctx.get());
        EXPECT_EQ(f + g, from_fmpq_mpoly(r.get(), ctx));
        fmpq_mpoly_sub(r.get(), ff.get(), fg.get(), ctx.get());
        EXPECT_EQ(f - g, from_fmpq_mpoly(r.get(), ctx));
        fmpq_mpoly_mul(r.get(), ff.get(), fg.get(), ctx.get());
        const Polynomial product = f * g;
        EXPECT_EQ(product, from_fmpq_mpoly(r.get(), ctx));
        EXPECT_TRUE(product.is_canonical());
        fmpq_mpoly_pow_ui(r.get(), ff.get(), 3, ctx.get());
        EXPECT_EQ(f.pow(3), from_fmpq_mpoly(r.get(), ctx));
        fmpq_mpoly_derivative(r.get(), ff.get(), 1, ctx.get());
        EXPECT_EQ(f.derivative(1), from_fmpq_mpoly(r.get(), ctx));
        // Identities: (f + g) − g = f, f·g = g·f, round trip through FLINT.
        EXPECT_EQ((f + g) - g, f);
        EXPECT_EQ(f * g, g * f);
        EXPECT_EQ(from_fmpq_mpoly(ff.get(), ctx), f);
    }
}

TEST(Polynomial, EvaluateSubstituteAndContent) {
    for (int seed = 0; seed < test::seed_count(100); ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        std::mt19937_64 rng(seed);
        const RingPtr ring = ring_for_seed(seed);
        const Polynomial f = test::random_polynomial(ring, rng, 1 + seed % 6, 3);
        const Polynomial g = test::random_polynomial(ring, rng, 1 + seed % 4, 2);
        const std::vector<Rational> point = {Rational(1, 2), Rational(-3), Rational(2, 3)};
        // Evaluation is a ring homomorphism.
        EXPECT_EQ((f * g).evaluate(point), f.evaluate(point) * g.evaluate(point));
        EXPECT_EQ((f + g).evaluate(point), f.evaluate(point) + g.evaluate(point));
        // Substituting constants equals evaluating.
        std::vector<Polynomial> constants;
        for (const auto& p : point) {
            constants.push_back(Polynomial::constant(ring, p));
        }
        const Polynomial at = f.substitute(constants);
        EXPECT_TRUE(at.is_constant());
        EXPECT_EQ(at.is_zero() ? Rational() : at.leading_coefficient(), f.evaluate(point));
        // Substituting the variables themselves is the identity.
        std::vector<Polynomial> vars;
        for (std::size_t v = 0; v < 3; ++v) {
            vars.push_back(Polynomial::variable(ring, v));
        }
        EXPECT_EQ(f.substitute(vars), f);
        // f = content · primitive part, with integer coprime coefficients.
        if (!f.is_zero()) {
            const Polynomial pp = f.primitive_part();
            EXPECT_TRUE(pp.leading_coefficient().sign() > 0);
            EXPECT_TRUE(pp.content().is_one());
            const Rational ratio = f.leading_coefficient() / pp.leading_coefficient();
            EXPECT_EQ(pp * ratio, f);
        }
    }
}

// Powers are refused before the work when they could be too large or too slow, and computed
// (against FLINT) just inside the limits.
TEST(Polynomial, PowerLimitsRefuseBeforeExpanding) {
    const RingPtr r = PolyRing::make({"s", "t"}, MonomialOrder::grevlex(2));
    const Polynomial base = parse_polynomial("1+s^2+t^2", r);
    EXPECT_THROW(base.pow(555), ResourceLimit);  // 39 060² term products (a fuzzer's timeout)
    EXPECT_THROW(parse_polynomial("(s+t+1)^32767", r), ResourceLimit);  // 5e8 terms
    // Few terms but wide coefficients: 1508² products of 1500-bit binomials (a fuzzer's timeout).
    EXPECT_THROW(parse_polynomial("(1-t)^3015", r), ResourceLimit);
    EXPECT_THROW(parse_polynomial("(1/3-t/7)^2000", r), ResourceLimit);
    const Polynomial binomial = parse_polynomial("(1-t)^600", r);
    EXPECT_EQ(binomial.num_terms(), 601u);
    Integer middle;
    fmpz_bin_uiui(middle.get(), 600, 300);
    EXPECT_EQ(binomial.coefficient(300), Rational(middle));  // C(600, 300)·(−t)^300
    const Polynomial inside = base.pow(60);  // s^2a·t^2b, a + b ≤ 60: C(62, 2) = 1891 terms
    EXPECT_EQ(inside.num_terms(), 1891u);
    FlintContext ctx(r);
    FlintPolynomial flint_base = to_fmpq_mpoly(base, ctx), power(ctx);
    fmpq_mpoly_pow_ui(power.get(), flint_base.get(), 60, ctx.get());
    EXPECT_EQ(inside, from_fmpq_mpoly(power.get(), ctx));
}

TEST(Polynomial, MixedRingsThrow) {
    const RingPtr a = PolyRing::make({"x", "y"}, MonomialOrder::lex(2));
    const RingPtr b = PolyRing::make({"x", "y"}, MonomialOrder::grevlex(2));
    EXPECT_THROW(Polynomial::variable(a, 0) + Polynomial::variable(b, 0), MixedRings);
    // Equal rings made separately are the same ring.
    const RingPtr c = PolyRing::make({"x", "y"}, MonomialOrder::lex(2));
    EXPECT_NO_THROW(Polynomial::variable(a, 0) + Polynomial::variable(c, 1));
}

TEST(Polynomial, InRingResortsTerms) {
    const RingPtr lex = PolyRing::make({"x", "y"}, MonomialOrder::lex(2));
    const RingPtr grevlex = lex->with_order(MonomialOrder::grevlex(2));
    const Polynomial f = parse_polynomial("x + y^2", lex);
    EXPECT_EQ(to_string(f), "x+y^2");
    EXPECT_EQ(to_string(f.in_ring(grevlex)), "y^2+x");
}

TEST(FlintConvert, GcdFactorAndSquareFreePart) {
    const RingPtr ring = PolyRing::make({"x", "y", "z"}, MonomialOrder::grevlex(3));
    const Polynomial sphere = parse_polynomial("x^2+y^2+z^2-1", ring);
    const Polynomial plane = parse_polynomial("2*x-y", ring);
    EXPECT_EQ(gcd(sphere * plane, plane * plane), plane.monic());
    const Factorization fac = factor(Rational(3) * sphere.pow(2) * plane);
    ASSERT_EQ(fac.factors.size(), 2u);
    Polynomial product = Polynomial::constant(ring, fac.unit);
    for (const auto& [p, k] : fac.factors) {
        product *= p.pow(k);
    }
    EXPECT_EQ(product, Rational(3) * sphere.pow(2) * plane);
    EXPECT_EQ(square_free_part(sphere.pow(2) * plane.pow(3)), (sphere * plane).primitive_part());
}

// The product of the distinct factors of FLINT's full factorization, primitive: what
// square_free_part (FLINT's square-free factorization, a different algorithm) must return.
Polynomial distinct_factors(const Polynomial& f) {
    Polynomial product = Polynomial::constant(f.ring(), Rational(1));
    for (const auto& [p, k] : factor(f).factors) {
        product *= p;
    }
    return product.primitive_part();
}

TEST(FlintConvert, SquareFreePartAgreesWithTheFullFactorization) {
    for (int seed = 0; seed < test::seed_count(150); ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        std::mt19937_64 rng(seed);
        const RingPtr ring = ring_for_seed(seed);
        Polynomial f = Polynomial::constant(ring, Rational(1 + seed % 4));
        for (int piece = 0; piece < 1 + seed % 3; ++piece) {
            const Polynomial g = test::random_polynomial(ring, rng, 1 + seed % 4, 2);
            if (!g.is_zero()) {
                f *= g.pow(1 + static_cast<unsigned>(rng() % 3));
            }
        }
        if (f.is_constant()) {
            continue;
        }
        EXPECT_EQ(square_free_part(f), distinct_factors(f));
    }
}

}  // namespace
}  // namespace locus::algebra
