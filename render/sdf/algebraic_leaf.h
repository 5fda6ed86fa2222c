// An algebraic surface f(x, y, z) = 0 inside its clip region as a leaf of an SDF scene.
//
// Along a ray it keeps its exact root finders (render/surface_tracer.h): traces_exactly() is
// true, so a union of algebraic surfaces and primitives is traced as the nearest of exact hits
// and sphere-traced hits (render/sdf/scene_tracer.h). Only where a blend, boolean or
// deformation needs a field value does it fall back to max(clip distance, f/|∇f|): a
// first-order estimate (DistanceKind::estimate), which the tracer protects by bisecting back
// over sign changes; a tangent touch between two samples can still be missed there.
#pragma once

#include <memory>

#include "algebra/compiled.h"
#include "render/clip_region.h"
#include "render/scene.h"
#include "render/sdf/node.h"

namespace locus::render::sdf {

NodePtr make_algebraic(std::shared_ptr<const algebra::CompiledPolynomial> f, const ClipRegion& clip,
                       MaterialPtr material, TraceMethod method);

// The signed distance to the clip region (exact for a sphere and a box).
double clip_distance(const ClipRegion& clip, const Vec3& p);

}  // namespace locus::render::sdf
