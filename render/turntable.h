// Cameras for an animation that pays start-up once: `locus render --turntable N` renders N
// frames with the camera carried around the up axis through the target, and writes them as
// numbered files.
#pragma once

#include <string>

#include "render/camera.h"

namespace locus::render {

// `base` turned by `angle_radians` about the line through base.target along base.up
// (right-handed: positive angles turn counter-clockwise seen from above). The target, the up
// direction and the field of view stay; the eye keeps its height and its distance to the axis.
CameraSpec orbit_camera(const CameraSpec& base, double angle_radians);

// The k-th camera of `frames` evenly spaced around a full turn (k = 0 is `base`).
CameraSpec turntable_camera(const CameraSpec& base, int k, int frames);

// "out/name.png" → "out/name_0007.png" for frame 7 (1-based; at least four digits, more when
// `frames` needs them, so that the files sort in frame order).
std::string frame_path(const std::string& path, int frame, int frames);

}  // namespace locus::render
