// Surface extents and framing (render/surface_extent.h, render/framing.h), against boxes known
// in closed form: spheres, a torus, and random rotated ellipsoids whose box is
// c ± (Σ_k (R_jk·a_k)²)^{1/2} per axis, computed from the rotation and axes, not from f.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <tuple>
#include <utility>

#include "algebra/compiled.h"
#include "algebra/error.h"
#include "render/framing.h"
#include "render/renderer.h"
#include "render/scene_file.h"
#include "render/surface_extent.h"

namespace locus::render {
namespace {

using Kind = SurfaceExtent::Kind;

void expect_box_near(const SurfaceExtent& extent, const Vec3& low, const Vec3& high,
                     double tolerance) {
    ASSERT_EQ(extent.kind, Kind::bounded);
    for (int j = 0; j < 3; ++j) {
        EXPECT_NEAR(extent.low[j], low[j], tolerance) << "axis " << j;
        EXPECT_NEAR(extent.high[j], high[j], tolerance) << "axis " << j;
    }
}

TEST(SurfaceExtent, SpheresAndATorusHaveTheirBoxes) {
    expect_box_near(estimate_extent(algebra::compile_surface("x^2+y^2+z^2-1")), Vec3(-1.0),
                    Vec3(1.0), 0.01);
    // Centred away from the origin: the second round starts inside it.
    expect_box_near(estimate_extent(algebra::compile_surface("(x-3)^2+(y+2)^2+(z-1)^2-1")),
                    {2.0, -3.0, 0.0}, {4.0, -1.0, 2.0}, 0.01);
    // R = 3, r = 1: outside the default clip sphere of radius 2.
    expect_box_near(estimate_extent(algebra::compile_surface("(x^2+y^2+z^2+8)^2-36*(x^2+y^2)")),
                    {-4.0, -4.0, -1.0}, {4.0, 4.0, 1.0}, 0.03);
}

TEST(SurfaceExtent, SurfacesThatReachInfinityAreNotBounded) {
    for (const char* equation : {"x^2+y^2-1",                   // f_d vanishes along z
                                 "x^3+y^3+z^3-1",               // odd degree
                                 "x^2+y^2-z^2-1",               // f_d changes sign
                                 "x^4+y^4+z^4-x^2*y^2*z^2"}) {  // top form x²y²z² indefinite
        EXPECT_EQ(estimate_extent(algebra::compile_surface(equation)).kind, Kind::unbounded)
            << equation;
    }
}

// x⁴⁰ + y⁴⁰ + z⁴⁰ = 10⁴⁰ reaches x = ±10 on the axis (y = z = 0) and no farther: its box is
// [−10, 10]³. Its top form's least value on the unit sphere is 3⁻¹⁹ of its largest, below the
// sampled definiteness test's 1e-6 (it rendered an empty picture at the default frame); it is
// bounded by its terms' form. Without a pure power of every variable, or with terms of both
// signs, that form proves nothing, and the sampled test still answers.
TEST(SurfaceExtent, HighDegreeSumsOfEvenPowersAreBounded) {
    expect_box_near(estimate_extent(algebra::compile_surface("x^40+y^40+z^40-10^40")), Vec3(-10.0),
                    Vec3(10.0), 0.01);
    for (const char* equation : {"(x^2+y^2)*(x^38+y^38+z^38)-1",  // x ≈ z^-19 far along z
                                 "x^40+y^40-z^40-1"}) {           // f_d changes sign
        EXPECT_EQ(estimate_extent(algebra::compile_surface(equation)).kind, Kind::unbounded)
            << equation;
    }
}

// Random sums of pure even powers, a·(x − p)^d + b·(y − q)^d + c·(z − r)^d = 1 with d from 28 to
// 40: their top forms fall under the sampled test's 1e-6 at the diagonals, and the box is
// p ± a^(−1/d) (and so on) in closed form, computed here from a, d and p, not from f.
TEST(SurfaceExtent, RandomHighDegreeSumsOfEvenPowersAreFramed) {
    std::mt19937_64 random(20261128);
    std::uniform_int_distribution<int> half_degree(14, 20), numerator(1, 16), shift(-2, 2);
    for (int trial = 0; trial < 8; ++trial) {
        const int d = 2 * half_degree(random);
        std::string equation;
        Vec3 low(0.0), high(0.0);
        for (int axis = 0; axis < 3; ++axis) {
            const int weight = numerator(random), centre_twice = shift(random);  // a = weight/4
            const char* name[] = {"x", "y", "z"};
            equation += (axis == 0 ? "" : "+") + std::to_string(weight) + "/4*(" + name[axis] +
                        "-(" + std::to_string(centre_twice) + "/2))^" + std::to_string(d);
            const double half = std::pow(weight / 4.0, -1.0 / d);
            low[axis] = centre_twice / 2.0 - half;
            high[axis] = centre_twice / 2.0 + half;
        }
        equation += "-1";
        const SurfaceExtent extent = estimate_extent(algebra::compile_surface(equation));
        ASSERT_EQ(extent.kind, Kind::bounded) << equation;
        for (int j = 0; j < 3; ++j) {
            EXPECT_GE(extent.low[j], low[j] - 1e-9) << equation;
            EXPECT_LE(extent.high[j], high[j] + 1e-9) << equation;
            EXPECT_GE(extent.high[j] - extent.low[j], 0.99 * (high[j] - low[j])) << equation;
        }
    }
}

TEST(SurfaceExtent, ASurfaceWithoutRealPointsHasNoneFound) {
    const SurfaceExtent extent = estimate_extent(algebra::compile_surface("x^2+y^2+z^2+1"));
    EXPECT_EQ(extent.kind, Kind::none_found);
    EXPECT_EQ(extent.lines, 1024);
    EXPECT_FALSE(fitted_clip_sphere(extent).has_value());
}

// A component that no line through the origin meets — far away, or small beside the
// origin — is found from the point Newton's steps reach; its box is the closed-form one and its
// fitted sphere holds it snugly.
TEST(SurfaceExtent, FarAndSmallSurfacesAreFoundFromNewtonsPoint) {
    expect_box_near(estimate_extent(algebra::compile_surface("(x-1000)^2+y^2+z^2-1")),
                    {999.0, -1.0, -1.0}, {1001.0, 1.0, 1.0}, 0.01);
    expect_box_near(estimate_extent(algebra::compile_surface("(x-100000)^2+(y-3)^2+z^2-4")),
                    {99998.0, 1.0, -2.0}, {100002.0, 5.0, 2.0}, 0.02);
    const SurfaceExtent small =
        estimate_extent(algebra::compile_surface("(x-1/2)^2+y^2+z^2-1/100000000"));
    expect_box_near(small, {0.5 - 1e-4, -1e-4, -1e-4}, {0.5 + 1e-4, 1e-4, 1e-4}, 1e-6);
    const std::optional<ClipSphere> fitted = fitted_clip_sphere(small);
    ASSERT_TRUE(fitted.has_value());
    EXPECT_NEAR(fitted->center.x, 0.5, 1e-6);
    EXPECT_GE(fitted->radius, 1e-4 * std::sqrt(3.0));
    EXPECT_LE(fitted->radius, 2e-4 * std::sqrt(3.0));
    // A far torus (R = 3, r = 1, 50 away along x).
    expect_box_near(
        estimate_extent(algebra::compile_surface("((x-50)^2+y^2+z^2+8)^2-36*((x-50)^2+y^2)")),
        {46.0, -4.0, -1.0}, {54.0, 4.0, 1.0}, 0.03);
}

// x^T M x − 2 (M c)^T x + c^T M c − 1 for M = R diag(1/a²) R^T, as an equation over Q.
std::string ellipsoid_equation(const double rotation[3][3], const Vec3& axes, const Vec3& centre) {
    double m[3][3];
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            m[i][j] = 0.0;
            for (int k = 0; k < 3; ++k) {
                m[i][j] += rotation[i][k] * rotation[j][k] / (axes[k] * axes[k]);
            }
        }
    }
    const char* names = "xyz";
    std::string f;
    char term[96];
    double constant = -1.0;
    for (int i = 0; i < 3; ++i) {
        double linear = 0.0;
        for (int j = 0; j < 3; ++j) {
            linear -= 2.0 * m[i][j] * centre[j];
            constant += centre[i] * m[i][j] * centre[j];
            if (j >= i) {
                std::snprintf(term, sizeof term, "+(%.17g)*%c*%c", (i == j ? 1.0 : 2.0) * m[i][j],
                              names[i], names[j]);
                f += term;
            }
        }
        std::snprintf(term, sizeof term, "+(%.17g)*%c", linear, names[i]);
        f += term;
    }
    std::snprintf(term, sizeof term, "+(%.17g)", constant);
    return f + term;
}

// An ellipsoid with a random rotation (from a random unit quaternion), its equation over Q and
// its box in closed form: c_j ± (Σ_k (R_jk·a_k)²)^{1/2}.
struct RandomEllipsoid {
    double rotation[3][3];
    Vec3 axes, centre;
    std::string equation;

    double half_width(int j) const {
        double sum = 0.0;
        for (int k = 0; k < 3; ++k) {
            sum += std::pow(rotation[j][k] * axes[k], 2);
        }
        return std::sqrt(sum);
    }
};

// The rotation is drawn first, then `draw(random)` gives the axes and the centre.
template <class Draw>
RandomEllipsoid random_ellipsoid(std::mt19937_64& random, const Draw& draw) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    double q[4], norm = 0.0;
    for (double& v : q) {
        v = unit(random);
        norm += v * v;
    }
    for (double& v : q) {
        v /= std::sqrt(norm);
    }
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    RandomEllipsoid e{{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                       {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                       {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}},
                      Vec3(0.0),
                      Vec3(0.0),
                      ""};
    std::tie(e.axes, e.centre) = draw(random);
    e.equation = ellipsoid_equation(e.rotation, e.axes, e.centre);
    return e;
}

// The extent of `e` lies inside its true box (up to `slack`, the tracer's tolerance and the
// rounding of a far equation), reaches `reach` of its width on every axis, and its fitted sphere
// holds the whole ellipsoid. `e` must be found.
void expect_extent_fits(const RandomEllipsoid& e, const SurfaceExtent& extent, double slack,
                        double reach = 0.999) {
    ASSERT_EQ(extent.kind, Kind::bounded) << e.equation;
    const std::optional<ClipSphere> fitted = fitted_clip_sphere(extent);
    ASSERT_TRUE(fitted.has_value());
    for (int j = 0; j < 3; ++j) {
        const double half = e.half_width(j);
        // Every point found is on the surface, so inside the true box ...
        EXPECT_GE(extent.low[j], e.centre[j] - half - slack) << e.equation;
        EXPECT_LE(extent.high[j], e.centre[j] + half + slack) << e.equation;
        // ... and the lines, with the faces refined, reach most of it.
        EXPECT_LE(extent.high[j] - extent.low[j], 2.0 * half + 2.0 * slack) << e.equation;
        EXPECT_GE(extent.high[j] - extent.low[j], reach * 2.0 * half - 2.0 * slack) << e.equation;
    }
    // The whole ellipsoid is inside the fitted sphere: its farthest point from the sphere's
    // centre c' is at most |c − c'| + the largest axis away.
    const double largest_axis = std::max({e.axes.x, e.axes.y, e.axes.z});
    EXPECT_LE(glm::length(e.centre - fitted->center) + largest_axis,
              fitted->radius * 1.0001 + slack)
        << e.equation;
}

TEST(SurfaceExtent, RandomEllipsoidsAreInsideTheirFittedSpheres) {
    std::mt19937_64 random(20261126);
    std::uniform_real_distribution<double> axis(0.1, 4.0), offset(-3.0, 3.0);
    for (int trial = 0; trial < 40; ++trial) {
        const RandomEllipsoid e = random_ellipsoid(random, [&](std::mt19937_64& r) {
            const Vec3 axes{axis(r), axis(r), axis(r)};
            const Vec3 centre{offset(r), offset(r), offset(r)};
            return std::pair{axes, centre};
        });
        expect_extent_fits(e, estimate_extent(algebra::compile_surface(e.equation)), 1e-9);
    }
}

// Ellipsoids that no line through the origin meets, found from Newton's point: 200 far ones
// (10² to 10⁵ away in a random direction, axes 0.1 to 4) and 200 small ones beside the origin
// (axes 10⁻⁴ to 10⁻³, 0.2 to 0.8 away), against the closed-form boxes. Every one found is
// framed: its box inside the true one, reaching 99 % of its width (the search over directions
// stops short of 99.9 % on ridges of some), the fitted sphere around it. Newton's steps do not
// always arrive: along the gradient they zigzag across an elongated ellipsoid far away. The
// lines through where they stop find 2 of the 3 far ones here that zigzag; the third is
// reported as none found (1 % allowed: 3 failed it before the stopping point was used).
TEST(SurfaceExtent, RandomFarAndSmallEllipsoidsAreFramed) {
    std::mt19937_64 random(20261128);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), exponent(2.0, 5.0), axis(0.1, 4.0),
        small_axis(1e-4, 1e-3), near(0.2, 0.8);
    const auto random_direction = [&] {
        Vec3 d;
        do {
            d = {unit(random), unit(random), unit(random)};
        } while (glm::length(d) < 0.1 || glm::length(d) > 1.0);
        return glm::normalize(d);
    };
    constexpr int kTrials = 200;
    int far_missed = 0, small_missed = 0;
    for (int trial = 0; trial < kTrials; ++trial) {
        const double distance = std::pow(10.0, exponent(random));
        const RandomEllipsoid e = random_ellipsoid(random, [&](std::mt19937_64& r) {
            const Vec3 axes{axis(r), axis(r), axis(r)};
            return std::pair{axes, distance * random_direction()};
        });
        const SurfaceExtent extent = estimate_extent(algebra::compile_surface(e.equation));
        if (extent.kind != Kind::bounded) {
            ++far_missed;
            continue;
        }
        // The equation's coefficients carry 17 digits of terms near distance²: its surface is
        // the closed-form one to about 1e-12 of the distance.
        expect_extent_fits(e, extent, 1e-9 * distance, 0.99);
    }
    for (int trial = 0; trial < kTrials; ++trial) {
        const RandomEllipsoid e = random_ellipsoid(random, [&](std::mt19937_64& r) {
            const Vec3 axes{small_axis(r), small_axis(r), small_axis(r)};
            return std::pair{axes, near(r) * random_direction()};
        });
        const SurfaceExtent extent = estimate_extent(algebra::compile_surface(e.equation));
        if (extent.kind != Kind::bounded) {
            ++small_missed;
            continue;
        }
        expect_extent_fits(e, extent, 1e-9, 0.99);
    }
    RecordProperty("far_missed", far_missed);  // the figure rendering.md gives
    EXPECT_LE(far_missed, kTrials / 100);
    EXPECT_EQ(small_missed, 0);
}

TEST(SurfaceExtent, ThePastDeadlineStopsTheSearch) {
    EXPECT_THROW(estimate_extent(algebra::compile_surface("x^2+y^2+z^2-1"), 1024,
                                 std::chrono::steady_clock::now() - std::chrono::seconds(1)),
                 Timeout);
}

TEST(Framing, ATorusOutsideTheDefaultClipSphereIsFramedOnItsExtent) {
    Scene scene;
    scene.width = scene.height = 24;
    Surface torus;
    torus.equation = "(x^2+y^2+z^2+8.19)^2-36*(x^2+y^2)";  // R = 3, r = 0.9
    scene.surfaces.push_back(torus);
    const algebra::CompiledPolynomial compiled[] = {algebra::compile_surface(torus.equation)};
    RenderStats at_default;
    render(scene, compiled, {}, &at_default);
    EXPECT_EQ(at_default.hits, 0);  // the clip sphere of radius 2 lies in the hole
    const auto extents = fit_clip_regions(scene, compiled, false);
    ASSERT_TRUE(extents[0].has_value());
    const ClipSphere fitted = std::get<ClipSphere>(scene.surfaces[0].clip);
    EXPECT_NEAR(fitted.radius, 1.05 * std::sqrt(2 * 3.9 * 3.9 + 0.81), 0.2);
    RenderStats framed;
    render(scene, compiled, {}, &framed);
    EXPECT_GT(framed.hits, 24 * 24 / 8);
}

TEST(Framing, AGivenClipRegionIsKeptUnlessForced) {
    Scene scene = parse_scene(
        "[[surface]]\nequation = \"x^2+y^2+z^2-1\"\nclip_radius = 0.5\n"
        "[[surface]]\nequation = \"x^2+y^2+z^2-4\"\n");
    EXPECT_FALSE(scene.surfaces[0].fit_clip);
    EXPECT_TRUE(scene.surfaces[1].fit_clip);
    const algebra::CompiledPolynomial compiled[] = {
        algebra::compile_surface(scene.surfaces[0].equation),
        algebra::compile_surface(scene.surfaces[1].equation)};
    Scene fitted = scene;
    const auto extents = fit_clip_regions(fitted, compiled, false);
    EXPECT_FALSE(extents[0].has_value());
    EXPECT_EQ(std::get<ClipSphere>(fitted.surfaces[0].clip).radius, 0.5);
    EXPECT_NEAR(std::get<ClipSphere>(fitted.surfaces[1].clip).radius, 1.05 * 2.0 * std::sqrt(3.0),
                0.05);
    fit_clip_regions(scene, compiled, true);
    EXPECT_NEAR(std::get<ClipSphere>(scene.surfaces[0].clip).radius, 1.05 * std::sqrt(3.0), 0.03);
}

// The default camera at the far ends of the doubles: a clip radius whose square overflows
// (1e200) still places it, one whose extent overflows (1e308) is an input error that says so
// (it was "camera.eye (inf, inf, inf): the eye must differ from the target"), and a tiny one
// (1e-300, whose square underflows) places it too instead of at the target.
TEST(Framing, TheDefaultCameraAtTheEndsOfTheDoubles) {
    const auto camera_for = [](double radius) {
        Scene scene;
        Surface surface;
        surface.equation = "x^2+y^2+z^2-1";
        surface.clip = ClipSphere{{0.0, 0.0, 0.0}, radius};
        scene.surfaces.push_back(surface);
        return default_camera(scene);
    };
    for (const double radius : {1e-300, 1e-160, 1.0, 1e160, 1e200}) {
        const CameraSpec camera = camera_for(radius);
        const double distance = glm::length((camera.eye - camera.target) / radius);
        EXPECT_GT(distance, 1.0) << radius;
        EXPECT_LT(distance, 10.0) << radius;
    }
    try {
        camera_for(1e308);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("too large to place the default camera"),
                  std::string::npos)
            << e.what();
    }
}

TEST(Framing, AnEmptyPictureIsExplained) {
    // Each reason in words, with the kind of remedy the front end names its way (the library's
    // text names no command-line flag).
    using Remedy = EmptyPictureReason::Remedy;
    const auto expect = [](const EmptyPictureReason& why, const std::string& words, Remedy remedy) {
        EXPECT_NE(why.text.find(words), std::string::npos) << why.text;
        EXPECT_EQ(why.remedy, remedy) << why.text;
        EXPECT_EQ(why.text.find("--"), std::string::npos) << why.text;
    };
    Surface sphere;
    sphere.equation = "x^2+y^2+z^2-1";
    const algebra::CompiledPolynomial unit = algebra::compile_surface(sphere.equation);
    CameraSpec camera;  // eye (0, 0, 5) looking at the origin
    sphere.clip = ClipSphere{{0.0, 0.0, 0.0}, 0.5};
    expect(why_not_hit(sphere, unit, camera, 32, 32), "no point of it was found inside",
           Remedy::fit);
    // Inside its clip region, but a speck of it: the region is not what hides it (a message
    // that said "no point inside" here listed points inside).
    sphere.clip = ClipSphere{{0.0, 0.0, 0.0}, 1e150};
    expect(why_not_hit(sphere, unit, camera, 32, 32),
           "lies inside its clip region, the sphere of radius 1e+150 about (0, 0, 0), but spans "
           "only",
           Remedy::fit);
    sphere.clip = ClipSphere{};
    CameraSpec away = camera;
    away.target = {0.0, 0.0, 9.0};
    expect(why_not_hit(sphere, unit, away, 32, 32), "behind the camera", Remedy::none);
    away.target = {10.0, 0.0, 5.0};
    expect(why_not_hit(sphere, unit, away, 32, 32), "outside the camera's field of view",
           Remedy::none);
    Surface imaginary;
    imaginary.equation = "x^2+y^2+z^2+1";
    expect(why_not_hit(imaginary, algebra::compile_surface(imaginary.equation), camera, 32, 32),
           "no real point of it was found", Remedy::clip_region);
    // A cylinder (not bounded) clipped away from its wall: no extent to frame, but where its
    // nearest point is, 1 from the box's centre, for a larger region to take it in.
    Surface cylinder;
    cylinder.equation = "x^2+y^2-1";
    cylinder.clip = ClipBox{{-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}};
    const EmptyPictureReason wall =
        why_not_hit(cylinder, algebra::compile_surface(cylinder.equation), camera, 32, 32);
    expect(wall, "inside its clip region, the box from", Remedy::larger_clip_region);
    expect(wall, "the nearest point found on lines through its centre is",
           Remedy::larger_clip_region);
    // A plane 100 away from the default clip sphere.
    Surface plane;
    plane.equation = "x-100";
    expect(why_not_hit(plane, algebra::compile_surface(plane.equation), camera, 32, 32),
           "the nearest point found on lines through its centre is (100,",
           Remedy::larger_clip_region);
}

// The nearest point on the lattice's lines lies on the surface, and near the nearest point: a
// line at most half the lattice's spacing (0.11 rad) off the best direction, which lengthens
// the plane's distance by 1/cos(0.055) ≈ 1.0015 and, from 4.5 away, the unit sphere's by under
// 1 % (a factor 1.006 and 1.02 allowed).
TEST(SurfaceExtent, TheNearestPointOnTheLinesIsNearTheTrueOne) {
    const std::optional<Vec3> on_plane =
        nearest_point_on_lines(algebra::compile_surface("x+y-100"), Vec3(0.0));
    ASSERT_TRUE(on_plane.has_value());
    EXPECT_NEAR(on_plane->x + on_plane->y, 100.0, 1e-9);
    EXPECT_LE(glm::length(*on_plane), 100.0 / std::sqrt(2.0) * 1.006);
    const std::optional<Vec3> on_sphere =
        nearest_point_on_lines(algebra::compile_surface("(x-5)^2+y^2+z^2-1"), Vec3(1.0, 2.0, 0.0));
    ASSERT_TRUE(on_sphere.has_value());
    EXPECT_NEAR(glm::length(*on_sphere - Vec3(5.0, 0.0, 0.0)), 1.0, 1e-9);
    // The sphere's nearest point to (1, 2, 0) is √20 − 1 away.
    EXPECT_LE(glm::length(*on_sphere - Vec3(1.0, 2.0, 0.0)), (std::sqrt(20.0) - 1.0) * 1.02);
    EXPECT_FALSE(nearest_point_on_lines(algebra::compile_surface("x^2+y^2+z^2+1"), Vec3(0.0)));
}

}  // namespace
}  // namespace locus::render
