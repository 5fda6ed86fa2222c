// Scene files: defaults, every key read, and each bad scene rejected with a message that names
// the key, its position and what was expected.
#include "render/scene_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "algebra/error.h"
#include "render/camera.h"
#include "render/material.h"

namespace locus::render {
namespace {

std::string error_of(const std::string& text) {
    try {
        parse_scene(text);
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(SceneFile, MinimalSceneTakesTheDefaults) {
    const Scene scene = parse_scene("[[surface]]\nequation = \"x^2+y^2+z^2-1\"\n");
    ASSERT_EQ(scene.surfaces.size(), 1u);
    EXPECT_EQ(scene.width, 512);
    EXPECT_EQ(scene.options.method, TraceMethod::certified);
    EXPECT_FALSE(scene.camera.has_value());
    EXPECT_TRUE(scene.lights.empty());
    ASSERT_TRUE(std::holds_alternative<ClipSphere>(scene.surfaces[0].clip));
    EXPECT_EQ(std::get<ClipSphere>(scene.surfaces[0].clip).radius, 2.0);
}

TEST(SceneFile, ReadsEverySection) {
    const Scene scene = parse_scene(R"(
[image]
width = 320
height = 200
background = [1, 1, 1]
[camera]
eye = [0, 0, 6]
target = [0, 0, 0]
up = [0, 1, 0]
fov = 30
[[light]]
type = "point"
position = [2, 3, 4]
radius = 0.2
[[surface]]
equation = "x^2+y^2-z^2-1"
clip = "box"
clip_min = [-2, -2, -1]
clip_max = [2, 2, 1]
[surface.material]
color = [1, 0, 0]
shininess = 10
[render]
method = "bernstein"
samples = 3
shadows = false
ambient_occlusion = true
threads = 2
)");
    EXPECT_EQ(scene.width, 320);
    EXPECT_EQ(scene.height, 200);
    ASSERT_TRUE(scene.camera.has_value());
    EXPECT_EQ(scene.camera->fov_degrees, 30.0);
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.lights[0].kind, Light::Kind::point);
    EXPECT_EQ(scene.lights[0].radius, 0.2);
    ASSERT_TRUE(std::holds_alternative<ClipBox>(scene.surfaces[0].clip));
    EXPECT_EQ(std::get<ClipBox>(scene.surfaces[0].clip).max.z, 1.0);
    EXPECT_EQ(scene.surfaces[0].material.color, Vec3(1, 0, 0));
    EXPECT_EQ(scene.surfaces[0].material.inside, Vec3(1, 0, 0));  // one colour given: one colour
    EXPECT_TRUE(scene.notes.empty());
    EXPECT_EQ(scene.surfaces[0].material.shininess, 10.0);
    EXPECT_EQ(scene.options.method, TraceMethod::bernstein);
    EXPECT_EQ(scene.options.samples, 3);
    EXPECT_FALSE(scene.options.shadows);
    EXPECT_TRUE(scene.options.ambient_occlusion);
    EXPECT_EQ(scene.options.threads, 2);
}

// Both scene forms read their materials through one set of keys with one set of defaults:
// a [[surface]] material and a named [materials.NAME] accept the same keys, `outside` (the old
// [[surface]] name of `color`) is still read with a note, and a checker works in both.
TEST(SceneFile, MaterialsShareOneVocabulary) {
    const Scene old_key = parse_scene(
        "[[surface]]\nequation = \"x^2+y^2+z^2-1\"\n[surface.material]\noutside = [1, 0, 0]\n");
    EXPECT_EQ(old_key.surfaces[0].material.color, Vec3(1, 0, 0));
    EXPECT_EQ(old_key.surfaces[0].material.inside, Material{}.inside);  // its old meaning
    ASSERT_EQ(old_key.notes.size(), 1u);
    EXPECT_EQ(old_key.notes[0],
              "line 4, column 11: surface[1].material.outside: deprecated, read "
              "as 'color' (the name in every scene form)");
    EXPECT_EQ(error_of("[[surface]]\nequation = \"x\"\n[surface.material]\ncolor = [1, 0, "
                       "0]\noutside = [0, 1, 0]\n"),
              "line 5, column 11: surface[1].material.outside: 'outside' is the old name of "
              "'color'; give only 'color'");

    // Without colours, a material keeps the two-sided default; `inside` alone keeps `color`.
    const Scene surface = parse_scene(
        "[[surface]]\nequation = \"x^2+y^2+z^2-1\"\n"
        "[surface.material]\ninside = [0, 0, 1]\nchecker = [0, 1, "
        "0]\nchecker_size = 0.5\n");
    const Material& m = surface.surfaces[0].material;
    EXPECT_EQ(m.color, Material{}.color);
    EXPECT_EQ(m.inside, Vec3(0, 0, 1));
    ASSERT_TRUE(m.checker.has_value());
    EXPECT_EQ(m.at({0.25, 0.25, 0.25}).color, Material{}.color);
    EXPECT_EQ(m.at({0.75, 0.25, 0.25}).color, Vec3(0, 1, 0));
    EXPECT_EQ(m.at({0.75, 0.25, 0.25}).inside, Vec3(0, 1, 0));
    EXPECT_FALSE(m.at({0.75, 0.25, 0.25}).checker.has_value());

    // The same keys in a named material of a scene tree, which starts, like a primitive
    // without a material, light grey on both sides.
    const Scene tree = parse_scene(R"(
[materials.red]
outside = [1, 0, 0]
specular = 0.5
[materials.shiny]
specular = 0.9
[[object]]
type = "sphere"
material = "red"
[[object]]
type = "sphere"
material = "shiny"
translate = [3, 0, 0]
[[object]]
type = "box"
translate = [-3, 0, 0]
)");
    ASSERT_EQ(tree.objects.size(), 3u);
    ASSERT_EQ(tree.notes.size(), 1u);
    EXPECT_NE(tree.notes[0].find("materials.red.outside: deprecated"), std::string::npos);
    const Material red = tree.objects[0]->material_at({0, 0.9, 0}, {});
    const Vec3 grey(0.75, 0.75, 0.78);
    EXPECT_EQ(red.color, Vec3(1, 0, 0));
    EXPECT_EQ(red.inside, grey);
    EXPECT_EQ(red.specular, 0.5);
    const Material shiny = tree.objects[1]->material_at({3, 0.9, 0}, {});
    EXPECT_EQ(shiny.color, grey);
    EXPECT_EQ(shiny.inside, grey);
    EXPECT_EQ(shiny.specular, 0.9);
    EXPECT_EQ(tree.objects[2]->material_at({-3, 0.9, 0}, {}).color, grey);
}

TEST(SceneFile, ACameraPathStartsAtTheCameraAndKeepsWhatAKeyLeavesOut) {
    const Scene scene = parse_scene(R"(
[camera]
eye = [0, 0, 5]
fov = 30
frames = 24
[[camera.key]]
eye = [5, 0, 0]
[[camera.key]]
target = [0, 1, 0]
fov = 20
[[surface]]
equation = "x^2+y^2+z^2-1"
)");
    ASSERT_TRUE(scene.camera_path.has_value());
    const CameraPath& path = *scene.camera_path;
    EXPECT_EQ(path.frames, 24);
    ASSERT_EQ(path.keys.size(), 3u);
    EXPECT_EQ(path.keys[0].eye, Vec3(0, 0, 5));
    EXPECT_EQ(path.keys[1].eye, Vec3(5, 0, 0));
    EXPECT_EQ(path.keys[1].fov_degrees, 30.0);
    EXPECT_EQ(path.keys[2].eye, Vec3(5, 0, 0));
    EXPECT_EQ(path.keys[2].target, Vec3(0, 1, 0));
    EXPECT_EQ(path.keys[2].fov_degrees, 20.0);
    EXPECT_EQ(error_of("[camera]\nframes = 5\n[[surface]]\nequation = \"x\"\n"),
              "line 2, column 10: camera.frames: a camera path needs both `frames` and "
              "[[camera.key]] tables");
    EXPECT_EQ(error_of("[camera]\nframes = 1\n[[camera.key]]\neye = [1, 0, 0]\n[[surface]]\n"
                       "equation = \"x\"\n"),
              "line 2, column 10: camera.frames: expected an integer from 2 to 100000, found 1");
    EXPECT_EQ(error_of("[camera]\nframes = 3\n[[camera.key]]\neye = [0, 0, 0]\n[[surface]]\n"
                       "equation = \"x\"\n"),
              "line 4, column 7: camera.key[1].eye: the eye must differ from the target");
}

TEST(SceneFile, BadScenesNameTheKeyAndThePosition) {
    EXPECT_EQ(error_of("[[surface]]\nequation = \"x\"\ncolour = 3\n"),
              "line 3, column 1: surface[1].colour: unknown key");
    EXPECT_EQ(error_of("[[surface]]\nequation = \"x\"\nclip_radius = -2\n"),
              "line 3, column 15: surface[1].clip_radius: expected a positive number, found -2");
    EXPECT_EQ(error_of("[image]\nwidth = \"wide\"\n[[surface]]\nequation = \"x\"\n"),
              "line 2, column 9: image.width: expected an integer from 1 to 16384, found "
              "\"wide\"");
    EXPECT_EQ(error_of("[camera]\neye = [1, 2]\n[[surface]]\nequation = \"x\"\n"),
              "line 2, column 7: camera.eye: expected an array of three numbers, found an array "
              "of 2");
    EXPECT_EQ(
        error_of("[render]\nmethod = \"magic\"\n[[surface]]\nequation = \"x\"\n"),
        "method 'magic': unknown method; expected one of certified, sturm, bernstein, laguerre, "
        "eigen, "
        "sphere-gradient, sphere-lipschitz, exact");
    // A float where an integer belongs: refused without converting it (3e21 overflowed the
    // conversion to an integer, undefined behaviour the scene fuzzer found).
    EXPECT_EQ(error_of("[image]\nwidth = 3e21\n[[surface]]\nequation = \"x\"\n"),
              "line 2, column 9: image.width: expected an integer from 1 to 16384, found 3e+21");
    EXPECT_EQ(error_of("[[object]]\ntype = \"sphere\"\nrepeat = [2, 0, 0]\nrepeat_count = "
                       "[1e300, 0, 0]\n"),
              "line 4, column 16: object[1].repeat_count: expected three integers ≥ 0 (copies "
              "each side), found an array of 3");
    EXPECT_EQ(error_of("[image]\nwidth = 10\n"),
              "surface: a scene needs at least one [[surface]] or [[object]]");
    EXPECT_EQ(error_of("[[surface]]\nequation = \"x\"\nparam = \"a.param\"\n"),
              "line 1, column 1: surface[1]: give exactly one of 'equation' and 'param'");
    EXPECT_EQ(error_of("[[surface]]\nequation = \" \"\n"),
              "line 2, column 12: surface[1].equation: expected an equation, found \" \"");
    EXPECT_EQ(error_of("[[surface]]\nequation = \"x\"\nclip = \"cone\"\n"),
              "line 3, column 8: surface[1].clip: expected \"sphere\" or \"box\", found \"cone\"");
    EXPECT_EQ(error_of("[image\nwidth = 3\n"),
              "line 1, column 7: expected valid TOML, found Error while parsing table header: "
              "expected ']', saw '\\n'");
}

// A light's direction is normalized at any scale: [1e300, 1e300, 0] was normalized to the zero
// vector (its length overflowed), a picture without its key light.
TEST(SceneFile, LightDirectionsAreNormalizedAtAnyScale) {
    const auto direction_of = [](const std::string& direction) {
        const Scene scene = parse_scene(
            "[[surface]]\nequation = \"x^2+y^2+z^2-1\"\n[[light]]\ndirection = " + direction +
            "\n");
        return scene.lights.at(0).direction;
    };
    const Vec3 diagonal = direction_of("[1e300, 1e300, 0]");
    EXPECT_NEAR(diagonal.x, std::sqrt(0.5), 1e-15);
    EXPECT_NEAR(diagonal.y, std::sqrt(0.5), 1e-15);
    EXPECT_EQ(diagonal.z, 0.0);
    EXPECT_EQ(direction_of("[1e-320, 0, 0]"), Vec3(1.0, 0.0, 0.0));
    EXPECT_EQ(direction_of("[0, -3, 0]"), Vec3(0.0, -1.0, 0.0));
    EXPECT_THROW(direction_of("[0, 0, 0]"), InputError);
    EXPECT_THROW(direction_of("[inf, 0, 0]"), InputError);
}

TEST(Camera, DegenerateCamerasAreRejected) {
    EXPECT_THROW(Camera({{0, 0, 0}, {0, 0, 0}, {0, 1, 0}, 35}, 10, 10), InputError);
    EXPECT_THROW(Camera({{0, 5, 0}, {0, 0, 0}, {0, 1, 0}, 35}, 10, 10), InputError);
    EXPECT_THROW(Camera({{0, 0, 5}, {0, 0, 0}, {0, 0, 0}, 35}, 10, 10), InputError);
    EXPECT_THROW(Camera({{0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 180}, 10, 10), InputError);
    EXPECT_THROW(Camera({{0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 0}, 10, 10), InputError);
    try {
        Camera({{1, 2, 3}, {1, 2, 3}, {0, 1, 0}, 35}, 10, 10);
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "camera.eye (1, 2, 3): the eye must differ from the target (1, 2, 3), both "
                  "finite");
    }
    EXPECT_THROW(Camera({{INFINITY, 0, 5}, {0, 0, 0}, {0, 1, 0}, 35}, 10, 10), InputError);
    EXPECT_THROW(Camera({{0, 0, 5}, {0, 0, 0}, {0, NAN, 0}, 35}, 10, 10), InputError);
}

// Far from the unit scale a camera is still a camera: squaring the view (as glm::length does)
// overflowed past 1e154 and underflowed below 1e-154, and an eye at 1e-300 from its target was
// refused as "the eye must differ from the target (0.000000, …)".
TEST(Camera, FarScalesKeepTheirDirections) {
    for (const double scale : {1e-300, 1e-200, 1.0, 1e200, 1e300}) {
        const Camera camera({{0, 0, 5 * scale}, {0, 0, 0}, {0, scale, 0}, 35}, 11, 11);
        const Ray centre = camera.ray(5.5, 5.5);  // the middle of the middle pixel
        const Vec3 d =
            centre.direction / std::max({std::abs(centre.direction.x), std::abs(centre.direction.y),
                                         std::abs(centre.direction.z)});
        EXPECT_NEAR(d.z, -1.0, 1e-12) << scale;
        EXPECT_NEAR(d.x, 0.0, 1e-12) << scale;
        EXPECT_NEAR(d.y, 0.0, 1e-12) << scale;
    }
}

}  // namespace
}  // namespace locus::render
