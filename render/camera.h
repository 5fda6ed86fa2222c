// A pinhole camera (DESIGN.md: eye, target, up, vertical field of view in degrees; right-handed
// world, +y up). Pixel (x, y) has its top-left corner at (x, y) in continuous image coordinates,
// so a pixel centre is (x + 0.5, y + 0.5).
//
// The primary ray through image point (x, y) is eye + t·d with the unnormalised direction
//     d(x, y) = base + x·per_column + y·per_row,
// affine in the image coordinates. The renderer relies on this to expand the ray family once
// per frame (render/ray_family.h).
#pragma once

#include "render/surface_frame.h"
#include "render/vec3.h"

namespace locus::render {

struct CameraSpec {
    Vec3 eye{0.0, 0.0, 5.0};
    Vec3 target{0.0, 0.0, 0.0};
    Vec3 up{0.0, 1.0, 0.0};
    double fov_degrees = 35.0;
};

class Camera {
  public:
    // Throws InputError naming the offending value when eye == target, up is parallel to the
    // viewing direction or zero, or the field of view is not in (0, 180) degrees.
    Camera(const CameraSpec& spec, int width, int height);

    const Vec3& eye() const { return eye_; }
    Vec3 direction(double x, double y) const { return base_ + x * per_column_ + y * per_row_; }
    Ray ray(double x, double y) const { return {eye_, direction(x, y)}; }
    const Vec3& base() const { return base_; }
    const Vec3& per_column() const { return per_column_; }
    const Vec3& per_row() const { return per_row_; }
    // The viewing direction w, with d·w = 1 for every ray direction d (unit length in the
    // world's coordinates).
    const Vec3& forward() const { return forward_; }
    // The camera in a surface's frame: its rays are exactly frame.to_local(ray(x, y)) (the
    // scale is a power of two, so dividing the direction's terms by it commutes with rounding).
    Camera in_frame(const SurfaceFrame& frame) const;

  private:
    Vec3 eye_, forward_, base_, per_column_, per_row_;
};

}  // namespace locus::render
