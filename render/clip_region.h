// The region of space in which a surface is drawn: a sphere or an axis-aligned box. A ray meets
// a surface only inside its clip region, which also bounds the root finders' search interval.
#pragma once

#include <variant>

#include "render/vec3.h"

namespace locus::render {

struct ClipSphere {
    Vec3 center{0.0, 0.0, 0.0};
    double radius = 2.0;
};

struct ClipBox {
    Vec3 min{-1.0, -1.0, -1.0};
    Vec3 max{1.0, 1.0, 1.0};
};

using ClipRegion = std::variant<ClipSphere, ClipBox>;

// The parameters t of `ray` inside the region, intersected with `limits`; empty if none.
Interval clip(const ClipRegion& region, const Ray& ray, Interval limits);

// Centre and radius of a sphere containing the region (camera framing, scale of tolerances).
ClipSphere bounding_sphere(const ClipRegion& region);

}  // namespace locus::render
