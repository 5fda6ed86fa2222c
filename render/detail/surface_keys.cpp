#include "render/detail/surface_keys.h"

#include <algorithm>
#include <array>

namespace locus::render::detail {

AlgebraicSource read_algebraic_source(TableReader& r, const toml::table& table) {
    AlgebraicSource source;
    source.key = r.path().substr(0, r.path().size() - 1);
    const toml::node* equation = r.find("equation");
    const toml::node* param = r.find("param");
    if ((equation == nullptr) == (param == nullptr)) {
        throw InputError(position(table) + ": " + source.key,
                         "give exactly one of 'equation' and 'param'");
    }
    const std::string key = equation != nullptr ? "equation" : "param";
    const std::string text = r.text(key).value_or("");
    if (text.find_first_not_of(" \t\r\n") == std::string::npos) {
        r.fail(*table.get(key), key, key == "equation" ? "an equation" : "a file name");
    }
    (equation != nullptr ? source.equation : source.param_file) = text;
    return source;
}

std::optional<ClipRegion> read_clip_region(TableReader& r, const toml::table& table) {
    const bool given = std::ranges::any_of(
        std::array{"clip", "clip_radius", "clip_center", "clip_min", "clip_max"},
        [&table](const char* key) { return table.get(key) != nullptr; });
    if (!given) {
        return std::nullopt;
    }
    const std::string shape = r.text("clip").value_or("sphere");
    if (shape == "sphere") {
        ClipSphere sphere;
        sphere.radius = r.number("clip_radius", sphere.radius, true);
        sphere.center = r.vector("clip_center", sphere.center);
        return sphere;
    }
    if (shape == "box") {
        ClipBox box;
        box.min = r.vector("clip_min", box.min);
        box.max = r.vector("clip_max", box.max);
        if (!(box.min.x < box.max.x && box.min.y < box.max.y && box.min.z < box.max.z)) {
            throw InputError(position(table) + ": " + r.path() + "clip_min",
                             "must be below clip_max in every coordinate");
        }
        return box;
    }
    throw InputError(position(*table.get("clip")) + ": " + r.path() + "clip",
                     "expected \"sphere\" or \"box\", found \"" + shape + "\"");
}

Material read_material_keys(TableReader& r, const Material& start,
                            std::vector<std::string>& notes) {
    Material m = start;
    const toml::node* color = r.find("color");
    const toml::node* outside = r.find("outside");
    if (color != nullptr && outside != nullptr) {
        throw InputError(position(*outside) + ": " + r.path() + "outside",
                         "'outside' is the old name of 'color'; give only 'color'");
    }
    if (outside != nullptr) {
        notes.push_back(position(*outside) + ": " + r.path() +
                        "outside: deprecated, read as 'color' (the name in every scene form)");
    }
    m.color = r.vector(outside != nullptr ? "outside" : "color", m.color);
    // The old key keeps its old meaning: the inside stays at its default unless given.
    m.inside = r.vector("inside", color != nullptr ? m.color : m.inside);
    m.ambient = r.non_negative("ambient", m.ambient);
    m.diffuse = r.non_negative("diffuse", m.diffuse);
    m.specular = r.non_negative("specular", m.specular);
    m.shininess = r.number("shininess", m.shininess, true);
    if (r.find("checker") != nullptr) {
        m.checker = r.vector("checker", Vec3(0.2));
    }
    m.checker_size = r.number("checker_size", m.checker_size, true);
    return m;
}

}  // namespace locus::render::detail
