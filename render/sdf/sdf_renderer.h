// Rendering a scene with an SDF tree (Scene::objects): primary rays through the SceneTracer,
// Blinn–Phong shading with the materials of the nodes (mixed across smooth blends), hard or soft
// shadows (a light's radius sets the penumbra of sphere-traced occluders; exactly traced
// surfaces cast hard shadows), ambient occlusion from the field along the normal (Quilez),
// k×k supersampling, rows over oneTBB.
#pragma once

#include <span>

#include "render/renderer.h"
#include "render/sdf/scene_tracer.h"

namespace locus::render {

// Precondition: one compiled polynomial per scene surface, in order (they become exactly
// traced leaves beside the objects). RenderStats::primary_work counts primitive evaluations
// of primary rays plus root-finder work.
RenderedImage render_sdf_scene(const Scene& scene,
                               std::span<const algebra::CompiledPolynomial> surfaces,
                               const ExecutionSettings& execution, RenderStats* stats = nullptr,
                               sdf::SpeedUps speed_ups = {});

// The top-level items of a scene as the SDF renderer traces them: the objects, then the
// surfaces as algebraic leaves.
std::vector<sdf::NodePtr> scene_items(const Scene& scene,
                                      std::span<const algebra::CompiledPolynomial> surfaces);

}  // namespace locus::render
