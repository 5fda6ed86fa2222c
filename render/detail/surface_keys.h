// The keys that describe an algebraic surface in a scene file, one vocabulary for [[surface]]
// tables and the `algebraic` leaves of SDF scene trees (docs/rendering.md, docs/sdf-scenes.md):
// where its equation comes from, the region it is clipped to, and its material (whose keys
// the named [materials.NAME] of scene trees share). None of them calls r.finish(): the
// caller's table holds other keys too.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "render/clip_region.h"
#include "render/detail/toml_reader.h"
#include "render/material.h"
#include "render/scene.h"

namespace locus::render::detail {

// `equation` or `param`: exactly one of them, not blank. The source's key is the table's
// path ("surface[2]", "object[1].children[3]").
AlgebraicSource read_algebraic_source(TableReader& r, const toml::table& table);

// `clip` = "sphere" (default; clip_radius, clip_center) or "box" (clip_min below clip_max);
// nothing when the table has none of these keys (the surface is then fitted to its extent:
// render/framing.h).
std::optional<ClipRegion> read_clip_region(TableReader& r, const toml::table& table);

// color, inside, ambient, diffuse, specular, shininess, checker, checker_size on top of
// `start`, the default of what the material is for. `inside` defaults to `color` when `color`
// is given (a surface given one colour has one colour), and otherwise keeps the start's.
// `outside`, the old [[surface]] name of `color`, is still read with its old meaning (the
// inside keeps its default), with a deprecation note appended to `notes`; giving both is an
// error.
Material read_material_keys(TableReader& r, const Material& start, std::vector<std::string>& notes);

}  // namespace locus::render::detail
