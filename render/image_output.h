// Writing rendered images: PNG and PPM directly (ISA-L, in parallel), every other format with
// OpenImageIO, loaded only then. The colour image goes to `path` in the format its
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

// Throws InputError unless `path` names a known image format (by its extension) in an existing,
// writable folder: checked before rendering, so that a bad -o costs nothing.
void check_image_path(const std::string& path);

// Where an image is written before it is complete: ".locus-partial.NAME" beside it.
std::string partial_path(const std::string& path);

// Loads what the writer of `path`'s format loads on first use (for PNG, ISA-L), for a thread
// with nothing else to do before a frame (`locus render` calls it while it reads the scene).
void prepare_image_writer(const std::string& path);

// Throws ResourceLimit with the writer's message when a file cannot be written (nothing is
// left under its name). Returns the paths written, the colour image first.
std::vector<std::string> write_image(const RenderedImage& image, const std::string& path,
                                     const std::vector<Aov>& aovs = {});

// The colour of `image` as an 8-bit sRGB PNG in memory (for frames sent over HTTP).
std::string png_bytes(const RenderedImage& image);

}  // namespace locus::render
