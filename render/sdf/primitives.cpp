#include "render/sdf/primitives.h"

#include <algorithm>
#include <cmath>

#include "algebra/error.h"

namespace locus::render::sdf {

namespace {

double dot2(double x, double y) {
    return x * x + y * y;
}

// A leaf: one material, evaluated in the leaf's coordinates.
class Leaf : public Node {
  public:
    explicit Leaf(MaterialPtr material) : material_(std::move(material)) {}
    Material material_at(const Vec3& p, const Footprint& footprint) const override {
        return material_->at(p, footprint);
    }

  protected:
    MaterialPtr material_;
};

class Sphere final : public Leaf {
  public:
    Sphere(double radius, MaterialPtr m) : Leaf(std::move(m)), radius_(radius) {
        bounds_ = {Vec3(-radius), Vec3(radius)};
        convex_exact_ = true;
    }
    double value(const Vec3& p) const override { return glm::length(p) - radius_; }
    Vec3 gradient(const Vec3& p, double) const override {
        const double length = glm::length(p);
        return length > 0.0 ? p / length : Vec3(0.0, 1.0, 0.0);
    }
    std::string_view type() const override { return "sphere"; }

  private:
    double radius_;
};

class Plane final : public Leaf {
  public:
    Plane(const Vec3& normal, double offset, MaterialPtr m) : Leaf(std::move(m)) {
        const double length = glm::length(normal);
        normal_ = normal / length;
        offset_ = offset / length;
        convex_exact_ = true;
        // An axis-aligned half-space is bounded on one side.
        for (int i = 0; i < 3; ++i) {
            if (std::abs(normal_[i]) == 1.0) {
                if (normal_[i] > 0.0) {
                    bounds_.max[i] = offset_;
                } else {
                    bounds_.min[i] = -offset_;
                }
            }
        }
    }
    double value(const Vec3& p) const override { return glm::dot(p, normal_) - offset_; }
    Vec3 gradient(const Vec3&, double) const override { return normal_; }
    std::string_view type() const override { return "plane"; }

  private:
    Vec3 normal_;
    double offset_;
};

class Box final : public Leaf {
  public:
    Box(const Vec3& half, double rounding, MaterialPtr m)
        : Leaf(std::move(m)), inner_(half - Vec3(rounding)), rounding_(rounding) {
        bounds_ = {-half, half};
        convex_exact_ = true;
    }
    double value(const Vec3& p) const override {
        const Vec3 q = glm::abs(p) - inner_;
        return glm::length(glm::max(q, Vec3(0.0))) +
               std::min(std::max(q.x, std::max(q.y, q.z)), 0.0) - rounding_;
    }
    Vec3 gradient(const Vec3& p, double) const override {
        const Vec3 q = glm::abs(p) - inner_;
        const Vec3 sign{std::copysign(1.0, p.x), std::copysign(1.0, p.y), std::copysign(1.0, p.z)};
        const Vec3 outside = glm::max(q, Vec3(0.0));
        const double length = glm::length(outside);
        if (length > 0.0) {
            return sign * outside / length;
        }
        const int axis = q.x >= q.y && q.x >= q.z ? 0 : (q.y >= q.z ? 1 : 2);
        Vec3 g(0.0);
        g[axis] = sign[axis];
        return g;
    }
    std::string_view type() const override { return rounding_ > 0.0 ? "rounded_box" : "box"; }

  private:
    Vec3 inner_;
    double rounding_;
};

class Torus final : public Leaf {
  public:
    Torus(double major, double minor, MaterialPtr m)
        : Leaf(std::move(m)), major_(major), minor_(minor) {
        bounds_ = {{-major - minor, -minor, -major - minor}, {major + minor, minor, major + minor}};
    }
    double value(const Vec3& p) const override {
        const double q = std::hypot(p.x, p.z) - major_;
        return std::hypot(q, p.y) - minor_;
    }
    std::string_view type() const override { return "torus"; }

  private:
    double major_, minor_;
};

class Cylinder final : public Leaf {
  public:
    Cylinder(double radius, double half_height, MaterialPtr m)
        : Leaf(std::move(m)), radius_(radius), half_height_(half_height) {
        bounds_ = {{-radius, -half_height, -radius}, {radius, half_height, radius}};
        convex_exact_ = true;
    }
    double value(const Vec3& p) const override {
        const double dx = std::hypot(p.x, p.z) - radius_;
        const double dy = std::abs(p.y) - half_height_;
        return std::min(std::max(dx, dy), 0.0) + std::hypot(std::max(dx, 0.0), std::max(dy, 0.0));
    }
    Vec3 gradient(const Vec3& p, double) const override {
        const double r = std::hypot(p.x, p.z);
        const Vec3 radial = r > 0.0 ? Vec3(p.x / r, 0.0, p.z / r) : Vec3(1.0, 0.0, 0.0);
        const Vec3 axial{0.0, std::copysign(1.0, p.y), 0.0};
        const double dx = r - radius_;
        const double dy = std::abs(p.y) - half_height_;
        if (dx > 0.0 && dy > 0.0) {
            return (dx * radial + dy * axial) / std::hypot(dx, dy);
        }
        return dx > dy ? radial : axial;
    }
    std::string_view type() const override { return "cylinder"; }

  private:
    double radius_, half_height_;
};

class Cone final : public Leaf {
  public:
    Cone(double bottom, double top, double half_height, MaterialPtr m)
        : Leaf(std::move(m)), bottom_(bottom), top_(top), half_height_(half_height) {
        const double r = std::max(bottom, top);
        bounds_ = {{-r, -half_height, -r}, {r, half_height, r}};
    }
    double value(const Vec3& p) const override {
        const double qx = std::hypot(p.x, p.z);
        const double qy = p.y;
        const double k2x = top_ - bottom_, k2y = 2.0 * half_height_;
        const double cax = qx - std::min(qx, qy < 0.0 ? bottom_ : top_);
        const double cay = std::abs(qy) - half_height_;
        const double u =
            std::clamp(((top_ - qx) * k2x + (half_height_ - qy) * k2y) / dot2(k2x, k2y), 0.0, 1.0);
        const double cbx = qx - top_ + k2x * u;
        const double cby = qy - half_height_ + k2y * u;
        const double sign = cbx < 0.0 && cay < 0.0 ? -1.0 : 1.0;
        return sign * std::sqrt(std::min(dot2(cax, cay), dot2(cbx, cby)));
    }
    std::string_view type() const override { return "cone"; }

  private:
    double bottom_, top_, half_height_;
};

class Capsule final : public Leaf {
  public:
    Capsule(const Vec3& a, const Vec3& b, double radius, MaterialPtr m)
        : Leaf(std::move(m)), a_(a), axis_(b - a), radius_(radius) {
        bounds_ = Bounds{glm::min(a, b), glm::max(a, b)}.grown(radius);
        convex_exact_ = true;
    }
    double value(const Vec3& p) const override { return glm::length(offset(p)) - radius_; }
    Vec3 gradient(const Vec3& p, double) const override {
        const Vec3 v = offset(p);
        const double length = glm::length(v);
        return length > 0.0 ? v / length : Vec3(0.0, 1.0, 0.0);
    }
    std::string_view type() const override { return "capsule"; }

  private:
    Vec3 offset(const Vec3& p) const {
        const Vec3 pa = p - a_;
        const double square = glm::dot(axis_, axis_);
        const double h = square > 0.0 ? std::clamp(glm::dot(pa, axis_) / square, 0.0, 1.0) : 0.0;
        return pa - h * axis_;
    }
    Vec3 a_, axis_;
    double radius_;
};

class Ellipsoid final : public Leaf {
  public:
    Ellipsoid(const Vec3& radii, MaterialPtr m)
        : Leaf(std::move(m)), radii_(radii), smallest_(std::min({radii.x, radii.y, radii.z})) {
        bounds_ = {-radii, radii};
        kind_ = DistanceKind::bound;
    }
    // |∇|p/r|| ≤ 1/min r, so multiplying by min r gives Lipschitz 1.
    double value(const Vec3& p) const override {
        return (glm::length(p / radii_) - 1.0) * smallest_;
    }
    std::string_view type() const override { return "ellipsoid"; }

  private:
    Vec3 radii_;
    double smallest_;
};

class Superquadric final : public Leaf {
  public:
    Superquadric(const Vec3& radii, double exponent, MaterialPtr m)
        : Leaf(std::move(m)), radii_(radii), exponent_(exponent) {
        bounds_ = {-radii, radii};
        kind_ = DistanceKind::bound;
        // ∇ of the e-norm has unit dual (q-)norm, 1/e + 1/q = 1. Its Euclidean norm is at most
        // 1 for e ≥ 2 (q ≤ 2) and at most 3^(1/e − 1/2) for e < 2; the radii divide by min r.
        const double spread = exponent >= 2.0 ? 1.0 : std::pow(3.0, 1.0 / exponent - 0.5);
        scale_ = std::min({radii.x, radii.y, radii.z}) / spread;
    }
    double value(const Vec3& p) const override {
        const Vec3 u = glm::abs(p / radii_);
        const double largest = std::max({u.x, u.y, u.z});
        if (largest == 0.0) {
            return -scale_;
        }
        // Normalised by the largest component so that large exponents cannot overflow.
        const Vec3 w = u / largest;
        const double sum =
            std::pow(w.x, exponent_) + std::pow(w.y, exponent_) + std::pow(w.z, exponent_);
        return (largest * std::pow(sum, 1.0 / exponent_) - 1.0) * scale_;
    }
    std::string_view type() const override { return "superquadric"; }

  private:
    Vec3 radii_;
    double exponent_;
    double scale_;
};

double wyvill_falloff(double s_squared) {
    if (s_squared >= 1.0) {
        return 0.0;
    }
    const double s4 = s_squared * s_squared;
    return 1.0 - (4.0 / 9.0) * s4 * s_squared + (17.0 / 9.0) * s4 - (22.0 / 9.0) * s_squared;
}

class SoftObjects final : public Leaf {
  public:
    SoftObjects(std::vector<Metaball> balls, double threshold, MaterialPtr m)
        : Leaf(std::move(m)), balls_(std::move(balls)), threshold_(threshold) {
        kind_ = DistanceKind::bound;
        primitives_ = static_cast<int>(balls_.size());
        double slope = 0.0;
        Bounds box{Vec3(INFINITY), Vec3(-INFINITY)};
        for (const Metaball& ball : balls_) {
            slope += std::abs(ball.weight) * kWyvillSlope / ball.radius;
            if (ball.weight > 0.0) {
                box =
                    box.united({ball.center - Vec3(ball.radius), ball.center + Vec3(ball.radius)});
            }
        }
        bounds_ = box;
        inverse_slope_ = 1.0 / slope;
    }
    double value(const Vec3& p) const override {
        double field = 0.0;
        for (const Metaball& ball : balls_) {
            const Vec3 v = p - ball.center;
            field += ball.weight * wyvill_falloff(glm::dot(v, v) / (ball.radius * ball.radius));
        }
        // Where no ball of positive weight reaches, F ≤ 0 < T: the distance to those balls is
        // a second 1-Lipschitz field with the same sign there, and far better far away,
        // where (T − F)/L stays at T/L.
        double reach = INFINITY;
        for (const Metaball& ball : balls_) {
            if (ball.weight > 0.0) {
                reach = std::min(reach, glm::length(p - ball.center) - ball.radius);
            }
        }
        return std::max((threshold_ - field) * inverse_slope_, reach);
    }
    std::string_view type() const override { return "soft_objects"; }

  private:
    std::vector<Metaball> balls_;
    double threshold_;
    double inverse_slope_;
};

// max over s in [0, 1] of |C'(s)| = (24 s⁵ − 68 s³ + 44 s)/9, at the root of
// 120 s⁴ − 204 s² + 44 = 0 inside (0, 1).
double wyvill_slope() {
    const double s2 = (204.0 - std::sqrt(204.0 * 204.0 - 4.0 * 120.0 * 44.0)) / 240.0;
    const double s = std::sqrt(s2);
    return (24.0 * s2 * s2 * s - 68.0 * s2 * s + 44.0 * s) / 9.0;
}

void require_positive(double value, const char* what) {
    if (!(value > 0.0) || !std::isfinite(value)) {
        throw InputError(what, "must be a positive number");
    }
}

}  // namespace

const double kWyvillSlope = wyvill_slope();

NodePtr make_sphere(double radius, MaterialPtr material) {
    require_positive(radius, "radius");
    return std::make_shared<Sphere>(radius, std::move(material));
}

NodePtr make_plane(const Vec3& normal, double offset, MaterialPtr material) {
    if (!(glm::length(normal) > 0.0)) {
        throw InputError("normal", "must be non-zero");
    }
    return std::make_shared<Plane>(normal, offset, std::move(material));
}

NodePtr make_box(const Vec3& half, double rounding, MaterialPtr material) {
    for (int i = 0; i < 3; ++i) {
        require_positive(half[i], "half_size");
    }
    if (!(rounding >= 0.0) || rounding > std::min({half.x, half.y, half.z})) {
        throw InputError("rounding", "must be from 0 to the smallest half extent");
    }
    return std::make_shared<Box>(half, rounding, std::move(material));
}

NodePtr make_torus(double major, double minor, MaterialPtr material) {
    require_positive(major, "major_radius");
    require_positive(minor, "minor_radius");
    return std::make_shared<Torus>(major, minor, std::move(material));
}

NodePtr make_cylinder(double radius, double half_height, MaterialPtr material) {
    require_positive(radius, "radius");
    require_positive(half_height, "half_height");
    return std::make_shared<Cylinder>(radius, half_height, std::move(material));
}

NodePtr make_cone(double bottom, double top, double half_height, MaterialPtr material) {
    require_positive(half_height, "half_height");
    if (!(bottom >= 0.0) || !(top >= 0.0) || !(bottom + top > 0.0)) {
        throw InputError("bottom_radius", "the cone's radii must be ≥ 0 and not both 0");
    }
    return std::make_shared<Cone>(bottom, top, half_height, std::move(material));
}

NodePtr make_capsule(const Vec3& a, const Vec3& b, double radius, MaterialPtr material) {
    require_positive(radius, "radius");
    return std::make_shared<Capsule>(a, b, radius, std::move(material));
}

NodePtr make_ellipsoid(const Vec3& radii, MaterialPtr material) {
    for (int i = 0; i < 3; ++i) {
        require_positive(radii[i], "radii");
    }
    return std::make_shared<Ellipsoid>(radii, std::move(material));
}

NodePtr make_superquadric(const Vec3& radii, double exponent, MaterialPtr material) {
    for (int i = 0; i < 3; ++i) {
        require_positive(radii[i], "radii");
    }
    if (!(exponent >= 1.0 && exponent <= 100.0)) {
        throw InputError("exponent", "must be from 1 to 100 (convex shapes)");
    }
    return std::make_shared<Superquadric>(radii, exponent, std::move(material));
}

NodePtr make_soft_objects(std::vector<Metaball> balls, double threshold, MaterialPtr material) {
    require_positive(threshold, "threshold");
    bool any_positive = false;
    for (const Metaball& ball : balls) {
        require_positive(ball.radius, "balls.radius");
        if (!std::isfinite(ball.weight)) {
            throw InputError("balls.weight", "must be a number");
        }
        any_positive = any_positive || ball.weight > 0.0;
    }
    if (!any_positive) {
        throw InputError("balls", "soft objects need at least one ball of positive weight");
    }
    return std::make_shared<SoftObjects>(std::move(balls), threshold, std::move(material));
}

}  // namespace locus::render::sdf
