// Framing a scene on what it shows: clip spheres fitted to the surfaces' extents (the default
// for a surface given without clip keys, and `locus render --fit`), and the reason a picture
// came out empty.
#pragma once

#include <chrono>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "algebra/compiled.h"
#include "render/scene.h"
#include "render/surface_extent.h"

namespace locus::render {

// Gives every surface with `fit_clip` set (or every surface when `force`) the clip sphere
// fitted to its extent when that is bounded, and leaves the others as they are (a surface that
// is not bounded keeps ClipSphere{}, the documented default). Returns the extents estimated,
// one per surface (nothing where none was needed). Precondition: one compiled polynomial per
// surface. Throws Timeout when `deadline` passes.
std::vector<std::optional<SurfaceExtent>> fit_clip_regions(
    Scene& scene, std::span<const algebra::CompiledPolynomial> surfaces, bool force,
    std::optional<std::chrono::steady_clock::time_point> deadline = {});

// Why a picture of a surface is empty, in words, and what would help — as a kind, so that each
// front end names its own way to do it (the CLI its flags; the library names none).
struct EmptyPictureReason {
    enum class Remedy {
        none,                // behind the camera, outside the field of view: move the camera
        clip_region,         // nothing found near the origin: give a clip region around the surface
        larger_clip_region,  // the surface lies beyond its clip region: enlarge or move it
        fit,                 // points found outside the clip region: frame the surface's extent
        finer_sampling,      // met nowhere though inside and in view: more samples, a closer camera
    };
    std::string text;
    Remedy remedy = Remedy::none;
};

// Why no primary ray met `surface` through `camera`: no point of the surface was found at all,
// or none inside its clip region (box_in_region), or the part inside lies behind the camera or
// outside its field of view; otherwise that it is too thin or small for the pixel grid.
// `extent` is the surface's, estimated here when not given. Throws Timeout when `deadline`
// passes.
EmptyPictureReason why_not_hit(const Surface& surface, const algebra::CompiledPolynomial& f,
                               const CameraSpec& camera, int width, int height,
                               std::optional<SurfaceExtent> extent = {},
                               std::optional<std::chrono::steady_clock::time_point> deadline = {});

}  // namespace locus::render
