// A camera moving through keys, for animations written from a scene file: [camera] is the first
// key, each [[camera.key]] the next, and `frames` frames run from the first key to the last
// (docs/rendering.md, "Animation"). The surfaces are compiled once for all frames.
#pragma once

#include <vector>

#include "render/camera.h"

namespace locus::render {

struct CameraPath {
    std::vector<CameraSpec> keys;  // at least two
    int frames = 2;                // at least two: the first and the last key
};

// The camera of frame k (0 ≤ k < frames). The keys are spread evenly over the frames; the eye
// and the target follow a uniform Catmull–Rom spline through the keys (the end keys repeated,
// so the path starts and stops at them), the up direction and the field of view change
// linearly between neighbouring keys.
CameraSpec camera_on_path(const CameraPath& path, int k);

}  // namespace locus::render
