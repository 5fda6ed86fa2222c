// The primary rays of an image traced without shading: one ray through each pixel centre, first
// hit by a TraceMethod, exactly as the renderer finds it (per-frame RayFamily restriction, the
// same SurfaceTracer). This is what `locus-bench render` times and compares with `exact`.
#pragma once

#include <vector>

#include "render/camera.h"
#include "render/clip_region.h"
#include "render/surface_tracer.h"

namespace locus::render {

struct PrimaryRays {
    std::vector<RootResult> hits;     // row-major, one per pixel
    std::vector<double> ray_lengths;  // |d| per pixel, to turn t into a distance
    double seconds = 0.0;             // wall time, family expansion included
};

// `tolerance_factor` scales the sphere-tracing tolerances (1e-7 and 1e-9 × clip radius by
// default; the benchmark's tolerance settings); the root finders ignore it.
PrimaryRays trace_primary_rays(const algebra::CompiledPolynomial& f, const ClipRegion& region,
                               const Camera& camera, int width, int height, TraceMethod method,
                               int threads, double tolerance_factor = 1.0);

}  // namespace locus::render
