// The material keys of scene files, one vocabulary for [[surface]] materials and the named
// [materials.NAME] of SDF scene trees (docs/rendering.md and docs/sdf-scenes.md):
//   color, inside, ambient, diffuse, specular, shininess, checker, checker_size
#pragma once

#include <string>
#include <vector>

#include "render/detail/toml_reader.h"
#include "render/material.h"

namespace locus::render::detail {

// Reads the keys of `r`'s table on top of `start`, the default of what the material is for.
// `inside` defaults to `color` when `color` is given (a surface given one colour has one
// colour), and otherwise keeps the start's. `outside`, the old [[surface]] name of `color`,
// is still read, with a deprecation note appended to `notes`; giving both is an error.
// Does not call r.finish(): the caller's table may hold other keys.
Material read_material_keys(TableReader& r, const Material& start, std::vector<std::string>& notes);

}  // namespace locus::render::detail
