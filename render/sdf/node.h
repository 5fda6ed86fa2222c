// A scene as a tree of signed-distance nodes (Hart, "Sphere tracing", 1996; the seed thesis):
// primitives at the leaves, booleans, blends, transforms and deformations above them.
//
// Every node is a function f: R³ → R, negative inside, zero on its surface, and says how far
// its value can be trusted:
//   * kind() — `exact`: f is the signed Euclidean distance (outside at least); `bound`: f has
//     the right sign and |f(p) − f(q)| ≤ L·|p − q|, so f(p)/L never exceeds the distance to
//     the surface; `estimate`: only a first-order guess (an algebraic surface inside a blend,
//     |f|/|∇f|), which the tracer protects by bisecting back over sign changes.
//   * lipschitz() — the L above, derived per node type as Hart does (sums, composition, 1/s for
//     a scale, twists restricted to a radius, soft-object falloff, 3 per noise octave). The
//     tracer steps by f/L, so a bound never steps past the surface.
// tests/render/sdf_lipschitz_test.cpp checks |f(p) − f(q)| ≤ L·|p − q| for every node type.
#pragma once

#include <cmath>
#include <memory>
#include <string_view>
#include <vector>

#include "render/material.h"
#include "render/root_finder.h"
#include "render/vec3.h"

namespace locus::render::sdf {

enum class DistanceKind { exact = 0, bound = 1, estimate = 2 };
// The weaker of two kinds (exact < bound < estimate).
inline DistanceKind weaker(DistanceKind a, DistanceKind b) {
    return a > b ? a : b;
}
std::string_view to_string(DistanceKind kind);

// An axis-aligned box containing everything where f ≤ 0 (and so the surface); coordinates are
// ±infinity for unbounded nodes such as planes and infinite repetition.
struct Bounds {
    Vec3 min{-INFINITY};
    Vec3 max{INFINITY};
    bool is_finite() const;
    // The distance from p to the box (0 inside): a lower bound of the distance to the node.
    double distance(const Vec3& p) const;
    // The parameters t of the ray inside the box; empty if it misses.
    Interval clip(const Ray& ray, Interval limits) const;
    Bounds united(const Bounds& other) const;
    Bounds intersected(const Bounds& other) const;
    Bounds grown(double margin) const;
};

// A node's material, shared by the leaves below the operation or name that gave it. Patterns
// (a checker) are resolved in the leaf's own coordinates.
using MaterialPtr = std::shared_ptr<const Material>;

class Node;
using NodePtr = std::shared_ptr<const Node>;

// The footprint at p carried through a coordinate map (first order: the images of p + dx and
// p + dy less the image of p; exact for placements).
template <class Map>
Footprint mapped_footprint(const Footprint& footprint, const Vec3& p, const Map& map) {
    const Vec3 at = map(p);
    return {map(p + footprint.dx) - at, map(p + footprint.dy) - at};
}

class Node {
  public:
    virtual ~Node() = default;

    // The field value at p.
    virtual double value(const Vec3& p) const = 0;
    // The resolved material of the surface near p (the child that wins a boolean, a blend of
    // both in a smooth one), its pattern filtered over `footprint` (in p's coordinates; zero
    // for a point sample). Nodes that move their child's coordinates map the footprint with
    // them (mapped_footprint); folds pass it on, as they preserve lengths.
    virtual Material material_at(const Vec3& p, const Footprint& footprint) const = 0;
    // ∇f at p; by tetrahedral central differences of step h unless a node knows better
    // (transforms rotate their child's gradient; algebraic leaves use the analytic one).
    virtual Vec3 gradient(const Vec3& p, double h) const;
    virtual std::string_view type() const = 0;

    DistanceKind kind() const { return kind_; }
    double lipschitz() const { return lipschitz_; }
    const Bounds& bounds() const { return bounds_; }
    // Exact distance to a convex solid: the tracer may step to the tangent plane of the
    // unbounding sphere (Hart's convexity step), and drop the node when the ray turns away.
    bool is_convex_exact() const { return convex_exact_; }
    // Leaves below this node (the cost of one value() in primitive evaluations).
    int primitive_count() const { return primitives_; }

    // Nodes that find their first hit along a ray exactly (an algebraic surface under rigid
    // motions and uniform scale) rather than by sphere tracing.
    virtual bool traces_exactly() const { return false; }
    // Precondition: traces_exactly(). The first hit in `interval`; t in multiples of the
    // ray's direction, which need not be unit length.
    virtual RootResult first_hit(const Ray& ray, Interval interval) const;
    // The children of an operation, for flattening top-level unions.
    virtual const std::vector<NodePtr>* union_children() const { return nullptr; }
    // A placement of a plain union as the union of placed members (so that the tracer can
    // flatten it and keep exact leaves exact); empty for every other node.
    virtual std::vector<NodePtr> distribute_over_union() const { return {}; }

  protected:
    DistanceKind kind_ = DistanceKind::exact;
    double lipschitz_ = 1.0;
    Bounds bounds_;
    bool convex_exact_ = false;
    int primitives_ = 1;
};

}  // namespace locus::render::sdf
