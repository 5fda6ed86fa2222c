// Ideal operations on examples with known answers (CLO ch. 4) and their defining properties.
#include "algebra/ideal_ops.h"

#include <gtest/gtest.h>

#include <chrono>

#include "algebra/division.h"
#include "algebra/error.h"
#include "algebra/parse.h"
#include "algebra/print.h"
#include "tests/support/test_data.h"

namespace locus::algebra {
namespace {

RingPtr xyz() {
    return PolyRing::make({"x", "y", "z"}, MonomialOrder::grevlex(3));
}

std::vector<Polynomial> polys(const RingPtr& r, std::vector<const char*> texts) {
    std::vector<Polynomial> out;
    for (const char* t : texts) {
        out.push_back(parse_polynomial(t, r));
    }
    return out;
}

std::string printed(const std::vector<Polynomial>& basis) {
    std::string s;
    for (const auto& p : basis) {
        s += to_string(p) + ";";
    }
    return s;
}

TEST(IdealOps, MembershipWithCertificate) {
    const RingPtr r = xyz();
    const auto gens = polys(r, {"x^2-y", "x*y-z"});
    const auto inside = parse_polynomial("x^3 - z + (x+y)*(x^2-y)", r);
    const MembershipCertificate yes = ideal_membership(inside, gens);
    ASSERT_TRUE(yes.is_member);
    Polynomial sum(r);
    for (std::size_t i = 0; i < gens.size(); ++i) {
        sum += yes.cofactors[i] * gens[i];
    }
    EXPECT_EQ(sum, inside);
    const MembershipCertificate no = ideal_membership(parse_polynomial("x+1", r), gens);
    EXPECT_FALSE(no.is_member);
    EXPECT_FALSE(no.remainder.is_zero());
}

// Cofactors come from division by the generators when it reaches zero, else from the tracked
// Buchberger run; both are checked here as the product sum they claim to be.
TEST(IdealOps, MembershipCofactorsByDivisionOrByTrackedBuchberger) {
    const auto check = [](const Polynomial& f, const std::vector<Polynomial>& gens) {
        const MembershipCertificate c = ideal_membership(f, gens);
        ASSERT_TRUE(c.is_member);
        Polynomial sum(f.ring());
        for (std::size_t i = 0; i < gens.size(); ++i) {
            sum += c.cofactors[i] * gens[i];
        }
        EXPECT_EQ(sum, f);
    };
    // x − y is in ⟨xy − 1, y² − 1⟩ (x = x·y² = y·xy = y), but division by the generators
    // stops at x: the tracked run finds the cofactors.
    const RingPtr lex = PolyRing::make({"x", "y"}, MonomialOrder::lex(2));
    const auto pair = polys(lex, {"x*y-1", "y^2-1"});
    EXPECT_FALSE(divide(parse_polynomial("x-y", lex), pair).remainder.is_zero());
    check(parse_polynomial("x-y", lex), pair);
    // A generator of an ideal whose tracked run multiplied cofactors past the exponent range
    // (exit 2, "exponent overflow", from `locus ideal member`): division answers at once.
    const auto wide = polys(lex, {"x^20000*y^20000-1", "x-2"});
    check(parse_polynomial("x-2", lex), wide);
    check(parse_polynomial("3*x-6", lex), wide);
}

TEST(IdealOps, EliminationImplicitizesTheTwistedCubic) {
    const RingPtr r = PolyRing::make({"t", "x", "y", "z"}, MonomialOrder::grevlex(4));
    const auto gens = polys(r, {"x-t", "y-t^2", "z-t^3"});
    const std::size_t t[] = {0};
    EXPECT_EQ(printed(eliminate(gens, t)), "y^2-x*z;x*y-z;x^2-y;");
}

TEST(IdealOps, IntersectionQuotientSaturation) {
    const RingPtr r = xyz();
    // CLO ch. 4 §3: ⟨x²y⟩ ∩ ⟨xy²⟩ = ⟨x²y²⟩.
    EXPECT_EQ(printed(ideal_intersection(polys(r, {"x^2*y"}), polys(r, {"x*y^2"}))), "x^2*y^2;");
    // ⟨x z, y z⟩ : ⟨z⟩ = ⟨x, y⟩.
    EXPECT_EQ(printed(ideal_quotient(polys(r, {"x*z", "y*z"}), polys(r, {"z"}))), "y;x;");
    // ⟨x² y⟩ : ⟨x⟩^∞ = ⟨y⟩.
    EXPECT_EQ(printed(saturation(polys(r, {"x^2*y"}), polys(r, {"x"}))), "y;");
    // Sum and product.
    EXPECT_EQ(printed(ideal_sum(polys(r, {"x"}), polys(r, {"y"}))), "y;x;");
    EXPECT_EQ(printed(ideal_product(polys(r, {"x", "y"}), polys(r, {"z"}))), "y*z;x*z;");
}

TEST(IdealOps, EveryOperationStopsWithATimeoutAtTheDeadline) {
    const RingPtr r = xyz();
    // Leading monomials x², x·y, y² (grevlex): S-pairs to reduce, so a deadline is polled.
    const auto i = polys(r, {"x^2-y*z-1", "x*y-z^2-2", "x*z-y^2-3"});
    const auto j = polys(r, {"y^3-x", "z^3-y"});
    GroebnerOptions passed;
    passed.deadline = std::chrono::steady_clock::now();
    const std::size_t x[] = {0};
    const Polynomial f = parse_polynomial("x*y-z", r);
    EXPECT_THROW(ideal_membership(f, i, passed), Timeout);
    EXPECT_THROW(radical_membership(f, i, passed), Timeout);
    EXPECT_THROW(eliminate(i, x, passed), Timeout);
    EXPECT_THROW(ideal_sum(i, j, passed), Timeout);
    EXPECT_THROW(ideal_product(i, j, passed), Timeout);
    EXPECT_THROW(ideal_intersection(i, j, passed), Timeout);
    EXPECT_THROW(ideal_quotient(i, j, passed), Timeout);
    EXPECT_THROW(saturation(i, j, passed), Timeout);
    EXPECT_THROW(ideal_contains(i, j, passed), Timeout);
    EXPECT_THROW(ideal_equal(i, j, passed), Timeout);
    EXPECT_THROW(zero_dimension_test(i, passed), Timeout);
    try {
        ideal_quotient(i, j, passed);
        ADD_FAILURE() << "a passed deadline completed the quotient";
    } catch (const Timeout& e) {
        EXPECT_STREQ(e.what(), "timeout: a Gröbner basis was not complete at the deadline");
    }
    // A deadline far ahead changes nothing.
    GroebnerOptions later;
    later.deadline = std::chrono::steady_clock::now() + std::chrono::hours(1);
    EXPECT_EQ(printed(ideal_intersection(i, j, later)), printed(ideal_intersection(i, j)));
}

// The options must reach the nested Gröbner runs too (quotient: intersections of
// intersections), not only the first: counted through the progress callback, which every run
// calls with pairs_done == 1 (its first signature). The counts follow the constructions in
// ideal_ops.cpp; a run left without the options is missing from them.
TEST(IdealOps, OptionsReachEveryNestedGroebnerRun) {
    const RingPtr r = xyz();
    const auto i = polys(r, {"x^2-y*z-1", "x*y-z^2-2", "x*z-y^2-3"});
    const auto j = polys(r, {"y^3-x*z", "y^2*z-x"});  // y³ and y²z: an S-pair of its own
    std::size_t runs = 0;
    GroebnerOptions counting;
    counting.progress = [&](const GroebnerProgress& p) { runs += p.pairs_done == 1 ? 1 : 0; };
    auto runs_of = [&](auto&& operation) {
        runs = 0;
        operation();
        return runs;
    };
    const std::size_t x[] = {0};
    // Every nested run reports its first signature (the generators' own count), so these are
    // the numbers of Gröbner bases each operation computes: eliminate 2 (under elim(x), then of
    // the elements kept), intersection 2 (an elimination), quotient 2·3 + 2 (per generator of
    // j an intersection and the basis of the quotients, then the two parts intersected),
    // saturation 2·2 + 2 (an elimination per generator, then an intersection), equality 2.
    EXPECT_EQ(runs_of([&] { eliminate(i, x, counting); }), 2u);
    EXPECT_EQ(runs_of([&] { ideal_intersection(i, j, counting); }), 2u);
    EXPECT_EQ(runs_of([&] { ideal_quotient(i, j, counting); }), 8u);
    EXPECT_EQ(runs_of([&] { saturation(i, j, counting); }), 6u);
    EXPECT_EQ(runs_of([&] { ideal_equal(i, i, counting); }), 2u);  // both inclusions
}

TEST(IdealOps, IntersectionIsContainedInBothAndContainsTheProduct) {
    for (int seed = 0; seed < test::seed_count(12); ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        std::mt19937_64 rng(seed);
        const RingPtr r = PolyRing::make({"x", "y"}, MonomialOrder::grevlex(2));
        const std::vector<Polynomial> i = {test::random_polynomial(r, rng, 2, 2, false),
                                           test::random_polynomial(r, rng, 2, 2, false)};
        const std::vector<Polynomial> j = {test::random_polynomial(r, rng, 2, 2, false)};
        const auto meet = ideal_intersection(i, j);
        EXPECT_TRUE(ideal_contains(i, meet));
        EXPECT_TRUE(ideal_contains(j, meet));
        EXPECT_TRUE(ideal_contains(meet, ideal_product(i, j)));
        EXPECT_TRUE(ideal_equal(ideal_sum(i, j), ideal_sum(j, i)));
    }
}

// The zero ideal's basis is empty, and operations that return it take it back: found by the
// intersection test at LOCUS_TEST_MULTIPLIER=20, whose random generators cancelled to zero,
// so that the intersection was the zero ideal and the containment after it threw.
TEST(IdealOps, TheZeroIdealAsAnEmptyBasisIsAnArgument) {
    const RingPtr r = xyz();
    const auto i = polys(r, {"x^2-y", "y*z"});
    const auto zero_generator = polys(r, {"0"});
    const std::vector<Polynomial> zero = ideal_intersection(i, zero_generator);
    EXPECT_TRUE(zero.empty());
    const std::vector<Polynomial> none;
    EXPECT_TRUE(ideal_contains(i, zero));
    EXPECT_TRUE(ideal_contains(zero, zero));
    EXPECT_TRUE(ideal_contains(zero, zero_generator));
    EXPECT_FALSE(ideal_contains(zero, i));
    EXPECT_TRUE(ideal_equal(zero, zero_generator));
    EXPECT_FALSE(ideal_equal(zero, i));
    EXPECT_TRUE(ideal_product(i, zero).empty());
    EXPECT_TRUE(ideal_intersection(zero, i).empty());
    EXPECT_TRUE(ideal_equal(ideal_sum(i, zero), i));
    EXPECT_TRUE(ideal_sum(zero, none).empty());
    // What needs the ring still says so.
    EXPECT_THROW(ideal_quotient(zero, none), InputError);
}

TEST(IdealOps, RadicalMembershipAndDimension) {
    const RingPtr r = xyz();
    const auto gens = polys(r, {"x^3", "y^2"});
    EXPECT_TRUE(radical_membership(parse_polynomial("x+y", r), gens));
    EXPECT_FALSE(ideal_membership(parse_polynomial("x+y", r), gens).is_member);
    EXPECT_FALSE(radical_membership(parse_polynomial("z", r), gens));

    const DimensionReport points = zero_dimension_test(polys(r, {"x^2-1", "y^2-4", "z-x*y"}));
    EXPECT_EQ(points.kind, Dimension::zero_dimensional);
    EXPECT_EQ(points.quotient_dimension, 4u);
    EXPECT_EQ(zero_dimension_test(polys(r, {"x^2+y^2-1"})).kind, Dimension::positive);
    EXPECT_EQ(zero_dimension_test(polys(r, {"x", "x-1"})).kind, Dimension::unit_ideal);
    // A double point counts twice.
    EXPECT_EQ(zero_dimension_test(polys(r, {"x^2", "y", "z"})).quotient_dimension, 2u);
}

TEST(IdealOps, EqualityUnderDifferentGenerators) {
    const RingPtr r = xyz();
    EXPECT_TRUE(ideal_equal(polys(r, {"x", "y"}), polys(r, {"x+y", "x-y"})));
    EXPECT_FALSE(ideal_equal(polys(r, {"x", "y"}), polys(r, {"x+y"})));
}

}  // namespace
}  // namespace locus::algebra
