// SDF nodes against closed forms and truth tables: primitive distances at known
// points, the CSG truth table on random points, the smooth operations' continuity and
// material weights, repetition and symmetry mapping points to the right cell, transforms
// against their closed forms, and scene-file errors that name the node and the key.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "algebra/error.h"
#include "render/scene_file.h"
#include "sdf_test_nodes.h"

namespace locus::render::sdf {
namespace {

using testing::plain_material;

TEST(SdfPrimitives, ExactDistancesAtKnownPoints) {
    const MaterialPtr m = plain_material();
    EXPECT_DOUBLE_EQ(make_sphere(1.0, m)->value({3, 0, 4}), 4.0);
    const NodePtr box = make_box({1, 2, 3}, 0.0, m);
    EXPECT_DOUBLE_EQ(box->value({4, 0, 0}), 3.0);
    EXPECT_DOUBLE_EQ(box->value({4, 6, 0}), 5.0);     // corner region: √(3² + 4²)
    EXPECT_DOUBLE_EQ(box->value({0.5, 0, 0}), -0.5);  // inside: distance to the nearest face
    EXPECT_DOUBLE_EQ(make_box({1, 1, 1}, 0.25, m)->value({3, 0, 0}), 2.0);
    EXPECT_DOUBLE_EQ(make_torus(2.0, 0.5, m)->value({2, 1, 0}), 0.5);
    EXPECT_DOUBLE_EQ(make_torus(2.0, 0.5, m)->value({0, 0, 0}), 1.5);
    EXPECT_DOUBLE_EQ(make_cylinder(1.0, 1.0, m)->value({4, 5, 0}), 5.0);
    EXPECT_DOUBLE_EQ(make_capsule({0, -1, 0}, {0, 1, 0}, 0.5, m)->value({0, 3, 0}), 1.5);
    EXPECT_DOUBLE_EQ(make_capsule({0, -1, 0}, {0, 1, 0}, 0.5, m)->value({2, 0.3, 0}), 1.5);
    EXPECT_DOUBLE_EQ(make_plane({0, 2, 0}, 2.0, m)->value({5, 3, 1}), 2.0);  // y ≤ 1
    // A cone with apex (0, 1, 0) and base radius 1 at y = −1: the slanted side.
    const NodePtr cone = make_cone(1.0, 0.0, 1.0, m);
    EXPECT_NEAR(cone->value({0, 2, 0}), 1.0, 1e-12);
    EXPECT_NEAR(cone->value({0, -3, 0}), 2.0, 1e-12);
    EXPECT_NEAR(cone->value({1, 1, 0}), 2.0 / std::sqrt(5.0), 1e-12);
    // Bounds: zero on the surface and the same sign as the distance.
    const NodePtr ellipsoid = make_ellipsoid({2, 1, 1}, m);
    EXPECT_DOUBLE_EQ(ellipsoid->value({2, 0, 0}), 0.0);
    EXPECT_LT(ellipsoid->value({1.9, 0, 0}), 0.0);
    EXPECT_LE(ellipsoid->value({4, 0, 0}), 2.0);
    const NodePtr cube_like = make_superquadric({1, 1, 1}, 20.0, m);
    EXPECT_NEAR(cube_like->value({1, 0, 0}), 0.0, 1e-12);
    EXPECT_LT(cube_like->value({0.9, 0.9, 0}), 0.0);  // nearly a cube: the corner is inside
}

TEST(SdfPrimitives, SoftObjectSurfaceIsWhereTheFieldMeetsTheThreshold) {
    // One ball: C(s) = T at s² = the root of the falloff; check the sign change there.
    const NodePtr blob = make_soft_objects({{{0, 0, 0}, 2.0, 1.0}}, 0.5, plain_material());
    double lo = 0.0, hi = 2.0;
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (blob->value({mid, 0, 0}) < 0.0 ? lo : hi) = mid;
    }
    const double s2 = lo * lo / 4.0;
    const double falloff = 1 - 4.0 / 9 * s2 * s2 * s2 + 17.0 / 9 * s2 * s2 - 22.0 / 9 * s2;
    EXPECT_NEAR(falloff, 0.5, 1e-9);
    EXPECT_GT(blob->value({5, 0, 0}), 2.9);  // far away the distance to the ball takes over
}

TEST(SdfBooleans, FollowTheCsgTruthTableOnRandomPoints) {
    const MaterialPtr m = plain_material();
    const NodePtr a = make_sphere(1.0, m);
    const NodePtr b =
        make_placement(make_box({0.6, 0.6, 0.6}, 0.0, m), glm::dmat3(1.0), 1.0, {0.8, 0.2, 0});
    const NodePtr c = make_torus(0.9, 0.3, m);
    const NodePtr united = make_union({a, b, c});
    const NodePtr common = make_intersection({a, b, c});
    const NodePtr carved = make_difference({a, b, c});
    const Blend blend{BlendKind::polynomial, 0.3, 2};
    const NodePtr smooth_united = make_smooth_union({a, b, c}, blend);
    const NodePtr smooth_common = make_smooth_intersection({a, b, c}, blend);
    const NodePtr smooth_carved = make_smooth_difference({a, b, c}, blend);
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> coordinate(-1.8, 1.8);
    int inside_union = 0, inside_intersection = 0, inside_difference = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 p{coordinate(random), coordinate(random), coordinate(random)};
        const bool in_a = a->value(p) < 0, in_b = b->value(p) < 0, in_c = c->value(p) < 0;
        EXPECT_EQ(united->value(p) < 0, in_a || in_b || in_c);
        EXPECT_EQ(common->value(p) < 0, in_a && in_b && in_c);
        EXPECT_EQ(carved->value(p) < 0, in_a && !in_b && !in_c);
        // Smooth versions only add material near seams (union) or remove it (intersection,
        // difference): implications, not equivalences.
        if (in_a || in_b || in_c) {
            EXPECT_LT(smooth_united->value(p), 0.0);
        }
        if (smooth_common->value(p) < 0) {
            EXPECT_TRUE(in_a && in_b && in_c);
        }
        if (smooth_carved->value(p) < 0) {
            EXPECT_TRUE(in_a && !in_b && !in_c);
        }
        inside_union += in_a || in_b || in_c;
        inside_intersection += in_a && in_b && in_c;
        inside_difference += in_a && !in_b && !in_c;
    }
    // The table was exercised on every side.
    EXPECT_GT(inside_union, 1000);
    EXPECT_GT(inside_intersection, 20);
    EXPECT_GT(inside_difference, 200);
}

TEST(SdfBooleans, SmoothMinimaAreContinuousAndBlendMaterialsEvenly) {
    for (const BlendKind kind : {BlendKind::polynomial, BlendKind::exponential, BlendKind::root}) {
        for (const int order : {2, 3, 5}) {
            const Blend blend{kind, 0.4, order};
            // Continuous across the edge of the blend zone |a − b| = k and everywhere else.
            double previous = smooth_min(0.0, -1.0, blend).value;
            for (int i = 1; i <= 4000; ++i) {
                const double b = -1.0 + 2.0 * i / 4000.0;
                const double value = smooth_min(0.0, b, blend).value;
                EXPECT_LE(std::abs(value - previous), 2.0 / 4000.0 + 1e-12);
                EXPECT_LE(value, std::min(0.0, b) + 1e-15);
                EXPECT_GE(value, std::min(0.0, b) - blend.max_lowering() - 1e-12);
                previous = value;
            }
            EXPECT_NEAR(smooth_min(0.3, 0.3, blend).weight_of_b, 0.5, 1e-12);
            // The root blend decays slowly (k²/(4(a − b)²)); the others vanish.
            const double tail = kind == BlendKind::root ? 2e-3 : 1e-5;
            EXPECT_LT(smooth_min(0.0, 5.0, blend).weight_of_b, tail);
            EXPECT_GT(smooth_min(5.0, 0.0, blend).weight_of_b, 1.0 - tail);
        }
    }
    // The polynomial blend leaves min alone outside the zone.
    EXPECT_DOUBLE_EQ(smooth_min(0.0, 0.5, {BlendKind::polynomial, 0.4, 2}).value, 0.0);
}

TEST(SdfBooleans, SmoothUnionMixesTheMaterialsAcrossTheSeam) {
    const NodePtr red = make_sphere(1.0, plain_material({1, 0, 0}));
    const NodePtr blue = make_placement(make_sphere(1.0, plain_material({0, 0, 1})),
                                        glm::dmat3(1.0), 1.0, {1.6, 0, 0});
    const NodePtr blended = make_smooth_union({red, blue}, {BlendKind::polynomial, 0.5, 2});
    const Material middle = blended->material_at({0.8, 0.7, 0}, {});
    EXPECT_NEAR(middle.color.x, 0.5, 1e-12);
    EXPECT_NEAR(middle.color.z, 0.5, 1e-12);
    EXPECT_EQ(blended->material_at({-1, 0, 0}, {}).color, Vec3(1, 0, 0));
    EXPECT_EQ(blended->material_at({2.6, 0, 0}, {}).color, Vec3(0, 0, 1));
}

TEST(SdfDomain, RepetitionMapsPointsToTheirCell) {
    EXPECT_EQ(repetition_cell(0.49, 1.0, std::nullopt), 0);
    EXPECT_EQ(repetition_cell(0.51, 1.0, std::nullopt), 1);
    EXPECT_EQ(repetition_cell(-2.6, 1.0, std::nullopt), -3);
    EXPECT_EQ(repetition_cell(-2.6, 1.0, 2), -2);
    EXPECT_EQ(repetition_cell(40.0, 2.0, 3), 3);
    const MaterialPtr m = plain_material();
    const NodePtr ball = make_sphere(0.3, m);
    const NodePtr field = make_repeat(ball, {1.0, 0.0, 2.0}, {});
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> coordinate(-20, 20);
    for (int i = 0; i < 2000; ++i) {
        const Vec3 p{coordinate(random), coordinate(random) * 0.02, coordinate(random)};
        const Vec3 nearest{std::round(p.x), 0.0, 2.0 * std::round(p.z / 2.0)};
        // The value is the distance to the nearest copy, capped by spacing − extent = 0.7.
        EXPECT_NEAR(field->value(p), std::min(glm::length(p - nearest) - 0.3, 0.7), 1e-12);
    }
    // Finite repetition: cells −2 … 2 along x; beyond them the last copy is the nearest.
    const NodePtr row = make_repeat(ball, {1.0, 0.0, 0.0}, {2, std::nullopt, std::nullopt});
    EXPECT_NEAR(row->value({2.0, 0.5, 0}), 0.2, 1e-12);
    EXPECT_NEAR(row->value({4.0, 0.0, 0}), std::min(2.0 - 0.3, 0.7), 1e-12);
    EXPECT_GT(row->value({3.0, 0.0, 0}), 0.0);  // no copy in cell 3
    EXPECT_THROW(make_repeat(make_sphere(0.6, m), {1.0, 0, 0}, {}), InputError);
}

TEST(SdfDomain, MirrorsAreSymmetric) {
    const MaterialPtr m = plain_material();
    const NodePtr off_centre =
        make_placement(make_sphere(0.4, m), glm::dmat3(1.0), 1.0, {0.8, 0.5, 0.3});
    const NodePtr mirrored = make_mirror_axes(off_centre, {true, false, true});
    const NodePtr plane_mirrored = make_mirror_plane(off_centre, {1, 1, 0}, {0, 0, 0});
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> coordinate(-2, 2);
    const Vec3 n = glm::normalize(Vec3{1, 1, 0});
    for (int i = 0; i < 1000; ++i) {
        const Vec3 p{coordinate(random), coordinate(random), coordinate(random)};
        EXPECT_DOUBLE_EQ(mirrored->value(p), mirrored->value({-p.x, p.y, -p.z}));
        EXPECT_DOUBLE_EQ(mirrored->value(p),
                         off_centre->value(glm::abs(p) * Vec3(1, 0, 1) + Vec3(0, p.y, 0)));
        const Vec3 reflected = p - 2.0 * glm::dot(p, n) * n;
        EXPECT_NEAR(plane_mirrored->value(p), plane_mirrored->value(reflected), 1e-12);
    }
    // The copy appears at the reflected centre.
    EXPECT_NEAR(mirrored->value({-0.8, 0.5, -0.3}), -0.4, 1e-12);
    EXPECT_NEAR(plane_mirrored->value({-0.5, -0.8, 0.3}), -0.4, 1e-12);
}

TEST(SdfTransforms, MatchTheirClosedForms) {
    const MaterialPtr m = plain_material();
    const NodePtr placed =
        make_placement(make_sphere(1.0, m), rotation_about({0, 0, 1}, 33.0), 2.0, {1, 2, 3});
    EXPECT_NEAR(placed->value({1, 2, 8}), 3.0, 1e-12);  // |p − c| − s·r
    // A box turned 90° about y swaps its x and z extents.
    const NodePtr turned =
        make_placement(make_box({1, 2, 3}, 0.0, m), rotation_about({0, 1, 0}, 90.0), 1.0, Vec3(0));
    const NodePtr swapped = make_box({3, 2, 1}, 0.0, m);
    std::mt19937_64 random(9);
    std::uniform_real_distribution<double> coordinate(-5, 5);
    for (int i = 0; i < 500; ++i) {
        const Vec3 p{coordinate(random), coordinate(random), coordinate(random)};
        EXPECT_NEAR(turned->value(p), swapped->value(p), 1e-12);
    }
    // Euler angles are rotations about x, then y, then z.
    const glm::dmat3 euler = rotation_euler({30, 40, 50});
    const glm::dmat3 composed = rotation_about({0, 0, 1}, 50) * rotation_about({0, 1, 0}, 40) *
                                rotation_about({1, 0, 0}, 30);
    for (int c = 0; c < 3; ++c) {
        for (int r = 0; r < 3; ++r) {
            EXPECT_NEAR(euler[c][r], composed[c][r], 1e-15);
        }
    }
    EXPECT_NEAR(glm::length(rotation_about({0, 0, 1}, 90) * Vec3(1, 0, 0) - Vec3(0, 1, 0)), 0.0,
                1e-15);
    // A twist of rate k turns the slice at height y by k·y: the twisted box's value equals
    // the box's at the point turned back, divided by the twist's Lipschitz factor.
    const NodePtr box = make_box({0.5, 1.0, 0.2}, 0.0, m);
    const double k = 1.3;
    const NodePtr twisted = make_twist(box, k);
    const double radius = std::hypot(0.5, 0.2);
    for (const Vec3 p : {Vec3{0.1, 0.7, 0.1}, Vec3{0.3, -0.4, 0.0}, Vec3{0.0, 0.9, 0.2}}) {
        const double angle = k * p.y;
        const Vec3 back{std::cos(angle) * p.x - std::sin(angle) * p.z, p.y,
                        std::sin(angle) * p.x + std::cos(angle) * p.z};
        EXPECT_NEAR(twisted->value(p),
                    std::max(box->value(back) / (1 + k * radius), std::hypot(p.x, p.z) - radius),
                    1e-12);
    }
    // Elongation stretches a sphere into a capsule; rounding grows a box.
    const NodePtr stretched = make_elongate(make_sphere(0.5, m), {0, 1, 0});
    const NodePtr capsule = make_capsule({0, -1, 0}, {0, 1, 0}, 0.5, m);
    const NodePtr rounded = make_round(make_box({1, 1, 1}, 0.0, m), 0.25);
    for (int i = 0; i < 500; ++i) {
        const Vec3 p{coordinate(random), coordinate(random), coordinate(random)};
        EXPECT_NEAR(stretched->value(p), capsule->value(p), 1e-12);
        EXPECT_NEAR(rounded->value(p), make_box({1.25, 1.25, 1.25}, 0.25, m)->value(p), 1e-12);
    }
    // A checker seen through the stretch: inside the straight section the squeezed y is 0, and
    // a footprint along y must shrink to nothing there (mapped), not average the cell boundary
    // at 0 into grey (review finding).
    Material checkered = Material::plain(Vec3(1.0));
    checkered.checker = Vec3(0.0);
    checkered.checker_size = 0.25;
    const NodePtr striped =
        make_elongate(make_sphere(0.5, std::make_shared<const Material>(checkered)), {0, 1, 0});
    Footprint along_y;
    along_y.dy = {0.0, 0.05, 0.0};
    const Vec3 colour = striped->material_at({0.1, 0.3, 0.1}, along_y).color;
    EXPECT_TRUE(colour == Vec3(1.0) || colour == Vec3(0.0)) << colour.x;
}

std::string scene_error(const std::string& text) {
    try {
        parse_scene(text);
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(SdfSceneFile, ReadsATreeWithMaterialsAndTransforms) {
    const Scene scene = parse_scene(R"(
[materials.gold]
color = [0.9, 0.7, 0.2]
[[object]]
type = "plane"
[[object]]
type = "smooth_union"
k = 0.3
material = "gold"
translate = [0, 1, 0]
  [[object.children]]
  type = "sphere"
  radius = 0.5
  [[object.children]]
  type = "box"
  half_size = [0.3, 0.3, 0.3]
  translate = [0.5, 0, 0]
)");
    ASSERT_EQ(scene.objects.size(), 2u);
    EXPECT_TRUE(scene.surfaces.empty());
    const NodePtr& blend = scene.objects[1];
    EXPECT_LT(blend->value({0, 1, 0}), 0.0);
    EXPECT_GT(blend->value({0, 0, 0}), 0.0);
    EXPECT_EQ(blend->material_at({0, 1.5, 0}, {}).color,
              Vec3(0.9, 0.7, 0.2));  // inherited material
}

TEST(SdfSceneFile, ErrorsNameTheNodeTheKeyAndThePosition) {
    EXPECT_EQ(scene_error("[[object]]\ntype = \"sphre\"\n"),
              "line 2, column 8: object[1].type: expected a node type (sphere, plane, box, "
              "rounded_box, torus, cylinder, cone, capsule, ellipsoid, superquadric, "
              "soft_objects, algebraic, group, union, intersection, difference, smooth_union, "
              "smooth_intersection, smooth_difference), found \"sphre\"");
    EXPECT_EQ(scene_error("[[object]]\ntype = \"sphere\"\nradius = 1\nradus = 2\n"),
              "line 4, column 1: object[1].radus: unknown key");
    EXPECT_EQ(scene_error("[[object]]\ntype = \"union\"\n[[object.children]]\ntype = "
                          "\"torus\"\nminor_radius = -1\n"),
              "line 5, column 16: object[1].children[1].minor_radius: must be a positive number");
    EXPECT_EQ(scene_error("[[object]]\ntype = \"sphere\"\nmaterial = \"gold\"\n"),
              "line 3, column 12: object[1].material: no [materials.gold] in this scene");
    EXPECT_EQ(scene_error("[[object]]\ntype = \"plane\"\ntwist = 1.0\n"),
              "line 3, column 9: object[1].twist: needs a child bounded across its axis");
    EXPECT_EQ(scene_error("[[object]]\ntype = \"smooth_union\"\nblend = \"cubic\"\n"),
              "line 3, column 9: object[1].blend: expected \"polynomial\", \"exponential\" or "
              "\"root\", found \"cubic\"");
    EXPECT_EQ(scene_error("[[object]]\nradius = 1\n"),
              "line 1, column 1: object[1].type: missing; expected one of sphere, plane, box, "
              "rounded_box, torus, cylinder, cone, capsule, ellipsoid, superquadric, "
              "soft_objects, algebraic, group, union, intersection, difference, smooth_union, "
              "smooth_intersection, smooth_difference");
    // Regressions: the key path was doubled, factories named parameters that are not keys.
    EXPECT_EQ(scene_error("[[object]]\ntype = \"sphere\"\nmirror = \"xw\"\n"),
              "line 3, column 10: object[1].mirror: expected axes among x, y, z such as "
              "\"xz\", found \"xw\"");
    EXPECT_EQ(scene_error("[[object]]\ntype = \"box\"\nhalf_size = [1, -1, 1]\n"),
              "line 3, column 13: object[1].half_size: must be a positive number");
    EXPECT_EQ(scene_error("[[object]]\ntype = \"sphere\"\nrepeat_count = [1, 1, 1]\n"),
              "line 3, column 16: object[1].repeat_count: needs repeat = [sx, sy, sz] (the "
              "spacing)");
    // Without a compiler (the command line passes one), algebraic leaves are refused clearly.
    EXPECT_NE(scene_error("[[object]]\ntype = \"algebraic\"\nequation = \"x^2+y^2+z^2-1\"\n")
                  .find("object[1]"),
              std::string::npos);
}

}  // namespace
}  // namespace locus::render::sdf
