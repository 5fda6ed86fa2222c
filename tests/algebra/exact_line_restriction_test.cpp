// The exact restriction of f(x, y, z) to a line of doubles, computed in integers
// (algebra/exact_line_restriction.h), against FLINT's composition over Q (fmpq_mpoly_compose_
// fmpq_poly and fmpq_poly_compose), which shares none of its code: both must be the same
// polynomial up to a positive factor, on random polynomials and random lines — coordinates of
// every magnitude from 2^-300 to 2^300, zeros, negative and subnormal values — and on the
// degree-30 surface whose frames the integer path was written for.
#include "algebra/exact_line_restriction.h"

#include <gtest/gtest.h>

#include <flint/fmpq_mpoly.h>
#include <flint/fmpq_poly.h>

#include <cmath>
#include <random>

#include "algebra/flint_convert.h"
#include "algebra/parse.h"
#include "algebra/poly_ring.h"
#include "algebra/polynomial.h"
#include "algebra/print.h"
#include "algebra/real_roots.h"
#include "tests/support/chmutov.h"

namespace locus::algebra {
namespace {

RingPtr xyz() {
    return PolyRing::make({"x", "y", "z"}, MonomialOrder::grevlex(3));
}

// Whether the integer polynomial p equals c·q for some rational c > 0 (both zero counts).
bool positive_multiple(const fmpz_poly_t p, const fmpq_poly_t q) {
    fmpq_poly_t pq, scaled;
    fmpq_poly_init(pq);
    fmpq_poly_init(scaled);
    fmpq_poly_set_fmpz_poly(pq, p);
    bool same = fmpq_poly_length(pq) == fmpq_poly_length(q);
    if (same && !fmpq_poly_is_zero(q)) {
        // c = lc(p)/lc(q) must be positive and p = c·q.
        fmpq_t c, lq;
        fmpq_init(c);
        fmpq_init(lq);
        fmpq_poly_get_coeff_fmpq(c, pq, fmpq_poly_degree(pq));
        fmpq_poly_get_coeff_fmpq(lq, q, fmpq_poly_degree(q));
        fmpq_div(c, c, lq);
        same = fmpq_sgn(c) > 0;
        fmpq_poly_scalar_mul_fmpq(scaled, q, c);
        same = same && fmpq_poly_equal(scaled, pq);
        fmpq_clear(c);
        fmpq_clear(lq);
    }
    fmpq_poly_clear(pq);
    fmpq_poly_clear(scaled);
    return same;
}

// FLINT's F(t) = f(o + t·d) over Q.
void flint_restriction(fmpq_poly_t out, const Polynomial& f, const std::array<double, 3>& o,
                       const std::array<double, 3>& d) {
    FlintContext context(f.ring());
    const FlintPolynomial flint_f = to_fmpq_mpoly(f, context);
    std::array<fmpq_poly_t, 3> line;
    std::array<fmpq_poly_struct*, 3> pointers;
    fmpq_t value;
    fmpq_init(value);
    for (int axis = 0; axis < 3; ++axis) {
        fmpq_poly_init(line[axis]);
        set_exact_double(value, o[axis]);
        fmpq_poly_set_coeff_fmpq(line[axis], 0, value);
        set_exact_double(value, d[axis]);
        fmpq_poly_set_coeff_fmpq(line[axis], 1, value);
        pointers[axis] = line[axis];
    }
    fmpq_mpoly_compose_fmpq_poly(out, flint_f.get(), pointers.data(), context.get());
    for (auto& l : line) {
        fmpq_poly_clear(l);
    }
    fmpq_clear(value);
}

using IntegerPoly = detail::FmpzPoly;

struct RationalPoly {
    fmpq_poly_t p;
    RationalPoly() { fmpq_poly_init(p); }
    ~RationalPoly() { fmpq_poly_clear(p); }
    RationalPoly(const RationalPoly&) = delete;
    RationalPoly& operator=(const RationalPoly&) = delete;
};

// A random double: zero, a small integer, or ±m·2^e with e anywhere in [−300, 300] (and now and
// then a subnormal).
double random_coordinate(std::mt19937_64& random) {
    std::uniform_int_distribution<int> kind(0, 9);
    std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
    switch (kind(random)) {
    case 0:
        return 0.0;
    case 1:
        return static_cast<double>(std::uniform_int_distribution<int>(-5, 5)(random));
    case 2:
        return std::ldexp(mantissa(random), std::uniform_int_distribution<int>(-300, 300)(random));
    case 3:
        return std::ldexp(mantissa(random), -1060);  // subnormal
    default:
        return std::ldexp(mantissa(random), std::uniform_int_distribution<int>(-8, 8)(random));
    }
}

Polynomial random_polynomial(std::mt19937_64& random, const RingPtr& ring, int degree) {
    std::uniform_int_distribution<int> exponent(0, degree);
    std::uniform_int_distribution<long> numerator(-1000, 1000);
    std::uniform_int_distribution<unsigned long> denominator(1, 12);
    std::uniform_int_distribution<int> count(1, 14);
    std::vector<std::pair<Rational, std::vector<std::uint32_t>>> terms;
    for (int k = count(random); k > 0; --k) {
        const int a = exponent(random),
                  b = std::uniform_int_distribution<int>(0, degree - a)(random);
        const int c = std::uniform_int_distribution<int>(0, degree - a - b)(random);
        terms.push_back({Rational(numerator(random), denominator(random)),
                         {static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b),
                          static_cast<std::uint32_t>(c)}});
    }
    return Polynomial::from_terms(ring, std::move(terms));
}

TEST(ExactLineRestriction, IsFlintsCompositionUpToAPositiveFactorOnRandomInput) {
    std::mt19937_64 random(20261127);
    const RingPtr ring = xyz();
    for (int trial = 0; trial < 300; ++trial) {
        const Polynomial f = random_polynomial(random, ring, 1 + trial % 9);
        const detail::ExactLineRestriction restriction(f);
        for (int line = 0; line < 3; ++line) {
            std::array<double, 3> o{}, d{};
            for (int i = 0; i < 3; ++i) {
                o[i] = random_coordinate(random);
                d[i] = random_coordinate(random);
            }
            IntegerPoly mine;
            RationalPoly theirs;
            restriction.restrict(o, d, mine.p);
            flint_restriction(theirs.p, f, o, d);
            ASSERT_TRUE(positive_multiple(mine.p, theirs.p))
                << "f = " << to_string(f) << ", o = (" << o[0] << ", " << o[1] << ", " << o[2]
                << "), d = (" << d[0] << ", " << d[1] << ", " << d[2] << ")";
        }
    }
}

TEST(ExactLineRestriction, HandlesTheDegreeThirtySurfaceAndConstantCoordinates) {
    // Chmutov's T₃₀(x) + T₃₀(y) + T₃₀(z), by the recurrence, and a sparse quartic whose line
    // keeps y fixed (d_y = 0) and passes through x = 0 (o_x = 0).
    const RingPtr ring = xyz();
    const Polynomial t30 = parse_polynomial(test::chmutov_equation(30), ring);
    const Polynomial quartic = parse_polynomial("x^4 - 3/7*x*y^2*z + y^3 - 1/2", ring);
    const std::array<std::array<double, 3>, 4> origins{
        {{0.1234567, -1.2, 0.5}, {0.0, 0.25, -3.0}, {1e-5, 1e5, -0.75}, {0.0, 0.0, 0.0}}};
    const std::array<std::array<double, 3>, 4> directions{
        {{-0.3, 0.9, 0.31}, {1.0, 0.0, 0.5}, {0.0, 0.0, 1.0}, {0.0, 0.0, 0.0}}};
    for (const Polynomial* f : {&t30, &quartic}) {
        const detail::ExactLineRestriction restriction(*f);
        for (std::size_t k = 0; k < origins.size(); ++k) {
            IntegerPoly mine;
            RationalPoly theirs;
            restriction.restrict(origins[k], directions[k], mine.p);
            flint_restriction(theirs.p, *f, origins[k], directions[k]);
            EXPECT_TRUE(positive_multiple(mine.p, theirs.p)) << to_string(*f) << ", line " << k;
        }
    }
}

TEST(ComposeWithLine, IsFlintsCompositionScaledByThePowerOfTheDenominator) {
    std::mt19937_64 random(7);
    std::uniform_int_distribution<long> coefficient(-1000000, 1000000);
    for (int trial = 0; trial < 200; ++trial) {
        IntegerPoly p, mine;
        const int degree = trial % 12;
        for (int i = 0; i <= degree; ++i) {
            fmpz_poly_set_coeff_si(p.p, i, coefficient(random));
        }
        fmpz_t a, b, d;
        fmpz_init_set_si(a, coefficient(random));
        fmpz_init_set_si(b, coefficient(random));
        fmpz_init_set_ui(d, static_cast<ulong>(1 + trial % 17));
        detail::compose_with_line(mine.p, p.p, a, b, d);
        // FLINT: p((a + b·s)/d), times d^n.
        RationalPoly pq, line, theirs;
        fmpq_poly_set_fmpz_poly(pq.p, p.p);
        fmpq_t c;
        fmpq_init(c);
        fmpq_set_fmpz_frac(c, a, d);
        fmpq_poly_set_coeff_fmpq(line.p, 0, c);
        fmpq_set_fmpz_frac(c, b, d);
        fmpq_poly_set_coeff_fmpq(line.p, 1, c);
        fmpq_poly_compose(theirs.p, pq.p, line.p);
        fmpz_pow_ui(fmpq_numref(c), d, static_cast<ulong>(std::max(fmpz_poly_degree(p.p), 0L)));
        fmpz_one(fmpq_denref(c));
        fmpq_poly_scalar_mul_fmpq(theirs.p, theirs.p, c);
        RationalPoly mine_q;
        fmpq_poly_set_fmpz_poly(mine_q.p, mine.p);
        EXPECT_TRUE(fmpq_poly_equal(mine_q.p, theirs.p)) << "trial " << trial;
        fmpq_clear(c);
        fmpz_clear(a);
        fmpz_clear(b);
        fmpz_clear(d);
    }
}

}  // namespace
}  // namespace locus::algebra
