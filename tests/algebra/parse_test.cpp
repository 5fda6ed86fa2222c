// Parser: round trips, exact decimals, and every malformed input at the right line and column.
#include "algebra/parse.h"

#include <gtest/gtest.h>

#include "algebra/error.h"
#include "algebra/print.h"
#include "tests/support/parse_error.h"
#include "tests/support/test_data.h"

namespace locus::algebra {
namespace {

RingPtr xyz() {
    return PolyRing::make({"x", "y", "z"}, MonomialOrder::grevlex(3));
}

TEST(Parse, ExactNumbersAndPrecedence) {
    const RingPtr r = xyz();
    EXPECT_EQ(to_string(parse_polynomial("0.1*x", r)), "1/10*x");
    EXPECT_EQ(to_string(parse_polynomial("3/4 - x/2", r)), "-1/2*x+3/4");
    EXPECT_EQ(to_string(parse_polynomial("-x^2*y", r)), "-x^2*y");
    EXPECT_EQ(to_string(parse_polynomial("(x+y)^2", r)), "x^2+2*x*y+y^2");
    EXPECT_EQ(to_string(parse_polynomial("-(x - 1)^3", r)), "-x^3+3*x^2-3*x+1");
    EXPECT_EQ(to_string(parse_polynomial("2*x*3*y", r)), "6*x*y");
    EXPECT_EQ(to_string(parse_polynomial("x - x", r)), "0");
    EXPECT_EQ(to_string(parse_polynomial("1.25 + .5", r)), "7/4");
}

// Numbers as numerical tools print them, read exactly: 1.5e-3 is 3/2000, not the double
// nearest it. The exponent's size is bounded (1e999999999 would have a billion digits), and an
// 'e' not followed by digits is a name, an error after a number as before.
TEST(Parse, DecimalExponentsAreExact) {
    const RingPtr r = xyz();
    EXPECT_EQ(to_string(parse_polynomial("1.5e-3*x", r)), "3/2000*x");
    EXPECT_EQ(to_string(parse_polynomial("2E3 + 2e+3 + .5e1", r)), "4005");
    EXPECT_EQ(to_string(parse_polynomial("1e-0 - 10e-1", r)), "0");
    EXPECT_EQ(parse_polynomial("1e-999*x", r),
              parse_polynomial("1/1" + std::string(999, '0') + "*x", r));
    EXPECT_EQ(parse_polynomial("7e0007", r), parse_polynomial("70000000", r));
    const RingPtr with_e = PolyRing::make({"e", "x"}, MonomialOrder::grevlex(2));
    EXPECT_EQ(to_string(parse_polynomial("2*e + 2e1*x", with_e)), "2*e+20*x");
    EXPECT_EQ(to_string(parse_polynomial("3/4e2", r)), "3/400");
    const test::BadInput cases[] = {
        {"1e1000*x", 1, 1, "decimal exponents of at most 999"},
        {"1.5e-3.2", 1, 7, "an operator"},
        {"2e", 1, 2, "an operator"},
        {"2e-", 1, 2, "an operator"},
        {"x^2e1", 1, 3, "non-negative integer exponent"},
    };
    for (const auto& c : cases) {
        test::expect_parse_error(c, [&] { parse_polynomial(c.text, r); });
    }
}

// Python's and SymPy's `**` is the power operator too (pasted from str() of a SymPy expression).
TEST(Parse, DoubleStarIsAPower) {
    const RingPtr r = xyz();
    EXPECT_EQ(parse_polynomial("x**2*y**3 - (x+1)**2", r), parse_polynomial("x^2*y^3-(x+1)^2", r));
    EXPECT_EQ(parse_polynomial("2 ** 3 * x", r), parse_polynomial("8*x", r));
    for (const char* bad : {"x***2", "x** *2", "x**", "x**2**3", "x**-1"}) {
        EXPECT_THROW(parse_polynomial(bad, r), ParseError) << bad;
    }
    try {
        parse_polynomial("x**y", r);
        FAIL();
    } catch (const ParseError& e) {
        EXPECT_EQ(e.column(), 4u);  // at the exponent
    }
}

TEST(Parse, PrintParseRoundTrip) {
    for (int seed = 0; seed < test::seed_count(200); ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        std::mt19937_64 rng(seed);
        const RingPtr r = xyz();
        const Polynomial f = test::random_polynomial(r, rng, 1 + seed % 8, 5);
        EXPECT_EQ(parse_polynomial(to_string(f), r), f);
    }
}

using test::BadInput;
using test::expect_parse_error;

TEST(Parse, MalformedInputsReportLineAndColumn) {
    const RingPtr r = xyz();
    const BadInput cases[] = {
        {"(x+y", 1, 5, "')' to close"},
        {"x+y)", 1, 4, "unbalanced ')'"},
        {"x^-1", 1, 3, "non-negative integer exponent"},
        {"x^1.5", 1, 3, "non-negative integer exponent"},
        {"x + q", 1, 5, "a declared variable"},
        {"x / y", 1, 5, "a constant divisor"},
        {"x / (1-1)", 1, 5, "a non-zero divisor"},
        {"", 1, 1, "a polynomial"},
        {"x^40000", 1, 3, "an exponent of at most 32767"},
        {"x^20000*x^20000", 1, 8, "exponents of at most 32767"},
        {"2 x", 1, 3, "an operator"},
        {"x +\n  * y", 2, 3, "a number, a variable or '('"},
    };
    for (const auto& c : cases) {
        expect_parse_error(c, [&] { parse_polynomial(c.text, r); });
    }
}

// Every operation of these expressions is within its own bound, but together they would take
// minutes to expand (a fuzzer's timeout in a .param file chained dozens of such products): the
// whole expression has a budget, and the step that exceeds it is named.
TEST(Parse, ExpressionWorkIsBoundedAsAWhole) {
    const RingPtr st = PolyRing::make({"s", "t"}, MonomialOrder::grevlex(2));
    const std::string chain = "(1-t)^800*(1+s)^800+(1-s)^800*(1+t)^800";
    EXPECT_THROW(parse_polynomial(chain, st), ResourceLimit);
    EXPECT_THROW(parse_rational_function(chain, st), ResourceLimit);
    EXPECT_THROW(parse_rational_function("1/(1-t)^100+1/(1-s)^100+1/(1+t)^100+1/(1+s)^100", st),
                 ResourceLimit);
    try {
        parse_polynomial(chain, st);
    } catch (const ResourceLimit& e) {
        // The step that crosses the budget: the first product, its '*' at column 10.
        EXPECT_NE(std::string(e.what()).find(
                      "line 1, column 10: the expression would take more than " +
                      std::to_string(static_cast<long>(kMaxPowerWork)) + " limb products"),
                  std::string::npos)
            << e.what();
    }
    // Well inside the budget: the bicubic patch's products and a moderate power.
    EXPECT_EQ(parse_polynomial("(1-t)^200*(1+s)^200", st).num_terms(), 201u * 201u);
}

TEST(Parse, IdealFile) {
    const IdealFile f = parse_ideal_file(
        "# comment\nvars: x, y ,z\norder: elim(z)  # block order\n\nx^2 - y\r\nz*x-1 # tail\n");
    EXPECT_EQ(f.ring->variable_names(), (std::vector<std::string>{"x", "y", "z"}));
    EXPECT_EQ(f.ring->order().kind(), MonomialOrder::Kind::elimination);
    ASSERT_EQ(f.generators.size(), 2u);
    EXPECT_EQ(f.generator_lines, (std::vector<std::size_t>{5, 6}));
    EXPECT_EQ(to_string(f.generators[1]), "x*z-1");
    // Default order is grevlex.
    EXPECT_EQ(parse_ideal_file("vars: a\na").ring->order().kind(), MonomialOrder::Kind::grevlex);
}

TEST(Parse, MalformedIdealFiles) {
    const BadInput cases[] = {
        {"", 1, 1, "a 'vars:' line"},
        {"x+1\n", 1, 1, "a 'vars:' line before the generators"},
        {"vars: x,,y\n", 1, 9, "a variable name"},
        {"vars: x,y,x\n", 1, 11, "a name not declared before"},
        {"vars: x,y\norder: revlex\n", 2, 8, "an order"},
        {"vars: x,y\norder: elim(q)\n", 2, 13, "a declared variable"},
        {"vars: x,y\nx+y\nvars: z\n", 3, 1, "headers come first"},
        {"vars: x,y\ncolour: red\n", 2, 1, "'vars:', 'order:', 'characteristic:' or a generator"},
        {"vars: x,y\nx^2+y\n  x*(y+1\n", 3, 9, "')' to close"},
        {"vars: x,y\nx^2+u\n", 2, 5, "a declared variable"},
        {"vars: x,y\ncharacteristic: 7\ncharacteristic: 11\nx\n", 3, 1,
         "one 'characteristic:' line"},
    };
    for (const auto& c : cases) {
        expect_parse_error(c, [&] { parse_ideal_file(c.text); });
    }
}

}  // namespace
}  // namespace locus::algebra
