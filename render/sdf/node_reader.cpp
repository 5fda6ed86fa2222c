#include "render/sdf/node_reader.h"

#include <chrono>
#include <map>
#include <optional>

#include "render/detail/surface_keys.h"
#include "render/detail/toml_reader.h"
#include "render/sdf/algebraic_leaf.h"
#include "render/sdf/booleans.h"
#include "render/sdf/deformations.h"
#include "render/sdf/domain.h"
#include "render/sdf/primitives.h"
#include "render/sdf/transforms.h"
#include "render/surface_extent.h"

namespace locus::render::sdf {

namespace {

using detail::position;
using detail::TableReader;

constexpr std::string_view kNodeTypes =
    "sphere, plane, box, rounded_box, torus, cylinder, cone, capsule, ellipsoid, superquadric, "
    "soft_objects, algebraic, group, union, intersection, difference, smooth_union, "
    "smooth_intersection, smooth_difference";

// What a primitive without a material looks like, and where a named material starts: light
// grey on both sides (an algebraic leaf without a material keeps the two-sided Material{}).
const Material kPrimitiveMaterial = Material::plain({0.75, 0.75, 0.78});

class Reader {
  public:
    Reader(const toml::table* materials, const SurfaceCompiler& compile, TraceMethod method,
           std::optional<std::chrono::steady_clock::time_point> deadline,
           std::vector<std::string>& notes)
        : compile_(compile), method_(method), deadline_(deadline) {
        if (materials == nullptr) {
            return;
        }
        for (const auto& [key, node] : *materials) {
            const std::string name(key.str());
            if (!node.is_table()) {
                throw InputError(position(node) + ": materials." + name,
                                 "expected a table ([materials." + name + "])");
            }
            TableReader r(*node.as_table(), "materials." + name + ".");
            materials_[name] = std::make_shared<const Material>(
                detail::read_material_keys(r, kPrimitiveMaterial, notes));
            r.finish();
        }
    }

    NodePtr read(const toml::table& table, const std::string& path, const MaterialPtr& inherited) {
        TableReader r(table, path);
        MaterialPtr material = inherited;
        if (const auto name = r.text("material")) {
            const auto found = materials_.find(*name);
            if (found == materials_.end()) {
                throw InputError(position(*table.get("material")) + ": " + path + "material",
                                 "no [materials." + *name + "] in this scene");
            }
            material = found->second;
        }
        const toml::node* type_node = r.find("type");
        if (type_node == nullptr) {
            throw InputError(position(table) + ": " + path + "type",
                             std::string("missing; expected one of ") + std::string(kNodeTypes));
        }
        const std::string type = r.text("type").value_or("");
        NodePtr node;
        try {
            node = shape(type, r, table, path, material);
            if (!node) {
                r.fail(*type_node, "type",
                       std::string("a node type (") + std::string(kNodeTypes) + ")");
            }
            node = deform(std::move(node), r, path);
        } catch (const InputError& e) {
            // Factories name the parameter; add where it is.
            if (e.subject().find("line ") == 0) {
                throw;
            }
            const std::string what = e.what();
            const toml::node* at = table.get(e.subject());
            throw InputError(position(at != nullptr ? *at : table) + ": " + path + e.subject(),
                             what.substr(e.subject().size() + 2));
        }
        r.finish();
        return node;
    }

  private:
    std::vector<NodePtr> children(TableReader& r, const toml::table& table, const std::string& path,
                                  const MaterialPtr& material) {
        const toml::array* list = r.array_of_tables("children");
        if (list == nullptr || list->empty()) {
            throw InputError(position(table) + ": " + path + "children",
                             "an operation needs at least one child ([[...children]])");
        }
        std::vector<NodePtr> nodes;
        for (std::size_t i = 0; i < list->size(); ++i) {
            nodes.push_back(read(*(*list)[i].as_table(),
                                 path + "children[" + std::to_string(i + 1) + "].", material));
        }
        return nodes;
    }

    Blend blend(TableReader& r, const std::string& path, const toml::table& table) {
        Blend b;
        const std::string kind = r.text("blend").value_or("polynomial");
        if (kind == "polynomial") {
            b.kind = BlendKind::polynomial;
        } else if (kind == "exponential") {
            b.kind = BlendKind::exponential;
        } else if (kind == "root") {
            b.kind = BlendKind::root;
        } else {
            throw InputError(
                position(*table.get("blend")) + ": " + path + "blend",
                "expected \"polynomial\", \"exponential\" or \"root\", found \"" + kind + "\"");
        }
        b.k = r.number("k", b.k, true);
        b.order = r.count("n", b.order, 2, 8);
        return b;
    }

    NodePtr algebraic(TableReader& r, const toml::table& table, const MaterialPtr& material) {
        const AlgebraicSource source = detail::read_algebraic_source(r, table);
        const std::optional<ClipRegion> given = detail::read_clip_region(r, table);
        if (!compile_) {
            throw InputError(source.key, "algebraic leaves need a surface compiler");
        }
        auto compiled = std::make_shared<const algebra::CompiledPolynomial>(compile_(source));
        // Without clip keys, as for [[surface]] tables: fitted to a bounded surface's extent.
        const ClipRegion region =
            given ? *given
                  : fitted_clip_sphere(estimate_extent(*compiled, 1024, deadline_))
                        .value_or(ClipSphere{});
        // Without a material, the two-sided default (orange outside, blue inside).
        return make_algebraic(std::move(compiled), region,
                              material ? material : std::make_shared<const Material>(), method_);
    }

    NodePtr shape(const std::string& type, TableReader& r, const toml::table& table,
                  const std::string& path, const MaterialPtr& inherited) {
        const MaterialPtr m = inherited ? inherited : default_material();
        if (type == "sphere") {
            return make_sphere(r.number("radius", 1.0), m);
        }
        if (type == "plane") {
            return make_plane(r.vector("normal", {0, 1, 0}), r.number("offset", 0.0), m);
        }
        if (type == "box") {
            return make_box(r.vector("half_size", Vec3(0.5)), 0.0, m);
        }
        if (type == "rounded_box") {
            return make_box(r.vector("half_size", Vec3(0.5)), r.number("rounding", 0.1), m);
        }
        if (type == "torus") {
            return make_torus(r.number("major_radius", 1.0), r.number("minor_radius", 0.25), m);
        }
        if (type == "cylinder") {
            return make_cylinder(r.number("radius", 0.5), r.number("half_height", 0.5), m);
        }
        if (type == "cone") {
            return make_cone(r.number("bottom_radius", 0.5), r.number("top_radius", 0.0),
                             r.number("half_height", 0.5), m);
        }
        if (type == "capsule") {
            return make_capsule(r.vector("a", {0, -0.5, 0}), r.vector("b", {0, 0.5, 0}),
                                r.number("radius", 0.25), m);
        }
        if (type == "ellipsoid") {
            return make_ellipsoid(r.vector("radii", {1.0, 0.6, 0.4}), m);
        }
        if (type == "superquadric") {
            return make_superquadric(r.vector("radii", Vec3(1.0)), r.number("exponent", 4.0), m);
        }
        if (type == "soft_objects") {
            std::vector<Metaball> balls;
            const toml::array* list = r.array_of_tables("balls");
            if (list == nullptr) {
                throw InputError(position(table) + ": " + path + "balls",
                                 "soft objects need balls = [{center = [...], radius = ...}]");
            }
            for (std::size_t i = 0; i < list->size(); ++i) {
                TableReader rb(*(*list)[i].as_table(),
                               path + "balls[" + std::to_string(i + 1) + "].");
                Metaball ball;
                ball.center = rb.vector("center", ball.center);
                ball.radius = rb.number("radius", ball.radius, true);
                ball.weight = rb.number("weight", ball.weight);
                rb.finish();
                balls.push_back(ball);
            }
            return make_soft_objects(std::move(balls), r.number("threshold", 0.5), m);
        }
        if (type == "algebraic") {
            return algebraic(r, table, inherited);
        }
        if (type == "group" || type == "union") {
            return make_union(children(r, table, path, inherited));
        }
        if (type == "intersection") {
            return make_intersection(children(r, table, path, inherited));
        }
        if (type == "difference") {
            return make_difference(children(r, table, path, inherited));
        }
        if (type == "smooth_union" || type == "smooth_intersection" ||
            type == "smooth_difference") {
            const Blend b = blend(r, path, table);
            std::vector<NodePtr> nodes = children(r, table, path, inherited);
            if (type == "smooth_union") {
                return make_smooth_union(std::move(nodes), b);
            }
            if (type == "smooth_intersection") {
                return make_smooth_intersection(std::move(nodes), b);
            }
            return make_smooth_difference(std::move(nodes), b);
        }
        return nullptr;
    }

    // Deformations, then symmetry and repetition, then the placement, in this order; a
    // `group` with one child applies them in another order.
    NodePtr deform(NodePtr node, TableReader& r, const std::string& path) {
        if (r.find("elongate") != nullptr) {
            node = make_elongate(std::move(node), r.vector("elongate", Vec3(0.0)));
        }
        if (r.find("round") != nullptr) {
            node = make_round(std::move(node), r.number("round", 0.0));
        }
        if (const toml::table* noise = r.subtable("displace")) {
            TableReader rn(*noise, path + "displace.");
            const double amplitude = rn.number("amplitude", 0.05, true);
            const double frequency = rn.number("frequency", 4.0, true);
            const int octaves = rn.count("octaves", 3, 1, 12);
            const int seed = rn.count("seed", 1, 0, 1 << 30);
            rn.finish();
            node = make_displace(std::move(node),
                                 Noise(amplitude, frequency, octaves, static_cast<unsigned>(seed)));
        }
        if (r.find("bend") != nullptr) {
            node = make_bend(std::move(node), r.number("bend", 0.0));
        }
        if (r.find("twist") != nullptr) {
            node = make_twist(std::move(node), r.number("twist", 0.0));
        }
        if (r.find("repeat") == nullptr && r.find("repeat_count") != nullptr) {
            throw InputError("repeat_count", "needs repeat = [sx, sy, sz] (the spacing)");
        }
        if (r.find("repeat") != nullptr) {
            const Vec3 spacing = r.vector("repeat", Vec3(0.0));
            std::array<std::optional<int>, 3> counts{};
            if (const toml::node* count = r.find("repeat_count")) {
                const toml::array* array = count->as_array();
                if (array == nullptr || array->size() != 3) {
                    r.fail(*count, "repeat_count", "three integers ≥ 0 (copies each side)");
                }
                for (std::size_t i = 0; i < 3; ++i) {
                    const std::optional<std::int64_t> value = detail::integer_of((*array)[i]);
                    if (!value || *value < 0 || *value > 10000) {
                        r.fail(*count, "repeat_count", "three integers ≥ 0 (copies each side)");
                    }
                    counts[i] = static_cast<int>(*value);
                }
            }
            node = make_repeat(std::move(node), spacing, counts);
        }
        if (const auto axes = r.text("mirror")) {
            std::array<bool, 3> mirrored{};
            for (const char c : *axes) {
                if (c < 'x' || c > 'z') {
                    throw InputError(
                        "mirror",
                        "expected axes among x, y, z such as \"xz\", found \"" + *axes + "\"");
                }
                mirrored[static_cast<std::size_t>(c - 'x')] = true;
            }
            node = make_mirror_axes(std::move(node), mirrored);
        }
        if (const toml::table* plane = r.subtable("mirror_plane")) {
            TableReader rp(*plane, path + "mirror_plane.");
            const Vec3 normal = rp.vector("normal", {1, 0, 0});
            const Vec3 point = rp.vector("point", Vec3(0.0));
            rp.finish();
            node = make_mirror_plane(std::move(node), normal, point);
        }
        glm::dmat3 rotation(1.0);
        bool placed = false;
        if (r.find("rotate_axis") != nullptr || r.find("rotate_degrees") != nullptr) {
            rotation =
                rotation_about(r.vector("rotate_axis", {0, 1, 0}), r.number("rotate_degrees", 0.0));
            placed = true;
        }
        if (r.find("euler") != nullptr) {
            rotation = rotation_euler(r.vector("euler", Vec3(0.0))) * rotation;
            placed = true;
        }
        const double scale = r.number("scale", 1.0, true);
        const Vec3 translation = r.vector("translate", Vec3(0.0));
        if (placed || scale != 1.0 || translation != Vec3(0.0)) {
            node = make_placement(std::move(node), rotation, scale, translation);
        }
        return node;
    }

    static MaterialPtr default_material() {
        static const MaterialPtr material = std::make_shared<const Material>(kPrimitiveMaterial);
        return material;
    }

    std::map<std::string, MaterialPtr> materials_;
    const SurfaceCompiler& compile_;
    TraceMethod method_;
    std::optional<std::chrono::steady_clock::time_point> deadline_;
};

}  // namespace

std::vector<NodePtr> read_objects(const toml::array& objects, const toml::table* materials,
                                  const SurfaceCompiler& compile, TraceMethod method,
                                  std::optional<std::chrono::steady_clock::time_point> deadline,
                                  std::vector<std::string>& notes) {
    Reader reader(materials, compile, method, deadline, notes);
    std::vector<NodePtr> nodes;
    for (std::size_t i = 0; i < objects.size(); ++i) {
        nodes.push_back(
            reader.read(*objects[i].as_table(), "object[" + std::to_string(i + 1) + "].", nullptr));
    }
    return nodes;
}

}  // namespace locus::render::sdf
