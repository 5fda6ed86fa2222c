#include "render/sdf/scene_tracer.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <queue>

namespace locus::render::sdf {

namespace {

// Sphere-traced rays give up after this many evaluations of one item, or of all items without
// the triangle-inequality speed-up (grazing rays creep along a surface).
constexpr int kMaxSteps = 512;

void flatten(const NodePtr& node, std::vector<NodePtr>& out) {
    if (const std::vector<NodePtr>* children = node->union_children()) {
        for (const NodePtr& child : *children) {
            flatten(child, out);
        }
    } else if (std::vector<NodePtr> members = node->distribute_over_union(); !members.empty()) {
        for (const NodePtr& member : members) {
            flatten(member, out);
        }
    } else {
        out.push_back(node);
    }
}

// Per-item marching state along one ray.
struct Progress {
    double safe_until;  // the item is not hit before this t
    double exit;        // nor after this t (leaving its bounding box)
    double last_t = -INFINITY;
    double last_value = 0.0;
    int steps = 0;
    bool active = true;
};

}  // namespace

Bounds finite_bounds(const std::vector<NodePtr>& objects) {
    Bounds box{Vec3(INFINITY), Vec3(-INFINITY)};
    for (const NodePtr& object : objects) {
        if (object->bounds().is_finite()) {
            box = box.united(object->bounds());
        }
    }
    return box;
}

double scene_scale(const Bounds& finite) {
    if (!(finite.min.x <= finite.max.x)) {
        return 1.0;
    }
    return std::max(1e-3, 0.5 * glm::length(finite.max - finite.min));
}

double SceneTracer::bounded_value(const Item& item, const Vec3& p) const {
    // Outside its bounding box an item is at least as far as the box: a second lower bound
    // of the distance, much better than value/L for fields that flatten out far away (soft
    // objects, a large Lipschitz constant).
    const double v = item.node->value(p) * item.inverse_lipschitz;
    return v > 0.0 ? std::max(v, item.node->bounds().distance(p)) : v;
}

SceneTracer::SceneTracer(const std::vector<NodePtr>& objects, double scale, SpeedUps speed_ups)
    : scale_(scale), speed_ups_(speed_ups) {
    std::vector<NodePtr> flat;
    for (const NodePtr& object : objects) {
        flatten(object, flat);
    }
    for (const NodePtr& node : flat) {
        const int index = static_cast<int>(items_.size());
        items_.push_back({node, 1.0 / node->lipschitz(), node->traces_exactly(),
                          node->is_convex_exact(), node->primitive_count()});
        (node->traces_exactly() ? exact_ : marched_).push_back(index);
    }
    finite_box_ = finite_bounds(flat);
}

SceneHit SceneTracer::first_hit(const Ray& ray, Interval interval, double footprint,
                                TraceCounters& counters) const {
    SceneHit best;
    best.t = interval.hi;
    for (int index : exact_) {
        const RootResult root =
            items_[static_cast<std::size_t>(index)].node->first_hit(ray, {interval.lo, best.t});
        counters.root_work += root.work;
        if (root.status == RootStatus::hit && root.t <= best.t) {
            best = {root.t, index};
        }
    }
    if (marched_.empty()) {
        return best;
    }
    const double floor_epsilon = 1e-6 * scale_;
    std::vector<Progress> progress;
    progress.reserve(marched_.size());
    for (int index : marched_) {
        const Item& item = items_[static_cast<std::size_t>(index)];
        Interval span{interval.lo, best.t};
        if (speed_ups_.bounding_volumes) {
            span = item.node->bounds().clip(ray, span);
        }
        Progress p{span.lo, span.hi};
        p.active = !span.is_empty();
        progress.push_back(p);
    }
    // Evaluates item i at t: a hit (the value within the floor tolerance, or a sign change
    // bisected back), or a new safe_until.
    auto advance_item = [&](std::size_t i, double t) {
        Progress& p = progress[i];
        const Vec3 point = ray.at(t);
        const double epsilon = std::max(floor_epsilon, 0.5 * footprint * t);
        const Item& item = items_[static_cast<std::size_t>(marched_[i])];
        const double v = bounded_value(item, point);
        counters.evaluations += item.primitives;
        const bool crossed = p.last_t > -INFINITY && (v < 0.0) != (p.last_value < 0.0);
        if (std::abs(v) < floor_epsilon || crossed) {
            double hit_t = t;
            if (crossed) {
                // An estimate stepped over the surface: bisect back to the sign change.
                double lo = p.last_t, hi = t;
                const bool lo_negative = p.last_value < 0.0;
                for (int k = 0; k < 60 && hi - lo > 1e-3 * epsilon; ++k) {
                    const double mid = 0.5 * (lo + hi);
                    const double vm = item.node->value(ray.at(mid)) * item.inverse_lipschitz;
                    counters.evaluations += item.primitives;
                    ((vm < 0.0) == lo_negative ? lo : hi) = mid;
                }
                hit_t = hi;
            }
            if (hit_t < best.t) {
                best = {hit_t, marched_[i]};
            }
            p.active = false;
            return;
        }
        // Within the pixel's tolerance of a surface, the march goes on in steps of half
        // the tolerance until the sign changes (a hit, bisected back) or the value grows
        // again (a near miss): silhouettes stay where the surface is instead of growing
        // by the tolerance times L. A sheet thinner than half a tolerance can be missed.
        double advance = std::max(std::abs(v), 0.5 * epsilon);
        if (speed_ups_.convexity && item.convex && v > 0.0) {
            const Vec3 g = item.node->gradient(point, epsilon);
            const double approach = -glm::dot(ray.direction, g) / glm::length(g);
            if (!(approach > 0.0)) {
                p.active = false;  // moving away from a supporting plane of a convex solid
                return;
            }
            advance = std::max(advance, v / approach);
        }
        p.last_t = t;
        p.last_value = v;
        p.safe_until = t + advance;
        if (++p.steps > kMaxSteps) {
            // Creeping along a surface: call it a hit if it is within the tolerance.
            if (std::abs(v) < epsilon && t < best.t) {
                best = {t, marched_[i]};
            } else {
                ++counters.undecided;
            }
            p.active = false;
        } else if (p.safe_until > p.exit) {
            p.active = false;
        }
    };
    if (speed_ups_.triangle_inequality) {
        // Lazily: only the item that limits the step is evaluated, taken from a heap of the
        // items' safe_until (entries are dropped when stale).
        using Entry = std::pair<double, std::size_t>;
        std::priority_queue<Entry, std::vector<Entry>, std::greater<>> due;
        for (std::size_t i = 0; i < progress.size(); ++i) {
            if (progress[i].active) {
                due.emplace(progress[i].safe_until, i);
            }
        }
        while (!due.empty()) {
            const auto [t, i] = due.top();
            due.pop();
            Progress& p = progress[i];
            if (!p.active || t != p.safe_until) {
                continue;
            }
            if (t >= best.t) {
                break;
            }
            advance_item(i, t);
            if (p.active) {
                due.emplace(p.safe_until, i);
            }
        }
    } else {
        // Every item whose bounding box the ray has entered, at every step.
        for (;;) {
            double t = INFINITY;
            for (const Progress& p : progress) {
                if (p.active && p.safe_until < t) {
                    t = p.safe_until;
                }
            }
            if (!(t < best.t)) {
                break;
            }
            for (std::size_t i = 0; i < progress.size(); ++i) {
                const Progress& p = progress[i];
                if (p.active && (p.last_t > -INFINITY || p.safe_until <= t)) {
                    advance_item(i, t);
                }
            }
        }
    }
    if (best.item < 0 || best.t >= interval.hi) {
        return {};
    }
    return best;
}

double SceneTracer::transmittance(const Ray& ray, double t_max, double penumbra,
                                  TraceCounters& counters) const {
    if (penumbra <= 0.0) {
        // Hard shadows: any hit blocks the light; every speed-up applies.
        const double footprint = 0.0;
        return first_hit(ray, {0.0, t_max}, footprint, counters).found() ? 0.0 : 1.0;
    }
    for (int index : exact_) {
        const RootResult root =
            items_[static_cast<std::size_t>(index)].node->first_hit(ray, {0.0, t_max});
        counters.root_work += root.work;
        if (root.status == RootStatus::hit) {
            return 0.0;
        }
    }
    if (marched_.empty()) {
        return 1.0;
    }
    // The penumbra needs the distance to the closest item at every step. The distance to an
    // item's bounding box is a cheap lower bound of it: the item whose box is nearest is
    // evaluated first, then only items whose box is nearer than the best value so far
    // (Hart's bounding volumes for unions). Keeping per-item triangle-inequality bounds
    // instead was tried and cost ten times more here: a stale bound decays by every step
    // while a box distance follows the ray.
    std::vector<double> box_distance(marched_.size());
    const double epsilon = 1e-5 * scale_;
    double light = 1.0;
    double previous = 1e20;
    double t = 0.0;
    // Past the box of all bounded items, only unbounded ones remain; when the ray also moves
    // away from each of those (convex exact solids such as a floor), nothing can darken it.
    double quiet_after = finite_box_.clip(ray, {0.0, t_max}).hi;
    for (int index : marched_) {
        const Item& item = items_[static_cast<std::size_t>(index)];
        if (!item.node->bounds().is_finite()) {
            const bool leaving =
                item.convex && glm::dot(ray.direction, item.node->gradient(ray.origin, 1e-6)) > 0.0;
            if (!leaving) {
                quiet_after = t_max;
            }
        }
    }
    for (int step = 0; step < kMaxSteps && t < std::min(t_max, quiet_after); ++step) {
        const Vec3 point = ray.at(t);
        std::size_t nearest_box = 0;
        for (std::size_t i = 0; i < marched_.size(); ++i) {
            box_distance[i] =
                items_[static_cast<std::size_t>(marched_[i])].node->bounds().distance(point);
            if (box_distance[i] < box_distance[nearest_box]) {
                nearest_box = i;
            }
        }
        double h = INFINITY;
        for (std::size_t k = 0; k <= marched_.size(); ++k) {
            // k = 0 visits the nearest box first; then every other item in order.
            const std::size_t i = k == 0 ? nearest_box : k - 1;
            if ((k > 0 && i == nearest_box) || box_distance[i] >= h) {
                continue;
            }
            const Item& item = items_[static_cast<std::size_t>(marched_[i])];
            h = std::min(h, std::abs(bounded_value(item, point)));
            counters.evaluations += item.primitives;
        }
        if (h < epsilon) {
            return 0.0;
        }
        if (step > 0) {
            // Quilez's improved penumbra: the closest approach between this sample and the
            // previous one, not the sample itself.
            // When the field grows faster than the step (h > 2·previous), the two spheres do
            // not overlap and the estimate says nothing: take the sample itself.
            double y = h * h / (2.0 * previous);
            if (y >= h) {
                y = 0.0;
            }
            const double d = std::sqrt(std::max(0.0, h * h - y * y));
            light = std::min(light, penumbra * d / std::max(1e-12, t - y));
            if (light < 1e-3) {
                return 0.0;
            }
        }
        previous = h;
        t += h;
    }
    light = std::clamp(light, 0.0, 1.0);
    return light * light * (3.0 - 2.0 * light);
}

double SceneTracer::value(const Vec3& p, TraceCounters& counters) const {
    double best = INFINITY;
    for (const Item& item : items_) {
        if (item.node->bounds().distance(p) >= best) {
            continue;
        }
        best = std::min(best, bounded_value(item, p));
        counters.evaluations += item.primitives;
    }
    return best;
}

Vec3 SceneTracer::normal(int item, const Vec3& p, double h) const {
    return items_[static_cast<std::size_t>(item)].node->gradient(p, h);
}

Material SceneTracer::material_at(int item, const Vec3& p, const Footprint& footprint) const {
    return items_[static_cast<std::size_t>(item)].node->material_at(p, footprint);
}

}  // namespace locus::render::sdf
