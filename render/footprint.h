// A pixel sample's extent on the surface it hits, for filtering surface patterns (the checker)
// by what the sample covers instead of point-sampling them: point samples of a checker alias
// into moiré toward the horizon of a floor. This is pbrt's ray differentials, for a pinhole
// camera whose ray directions are affine in the image coordinates (render/camera.h).
#pragma once

#include "render/vec3.h"

namespace locus::render {

// The offsets from a hit to where the neighbouring samples' rays meet the tangent plane there.
// Zero offsets (the default) ask for a point sample.
struct Footprint {
    Vec3 dx{0.0};
    Vec3 dy{0.0};
};

// A sample's ray direction (unnormalised, as Camera::direction gives it) and the changes of it
// to the next sample across and down: the camera's per-column and per-row steps divided by the
// samples per pixel side.
struct SampleDirections {
    Vec3 direction;
    Vec3 step_x;
    Vec3 step_y;
};

// The footprint at `point` (unit `normal`) of the sample whose ray leaves `eye`. A neighbouring
// ray that meets the tangent plane farther than `limit` away, or not at all (grazing hits near
// the horizon), is given an offset of length `limit` along the plane: far more than any pattern
// cell, so that the pattern averages out there.
inline Footprint surface_footprint(const Vec3& eye, const SampleDirections& sample,
                                   const Vec3& point, const Vec3& normal, double limit) {
    const double height = glm::dot(normal, point - eye);
    const auto offset = [&](const Vec3& step) {
        const Vec3 neighbour = sample.direction + step;
        const double t = height / glm::dot(normal, neighbour);
        Vec3 to_neighbour = eye + t * neighbour - point;
        const double length = glm::length(to_neighbour);
        if (t > 0.0 && length <= limit) {
            return to_neighbour;
        }
        const Vec3 along_plane = neighbour - glm::dot(neighbour, normal) * normal;
        const double along_length = glm::length(along_plane);
        return along_length > 0.0 ? (limit / along_length) * along_plane : Vec3(0.0);
    };
    return {offset(sample.step_x), offset(sample.step_y)};
}

}  // namespace locus::render
