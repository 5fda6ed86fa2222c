// Division: the certificate f = Σ qᵢfᵢ + r holds and r is reduced, on random inputs; CLO's
// worked examples give the expected quotients.
#include "algebra/division.h"

#include <gtest/gtest.h>

#include "algebra/error.h"
#include "algebra/parse.h"
#include "algebra/print.h"
#include "tests/support/test_data.h"

namespace locus::algebra {
namespace {

TEST(Division, CloExampleChapter2Section3) {
    // CLO, IVA ch. 2 §3, Example 2: x^2 y + x y^2 + y^2 divided by (x y − 1, y^2 − 1), lex.
    const RingPtr r = PolyRing::make({"x", "y"}, MonomialOrder::lex(2));
    const std::vector<Polynomial> d = {parse_polynomial("x*y-1", r), parse_polynomial("y^2-1", r)};
    const Polynomial f = parse_polynomial("x^2*y+x*y^2+y^2", r);
    const DivisionResult res = divide(f, d);
    EXPECT_EQ(to_string(res.quotients[0]), "x+y");
    EXPECT_EQ(to_string(res.quotients[1]), "1");
    EXPECT_EQ(to_string(res.remainder), "x+y+1");
    EXPECT_TRUE(check_division(f, d, res));
}

TEST(Division, CertificateOnRandomInputs) {
    for (int seed = 0; seed < test::seed_count(150); ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        std::mt19937_64 rng(seed);
        const std::vector<std::string> names = {"x", "y", "z"};
        const char* orders[] = {"lex", "grlex", "grevlex", "weights(3,1,2)", "elim(x)"};
        const RingPtr r = PolyRing::make(names, parse_monomial_order(orders[seed % 5], names));
        const Polynomial f = test::random_polynomial(r, rng, 2 + seed % 8, 4);
        std::vector<Polynomial> d;
        for (int k = 0; k < 1 + seed % 3; ++k) {
            d.push_back(test::random_polynomial(r, rng, 1 + (seed + k) % 3, 2));
        }
        const DivisionResult res = divide(f, d);
        EXPECT_TRUE(check_division(f, d, res));
        // A deliberately wrong certificate is rejected.
        DivisionResult broken = res;
        broken.remainder += Polynomial::constant(r, Rational(1));
        EXPECT_FALSE(check_division(f, d, broken));
    }
}

TEST(Division, ExactQuotient) {
    const RingPtr r = PolyRing::make({"x", "y"}, MonomialOrder::grevlex(2));
    const Polynomial g = parse_polynomial("x-y", r);
    const Polynomial h = parse_polynomial("x^2+3*y", r);
    EXPECT_EQ(exact_quotient(g * h, g), h);
    EXPECT_THROW(exact_quotient(h, g), InputError);
}

}  // namespace
}  // namespace locus::algebra
