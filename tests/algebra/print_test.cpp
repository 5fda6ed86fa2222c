// Printers: the normalized form, and input for Singular, Macaulay2 and LaTeX.
#include "algebra/print.h"

#include <gtest/gtest.h>

#include "algebra/error.h"
#include "algebra/parse.h"

namespace locus::algebra {
namespace {

TEST(Print, NormalizedForm) {
    const RingPtr r = PolyRing::make({"x", "y", "z"}, MonomialOrder::grevlex(3));
    EXPECT_EQ(to_string(parse_polynomial("3 - 1/2*z + x^2*y", r)), "x^2*y-1/2*z+3");
    EXPECT_EQ(to_string(parse_polynomial("-x - 1", r)), "-x-1");
    EXPECT_EQ(to_string(parse_polynomial("-2/6", r)), "-1/3");
    EXPECT_EQ(to_string(Polynomial(r)), "0");
}

TEST(Print, NormalizeBasisSortsAscendingAndMakesMonic) {
    const RingPtr r = PolyRing::make({"x", "y"}, MonomialOrder::lex(2));
    const std::vector<Polynomial> basis = {parse_polynomial("2*x - y", r),
                                           parse_polynomial("3*y^2 + 1", r)};
    const auto n = normalize_basis(basis);
    ASSERT_EQ(n.size(), 2u);
    EXPECT_EQ(to_string(n[0]), "y^2+1/3");
    EXPECT_EQ(to_string(n[1]), "x-1/2*y");
}

TEST(Print, LatexUsesFracAndSubscripts) {
    const RingPtr r = PolyRing::make({"x1", "y", "beta"}, MonomialOrder::grevlex(3));
    EXPECT_EQ(to_latex(parse_polynomial("x1^2 - 1/2*y*beta + 3", r)),
              "x_{1}^{2}-\\frac{1}{2} y \\mathit{beta}+3");
}

TEST(Print, SingularRingForEveryOrderKind) {
    auto ring = [](const char* order) {
        const std::vector<std::string> names = {"x", "y", "z"};
        return PolyRing::make(names, parse_monomial_order(order, names));
    };
    EXPECT_EQ(singular_ring(*ring("lex")), "ring r = 0, (x,y,z), lp;");
    EXPECT_EQ(singular_ring(*ring("grlex")), "ring r = 0, (x,y,z), Dp;");
    EXPECT_EQ(singular_ring(*ring("grevlex")), "ring r = 0, (x,y,z), dp;");
    EXPECT_EQ(singular_ring(*ring("weights(1,2,3)")), "ring r = 0, (x,y,z), wp(1,2,3);");
    // Eliminated variables move to the front block.
    EXPECT_EQ(singular_ring(*ring("elim(z)")), "ring r = 0, (z,x,y), (dp(1),dp(2));");
    EXPECT_EQ(singular_ring(*ring("matrix((1,1,1),(0,0,-1),(0,-1,0))")),
              "ring r = 0, (x,y,z), M(1,1,1,0,0,-1,0,-1,0);");
}

TEST(Print, FormatsAWholeBasis) {
    const RingPtr r = PolyRing::make({"x", "y"}, MonomialOrder::grevlex(2));
    const std::vector<Polynomial> b = {parse_polynomial("x*y-1", r), parse_polynomial("x^2", r)};
    EXPECT_EQ(format_polynomials(b, *r, OutputFormat::normalized), "x*y-1\nx^2\n");
    EXPECT_EQ(format_polynomials(b, *r, OutputFormat::singular),
              "ring r = 0, (x,y), dp;\nideal G =\n  x*y-1,\n  x^2;\n");
    EXPECT_EQ(format_polynomials(b, *r, OutputFormat::macaulay2),
              "R = QQ[x,y, MonomialOrder => GRevLex];\nG = ideal(\n  x*y-1,\n  x^2)\n");
    EXPECT_THROW(parse_output_format("maxima"), InputError);
}

}  // namespace
}  // namespace locus::algebra
