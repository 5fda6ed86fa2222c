#include "render/scene_file.h"

#include <string>

#include "render/detail/surface_keys.h"
#include "render/detail/toml_reader.h"
#include "render/sdf/node_reader.h"

namespace locus::render {

namespace {

using detail::position;
using detail::TableReader;

Surface read_surface(const toml::table& table, const std::string& path,
                     std::vector<std::string>& notes) {
    TableReader r(table, path);
    Surface s;
    const AlgebraicSource source = detail::read_algebraic_source(r, table);
    s.equation = source.equation;
    s.param_file = source.param_file;
    const char* given = source.equation.empty() ? "param" : "equation";
    s.source = position(*table.get(given)) + ": " + path + given;
    if (const std::optional<ClipRegion> clip = detail::read_clip_region(r, table)) {
        s.clip = *clip;
        s.fit_clip = false;
    }
    if (const toml::table* material = r.subtable("material")) {
        TableReader m(*material, path + "material.");
        s.material = detail::read_material_keys(m, s.material, notes);
        m.finish();
    }
    r.finish();
    return s;
}

// eye, target, up and fov on top of `start` (the previous key of a camera path).
CameraSpec read_camera_keys(TableReader& r, const toml::table& table, const CameraSpec& start) {
    CameraSpec spec = start;
    spec.eye = r.vector("eye", spec.eye);
    spec.target = r.vector("target", spec.target);
    spec.up = r.vector("up", spec.up);
    spec.fov_degrees = r.number("fov", spec.fov_degrees, true);
    if (spec.eye == spec.target) {
        const toml::node* at = table.get("eye") ? table.get("eye") : table.get("target");
        throw InputError(position(at != nullptr ? *at : table) + ": " + r.path() + "eye",
                         "the eye must differ from the target");
    }
    return spec;
}

Light read_light(const toml::table& table, const std::string& path) {
    TableReader r(table, path);
    Light light;
    const std::string type = r.text("type").value_or("directional");
    if (type == "directional") {
        light.direction = r.vector("direction", light.direction);
        // Normalized at any scale: [1e300, 1e300, 0] has an infinite glm::length, and
        // glm::normalize made it the zero vector (a picture without its key light).
        light.direction = scaled_normalize(light.direction);
        if (light.direction == Vec3(0.0)) {
            throw InputError(position(table) + ": " + path + "direction",
                             "must be non-zero and finite");
        }
    } else if (type == "point") {
        light.kind = Light::Kind::point;
        if (table.get("position") == nullptr) {
            throw InputError(position(table) + ": " + path + "position",
                             "a point light needs a position");
        }
        light.position = r.vector("position", light.position);
    } else {
        throw InputError(position(*table.get("type")) + ": " + path + "type",
                         "expected \"directional\" or \"point\", found \"" + type + "\"");
    }
    light.color = r.vector("color", light.color);
    light.intensity = r.non_negative("intensity", light.intensity);
    light.radius = r.non_negative("radius", light.radius);
    r.finish();
    return light;
}

}  // namespace

Scene parse_scene(std::string_view text, const SurfaceCompiler& compile,
                  std::optional<TraceMethod> method,
                  std::optional<std::chrono::steady_clock::time_point> deadline) {
    toml::table root;
    try {
        root = toml::parse(text);
    } catch (const toml::parse_error& e) {
        const toml::source_position begin = e.source().begin;
        throw ParseError(begin.line, begin.column, "valid TOML", std::string(e.description()));
    }
    Scene scene;
    TableReader r(root, "");
    if (const toml::table* image = r.subtable("image")) {
        TableReader ri(*image, "image.");
        scene.width = ri.count("width", scene.width, 1, 16384);
        scene.height = ri.count("height", scene.height, 1, 16384);
        scene.background = ri.vector("background", scene.background);
        ri.finish();
    }
    if (const toml::table* camera = r.subtable("camera")) {
        TableReader rc(*camera, "camera.");
        const CameraSpec spec = read_camera_keys(rc, *camera, CameraSpec{});
        scene.camera = spec;
        const toml::node* frames = rc.find("frames");
        const toml::array* keys = rc.array_of_tables("key");
        if ((frames == nullptr) != (keys == nullptr)) {
            throw InputError(position(frames != nullptr ? *frames : *camera->get("key")) + ": " +
                                 (frames != nullptr ? "camera.frames" : "camera.key"),
                             "a camera path needs both `frames` and [[camera.key]] tables");
        }
        if (keys != nullptr) {
            CameraPath path;
            path.frames = rc.count("frames", 2, 2, 100000);
            path.keys.push_back(spec);
            for (std::size_t i = 0; i < keys->size(); ++i) {
                const toml::table& table = *(*keys)[i].as_table();
                TableReader rk(table, "camera.key[" + std::to_string(i + 1) + "].");
                path.keys.push_back(read_camera_keys(rk, table, path.keys.back()));
                rk.finish();
            }
            scene.camera_path = path;
        }
        rc.finish();
    }
    if (const toml::array* lights = r.array_of_tables("light")) {
        for (std::size_t i = 0; i < lights->size(); ++i) {
            scene.lights.push_back(
                read_light(*(*lights)[i].as_table(), "light[" + std::to_string(i + 1) + "]."));
        }
    }
    if (const toml::array* surfaces = r.array_of_tables("surface")) {
        for (std::size_t i = 0; i < surfaces->size(); ++i) {
            scene.surfaces.push_back(read_surface(*(*surfaces)[i].as_table(),
                                                  "surface[" + std::to_string(i + 1) + "].",
                                                  scene.notes));
        }
    }
    if (const toml::table* options = r.subtable("render")) {
        TableReader ro(*options, "render.");
        if (const auto name = ro.text("method")) {
            scene.options.method = parse_trace_method(*name);
        }
        scene.options.samples = ro.count("samples", scene.options.samples, 1, 16);
        scene.options.shadows = ro.flag("shadows", scene.options.shadows);
        scene.options.ambient_occlusion =
            ro.flag("ambient_occlusion", scene.options.ambient_occlusion);
        scene.options.threads = ro.count("threads", scene.options.threads, 0, 1024);
        ro.finish();
    }
    if (method) {
        scene.options.method = *method;
    }
    const toml::table* materials = r.subtable("materials");
    if (const toml::array* objects = r.array_of_tables("object")) {
        scene.objects = sdf::read_objects(*objects, materials, compile, scene.options.method,
                                          deadline, scene.notes);
    } else if (materials != nullptr) {
        throw InputError(position(*root.get("materials")) + ": materials",
                         "named materials are for [[object]] trees; this scene has none");
    }
    r.finish();
    if (scene.surfaces.empty() && scene.objects.empty()) {
        throw InputError("surface", "a scene needs at least one [[surface]] or [[object]]");
    }
    return scene;
}

}  // namespace locus::render
