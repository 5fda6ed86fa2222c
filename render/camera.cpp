#include "render/camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "algebra/error.h"

namespace locus::render {

Camera::Camera(const CameraSpec& spec, int width, int height) : eye_(spec.eye) {
    if (!(spec.fov_degrees > 0.0 && spec.fov_degrees < 180.0)) {
        throw InputError("camera.fov " + std::to_string(spec.fov_degrees),
                         "the vertical field of view must lie strictly between 0 and 180 "
                         "degrees");
    }
    const Vec3 view = spec.target - spec.eye;
    forward_ = scaled_normalize(view);
    if (forward_ == Vec3(0.0)) {
        throw InputError("camera.eye " + format_point(spec.eye, 6),
                         "the eye must differ from the target " + format_point(spec.target, 6) +
                             ", both finite");
    }
    const Vec3 up = scaled_normalize(spec.up);
    const Vec3 side = glm::cross(forward_, up);
    if (!(glm::length(side) > 1e-9)) {  // also a zero or non-finite up
        throw InputError("camera.up " + format_point(spec.up, 6),
                         "the up vector must be non-zero and not parallel to the viewing "
                         "direction");
    }
    const Vec3 right = glm::normalize(side);
    const Vec3 true_up = glm::cross(right, forward_);
    const double half_height = std::tan(spec.fov_degrees * std::numbers::pi / 360.0);
    const double half_width = half_height * width / height;
    per_column_ = (2.0 * half_width / width) * right;
    per_row_ = (-2.0 * half_height / height) * true_up;
    base_ = forward_ - half_width * right + half_height * true_up;
}

Camera Camera::in_frame(const SurfaceFrame& frame) const {
    Camera local = *this;
    const double inverse = 1.0 / frame.scale;
    local.eye_ = (eye_ - frame.origin) * inverse;
    local.base_ = base_ * inverse;
    local.per_column_ = per_column_ * inverse;
    local.per_row_ = per_row_ * inverse;
    // Scaled so that d·forward stays 1 for every ray direction d (the ray families' premise).
    local.forward_ = forward_ * frame.scale;
    return local;
}

}  // namespace locus::render
