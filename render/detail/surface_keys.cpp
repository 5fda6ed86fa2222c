#include "render/detail/surface_keys.h"

namespace locus::render::detail {

AlgebraicSource read_algebraic_source(TableReader& r, const toml::table& table) {
    AlgebraicSource source;
    source.equation = r.text("equation").value_or("");
    source.param_file = r.text("param").value_or("");
    source.key = r.path().substr(0, r.path().size() - 1);
    if (source.equation.empty() == source.param_file.empty()) {
        throw InputError(position(table) + ": " + source.key,
                         "give exactly one of 'equation' and 'param'");
    }
    return source;
}

ClipRegion read_clip_region(TableReader& r, const toml::table& table) {
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
    const std::string color_key = outside != nullptr ? "outside" : "color";
    m.color = r.vector(color_key, m.color);
    const bool color_given = color != nullptr || outside != nullptr;
    m.inside = r.vector("inside", color_given ? m.color : m.inside);
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
