// Trigonometric maps and the verification of implicit equations: maps that mix an angle with its
// sine or cosine are refused with their position; multiple angles and sums are expanded; the
// check on the map as written uses sin² + cos² = 1, not the substitution; and the proof grid of
// vanishes_on is as large as its argument needs (a polynomial that vanishes on one point fewer
// per parameter but not identically is caught).
#include "implicit/verify.h"

#include <gtest/gtest.h>

#include "algebra/error.h"
#include "algebra/parse.h"
#include "algebra/print.h"
#include "implicit/implicitize.h"
#include "tests/support/parse_error.h"

namespace locus::implicit {
namespace {

// The ParseError of parsing `text` as a parametrization, as "line L, column C: message".
std::string refusal(const char* text) {
    try {
        parse_parametrization(text);
    } catch (const ParseError& e) {
        return e.what();  // "line L, column C: expected …, found …"
    }
    return "accepted";
}

TEST(Trigonometric, NonAlgebraicMapsAreRefusedWithTheirPosition) {
    // The helicoid: v inside cos and sin, and alone in z.
    EXPECT_NE(refusal("params: u,v\nx = u*cos(v)\ny = u*sin(v)\nz = v\n").find("line 4, column 5"),
              std::string::npos);
    EXPECT_NE(refusal("params: u,v\nx = u*cos(v)\ny = u*sin(v)\nz = v\n")
                  .find("the angle v only inside sin and cos"),
              std::string::npos);
    EXPECT_NE(refusal("params: u\nx = cos(u)\ny = u\n").find("line 3, column 5"),
              std::string::npos);
    // u·cos(u): the plain use comes first on the line.
    EXPECT_NE(refusal("params: u\nx = u*cos(u)\ny = u*sin(u)\n").find("line 2, column 5"),
              std::string::npos);
    // Arguments that are not integer combinations of parameters.
    EXPECT_NE(refusal("params: u\nx = cos(u+1)\ny = sin(u)\n").find("integer combination"),
              std::string::npos);
    EXPECT_NE(refusal("params: u\nx = cos(u/2)\ny = sin(u)\n").find("integer combination"),
              std::string::npos);
    EXPECT_NE(refusal("params: u\nx = cos(u^2)\ny = sin(u)\n").find("integer combination"),
              std::string::npos);
    EXPECT_NE(refusal("params: u\nx = cos(0.5*u)\ny = sin(u)\n").find("integer combination"),
              std::string::npos);
    EXPECT_EQ(refusal("params: u,v\nx = cos(2*u-v)\ny = sin(u*3)\nz = cos(-v)\n"), "accepted");
}

struct TrigonometricCase {
    const char* param_file;
    const char* equation;
};

class MultipleAngles : public ::testing::TestWithParam<TrigonometricCase> {};

TEST_P(MultipleAngles, KnownEquationVerifiedOnTheMapAsWritten) {
    const Parametrization map = parse_parametrization(GetParam().param_file);
    const ImplicitResult r = implicitize_auto(map);
    ASSERT_TRUE(r.equation.has_value());
    EXPECT_EQ(algebra::to_string(*r.equation), GetParam().equation);
    EXPECT_TRUE(vanishes_on_map_as_written(*r.equation, map));
    EXPECT_TRUE(vanishes_on(*r.equation, map));
    EXPECT_FALSE(
        vanishes_on_map_as_written(*r.equation + algebra::Polynomial::variable(r.ring, 1), map));
}

const TrigonometricCase multiple_angle_cases[] = {
    // cos(2u) = x and sin(3u) = y: 2y² = 1 − cos 6u = 1 − T₃(x).
    {"params: u\nx = cos(2*u)\ny = sin(3*u)\n", "4*x^3+2*y^2-3*x-1"},
    // A circle traced twice, and once backwards.
    {"params: u\nx = cos(2*u)\ny = sin(2*u)\n", "x^2+y^2-1"},
    {"params: u\nx = cos(-u)\ny = sin(-u)\n", "x^2+y^2-1"},
    // cos(u + v)·… : (2 cos u cos v, sin(u + v), sin(u − v)).
    {"params: u,v\nx = cos(u+v)+cos(u-v)\ny = sin(u+v)\nz = sin(u-v)\n",
     "x^4+2*x^2*y^2+y^4+2*x^2*z^2-2*y^2*z^2+z^4-4*x^2"},
    // The torus of revolution.
    {"params: u,v\nx = (2+cos(v))*cos(u)\ny = (2+cos(v))*sin(u)\nz = sin(v)\n",
     "x^4+2*x^2*y^2+y^4+2*x^2*z^2+2*y^2*z^2+z^4-10*x^2-10*y^2+6*z^2+9"},
};

INSTANTIATE_TEST_SUITE_P(Trigonometric, MultipleAngles, ::testing::ValuesIn(multiple_angle_cases));

TEST(Trigonometric, TheMapAsWrittenNeedsTheCircleRelation) {
    const Parametrization circle = parse_parametrization("params: u\nx = cos(u)\ny = sin(u)\n");
    ASSERT_EQ(circle.circle_relations.size(), 1u);
    const algebra::RingPtr xy =
        algebra::PolyRing::make({"x", "y"}, algebra::MonomialOrder::grevlex(2));
    EXPECT_TRUE(vanishes_on_map_as_written(algebra::parse_polynomial("x^2+y^2-1", xy), circle));
    // x⁴ − y⁴ = (x² − y²)(x² + y²) = cos 2u on the circle: not zero; minus x² − y² it is.
    EXPECT_FALSE(vanishes_on_map_as_written(algebra::parse_polynomial("x^4-y^4", xy), circle));
    EXPECT_TRUE(
        vanishes_on_map_as_written(algebra::parse_polynomial("x^4-y^4-x^2+y^2", xy), circle));
}

// g(u) = f(u, u) for f = Π_{k<D} (x − p_k) with p_k the first D points of vanishes_on's grid
// (u = j − ⌊B/2⌋, B = D for the line x = y = u): g has degree D and vanishes on D of the
// D + 1 grid points. A grid one point smaller (or two points per parameter) would call it zero.
TEST(VanishesOn, TheProofGridHasOneMorePointThanTheDegree) {
    const Parametrization line = parse_parametrization("params: u\nx = u\ny = u\n");
    const algebra::RingPtr xy =
        algebra::PolyRing::make({"x", "y"}, algebra::MonomialOrder::grevlex(2));
    for (int degree = 1; degree <= 7; ++degree) {
        SCOPED_TRACE("degree " + std::to_string(degree));
        algebra::Polynomial f = algebra::Polynomial::constant(xy, algebra::Rational(1));
        for (int j = 0; j < degree; ++j) {
            const long point = j - degree / 2;
            f *= algebra::Polynomial::variable(xy, 0) -
                 algebra::Polynomial::constant(xy, algebra::Rational(point));
        }
        EXPECT_FALSE(vanishes_on(f, line));
        // The same with y, and for two parameters: the bound is per parameter.
        EXPECT_TRUE(vanishes_on(
            algebra::Polynomial::variable(xy, 0) - algebra::Polynomial::variable(xy, 1), line));
    }
    const Parametrization plane = parse_parametrization("params: s,t\nx = s\ny = t\nz = s*t\n");
    const algebra::RingPtr xyz =
        algebra::PolyRing::make({"x", "y", "z"}, algebra::MonomialOrder::grevlex(3));
    // z − x·y vanishes; (z − x·y) + x(x−a)(x−b)… of degree 3 in s must not.
    EXPECT_TRUE(vanishes_on(algebra::parse_polynomial("z-x*y", xyz), plane));
    EXPECT_FALSE(vanishes_on(algebra::parse_polynomial("z-x*y+(x+1)*x*(x-1)", xyz), plane));
    EXPECT_FALSE(vanishes_on(algebra::parse_polynomial("(y+1)*y*(y-1)*(x+1)*x", xyz), plane));
}

}  // namespace
}  // namespace locus::implicit
