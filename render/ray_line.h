// One line of `locus trace` input (DESIGN.md): `ox oy oz dx dy dz`, six finite decimal numbers
// separated by spaces or tabs, the direction not zero. Blank lines carry no ray.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

#include "render/vec3.h"

namespace locus::render {

// The ray on `text` (which holds no newline), or nothing for a blank line. Throws ParseError
// naming `line` and the column of the first character that does not fit.
std::optional<Ray> parse_ray_line(std::string_view text, std::size_t line);

}  // namespace locus::render
