// Implicitization of classic parametrizations against their known equations, verified by
// substitution, plus non-principal images and malformed parametrization files.
#include "implicit/implicitize.h"
#include "tests/support/test_data.h"

#include <gtest/gtest.h>

#include <string>

#include "algebra/error.h"
#include "algebra/parse.h"
#include "algebra/print.h"
#include "tests/support/parse_error.h"

namespace locus::implicit {
namespace {

struct ClassicCase {
    const char* name;
    const char* param_file;
    const char* equation;  // expected, normalized (primitive, lc > 0 under grevlex x > y > z)
};

class Classic : public ::testing::TestWithParam<ClassicCase> {};

TEST_P(Classic, KnownEquationVerified) {
    const ClassicCase& c = GetParam();
    const Parametrization map = parse_parametrization(c.param_file);
    const ImplicitResult r = implicitize(map);
    ASSERT_TRUE(r.equation.has_value());
    const algebra::Polynomial expected = algebra::parse_polynomial(c.equation, r.ring);
    EXPECT_EQ(*r.equation, expected.primitive_part()) << algebra::to_string(*r.equation);
    EXPECT_TRUE(vanishes_on(*r.equation, map));
    // The resultant route must agree wherever it applies (plane curves and surfaces).
    const ImplicitResult by_resultant = implicitize_by_resultant(map);
    ASSERT_TRUE(by_resultant.equation.has_value());
    EXPECT_EQ(*by_resultant.equation, *r.equation);
    // So must interpolation modulo primes.
    const ImplicitResult by_interpolation = implicitize_by_interpolation(map);
    ASSERT_TRUE(by_interpolation.equation.has_value());
    EXPECT_EQ(*by_interpolation.equation, *r.equation);
    EXPECT_EQ(by_interpolation.method, "interpolate");
    // A deliberately wrong equation must fail the check.
    EXPECT_FALSE(vanishes_on(*r.equation + algebra::Polynomial::variable(r.ring, 0), map));
}

const ClassicCase classic_cases[] = {
    {"whitney_umbrella", "params: s,t\nx = s*t\ny = s\nz = t^2\n", "y^2*z-x^2"},
    {"cusp", "params: t\nx = t^2\ny = t^3\n", "x^3-y^2"},
    {"rational_circle", "params: t\nx = (1-t^2)/(1+t^2)\ny = 2*t/(1+t^2)\n", "x^2+y^2-1"},
    {"folium", "params: t\nx = 3*t/(1+t^3)\ny = 3*t^2/(1+t^3)\n", "x^3+y^3-3*x*y"},
    {"hyperbolic_paraboloid", "params: s,t\nx = s\ny = t\nz = s^2-t^2\n", "x^2-y^2-z"},
    {"stereographic_sphere",
     "params: u,v\nx = 2*u/(1+u^2+v^2)\ny = 2*v/(1+u^2+v^2)\nz = (u^2+v^2-1)/(1+u^2+v^2)\n",
     "x^2+y^2+z^2-1"},
    {"saddle_xyz", "params: s,t\nx = s*t\ny = s\nz = t\n", "y*z-x"},
    // The cylinder over the cusp: x³ = s⁶ = y², whatever z.
    {"cusp_cylinder", "params: s,t\nx = s^2\ny = s^3\nz = t\n", "x^3-y^2"},
    {"lemniscate", "params: t\nx = t*(1+t^2)/(1+t^4)\ny = t*(1-t^2)/(1+t^4)\n",
     "(x^2+y^2)^2-x^2+y^2"},
    {"cardioid", "params: t\nx = 2*(1-t^2)/(1+t^2)^2\ny = 4*t/(1+t^2)^2\n",
     "(x^2+y^2-x)^2-x^2-y^2"},
    // T₂(T₃) = T₃(T₂) = T₆ with x = T₂(t), y = T₃(t).
    {"chebyshev_curve", "params: t\nx = 2*t^2-1\ny = 4*t^3-3*t\n", "4*x^3-3*x-2*y^2+1"},
    {"bilinear_patch", "params: s,t\nx = s\ny = t\nz = (1-s)*(1-t)*0+s*(1-t)*0+(1-s)*t*0+s*t*1\n",
     "x*y-z"},
    {"roman_rational",
     "params: s,t\nx = 2*t*(s^2+t^2-1)/(1+s^2+t^2)^2\ny = 2*s*(s^2+t^2-1)/(1+s^2+t^2)^2\n"
     "z = 4*s*t/(1+s^2+t^2)^2\n",
     "x^2*y^2+x^2*z^2+y^2*z^2-x*y*z"},
    // z = sin 2θ with x = s cos θ, y = s sin θ, by the half-angle substitution.
    {"plucker_conoid",
     "params: s,t\nx = s*(1-t^2)/(1+t^2)\ny = 2*s*t/(1+t^2)\nz = 4*t*(1-t^2)/(1+t^2)^2\n",
     "x^2*z+y^2*z-2*x*y"},
};

INSTANTIATE_TEST_SUITE_P(Implicitize, Classic, ::testing::ValuesIn(classic_cases),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

TEST(Implicitize, TrigonometricTorusAndSphereByHalfAngle) {
    const Parametrization torus = parse_parametrization(
        "params: u,v\nx = (2+cos(v))*cos(u)\ny = (2+cos(v))*sin(u)\nz = sin(v)\n");
    EXPECT_EQ(torus.half_angle.size(), 2u);
    const ImplicitResult r = implicitize(torus);
    ASSERT_TRUE(r.equation.has_value());
    // (x² + y² + z² + R² − r²)² − 4R²(x² + y²) with R = 2, r = 1.
    const algebra::Polynomial expected =
        algebra::parse_polynomial("(x^2+y^2+z^2+3)^2-16*(x^2+y^2)", r.ring);
    EXPECT_EQ(*r.equation, expected.primitive_part());
    EXPECT_TRUE(vanishes_on(*r.equation, torus));

    const Parametrization sphere =
        parse_parametrization("params: u,v\nx = cos(u)*cos(v)\ny = sin(u)*cos(v)\nz = sin(v)\n");
    const ImplicitResult s = implicitize(sphere);
    ASSERT_TRUE(s.equation.has_value());
    EXPECT_EQ(algebra::to_string(*s.equation), "x^2+y^2+z^2-1");
}

TEST(Implicitize, EnneperHasDegreeNine) {
    const Parametrization map = parse_parametrization(
        "params: u,v\nx = u - u^3/3 + u*v^2\ny = v - v^3/3 + v*u^2\nz = u^2 - v^2\n");
    const ImplicitResult r = implicitize(map);
    ASSERT_TRUE(r.equation.has_value());
    EXPECT_EQ(r.equation->total_degree(), 9);
    EXPECT_TRUE(vanishes_on(*r.equation, map));
}

// Enneper's surface (degree 9) and the trigonometric torus: the larger classic surfaces.
const char* const kEnneperAndTorus[] = {
    "params: u,v\nx = u - u^3/3 + u*v^2\ny = v - v^3/3 + v*u^2\nz = u^2 - v^2\n",
    "params: u,v\nx = (2+cos(v))*cos(u)\ny = (2+cos(v))*sin(u)\nz = sin(v)\n"};

TEST(Implicitize, ResultantAgreesOnEnneperAndTorusAndRefusesSpaceCurves) {
    for (const char* f : kEnneperAndTorus) {
        SCOPED_TRACE(f);
        const Parametrization map = parse_parametrization(f);
        EXPECT_EQ(implicitize_by_resultant(map).equation, implicitize(map).equation);
    }
    EXPECT_THROW(implicitize_by_resultant(parse_parametrization("params: t\nx=t\ny=t^2\nz=t^3\n")),
                 InputError);
}

TEST(Implicitize, InterpolationAgreesOnEnneperAndTorusAndGivesUpOnDegenerateMaps) {
    for (const char* f : kEnneperAndTorus) {
        SCOPED_TRACE(f);
        const Parametrization map = parse_parametrization(f);
        EXPECT_EQ(implicitize_by_interpolation(map).equation, implicitize(map).equation);
    }
    // A surface map whose image is a line: the kernel is not one-dimensional.
    EXPECT_THROW(implicitize_by_interpolation(
                     parse_parametrization("params: s,t\nx = s+t\ny = 2*s+2*t\nz = s+t+1\n")),
                 Error);
    EXPECT_THROW(
        implicitize_by_interpolation(parse_parametrization("params: t\nx=t\ny=t^2\nz=t^3\n")),
        InputError);
    // auto falls back to elimination there and still classifies the image.
    const ImplicitResult line =
        implicitize_auto(parse_parametrization("params: s,t\nx = s+t\ny = 2*s+2*t\nz = s+t+1\n"));
    EXPECT_EQ(line.image, ImageKind::lower_dimensional);
}

// auto decides from the map whether elimination gets its probe: a surface map with a numerator
// or denominator of 9 terms or more (every Bézier patch of the bench) goes straight to the
// Dixon determinant, one with fewer (every classic map) is eliminated. The dense map here is a
// graph, whose elimination would be instant: the decision is the map's shape, not the clock.
// A dense map whose image is not a surface ends in elimination all the same.
TEST(Implicitize, AutoSendsDenseSurfaceMapsToDixonWithoutTheEliminationProbe) {
    const std::string nine = "(1 + s + t + s*t + s^2 + t^2 + s^2*t + s*t^2 + s^2*t^2)";
    const Parametrization graph =
        parse_parametrization("params: s,t\nx = s\ny = t\nz = " + nine + "\n");
    const ImplicitResult dense = implicitize_auto(graph);
    EXPECT_EQ(dense.method.rfind("dixon", 0), 0u) << dense.method;
    ASSERT_TRUE(dense.equation.has_value());
    EXPECT_EQ(dense.equation, implicitize(graph).equation);
    // Eight terms: the probe, which eliminates it.
    const ImplicitResult sparse = implicitize_auto(parse_parametrization(
        "params: s,t\nx = s\ny = t\nz = 1 + s + t + s*t + s^2 + t^2 + s^2*t + s*t^2\n"));
    EXPECT_EQ(sparse.method, "groebner");
    // A dense map onto a line: Dixon and interpolation give up, elimination classifies it.
    const ImplicitResult line = implicitize_auto(parse_parametrization(
        "params: s,t\nx = " + nine + "\ny = 2*" + nine + "\nz = " + nine + " + 1\n"));
    EXPECT_EQ(line.image, ImageKind::lower_dimensional);
}

TEST(Implicitize, BiquadraticPatchByInterpolationAndResultantsAgree) {
    // Gröbner elimination takes over a minute here; the other two routes must agree.
    const Parametrization map = parse_parametrization(
        test::read_text(test::source_dir() + "/tests/data/biquadratic_patch.param"));
    const ImplicitResult by_interpolation = implicitize_by_interpolation(map);
    ASSERT_TRUE(by_interpolation.equation.has_value());
    EXPECT_EQ(by_interpolation.equation->total_degree(), 8);
    EXPECT_EQ(by_interpolation.equation, implicitize_by_resultant(map).equation);
    EXPECT_TRUE(vanishes_on(*by_interpolation.equation, map));
}

TEST(Implicitize, InterpolationReachesTheCubicBezierTriangle) {
    const Parametrization map = parse_parametrization(
        test::read_text(test::source_dir() + "/bench/data/implicit/bezier_triangle3.param"));
    const ImplicitResult r = implicitize_by_interpolation(map);
    ASSERT_TRUE(r.equation.has_value());
    EXPECT_EQ(r.equation->total_degree(), 9);
    EXPECT_EQ(r.equation->num_terms(), 220u);
    EXPECT_TRUE(vanishes_on(*r.equation, map));  // proved again, independently of the route
}

TEST(Implicitize, TwistedCubicIsNotPrincipal) {
    const ImplicitResult r = implicitize(parse_parametrization("params: t\nx=t\ny=t^2\nz=t^3\n"));
    EXPECT_FALSE(r.equation.has_value());
    EXPECT_EQ(r.image, ImageKind::lower_dimensional);
    EXPECT_EQ(r.generators.size(), 3u);
}

TEST(Implicitize, DegenerateMaps) {
    const ImplicitResult point =
        implicitize(parse_parametrization("params: s,t\nx = 1\ny = 2\nz = 3\n"));
    EXPECT_EQ(point.image, ImageKind::point);
    const ImplicitResult line =
        implicitize(parse_parametrization("params: s,t\nx = s+t\ny = 2*s+2*t\nz = s+t+1\n"));
    EXPECT_EQ(line.image, ImageKind::lower_dimensional);
    EXPECT_EQ(line.generators.size(), 2u);
}

TEST(Parametrization, BadInputsReportLineAndColumn) {
    const test::BadInput cases[] = {
        {"x = t\n", 1, 1, "a 'params:' line before"},
        {"params: t\nx = q\ny = t\n", 2, 5, "a declared variable"},
        {"params: t\nx = t\nx = t^2\ny = t\n", 3, 1, "each coordinate assigned once"},
        {"params: t\nx = t\n", 3, 1, "an assignment 'y = ...'"},  // end of input: line 3
        {"params: t\nx = t/(t-t)\ny = t\n", 2, 7, "a non-zero divisor"},
        {"params: u\nx = tan(u)\ny = u\n", 2, 5, "tan is not supported yet"},
        {"params: u\nx = cos(2*u)\ny = u\n", 3, 5, "the angle u only inside sin and cos"},
        {"params: u\nx = cos(u+1)\ny = sin(u)\n", 2, 12, "an integer combination of parameters"},
        {"params: t\nw = t\n", 2, 1, "a coordinate x, y or z"},
        {"", 1, 1, "a 'params:' line"},
    };
    for (const auto& c : cases) {
        test::expect_parse_error(c, [&] { parse_parametrization(c.text); });
    }
}

}  // namespace
}  // namespace locus::implicit
