#include "render/sdf/booleans.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "algebra/error.h"

namespace locus::render::sdf {

double Blend::max_lowering() const {
    switch (kind) {
    case BlendKind::polynomial:
        return k / (2.0 * order);
    case BlendKind::exponential:
        return k * std::log(2.0);
    case BlendKind::root:
        return 0.5 * k;
    }
    return k;
}

Blended smooth_min(double a, double b, const Blend& blend) {
    const double k = blend.k;
    switch (blend.kind) {
    case BlendKind::polynomial: {
        const double h = std::max(k - std::abs(a - b), 0.0) / k;
        const double hn = std::pow(h, blend.order);
        const double mixed = 0.5 * hn;  // the share of the farther child at the seam
        const double lowered = hn * k / (2.0 * blend.order);
        return a < b ? Blended{a - lowered, mixed} : Blended{b - lowered, 1.0 - mixed};
    }
    case BlendKind::exponential: {
        // Shifted by the minimum so that the exponentials cannot overflow.
        const double m = std::min(a, b);
        const double ea = std::exp(-(a - m) / k);
        const double eb = std::exp(-(b - m) / k);
        return {m - k * std::log(ea + eb), eb / (ea + eb)};
    }
    case BlendKind::root: {
        const double root = std::sqrt((a - b) * (a - b) + k * k);
        return {0.5 * (a + b - root), 0.5 + 0.5 * (a - b) / root};
    }
    }
    return {std::min(a, b), a < b ? 0.0 : 1.0};
}

namespace {

enum class Operation { unite, intersect, subtract };

class Boolean final : public Node {
  public:
    Boolean(Operation operation, std::vector<NodePtr> children, std::optional<Blend> blend)
        : operation_(operation), children_(std::move(children)), blend_(blend) {
        lipschitz_ = 1.0;
        primitives_ = 0;
        kind_ = operation == Operation::unite && !blend ? DistanceKind::exact : DistanceKind::bound;
        for (const NodePtr& child : children_) {
            inverse_lipschitz_.push_back(1.0 / child->lipschitz());
            primitives_ += child->primitive_count();
            kind_ = weaker(kind_, child->kind());
        }
        bounds_ = children_.front()->bounds();
        for (std::size_t i = 1; i < children_.size(); ++i) {
            const Bounds& b = children_[i]->bounds();
            if (operation == Operation::unite) {
                bounds_ = bounds_.united(b);
            } else if (operation == Operation::intersect) {
                bounds_ = bounds_.intersected(b);
            }
        }
        if (blend && operation == Operation::unite) {
            bounds_ = bounds_.grown(blend->max_lowering());
        }
    }

    double value(const Vec3& p) const override { return fold(p, nullptr, {}); }

    Material material_at(const Vec3& p, const Footprint& footprint) const override {
        Material material;
        fold(p, &material, footprint);
        return material;
    }

    std::string_view type() const override {
        static constexpr std::string_view names[2][3] = {
            {"union", "intersection", "difference"},
            {"smooth_union", "smooth_intersection", "smooth_difference"}};
        return names[blend_ ? 1 : 0][static_cast<int>(operation_)];
    }

    const std::vector<NodePtr>* union_children() const override {
        return operation_ == Operation::unite && !blend_ ? &children_ : nullptr;
    }

  private:
    // The folded value; with `material`, also the folded material (mixed by the blend
    // weights).
    double fold(const Vec3& p, Material* material, const Footprint& footprint) const {
        double acc = children_[0]->value(p) * inverse_lipschitz_[0];
        if (material != nullptr) {
            *material = children_[0]->material_at(p, footprint);
        }
        for (std::size_t i = 1; i < children_.size(); ++i) {
            const double c = children_[i]->value(p) * inverse_lipschitz_[i];
            double weight = 0.0;
            if (!blend_) {
                switch (operation_) {
                case Operation::unite:
                    weight = c < acc ? 1.0 : 0.0;
                    acc = std::min(acc, c);
                    break;
                case Operation::intersect:
                    weight = c > acc ? 1.0 : 0.0;
                    acc = std::max(acc, c);
                    break;
                case Operation::subtract:
                    weight = -c > acc ? 1.0 : 0.0;
                    acc = std::max(acc, -c);
                    break;
                }
            } else {
                Blended b{};
                switch (operation_) {
                case Operation::unite:
                    b = smooth_min(acc, c, *blend_);
                    acc = b.value;
                    break;
                case Operation::intersect:
                    b = smooth_min(-acc, -c, *blend_);
                    acc = -b.value;
                    break;
                case Operation::subtract:
                    b = smooth_min(-acc, c, *blend_);
                    acc = -b.value;
                    break;
                }
                weight = b.weight_of_b;
            }
            if (material != nullptr && weight > 0.0) {
                *material = mix(*material, children_[i]->material_at(p, footprint), weight);
            }
        }
        return acc;
    }

    Operation operation_;
    std::vector<NodePtr> children_;
    std::vector<double> inverse_lipschitz_;
    std::optional<Blend> blend_;
};

NodePtr make_boolean(Operation operation, std::vector<NodePtr> children,
                     std::optional<Blend> blend) {
    if (children.empty()) {
        throw InputError("children", "an operation needs at least one child");
    }
    if (blend) {
        if (!(blend->k > 0.0) || !std::isfinite(blend->k)) {
            throw InputError("k", "the blend radius must be a positive number");
        }
        if (blend->kind == BlendKind::polynomial && (blend->order < 2 || blend->order > 8)) {
            throw InputError("n", "the polynomial blend order must be from 2 to 8");
        }
    }
    if (children.size() == 1 && operation != Operation::subtract) {
        return children.front();
    }
    return std::make_shared<Boolean>(operation, std::move(children), blend);
}

}  // namespace

NodePtr make_union(std::vector<NodePtr> children) {
    return make_boolean(Operation::unite, std::move(children), std::nullopt);
}
NodePtr make_intersection(std::vector<NodePtr> children) {
    return make_boolean(Operation::intersect, std::move(children), std::nullopt);
}
NodePtr make_difference(std::vector<NodePtr> children) {
    return make_boolean(Operation::subtract, std::move(children), std::nullopt);
}
NodePtr make_smooth_union(std::vector<NodePtr> children, const Blend& blend) {
    return make_boolean(Operation::unite, std::move(children), blend);
}
NodePtr make_smooth_intersection(std::vector<NodePtr> children, const Blend& blend) {
    return make_boolean(Operation::intersect, std::move(children), blend);
}
NodePtr make_smooth_difference(std::vector<NodePtr> children, const Blend& blend) {
    return make_boolean(Operation::subtract, std::move(children), blend);
}

}  // namespace locus::render::sdf
