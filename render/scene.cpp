#include "render/scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "algebra/error.h"

namespace locus::render {

std::vector<Light> default_lights() {
    Light key;
    key.direction = glm::normalize(Vec3{-0.5, 0.8, 0.7});
    key.color = {1.0, 0.97, 0.92};
    key.intensity = 0.85;
    Light fill;
    fill.direction = glm::normalize(Vec3{0.8, 0.1, 0.4});
    fill.color = {0.75, 0.82, 1.0};
    fill.intensity = 0.35;
    return {key, fill};
}

CameraSpec default_camera(const Scene& scene) {
    Vec3 low{INFINITY}, high{-INFINITY};
    for (const Surface& surface : scene.surfaces) {
        const ClipSphere sphere = bounding_sphere(surface.clip);
        low = glm::min(low, sphere.center - Vec3(sphere.radius));
        high = glm::max(high, sphere.center + Vec3(sphere.radius));
    }
    for (const sdf::NodePtr& object : scene.objects) {
        if (object->bounds().is_finite()) {
            low = glm::min(low, object->bounds().min);
            high = glm::max(high, object->bounds().max);
        }
    }
    if (!(low.x <= high.x)) {
        low = Vec3(-2.0);
        high = Vec3(2.0);
    }
    const Vec3 center = (low + high) * 0.5;
    const double radius = scaled_length(high - low) * 0.5 / std::sqrt(3.0);
    CameraSpec camera;
    camera.target = center;
    const double half_fov = camera.fov_degrees * std::numbers::pi / 360.0;
    const double distance = 1.08 * radius / std::sin(half_fov);
    camera.eye = center + distance * glm::normalize(Vec3{0.55, 0.45, 1.0});
    const bool eye_finite =
        std::isfinite(camera.eye.x) && std::isfinite(camera.eye.y) && std::isfinite(camera.eye.z);
    if (!eye_finite || camera.eye == camera.target) {  // a NaN or infinite distance included
        const bool large = !(radius < 1.0);            // NaN: an extent that overflowed
        throw InputError("the scene's extent " + format_point(low) + " to " + format_point(high),
                         std::string("too ") + (large ? "large" : "small") +
                             " to place the default camera in double precision (give a camera, "
                             "or " +
                             (large ? "smaller" : "larger") + " clip regions)");
    }
    return camera;
}

}  // namespace locus::render
