#include "render/turntable.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

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
