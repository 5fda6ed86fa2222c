// Bézier patches and the Dixon route. The patches' maps are checked against equations known in
// closed form; the Dixon equations against the interpolation route (a kernel modulo primes:
// no code in common but the lifting) and, for the teapot, by exact evaluation at rational
// points of the patch (Polynomial::evaluate, not the modular proof the route uses). Degenerate
// patches (a collapsed edge) take the maximal-minor path; maps whose image is a curve are
// refused, never answered with some surface through the curve.
#include <gtest/gtest.h>

#include "algebra/error.h"
#include "algebra/flint_convert.h"
#include "algebra/parse.h"
#include "implicit/bezier_patch.h"
#include "implicit/dixon.h"
#include "implicit/implicitize.h"
#include "implicit/verify.h"
#include "tests/support/test_data.h"

namespace locus::implicit {
namespace {

using algebra::Polynomial;
using algebra::Rational;

algebra::RingPtr xyz() {
    return algebra::PolyRing::make({"x", "y", "z"}, algebra::MonomialOrder::grevlex(3));
}

Polynomial xyz_polynomial(const char* text) {
    return algebra::parse_polynomial(text, xyz()).primitive_part();
}

// Is f zero at the patch's points for a few rational (s, t), evaluated exactly?
bool zero_at_sample_points(const Polynomial& f, const Parametrization& map) {
    for (long i = 1; i <= 3; ++i) {
        const std::vector<Rational> st{Rational(i, 7), Rational(5 - i, 9)};
        std::vector<Rational> point;
        for (const auto& c : map.components) {
            point.push_back(c.numerator().evaluate(st) / c.denominator().evaluate(st));
        }
        if (!f.evaluate(point).is_zero()) {
            return false;
        }
    }
    return true;
}

// The message with which `parse` refuses `text`, or "accepted".
template <class Parse>
std::string refusal(Parse&& parse, const char* text) {
    try {
        parse(text);
    } catch (const ParseError& e) {
        return e.what();
    }
    return "accepted";
}

std::string refusal_bpt(const char* text) {
    return refusal(parse_bpt, text);
}

TEST(BezierPatch, TheBilinearPatchIsTheHyperbolicParaboloid) {
    const auto patches = parse_bpt("1\n1 1\n0 0 0\n0 1 0\n1 0 0\n1 1 1\n");
    ASSERT_EQ(patches.size(), 1u);
    const Parametrization map = to_parametrization(patches[0]);
    const ImplicitResult r = implicitize_auto(map);
    ASSERT_TRUE(r.equation);
    EXPECT_EQ(*r.equation, xyz_polynomial("x*y - z"));
}

TEST(BezierPatch, TheParamFormReadsTheSamePatch) {
    const Parametrization from_param = parse_parametrization(
        "# bilinear\nbezier: 1 1\nparams: u, v\n0 0 0\n0 1 0\n1 0 0\n1 1 1\n");
    EXPECT_EQ(from_param.parameter_ring->variable_name(0), "u");
    const Parametrization from_bpt =
        to_parametrization(parse_bpt("1\n1 1\n0 0 0\n0 1 0\n1 0 0\n1 1 1\n")[0], {"u", "v"});
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(from_param.components[i].numerator(), from_bpt.components[i].numerator());
    }
    // A linear triangle is its plane; a quadratic one with its corners on the axes and edge
    // midpoints lifted is a quadric through them.
    const Parametrization plane =
        parse_parametrization("bezier: triangle 1\n1 0 0\n0 1 0\n0 0 1\n");
    const ImplicitResult r = implicitize_auto(plane);
    ASSERT_TRUE(r.equation);
    EXPECT_EQ(*r.equation, xyz_polynomial("x + y + z - 1"));
    const Parametrization quadric =
        parse_parametrization("bezier: triangle 2\n2 0 0\n1 1 1\n1 0 1\n0 2 0\n0 1 1\n0 0 2\n");
    const ImplicitResult q = implicitize_auto(quadric);
    ASSERT_TRUE(q.equation);
    EXPECT_TRUE(zero_at_sample_points(*q.equation, quadric));
    EXPECT_LE(q.equation->total_degree(), 4);
}

TEST(BezierPatch, DecimalsAreExactAndWeightsMakeTheMapRational) {
    const auto patches = parse_bpt("1\n1 1\n1.3375 0 0\n0 -0.784 0\n1 0 0 2\n1 1 1 0.5\n");
    EXPECT_TRUE(patches[0].rational);
    EXPECT_EQ(patches[0].points[0][0], Rational(107, 80));
    EXPECT_EQ(patches[0].points[1][1], Rational(-98, 125));
    const Parametrization map = to_parametrization(patches[0]);
    EXPECT_GT(map.components[0].denominator().total_degree(), 0);
}

TEST(BezierPatch, MalformedFilesAreRefusedAtTheirLineAndColumn) {
    EXPECT_NE(refusal_bpt("").find("line 1, column 1"), std::string::npos);
    EXPECT_NE(refusal_bpt("two\n").find("line 1, column 1: expected the number of patches"),
              std::string::npos);
    EXPECT_NE(refusal_bpt("1\n3\n").find("line 2, column 2"), std::string::npos);
    EXPECT_NE(refusal_bpt("1\n1 0\n").find("line 2, column 3"), std::string::npos);
    EXPECT_NE(refusal_bpt("1\n1 99\n").find("from 1 to 16"), std::string::npos);
    EXPECT_NE(refusal_bpt("1\n1 1\n0 0 0\n0 1 0\n1 0 0\n").find("control point 4 of 4"),
              std::string::npos);
    EXPECT_NE(refusal_bpt("1\n1 1\n0 0 0\n0 1 x\n1 0 0\n1 1 1\n").find("line 4, column 5"),
              std::string::npos);
    EXPECT_NE(refusal_bpt("1\n1 1\n0 0 0\n0 1 0 -1\n1 0 0\n1 1 1\n").find("a positive weight"),
              std::string::npos);
    EXPECT_NE(refusal_bpt("1\n1 1\n0 0 0\n0 1 0\n1 0 0\n1 1 1\n5 5 5\n").find("line 7, column 1"),
              std::string::npos);
    EXPECT_NE(refusal_bpt("2\n1 1\n0 0 0\n0 1 0\n1 0 0\n1 1 1\n").find("patch 2 of 2"),
              std::string::npos);
    EXPECT_THROW(parse_parametrization("bezier: 2\n0 0 0\n"), ParseError);
    EXPECT_THROW(parse_parametrization("bezier: 1 1\n0 0 0\n0 1 0\n1 0 0\n"), ParseError);
    EXPECT_THROW(parse_parametrization("bezier: 1 1\nparams: x, t\n0 0 0\n0 1 0\n1 0 0\n1 1 1\n"),
                 ParseError);
}

std::string refusal_param(const char* text) {
    return refusal(parse_parametrization, text);
}

TEST(ParamDomain, ADomainLineBoundsEveryParameterExactly) {
    const Parametrization map = parse_parametrization(
        "params: u,v\ndomain: v in [0, 1/3], u in [-2.5, 2]\nx = u\ny = v\nz = u*v\n");
    ASSERT_EQ(map.domain.size(), 2u);
    EXPECT_EQ(map.domain[0].first, Rational(-5, 2));
    EXPECT_EQ(map.domain[1].second, Rational(1, 3));
    const char* head = "params: u,v\n";
    const std::string tail = "x = u\ny = v\nz = u*v\n";
    auto with = [&](const std::string& line) {
        return refusal_param((head + line + "\n" + tail).c_str());
    };
    EXPECT_NE(with("domain: u in [0, 1]")
                  .find("line 2, column 20: expected an interval for "
                        "every parameter (v)"),
              std::string::npos);
    EXPECT_NE(with("domain: u in [1, 1], v in [0, 1]").find("an upper bound above the lower one"),
              std::string::npos);
    EXPECT_NE(with("domain: w in [0, 1], v in [0, 1]")
                  .find("line 2, column 9: expected a "
                        "parameter name"),
              std::string::npos);
    EXPECT_NE(with("domain: u in [0, 1], u in [0, 1]").find("each parameter once"),
              std::string::npos);
    EXPECT_NE(with("domain: u in [0 1], v in [0, 1]").find("line 2, column 17: expected ','"),
              std::string::npos);
    EXPECT_NE(with("domain: u in [a, 1], v in [0, 1]").find("a bound such as"), std::string::npos);
    EXPECT_NE(refusal_param("params: u,v\ndomain: u in [0, 1], v in [0, 1]\n"
                            "x = cos(u)\ny = sin(u)\nz = v\n")
                  .find("a parameter outside sin and cos"),
              std::string::npos);
    EXPECT_NE(refusal_param("params: u\ndomain: u in [0, 1]\ndomain: u in [0, 1]\nx = u\ny = u^2\n")
                  .find("line 3, column 1: expected one 'domain:' line"),
              std::string::npos);
}

TEST(Dixon, AgreesWithInterpolationOnTheBiquadraticPatch) {
    const Parametrization map = parse_parametrization(
        test::read_text(test::source_dir() + "/tests/data/biquadratic_patch.param"));
    const ImplicitResult dixon = implicitize_by_dixon(map);
    const ImplicitResult kernel = implicitize_by_interpolation(map);
    ASSERT_TRUE(dixon.equation && kernel.equation);
    EXPECT_EQ(dixon.method, "dixon");
    EXPECT_EQ(*dixon.equation, *kernel.equation);
    EXPECT_EQ(dixon.equation->total_degree(), 8);
}

TEST(Dixon, RationalAndDegeneratePatchesAgreeWithInterpolation) {
    // A rational biquadratic patch (weights), and one whose first row collapses to a point:
    // its Dixon matrix is singular everywhere and a maximal minor carries the equation.
    const char* rational =
        "bezier: 2 2\n1 0 0\n1 1 0 2\n0 1 1\n2 0 1 3\n1 2 1 1\n-1 1 2\n0 0 2\n1 -1 3 2\n2 1 1\n";
    const char* collapsed =
        "bezier: 2 2\n0 0 3\n0 0 3\n0 0 3\n2 0 1\n1 2 1\n-1 1 2\n0 1 0\n1 -1 3\n2 2 1\n";
    for (const char* text : {rational, collapsed}) {
        SCOPED_TRACE(text);
        const Parametrization map = parse_parametrization(text);
        const ImplicitResult dixon = implicitize_by_dixon(map);
        const ImplicitResult kernel = implicitize_by_interpolation(map);
        ASSERT_TRUE(dixon.equation && kernel.equation);
        EXPECT_EQ(*dixon.equation, *kernel.equation);
    }
    EXPECT_EQ(implicitize_by_dixon(parse_parametrization(collapsed)).method, "dixon-minor");
}

TEST(Dixon, TeapotPatchesAreIrreducibleAndVanishAtPointsOfThePatch) {
    const auto patches =
        parse_bpt(test::read_text(test::source_dir() + "/bench/data/implicit/teapot.bpt"));
    ASSERT_EQ(patches.size(), 32u);
    // A body patch, the handle, the lid (a collapsed edge) and the bottom.
    const std::vector<std::pair<std::size_t, long>> cases = {{5, 9}, {13, 18}, {21, 13}, {29, 9}};
    for (const auto& [number, degree] : cases) {
        SCOPED_TRACE("patch " + std::to_string(number));
        const Parametrization map = to_parametrization(patches[number - 1]);
        const ImplicitResult r = implicitize_by_dixon(map);
        ASSERT_TRUE(r.equation);
        EXPECT_EQ(r.equation->total_degree(), degree);
        const algebra::Factorization factors = algebra::factor(*r.equation);
        EXPECT_EQ(factors.factors.size(), 1u);
        EXPECT_TRUE(zero_at_sample_points(*r.equation, map));
        // The proof rejects a neighbour of the equation.
        EXPECT_FALSE(vanishes_on(*r.equation + Polynomial::constant(r.ring, Rational(1)), map));
    }
}

TEST(Dixon, MapsWhoseImageIsACurveAreRefused) {
    const Parametrization curve =
        parse_parametrization("params: s,t\nx = s+t\ny = (s+t)^2\nz = (s+t)^3\n");
    EXPECT_THROW(implicitize_by_dixon(curve), Error);
    EXPECT_THROW(implicitize_by_dixon(parse_parametrization("params: t\nx = t\ny = t^2\n")),
                 InputError);
    // The automatic route still describes the image.
    EXPECT_EQ(implicitize_auto(curve).image, ImageKind::lower_dimensional);
}

TEST(VanishesOn, PointsWhereTheDenominatorVanishesModuloPAreHandled) {
    // Q = t is zero on a whole line of the proof grid: those points take the homogeneous sum.
    const Parametrization map =
        parse_parametrization("params: s,t\nx = 1/t\ny = s\nz = s/t + s^2\n");
    EXPECT_TRUE(vanishes_on(xyz_polynomial("x*y + y^2 - z"), map));
    EXPECT_FALSE(vanishes_on(xyz_polynomial("x*y + y^2 - z + x"), map));
    EXPECT_FALSE(vanishes_on(xyz_polynomial("x*y^2 + y^3 - y*z + 1"), map));
}

}  // namespace
}  // namespace locus::implicit
