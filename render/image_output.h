// Writing rendered images with OpenImageIO. The colour image goes to `path` in the format its
// extension names: 8-bit sRGB for PNG/JPEG/TIFF and the like, linear half floats for EXR.
// Requested AOVs go beside it as EXR files named <stem>.<aov>.exr (depth: one channel, the
// distance from the eye, +inf on a miss; normal: three channels; work: one channel).
#pragma once

#include <string>
#include <vector>

#include "render/renderer.h"

namespace locus::render {

enum class Aov { depth, normal, work };

// "depth", "normal", "work"; anything else is an InputError.
Aov parse_aov(const std::string& name);

// Throws locus::Error with OpenImageIO's message when a file cannot be written. Returns the
// paths written, the colour image first.
std::vector<std::string> write_image(const RenderedImage& image, const std::string& path,
                                     const std::vector<Aov>& aovs = {});

}  // namespace locus::render
