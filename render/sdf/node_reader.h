// Reading the SDF scene tree of a scene file ([[object]] tables and [materials.NAME]), used only
// by render/scene_file.cpp; the format is documented in docs/sdf-scenes.md.
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "render/scene.h"
#include "render/sdf/node.h"

namespace locus::render::sdf {

// Every error is an InputError naming the position and the key path, such as
// "line 12, column 1: object[2].children[1].type: unknown node type \"sphre\" (expected ...)".
// Deprecated keys that were still read are appended to `notes`. An algebraic leaf without clip
// keys is fitted to its extent (render/surface_extent.h), which throws Timeout after
// `deadline`.
std::vector<NodePtr> read_objects(const toml::array& objects, const toml::table* materials,
                                  const SurfaceCompiler& compile, TraceMethod method,
                                  std::optional<std::chrono::steady_clock::time_point> deadline,
                                  std::vector<std::string>& notes);

}  // namespace locus::render::sdf
