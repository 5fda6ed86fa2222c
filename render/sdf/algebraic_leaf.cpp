#include "render/sdf/algebraic_leaf.h"

#include <cmath>

#include "render/surface_tracer.h"

namespace locus::render::sdf {

double clip_distance(const ClipRegion& clip, const Vec3& p) {
    if (const auto* sphere = std::get_if<ClipSphere>(&clip)) {
        return glm::length(p - sphere->center) - sphere->radius;
    }
    const auto& box = std::get<ClipBox>(clip);
    const Vec3 center = 0.5 * (box.min + box.max);
    const Vec3 q = glm::abs(p - center) - 0.5 * (box.max - box.min);
    return glm::length(glm::max(q, Vec3(0.0))) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0);
}

namespace {

class AlgebraicLeaf final : public Node {
  public:
    AlgebraicLeaf(std::shared_ptr<const algebra::CompiledPolynomial> f, const ClipRegion& clip,
                  MaterialPtr material, TraceMethod method)
        : f_(std::move(f)),
          material_(std::move(material)),
          clip_(clip),
          tracer_(*f_, method, bounding_sphere(clip).radius) {
        kind_ = DistanceKind::estimate;
        const ClipSphere sphere = bounding_sphere(clip);
        if (const auto* box = std::get_if<ClipBox>(&clip)) {
            bounds_ = {box->min, box->max};
        } else {
            bounds_ = {sphere.center - Vec3(sphere.radius), sphere.center + Vec3(sphere.radius)};
        }
    }

    double value(const Vec3& p) const override {
        const algebra::ValueGradient vg = f_->value_gradient(to_point(p));
        const double length = glm::length(to_vec(vg.gradient));
        // Where ∇f vanishes the estimate is unbounded; the clip distance then governs.
        const double estimate =
            length > 0.0 ? vg.value / length : std::copysign(INFINITY, vg.value);
        return std::max(clip_distance(clip_, p), estimate);
    }
    Material material_at(const Vec3& p, const Footprint& footprint) const override {
        return material_->at(p, footprint);
    }
    Vec3 gradient(const Vec3& p, double) const override {
        return to_vec(f_->value_gradient(to_point(p)).gradient);
    }
    std::string_view type() const override { return "algebraic"; }

    bool traces_exactly() const override { return true; }
    RootResult first_hit(const Ray& ray, Interval interval) const override {
        const Interval inside = clip(clip_, ray, interval);
        if (inside.is_empty()) {
            return {};
        }
        return tracer_.first_hit(ray, inside);
    }

  private:
    std::shared_ptr<const algebra::CompiledPolynomial> f_;
    MaterialPtr material_;
    ClipRegion clip_;
    SurfaceTracer tracer_;
};

}  // namespace

NodePtr make_algebraic(std::shared_ptr<const algebra::CompiledPolynomial> f, const ClipRegion& clip,
                       MaterialPtr material, TraceMethod method) {
    return std::make_shared<AlgebraicLeaf>(std::move(f), clip, std::move(material), method);
}

}  // namespace locus::render::sdf
