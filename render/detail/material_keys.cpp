#include "render/detail/material_keys.h"

namespace locus::render::detail {

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
