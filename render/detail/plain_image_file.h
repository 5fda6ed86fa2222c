// PNG and binary PPM written without OpenImageIO: 8-bit RGB only, the format of every colour
// image locus renders. Loading the OpenImageIO module costs 0.2 s per process on Debian 12
// (262 shared libraries), several times a 512² frame; these two formats need none of it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace locus::render::detail {

// The extension of `path` in lower case, with its dot (".png"; "" when there is none): what
// picks an image format.
std::string lowercase_extension(const std::string& path);

// True for the extensions this writer handles (".png", ".ppm", ".pnm", any case).
bool is_plain_image_format(const std::string& path);

// Writes width×height interleaved 8-bit RGB pixels (rows top to bottom) to `path` in the
// format its extension names. Returns an empty string on success, otherwise what went wrong
// (the file may then be incomplete: the caller writes to a temporary name).
std::string write_plain_image(const std::string& path, int width, int height,
                              const std::uint8_t* rgb);

// The same PNG in memory (for `locus view`, which sends frames over HTTP); nothing when libspng
// fails.
std::optional<std::string> encode_png(int width, int height, const std::uint8_t* rgb);

}  // namespace locus::render::detail
