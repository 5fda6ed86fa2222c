#include "render/sdf/domain.h"

#include <algorithm>
#include <cmath>

#include "algebra/error.h"

namespace locus::render::sdf {

namespace {

class MirrorAxes final : public Node {
  public:
    MirrorAxes(NodePtr child, std::array<bool, 3> axes) : child_(std::move(child)), axes_(axes) {
        kind_ = weaker(child_->kind(), DistanceKind::bound);
        lipschitz_ = child_->lipschitz();
        primitives_ = child_->primitive_count();
        bounds_ = child_->bounds();
        for (int i = 0; i < 3; ++i) {
            if (axes[static_cast<std::size_t>(i)]) {
                const double reach = std::max(bounds_.max[i], 0.0);
                bounds_.min[i] = -reach;
                bounds_.max[i] = reach;
            }
        }
    }
    double value(const Vec3& p) const override { return child_->value(folded(p)); }
    Material material_at(const Vec3& p, const Footprint& footprint) const override {
        return child_->material_at(folded(p), footprint);
    }
    std::string_view type() const override { return "mirror"; }

  private:
    Vec3 folded(const Vec3& p) const {
        Vec3 q = p;
        for (int i = 0; i < 3; ++i) {
            if (axes_[static_cast<std::size_t>(i)]) {
                q[i] = std::abs(q[i]);
            }
        }
        return q;
    }
    NodePtr child_;
    std::array<bool, 3> axes_;
};

class MirrorPlane final : public Node {
  public:
    MirrorPlane(NodePtr child, const Vec3& normal, const Vec3& point)
        : child_(std::move(child)), normal_(glm::normalize(normal)), point_(point) {
        kind_ = weaker(child_->kind(), DistanceKind::bound);
        lipschitz_ = child_->lipschitz();
        primitives_ = child_->primitive_count();
        const Bounds& b = child_->bounds();
        if (b.is_finite()) {
            bounds_ = b;
            for (int corner = 0; corner < 8; ++corner) {
                const Vec3 c{corner & 1 ? b.max.x : b.min.x, corner & 2 ? b.max.y : b.min.y,
                             corner & 4 ? b.max.z : b.min.z};
                const Vec3 reflected = c - 2.0 * glm::dot(c - point_, normal_) * normal_;
                bounds_ = bounds_.united({reflected, reflected});
            }
        }
    }
    double value(const Vec3& p) const override { return child_->value(folded(p)); }
    Material material_at(const Vec3& p, const Footprint& footprint) const override {
        return child_->material_at(folded(p), footprint);
    }
    std::string_view type() const override { return "mirror_plane"; }

  private:
    Vec3 folded(const Vec3& p) const {
        return p - 2.0 * std::min(0.0, glm::dot(p - point_, normal_)) * normal_;
    }
    NodePtr child_;
    Vec3 normal_, point_;
};

class Repeat final : public Node {
  public:
    Repeat(NodePtr child, const Vec3& spacing, std::array<std::optional<int>, 3> counts)
        : child_(std::move(child)), spacing_(spacing), counts_(counts) {
        kind_ = weaker(child_->kind(), DistanceKind::bound);
        lipschitz_ = 1.0;
        inverse_lipschitz_ = 1.0 / child_->lipschitz();
        const Bounds& b = child_->bounds();
        bounds_ = b;
        int repeated = 0;
        for (int i = 0; i < 3; ++i) {
            const auto axis = static_cast<std::size_t>(i);
            if (spacing[i] == 0.0) {
                continue;
            }
            ++repeated;
            const double extent = std::max(-b.min[i], b.max[i]);
            if (!std::isfinite(extent) || extent > 0.5 * spacing[i]) {
                throw InputError("repeat",
                                 "the child must fit in half a cell on every repeated axis");
            }
            cap_ = std::min(cap_, spacing[i] - extent);
            if (counts[axis]) {
                const double reach = *counts[axis] * spacing[i];
                bounds_.min[i] = b.min[i] - reach;
                bounds_.max[i] = b.max[i] + reach;
            } else {
                bounds_.min[i] = -INFINITY;
                bounds_.max[i] = INFINITY;
            }
        }
        primitives_ = child_->primitive_count() << repeated;
    }

    double value(const Vec3& p) const override {
        double best = cap_;
        visit(p,
              [&](const Vec3& q) { best = std::min(best, child_->value(q) * inverse_lipschitz_); });
        return best;
    }
    Material material_at(const Vec3& p, const Footprint& footprint) const override {
        double best = INFINITY;
        Vec3 nearest = p;
        visit(p, [&](const Vec3& q) {
            const double v = child_->value(q);
            if (v < best) {
                best = v;
                nearest = q;
            }
        });
        return child_->material_at(nearest, footprint);
    }
    std::string_view type() const override { return "repeat"; }

  private:
    // Calls `use` with p in the coordinates of each copy looked at: the cell of p and its
    // neighbour towards p on each repeated axis.
    template <class Use>
    void visit(const Vec3& p, Use&& use) const {
        std::array<long long, 3> cell{}, toward{};
        std::array<bool, 3> has_neighbour{};
        for (int i = 0; i < 3; ++i) {
            const auto axis = static_cast<std::size_t>(i);
            if (spacing_[i] == 0.0) {
                continue;
            }
            cell[axis] = repetition_cell(p[i], spacing_[i], counts_[axis]);
            toward[axis] = cell[axis] + (p[i] >= cell[axis] * spacing_[i] ? 1 : -1);
            has_neighbour[axis] = !counts_[axis] || std::llabs(toward[axis]) <= *counts_[axis];
        }
        for (int mask = 0; mask < 8; ++mask) {
            Vec3 q = p;
            bool valid = true;
            for (int i = 0; i < 3 && valid; ++i) {
                const auto axis = static_cast<std::size_t>(i);
                const bool neighbour = (mask >> i) & 1;
                if (spacing_[i] == 0.0 || !has_neighbour[axis]) {
                    valid = !neighbour;
                    if (spacing_[i] != 0.0) {
                        q[i] -= static_cast<double>(cell[axis]) * spacing_[i];
                    }
                    continue;
                }
                q[i] -= static_cast<double>(neighbour ? toward[axis] : cell[axis]) * spacing_[i];
            }
            if (valid) {
                use(q);
            }
        }
    }

    NodePtr child_;
    Vec3 spacing_;
    std::array<std::optional<int>, 3> counts_;
    double cap_ = INFINITY;
    double inverse_lipschitz_ = 1.0;
};

}  // namespace

long long repetition_cell(double x, double spacing, std::optional<int> count) {
    long long cell = std::llround(x / spacing);
    if (count) {
        cell = std::clamp<long long>(cell, -*count, *count);
    }
    return cell;
}

NodePtr make_mirror_axes(NodePtr child, std::array<bool, 3> axes) {
    return std::make_shared<MirrorAxes>(std::move(child), axes);
}

NodePtr make_mirror_plane(NodePtr child, const Vec3& normal, const Vec3& point) {
    if (!(glm::length(normal) > 0.0)) {
        throw InputError("mirror_plane.normal", "must be non-zero");
    }
    return std::make_shared<MirrorPlane>(std::move(child), normal, point);
}

NodePtr make_repeat(NodePtr child, const Vec3& spacing, std::array<std::optional<int>, 3> counts) {
    for (int i = 0; i < 3; ++i) {
        const auto axis = static_cast<std::size_t>(i);
        if (!(spacing[i] >= 0.0) || !std::isfinite(spacing[i])) {
            throw InputError("repeat", "spacings must be numbers ≥ 0 (0: not repeated)");
        }
        if (counts[axis] && *counts[axis] < 0) {
            throw InputError("repeat_count", "counts must be ≥ 0");
        }
    }
    if (spacing == Vec3(0.0)) {
        throw InputError("repeat", "at least one spacing must be positive");
    }
    return std::make_shared<Repeat>(std::move(child), spacing, counts);
}

}  // namespace locus::render::sdf
