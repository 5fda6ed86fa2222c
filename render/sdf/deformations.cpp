#include "render/sdf/deformations.h"

#include <algorithm>
#include <cmath>

#include "algebra/error.h"

namespace locus::render::sdf {

namespace {

// Outside the child's box, the larger of its value and the distance to the box (both lower
// bounds of the distance to it); inside, the value itself. Continuous, because the child's
// value is ≥ 0 on the box's faces (its solid lies inside), and 1-Lipschitz for a 1-Lipschitz
// value.
double at_least_box_distance(double value, const Bounds& box, const Vec3& p) {
    const double outside = box.distance(p);
    return outside > 0.0 ? std::max(value, outside) : value;
}

// A node that forwards to one child; derived classes change the point or the value.
class Unary : public Node {
  public:
    explicit Unary(NodePtr child) : child_(std::move(child)) {
        kind_ = child_->kind();
        lipschitz_ = child_->lipschitz();
        bounds_ = child_->bounds();
        primitives_ = child_->primitive_count();
    }

  protected:
    NodePtr child_;
};

// Twist about y (axis 1, rotating coordinates 0 and 2) or bend about z (axis 2, rotating
// coordinates 0 and 1 by an angle proportional to coordinate 0).
class Warp final : public Unary {
  public:
    enum class Kind { twist, bend };
    Warp(NodePtr child, Kind warp, double rate)
        : Unary(std::move(child)), warp_(warp), rate_(rate) {
        const Bounds& b = child_->bounds();
        const int u = 0, v = warp == Kind::twist ? 2 : 1;
        const int axis = warp == Kind::twist ? 1 : 2;
        if (!std::isfinite(b.min[u]) || !std::isfinite(b.max[u]) || !std::isfinite(b.min[v]) ||
            !std::isfinite(b.max[v])) {
            throw InputError(warp == Kind::twist ? "twist" : "bend",
                             "needs a child bounded across its axis");
        }
        radius_ = std::hypot(std::max(-b.min[u], b.max[u]), std::max(-b.min[v], b.max[v]));
        scale_ = 1.0 / (child_->lipschitz() * (1.0 + std::abs(rate) * radius_));
        kind_ = weaker(kind_, DistanceKind::bound);
        lipschitz_ = 1.0;
        bounds_ = Bounds{};
        bounds_.min[u] = bounds_.min[v] = -radius_;
        bounds_.max[u] = bounds_.max[v] = radius_;
        bounds_.min[axis] = b.min[axis];
        bounds_.max[axis] = b.max[axis];
    }

    double value(const Vec3& p) const override {
        const auto [u, v] = plane();
        // Outside the cylinder, project onto it (a 1-Lipschitz map) and take the larger of the
        // projected value and the signed distance to the cylinder: 1-Lipschitz everywhere,
        // with the same sign and zero set as the child since a warp keeps r.
        const double r = std::hypot(p[u], p[v]);
        Vec3 q = p;
        if (r > radius_) {
            q[u] *= radius_ / r;
            q[v] *= radius_ / r;
        }
        return std::max(child_->value(warped(q)) * scale_, r - radius_);
    }
    Material material_at(const Vec3& p, const Footprint& footprint) const override {
        return child_->material_at(
            warped(p), mapped_footprint(footprint, p, [this](const Vec3& q) { return warped(q); }));
    }
    std::string_view type() const override { return warp_ == Kind::twist ? "twist" : "bend"; }

  private:
    std::pair<int, int> plane() const { return {0, warp_ == Kind::twist ? 2 : 1}; }
    Vec3 warped(const Vec3& p) const {
        const auto [u, v] = plane();
        const double angle = rate_ * (warp_ == Kind::twist ? p.y : p.x);
        const double c = std::cos(angle), s = std::sin(angle);
        Vec3 q = p;
        q[u] = c * p[u] - s * p[v];
        q[v] = s * p[u] + c * p[v];
        return q;
    }

    Kind warp_;
    double rate_;
    double radius_ = 0.0;
    double scale_ = 1.0;
};

class Round final : public Unary {
  public:
    Round(NodePtr child, double radius)
        : Unary(std::move(child)), radius_(radius), child_box_(child_->bounds()) {
        inverse_lipschitz_ = 1.0 / lipschitz_;
        lipschitz_ = 1.0;
        bounds_ = bounds_.grown(radius);
    }
    // A bound below the distance (twist, ellipsoid, soft objects) would grow the child by more
    // than r and past its box grown by r, where the bounding volumes cut it off (29 % of the
    // pixels of a rounded twisted box differed, found in review): the distance to the child's
    // box, a second lower bound, keeps the shape inside the box grown by r.
    double value(const Vec3& p) const override {
        return at_least_box_distance(child_->value(p) * inverse_lipschitz_, child_box_, p) -
               radius_;
    }
    Material material_at(const Vec3& p, const Footprint& footprint) const override {
        return child_->material_at(p, footprint);
    }
    std::string_view type() const override { return "round"; }

  private:
    double radius_;
    Bounds child_box_;
    double inverse_lipschitz_ = 1.0;
};

class Elongate final : public Unary {
  public:
    Elongate(NodePtr child, const Vec3& half) : Unary(std::move(child)), half_(half) {
        bounds_ = {bounds_.min - half, bounds_.max + half};
    }
    double value(const Vec3& p) const override { return child_->value(squeezed(p)); }
    Material material_at(const Vec3& p, const Footprint& footprint) const override {
        // Mapped, not passed on: inside the stretched part a squeezed coordinate is 0, a cell
        // boundary, where an unmapped width would average a checker to flat grey.
        return child_->material_at(
            squeezed(p),
            mapped_footprint(footprint, p, [this](const Vec3& q) { return squeezed(q); }));
    }
    std::string_view type() const override { return "elongate"; }

  private:
    Vec3 squeezed(const Vec3& p) const { return p - glm::clamp(p, -half_, half_); }
    Vec3 half_;
};

class Displace final : public Unary {
  public:
    Displace(NodePtr child, const Noise& noise)
        : Unary(std::move(child)), noise_(noise), child_box_(child_->bounds()) {
        inverse_lipschitz_ = 1.0 / lipschitz_;
        lipschitz_ = 1.0 + noise.lipschitz();
        kind_ = weaker(kind_, DistanceKind::bound);
        bounds_ = bounds_.grown(noise.max_amplitude());
    }
    // As for round: the child's box keeps the displaced shape within the box grown by the
    // noise amplitude, whatever kind of bound the child gives.
    double value(const Vec3& p) const override {
        return at_least_box_distance(child_->value(p) * inverse_lipschitz_, child_box_, p) +
               noise_.value(p);
    }
    Material material_at(const Vec3& p, const Footprint& footprint) const override {
        return child_->material_at(p, footprint);
    }
    std::string_view type() const override { return "displace"; }

  private:
    Noise noise_;
    Bounds child_box_;
    double inverse_lipschitz_ = 1.0;
};

}  // namespace

NodePtr make_twist(NodePtr child, double rate) {
    if (!std::isfinite(rate)) {
        throw InputError("twist", "must be a number (radians per unit length)");
    }
    return std::make_shared<Warp>(std::move(child), Warp::Kind::twist, rate);
}

NodePtr make_bend(NodePtr child, double rate) {
    if (!std::isfinite(rate)) {
        throw InputError("bend", "must be a number (radians per unit length)");
    }
    return std::make_shared<Warp>(std::move(child), Warp::Kind::bend, rate);
}

NodePtr make_round(NodePtr child, double radius) {
    if (!(radius >= 0.0) || !std::isfinite(radius)) {
        throw InputError("round", "must be a number ≥ 0");
    }
    return std::make_shared<Round>(std::move(child), radius);
}

NodePtr make_elongate(NodePtr child, const Vec3& half) {
    if (!(half.x >= 0.0 && half.y >= 0.0 && half.z >= 0.0)) {
        throw InputError("elongate", "must be three numbers ≥ 0");
    }
    return std::make_shared<Elongate>(std::move(child), half);
}

NodePtr make_displace(NodePtr child, const Noise& noise) {
    return std::make_shared<Displace>(std::move(child), noise);
}

}  // namespace locus::render::sdf
