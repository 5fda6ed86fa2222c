// Scene files: defaults, every key read, and each bad scene rejected with a message that names
// the key, its position and what was expected.
#include "render/scene_file.h"

#include <gtest/gtest.h>

#include "algebra/error.h"
#include "render/camera.h"

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
outside = [1, 0, 0]
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
    EXPECT_EQ(scene.surfaces[0].material.outside, Vec3(1, 0, 0));
    EXPECT_EQ(scene.surfaces[0].material.shininess, 10.0);
    EXPECT_EQ(scene.options.method, TraceMethod::bernstein);
    EXPECT_EQ(scene.options.samples, 3);
    EXPECT_FALSE(scene.options.shadows);
    EXPECT_TRUE(scene.options.ambient_occlusion);
    EXPECT_EQ(scene.options.threads, 2);
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
    EXPECT_EQ(error_of("[image]\nwidth = 10\n"),
              "surface: a scene needs at least one [[surface]] or [[object]]");
    EXPECT_EQ(error_of("[[surface]]\nequation = \"x\"\nparam = \"a.param\"\n"),
              "line 1, column 1: surface[1]: give exactly one of 'equation' and 'param'");
    EXPECT_EQ(error_of("[[surface]]\nequation = \"x\"\nclip = \"cone\"\n"),
              "line 3, column 8: surface[1].clip: expected \"sphere\" or \"box\", found \"cone\"");
    EXPECT_EQ(error_of("[image\nwidth = 3\n"),
              "line 1, column 7: expected valid TOML, found Error while parsing table header: "
              "expected ']', saw '\\n'");
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
                  "camera.eye (1.000000, 2.000000, 3.000000): the eye must differ from the "
                  "target (1.000000, 2.000000, 3.000000)");
    }
}

}  // namespace
}  // namespace locus::render
