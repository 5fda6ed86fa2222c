// PNG (render/detail/png_encoder.h) and binary PPM written without OpenImageIO: 8-bit RGB only, the
// format of every colour image locus renders. Loading the OpenImageIO module costs 0.2 s per
// process on Debian 12 (262 shared libraries), several times a 512² frame; these two formats need
// none of it.
#pragma once

#include <string>

#include "render/detail/png_encoder.h"

namespace locus::render::detail {

// The extension of `path` in lower case, with its dot (".png"; "" when there is none): what
// picks an image format.
std::string lowercase_extension(const std::string& path);

// True for the extensions this writer handles (".png", ".ppm", ".pnm", any case).
bool is_plain_image_format(const std::string& path);

// Writes a width×height image of 8-bit RGB rows (asked of `row`, in parallel) to `path` in the
// format its extension names. Returns an empty string on success, otherwise what went wrong
// (the file may then be incomplete: the caller writes to a temporary name).
std::string write_plain_image(const std::string& path, int width, int height,
                              const RgbRowSource& row);

}  // namespace locus::render::detail
