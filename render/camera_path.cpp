#include "render/camera_path.h"

#include <algorithm>
#include <cmath>

namespace locus::render {

namespace {

// The uniform Catmull–Rom segment from p1 to p2 at u in [0, 1].
Vec3 catmull_rom(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3, double u) {
    const double u2 = u * u, u3 = u2 * u;
    return 0.5 * ((2.0 * p1) + (p2 - p0) * u + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * u2 +
                  (3.0 * p1 - p0 - 3.0 * p2 + p3) * u3);
}

}  // namespace

CameraSpec camera_on_path(const CameraPath& path, int k) {
    const int last_key = static_cast<int>(path.keys.size()) - 1;
    const double s = path.frames > 1 ? static_cast<double>(k) / (path.frames - 1) * last_key : 0.0;
    const int i = std::clamp(static_cast<int>(std::floor(s)), 0, std::max(last_key - 1, 0));
    const double u = std::clamp(s - i, 0.0, 1.0);
    const auto key = [&](int j) -> const CameraSpec& {
        return path.keys[static_cast<std::size_t>(std::clamp(j, 0, last_key))];
    };
    const CameraSpec& a = key(i);
    const CameraSpec& b = key(i + 1);
    CameraSpec camera;
    camera.eye = catmull_rom(key(i - 1).eye, a.eye, b.eye, key(i + 2).eye, u);
    camera.target = catmull_rom(key(i - 1).target, a.target, b.target, key(i + 2).target, u);
    camera.up = a.up + u * (b.up - a.up);
    camera.fov_degrees = a.fov_degrees + u * (b.fov_degrees - a.fov_degrees);
    return camera;
}

}  // namespace locus::render
