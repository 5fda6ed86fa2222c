#include "render/sdf/transforms.h"

#include <cmath>
#include <numbers>

#include <glm/matrix.hpp>

#include "algebra/error.h"

namespace locus::render::sdf {

glm::dmat3 rotation_about(const Vec3& axis, double degrees) {
    const double length = glm::length(axis);
    if (!(length > 0.0)) {
        throw InputError("rotate_axis", "must be non-zero");
    }
    const Vec3 u = axis / length;
    const double angle = degrees * std::numbers::pi / 180.0;
    const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
    // Rodrigues' formula; GLM matrices are column-major, m[column][row].
    glm::dmat3 m;
    m[0] = {t * u.x * u.x + c, t * u.x * u.y + s * u.z, t * u.x * u.z - s * u.y};
    m[1] = {t * u.x * u.y - s * u.z, t * u.y * u.y + c, t * u.y * u.z + s * u.x};
    m[2] = {t * u.x * u.z + s * u.y, t * u.y * u.z - s * u.x, t * u.z * u.z + c};
    return m;
}

glm::dmat3 rotation_euler(const Vec3& degrees) {
    return rotation_about({0, 0, 1}, degrees.z) * rotation_about({0, 1, 0}, degrees.y) *
           rotation_about({1, 0, 0}, degrees.x);
}

namespace {

class Placement final : public Node {
  public:
    Placement(NodePtr child, const glm::dmat3& rotation, double scale, const Vec3& translation)
        : child_(std::move(child)),
          rotation_(rotation),
          inverse_(glm::transpose(rotation)),
          scale_(scale),
          translation_(translation) {
        kind_ = child_->kind();
        lipschitz_ = child_->lipschitz();
        convex_exact_ = child_->is_convex_exact();
        primitives_ = child_->primitive_count();
        const Bounds& b = child_->bounds();
        if (b.is_finite()) {
            bounds_ = {Vec3(INFINITY), Vec3(-INFINITY)};
            for (int corner = 0; corner < 8; ++corner) {
                const Vec3 local{corner & 1 ? b.max.x : b.min.x, corner & 2 ? b.max.y : b.min.y,
                                 corner & 4 ? b.max.z : b.min.z};
                const Vec3 world = to_world(local);
                bounds_ = {glm::min(bounds_.min, world), glm::max(bounds_.max, world)};
            }
        } else if (rotation == glm::dmat3(1.0)) {
            bounds_ = {b.min * scale + translation, b.max * scale + translation};
        }  // else unbounded
    }

    double value(const Vec3& p) const override { return scale_ * child_->value(to_local(p)); }
    Material material_at(const Vec3& p, const Footprint& footprint) const override {
        return child_->material_at(
            to_local(p),
            mapped_footprint(footprint, p, [this](const Vec3& q) { return to_local(q); }));
    }
    Vec3 gradient(const Vec3& p, double h) const override {
        return rotation_ * child_->gradient(to_local(p), h / scale_);
    }
    std::string_view type() const override { return "placement"; }

    bool traces_exactly() const override { return child_->traces_exactly(); }
    std::vector<NodePtr> distribute_over_union() const override {
        std::vector<NodePtr> members;
        if (const std::vector<NodePtr>* children = child_->union_children()) {
            members = *children;
        } else {
            members = child_->distribute_over_union();
        }
        for (NodePtr& member : members) {
            member = std::make_shared<Placement>(member, rotation_, scale_, translation_);
        }
        return members;
    }
    RootResult first_hit(const Ray& ray, Interval interval) const override {
        const Ray local{to_local(ray.origin), (inverse_ * ray.direction) / scale_};
        return child_->first_hit(local, interval);
    }

  private:
    Vec3 to_local(const Vec3& p) const { return (inverse_ * (p - translation_)) / scale_; }
    Vec3 to_world(const Vec3& p) const { return rotation_ * (scale_ * p) + translation_; }

    NodePtr child_;
    glm::dmat3 rotation_, inverse_;
    double scale_;
    Vec3 translation_;
};

}  // namespace

NodePtr make_placement(NodePtr child, const glm::dmat3& rotation, double scale,
                       const Vec3& translation) {
    if (!(scale > 0.0) || !std::isfinite(scale)) {
        throw InputError("scale", "must be a positive number");
    }
    return std::make_shared<Placement>(std::move(child), rotation, scale, translation);
}

}  // namespace locus::render::sdf
