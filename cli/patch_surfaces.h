// Bézier patches as render surfaces (`locus render teapot.bpt`, `--param` with a `bezier:`
// file): each patch's implicit equation (implicitize --method auto, proved on the patch's map),
// clipped to the box of its control points — a patch with positive weights lies in their
// convex hull, so a ray solves only the patches whose boxes it meets — and trimmed to the
// patch's domain (render/patch_trim.h), so that the sheets of the implicit surface beyond the
// patch are not drawn.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "algebra/polynomial.h"

#include "cli/process_limits.h"
#include "render/scene.h"

namespace locus::cli {

// A frame centred on `box` and scaled to it (a power of two), and f written in it: g(x') =
// f(origin + scale·x') exactly, divided by its (positive) content, so that g keeps f's sides
// (render/surface_frame.h says why). Patches are rendered in their
// own frame, and so are equations whose clip region lies far from the origin.
std::pair<render::SurfaceFrame, algebra::Polynomial> framed(const algebra::Polynomial& f,
                                                            const render::ClipBox& box);

// Does the file hold patches (a .bpt file, or a .param file with a `bezier:` line)?
bool holds_patches(const std::string& path, const std::string& text);

// The surfaces of the patches in `text` (read from `path`); reports on standard error how many
// were implicitized by which route. Throws CommandFailure (exit 2 for bad input, 4 when a proof
// fails) and Timeout.
std::vector<render::Surface> patch_surfaces(const std::string& path, const std::string& text,
                                            Deadline deadline);

// For a parametrization file with a `domain:` line: `surface` (which renders the file's implicit
// equation) is trimmed to the image of that box and clipped to a box about it. Nothing changes
// without a domain.
void trim_to_domain(const std::string& path, const std::string& text, render::Surface& surface);

}  // namespace locus::cli
