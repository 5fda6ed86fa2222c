#include "render/turntable.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>

namespace locus::render {

CameraSpec orbit_camera(const CameraSpec& base, double angle_radians) {
    // Rodrigues' rotation of the eye about the axis through the target.
    const Vec3 axis = glm::normalize(base.up);
    const Vec3 offset = base.eye - base.target;
    const double c = std::cos(angle_radians);
    const double s = std::sin(angle_radians);
    const Vec3 turned =
        offset * c + glm::cross(axis, offset) * s + axis * glm::dot(axis, offset) * (1.0 - c);
    CameraSpec camera = base;
    camera.eye = base.target + turned;
    return camera;
}

CameraSpec turntable_camera(const CameraSpec& base, int k, int frames) {
    return orbit_camera(
        base, 2.0 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(frames));
}

std::string frame_path(const std::string& path, int frame, int frames) {
    const std::filesystem::path p(path);
    const int digits = std::max(4, static_cast<int>(std::to_string(frames).size()));
    char number[16];
    std::snprintf(number, sizeof number, "%0*d", digits, frame);
    return (p.parent_path() /
            (p.stem().string() + "_" + std::string(number) + p.extension().string()))
        .string();
}

}  // namespace locus::render
