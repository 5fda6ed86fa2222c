// One instance of every SDF node type with unremarkable parameters, shared by the SDF tests.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "render/sdf/booleans.h"
#include "render/sdf/deformations.h"
#include "render/sdf/domain.h"
#include "render/sdf/primitives.h"
#include "render/sdf/transforms.h"

namespace locus::render::sdf::testing {

inline MaterialPtr plain_material(Vec3 color = Vec3(0.8)) {
    return std::make_shared<const Material>(Material::plain(color));
}

inline std::vector<std::pair<std::string, NodePtr>> every_node_type() {
    const MaterialPtr m = plain_material();
    const NodePtr sphere = make_sphere(0.8, m);
    const NodePtr box = make_box({0.5, 0.4, 0.3}, 0.0, m);
    const NodePtr torus = make_torus(0.7, 0.2, m);
    const NodePtr shifted =
        make_placement(make_sphere(0.5, m), glm::dmat3(1.0), 1.0, {0.6, 0.1, 0});
    std::vector<std::pair<std::string, NodePtr>> nodes = {
        {"sphere", sphere},
        {"plane", make_plane({0.3, 1.0, -0.2}, 0.4, m)},
        {"box", box},
        {"rounded_box", make_box({0.5, 0.6, 0.4}, 0.15, m)},
        {"torus", torus},
        {"cylinder", make_cylinder(0.4, 0.7, m)},
        {"cone", make_cone(0.6, 0.1, 0.5, m)},
        {"capsule", make_capsule({-0.3, -0.4, 0.1}, {0.5, 0.3, -0.2}, 0.25, m)},
        {"ellipsoid", make_ellipsoid({1.0, 0.5, 0.3}, m)},
        {"superquadric_4", make_superquadric({0.9, 0.6, 0.5}, 4.0, m)},
        {"superquadric_1.5", make_superquadric({0.9, 0.6, 0.5}, 1.5, m)},
        {"soft_objects",
         make_soft_objects(
             {{{0, 0, 0}, 0.8, 1.0}, {{0.6, 0.2, 0}, 0.7, 1.0}, {{0, 0.5, 0}, 0.5, -0.5}}, 0.3, m)},
        {"union", make_union({sphere, shifted, box})},
        {"intersection", make_intersection({sphere, box})},
        {"difference", make_difference({box, shifted})},
        {"smooth_union_poly2",
         make_smooth_union({sphere, shifted}, {BlendKind::polynomial, 0.4, 2})},
        {"smooth_union_poly3",
         make_smooth_union({sphere, shifted}, {BlendKind::polynomial, 0.4, 3})},
        {"smooth_union_exp",
         make_smooth_union({sphere, shifted}, {BlendKind::exponential, 0.2, 2})},
        {"smooth_union_root", make_smooth_union({sphere, shifted}, {BlendKind::root, 0.3, 2})},
        {"smooth_intersection",
         make_smooth_intersection({sphere, box}, {BlendKind::polynomial, 0.3, 2})},
        {"smooth_difference",
         make_smooth_difference({box, shifted}, {BlendKind::polynomial, 0.3, 2})},
        {"placement", make_placement(box, rotation_about({1, 2, 3}, 40.0), 1.7, {0.3, -0.2, 0.5})},
        {"twist", make_twist(box, 2.5)},
        {"bend", make_bend(make_box({0.9, 0.2, 0.3}, 0.0, m), 1.5)},
        {"round", make_round(box, 0.1)},
        {"elongate", make_elongate(torus, {0.3, 0.0, 0.2})},
        {"displace", make_displace(sphere, Noise(0.1, 3.0, 3, 7))},
        {"mirror", make_mirror_axes(shifted, {true, false, true})},
        {"mirror_plane", make_mirror_plane(shifted, {1, 1, 0}, {0.2, 0, 0})},
        {"repeat", make_repeat(make_sphere(0.3, m), {1.0, 0.0, 0.8}, {})},
        {"repeat_finite", make_repeat(box, {1.2, 1.0, 0.0}, {2, 1, std::nullopt})},
    };
    return nodes;
}

}  // namespace locus::render::sdf::testing
