#include "render/turntable.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "render/camera_path.h"

namespace locus::render {
namespace {

void expect_near(const Vec3& got, const Vec3& want) {
    EXPECT_NEAR(got.x, want.x, 1e-12);
    EXPECT_NEAR(got.y, want.y, 1e-12);
    EXPECT_NEAR(got.z, want.z, 1e-12);
}

TEST(Turntable, TheEyeTurnsAboutTheUpAxisThroughTheTarget) {
    CameraSpec base;
    base.eye = {1.0, 3.0, 6.0};
    base.target = {1.0, 1.0, 1.0};
    base.up = {0.0, 2.0, 0.0};  // not unit: only its direction counts
    base.fov_degrees = 40.0;
    // A quarter turn counter-clockwise seen from above: +z goes to +x (right-handed about +y).
    const CameraSpec quarter = orbit_camera(base, std::numbers::pi / 2);
    expect_near(quarter.eye, {6.0, 3.0, 1.0});
    expect_near(quarter.target, base.target);
    expect_near(quarter.up, base.up);
    EXPECT_EQ(quarter.fov_degrees, 40.0);
    // Height along the axis and distance from it are kept at every angle.
    for (int k = 0; k < 7; ++k) {
        const Vec3 eye = turntable_camera(base, k, 7).eye;
        EXPECT_NEAR(eye.y, 3.0, 1e-12);
        EXPECT_NEAR(std::hypot(eye.x - 1.0, eye.z - 1.0), 5.0, 1e-12);
    }
    expect_near(turntable_camera(base, 0, 7).eye, base.eye);
    expect_near(turntable_camera(base, 7, 7).eye, base.eye);
    // A tilted axis: the component of the offset along it is kept.
    CameraSpec tilted = base;
    tilted.target = {0.0, 0.0, 0.0};
    tilted.up = {1.0, 1.0, 0.0};
    tilted.eye = {1.0, 1.0, 0.0};  // on the axis: does not move
    expect_near(orbit_camera(tilted, 1.234).eye, tilted.eye);
}

TEST(Turntable, FramePathsSortInFrameOrder) {
    EXPECT_EQ(frame_path("out/name.png", 7, 36), "out/name_0007.png");
    EXPECT_EQ(frame_path("name.exr", 1, 1), "name_0001.exr");
    EXPECT_EQ(frame_path("a.b/c.d.png", 12, 20), "a.b/c.d_0012.png");
    EXPECT_EQ(frame_path("x.png", 42, 123456), "x_000042.png");
}

}  // namespace
}  // namespace locus::render

namespace locus::render {
namespace {

TEST(CameraPath, ItStartsAndEndsAtTheEndKeysAndPassesEveryKey) {
    CameraPath path;
    CameraSpec a, b, c;
    a.eye = {0.0, 0.0, 5.0};
    b.eye = {5.0, 1.0, 0.0};
    b.fov_degrees = 20.0;
    c.eye = {0.0, 2.0, -5.0};
    c.target = {1.0, 0.0, 0.0};
    path.keys = {a, b, c};
    path.frames = 81;  // keys at frames 0, 40 and 80
    for (const auto& [frame, key] : {std::pair{0, a}, std::pair{40, b}, std::pair{80, c}}) {
        const CameraSpec at = camera_on_path(path, frame);
        EXPECT_NEAR(glm::length(at.eye - key.eye), 0.0, 1e-12) << "frame " << frame;
        EXPECT_NEAR(glm::length(at.target - key.target), 0.0, 1e-12) << "frame " << frame;
        EXPECT_NEAR(at.fov_degrees, key.fov_degrees, 1e-12) << "frame " << frame;
    }
    // Between keys the field of view changes linearly and the eye moves smoothly: the step
    // from one frame to the next changes little across the key at frame 40 (the spline's
    // tangent is continuous there; with linear interpolation the change would be about 1.4
    // times the step, a 90° turn).
    EXPECT_NEAR(camera_on_path(path, 20).fov_degrees, 27.5, 1e-12);
    const Vec3 before = camera_on_path(path, 40).eye - camera_on_path(path, 39).eye;
    const Vec3 after = camera_on_path(path, 41).eye - camera_on_path(path, 40).eye;
    EXPECT_LT(glm::length(after - before), 0.25 * glm::length(before));
    // Two keys: the middle frame is halfway.
    path.keys = {a, b};
    path.frames = 3;
    EXPECT_NEAR(glm::length(camera_on_path(path, 1).eye - 0.5 * (a.eye + b.eye)), 0.0, 1e-12);
}

}  // namespace
}  // namespace locus::render
