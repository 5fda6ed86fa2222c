// Tracing rays through an SDF scene: the top-level objects (plain unions flattened) are the
// items. Items that trace exactly (algebraic surfaces) give their first root; the others are
// sphere-traced together up to the nearest exact hit, so a plain union of algebraic surfaces
// and primitives loses no exactness.
//
// Hart's speed-ups, each switchable for the benchmark:
//  * bounding volumes: an item cannot be hit before the ray enters its bounding box, and is
//    done once the ray leaves it; a ray that misses the box never evaluates the item;
//  * triangle inequality: an item evaluated at t₀ with distance bound d cannot be hit before
//    t₀ + d, so it is evaluated again only when it is the item that limits the step (lazy
//    evaluation; without it every item is evaluated at every step);
//  * convexity: for an exact distance to a convex solid, the ray may go on to the tangent
//    plane of the unbounding sphere (distance d / cos θ), and an item whose tangent plane the
//    ray moves away from cannot be hit at all.
#pragma once

#include <vector>

#include "render/sdf/node.h"

namespace locus::render::sdf {

struct SpeedUps {
    bool bounding_volumes = true;
    bool triangle_inequality = true;
    bool convexity = true;
};
// The plain march, every speed-up off (the reference the speed-ups are measured against).
inline constexpr SpeedUps kNoSpeedUps{
    .bounding_volumes = false, .triangle_inequality = false, .convexity = false};

struct TraceCounters {
    long evaluations = 0;  // primitive evaluations (a node counts its leaves)
    long root_work = 0;    // root-finder work of exactly traced items
    long undecided = 0;    // rays that hit the step limit
};

struct SceneHit {
    double t = INFINITY;
    int item = -1;
    bool found() const { return item >= 0; }
};

// The box of the bounded objects (empty, min > max, when none are bounded), and the size of
// the scene derived from it: half its diagonal, at least 1e-3, and 1 for an empty box. The
// tracer's tolerances and the renderer's far distance scale with it.
Bounds finite_bounds(const std::vector<NodePtr>& objects);
double scene_scale(const Bounds& finite);

class SceneTracer {
  public:
    // `scale`: the size of the scene's finite part, for tolerances.
    SceneTracer(const std::vector<NodePtr>& objects, double scale, SpeedUps speed_ups = {});

    // The first hit of a ray with a unit direction in `interval`. `footprint`: the width of a
    // pixel per unit distance; a sphere-traced hit is accepted within footprint·t/2.
    SceneHit first_hit(const Ray& ray, Interval interval, double footprint,
                       TraceCounters& counters) const;

    // Light reaching the end of a unit-direction ray at t_max: 0 when anything blocks it;
    // with `penumbra` k > 0 (1/tan of the light's angular radius), Quilez's improved soft
    // shadow from the closest approach of sphere-traced items.
    double transmittance(const Ray& ray, double t_max, double penumbra,
                         TraceCounters& counters) const;

    // The scene's field: the minimum over items of value/L.
    double value(const Vec3& p, TraceCounters& counters) const;
    Vec3 normal(int item, const Vec3& p, double h) const;
    Material material_at(int item, const Vec3& p, const Footprint& footprint) const;

    int item_count() const { return static_cast<int>(items_.size()); }
    double scale() const { return scale_; }

  private:
    struct Item {
        NodePtr node;
        double inverse_lipschitz;
        bool exact;
        bool convex;
        int primitives;
    };
    double bounded_value(const Item& item, const Vec3& p) const;

    std::vector<Item> items_;
    std::vector<int> marched_;                            // indices of sphere-traced items
    std::vector<int> exact_;                              // indices of exactly traced items
    Bounds finite_box_{Vec3(INFINITY), Vec3(-INFINITY)};  // of all bounded items
    double scale_;
    SpeedUps speed_ups_;
};

}  // namespace locus::render::sdf
