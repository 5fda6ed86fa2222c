// Scene files in TOML: only what a scene needs, everything else defaulted (render/scene.h).
//
//     [image]    width = 640   height = 480   background = [0.1, 0.1, 0.1]
//     [camera]   eye = [3, 2, 6]   target = [0, 0, 0]   up = [0, 1, 0]   fov = 35
//     [[light]]  type = "directional"  direction = [-1, 1, 1]  color = [1, 1, 1]
//                intensity = 1  radius = 0.05          # or type = "point", position = [...]
//     [[surface]]
//     equation = "x^2+y^2+z^2-1"                        # or param = "torus.param"
//     clip = "sphere"  clip_radius = 2  clip_center = [0, 0, 0]
//                                                       # or clip = "box", clip_min, clip_max
//     [surface.material] color = [...]  inside = [...]  ambient  diffuse  specular  shininess
//                        checker = [...]  checker_size     (render/detail/surface_keys.h)
//     [render]   method = "sturm"  samples = 2  shadows = true  ambient_occlusion = false
//                threads = 0
//
// The SDF scene tree — [[object]] tables with nested [[object.children]] and named
// [materials.NAME] — is read by render/sdf/node_reader.h; docs/sdf-scenes.md has the format.
//
// Every error names the key (as a dotted path) and its position: a TOML syntax error is a
// ParseError with line and column; an unknown key, a value of the wrong type or out of range
// is an InputError such as "line 4, column 1: surface[1].clip_radius: expected a positive
// number, found -2". A deprecated key that is still read leaves a note in Scene::notes.
#pragma once

#include <chrono>
#include <optional>
#include <string_view>

#include "render/scene.h"

namespace locus::render {

// `compile` turns the algebraic leaves of [[object]] trees into compiled polynomials.
// `method`, when given, replaces [render] method before the algebraic leaves are built (the
// command line's --method). Fitting an algebraic leaf without clip keys to its extent throws
// Timeout after `deadline`.
Scene parse_scene(std::string_view text, const SurfaceCompiler& compile = {},
                  std::optional<TraceMethod> method = std::nullopt,
                  std::optional<std::chrono::steady_clock::time_point> deadline = std::nullopt);

}  // namespace locus::render
