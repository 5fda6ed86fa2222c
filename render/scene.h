// What a picture needs, with every default stated here (STYLE.md P11): the member initialisers
// are the documented defaults. A scene file (TOML, read by scene_file.h) or the command line
// sets only what differs.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "algebra/compiled.h"
#include "render/camera.h"
#include "render/camera_path.h"
#include "render/clip_region.h"
#include "render/material.h"
#include "render/patch_trim.h"
#include "render/sdf/node.h"
#include "render/surface_frame.h"
#include "render/trace_method.h"

namespace locus::render {

struct Light {
    enum class Kind { directional, point } kind = Kind::directional;
    Vec3 direction{-0.4, 0.8, 0.6};  // towards the light (directional)
    Vec3 position{0.0, 5.0, 5.0};    // point lights
    Vec3 color{1.0, 1.0, 1.0};
    double intensity = 1.0;
    // Soft shadows: the light's radius (world units for point lights, radians of angular
    // radius for directional ones); 0 gives hard shadows.
    double radius = 0.0;
};

struct Surface {
    std::string equation;    // over x, y, z: the coordinates of `frame`
    std::string param_file;  // or a .param file, implicitized by the caller (cli/)
    ClipRegion clip = ClipSphere{};
    Material material;
    std::string source;  // where it was given, for messages ("line 4, column 12: surface[1]")
    // No clip region given: render/framing.h's fit_clip_regions replaces `clip` by a sphere
    // about the surface's extent when the surface is bounded.
    bool fit_clip = true;
    // A surface that is a patch's implicit equation: only hits on the patch count
    // (render/patch_trim.h). Shared: copies of a scene share the map.
    std::shared_ptr<const PatchTrim> trim = nullptr;
    // The coordinates the equation is written in (identity: the world's). Patches get one
    // centred on them, which their equations need to be well conditioned in doubles.
    SurfaceFrame frame = {};
};

struct RenderOptions {
    TraceMethod method = TraceMethod::certified;
    int samples = 1;  // samples × samples per pixel
    bool shadows = true;
    int soft_shadow_samples = 8;  // shadow rays per light when its radius is non-zero
    bool ambient_occlusion = false;
    int ambient_occlusion_samples = 16;
    int threads = 0;  // 0: all hardware threads
};

struct Scene {
    int width = 512;
    int height = 512;
    Vec3 background{0.10, 0.11, 0.13};
    std::optional<CameraSpec> camera;  // none: framed on the clip regions (default_camera)
    // An animation: [camera] with `frames` and [[camera.key]] tables (camera is then its first
    // key).
    std::optional<CameraPath> camera_path;
    std::vector<Light> lights;  // empty: default_lights()
    std::vector<Surface> surfaces;
    // The SDF scene tree ([[object]] in scene files, render/sdf/): when present, the scene is
    // rendered by render_sdf_scene, with the surfaces above as exactly traced leaves.
    std::vector<sdf::NodePtr> objects;
    RenderOptions options;
    // What the scene reader accepted but the user should change (a deprecated key), each
    // naming its position and key; the command line prints them on stderr.
    std::vector<std::string> notes;
};

// Where an algebraic leaf of the scene tree comes from; `key` names it in errors
// ("object[3].children[1]").
struct AlgebraicSource {
    std::string equation;
    std::string param_file;
    std::string key;
};
// Compiles an algebraic leaf. The command line passes one that implicitizes .param files and
// reports square-free replacements; without one, scene files with algebraic objects are refused.
using SurfaceCompiler = std::function<algebra::CompiledPolynomial(const AlgebraicSource&)>;

// Two directional lights: a warm key from the upper left front, a cool fill from the right.
std::vector<Light> default_lights();
// Looks at the centre of the surfaces' clip regions from the front, upper right, at the
// distance where their bounding sphere fills the vertical field of view.
CameraSpec default_camera(const Scene& scene);

}  // namespace locus::render
