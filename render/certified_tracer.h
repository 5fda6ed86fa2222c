// The certified first hit of a ray with a surface — the `certified` method, the default of
// `locus render` and `locus trace`. Its contract (docs/rendering.md, "Accuracy"): for the exact
// surface f = 0 (the rational equation) and the exact ray o + t·d (the doubles given), the
// answer is
//   * a hit t with |t − t*| ≤ tolerance·max(1, |t*|), where t* is the smallest root of
//     F(t) = f(o + t·d) with lo < t ≤ hi — roots of every multiplicity, tangent touches
//     included; or
//   * a miss, only when F has no real root in (lo, hi].
// Nothing depends on the interval's length or the surface's scale.
//
// How (four tiers, each taken only when the one before cannot decide):
//  1. doubles with rigorous error bounds: the restriction of f to a segment of the ray with a
//     radius per coefficient (LineRestrictor::restrict_with_bounds), in the Bernstein basis,
//     roots isolated where no rounding can change the decision (certified_isolation.h); a
//     segment the radii blur is expanded again about its undecided piece, where the terms are
//     smaller;
//  2. a piece that re-expanding in doubles cannot decide (undecided at the interval's start, or
//     not shrinking) is restricted in double-double (restrict_with_double_double_bounds);
//  3. double-double evaluation of f at points of the ray (CompiledPolynomial::enclose_on_line)
//     to narrow a root that the balls isolated but cannot place to the tolerance;
//  4. exact arithmetic over Q (algebra::exact_first_root) for what none decides: tangent
//     rays, double roots, a root at the interval's start, rays lying in the surface — on the
//     undecided piece alone when it is at the start, the search going on past it.

#pragma once

#include <limits>

#include "algebra/compiled.h"
#include "render/bernstein_ball.h"
#include "render/ray_restriction.h"
#include "render/root_finder.h"
#include "render/vec3.h"

namespace locus::render {

// The accuracy contract of `locus trace`: |t − t*| ≤ 1e-12·max(1, |t*|).
inline constexpr double kTraceTolerance = 1e-12;
// The renderer's: which root is hit (or none) is decided exactly as for `locus trace`, and the
// hit is placed to 1e-7·max(1, |t*|) — the spacing of the 32-bit floats its depth layer is
// written in (6e-8 to 1.2e-7 relative; t is the depth along the view axis), a ten-thousandth
// of a pixel's depth step at 512², and a hundredth of the shadow rays' offset from a surface
// seen from ten times its size (a tenth from a hundred times; smaller scenes: below). Placing hits
// closer changes nothing the renderer writes: the suite's 8-bit pictures at 1e-9 differ in one
// channel of one pixel by one code, and 1e-9 cost endrass_octic's 512² frame 13 % more time (tier
// 3's evaluations at points, below).
inline constexpr double kRenderTolerance = 1e-7;
// The tolerance a frame's tracers take, for a scene whose clip regions reach `scale` from their
// centres: kRenderTolerance, times the scale when that is below 1 — max(1, |t|) is then 1, and
// the shadow rays' offset, 1e-4·scale, would otherwise be as small as the placement error (a
// scene of size 2e-3 seen from a few sizes away). Depths are then placed to 1e-7 of the scene.
inline double render_tolerance(double scale) {
    return scale > 0.0 && scale < 1.0 ? kRenderTolerance * scale : kRenderTolerance;
}

// What one primary ray's answer tells the next ray of its row: where its root was (NaN: no root)
// and the half-width of the piece that isolated it. A guess only (isolate_first_root_near):
// the next answer is certified all the same. And whether the family's balls have been deciding:
// a family too blurred to decide anything (degree 30: radii far above F's values near its
// roots) would cost every ray a fruitless search before it is traced alone, so after
// kFamilyFailuresBeforeRest undecided rays in a row the next kFamilyRest rays of the row are
// traced alone at once, and then the family is tried again (it may decide elsewhere).
// And whether roots have needed double-double evaluations: near the next ray's root, a pixel
// on, the doubles' error bound is likely as far above what the tolerance allows (at degree 30
// it nearly always is), so after a ray whose doubles fell short the next kDoublesRest rays of
// the row are narrowed in double-double at once, and then doubles are tried again.
struct NeighbourHint {
    double t = std::numeric_limits<double>::quiet_NaN();
    double reach = 0.0;
    int doubles_rest = 0;     // rays still to narrow without evaluating in doubles first
    int family_failures = 0;  // searches of the ball in a row that decided nothing
    int family_rest = 0;      // rays still to trace alone
};
inline constexpr int kFamilyFailuresBeforeRest = 8;
// Subdivision depth of a ray family's ball, which cannot be expanded again without tracing the
// ray alone.
inline constexpr int kFamilyDepth = 10;
inline constexpr int kFamilyRest = 32;
inline constexpr int kDoublesRest = 16;

class CertifiedTracer {
  public:
    // The polynomial must outlive the tracer.
    explicit CertifiedTracer(const algebra::CompiledPolynomial& f);

    // The first root in (interval.lo, interval.hi] to within `tolerance`·max(1, |t|), or a miss.
    // `hint`, when given, is the previous ray of the row's answer: the first segment's search
    // looks near its root first (isolate_first_root_near), and the hint is updated for the next
    // ray. A guess only: the answer is certified all the same.
    RootResult first_hit(const Ray& ray, Interval interval, double tolerance,
                         NeighbourHint* hint = nullptr) const;

    // The same, starting from a ball that a ray family computed for this ray: `ball` is the
    // restriction G(σ) = F(t0 + σ·width), σ ∈ [0, 1], of the exact ray with rigorous radii,
    // and [t0, t0 + width] ⊇ the interval to search. The ball's decision is used where it is
    // certain; the ray is traced alone (first_hit) where it is not. `hint`, when given, guides
    // the search and is updated for the next ray.
    RootResult first_hit_from(const BernsteinBall& ball, double t0, double width, const Ray& ray,
                              const Interval& interval, double tolerance,
                              NeighbourHint* hint = nullptr) const;

    // Statistics of the tiers (for tests and benchmarks) are in RootResult::decided_by.

  private:
    struct Piece;
    // first_hit with the guess (t, NaN for none) and its reach for the first segment's search;
    // `piece_reach` receives the half-width of the piece that isolated a root found by the balls.
    // `doubles_first`: whether narrow() evaluates in doubles before double-double.
    RootResult search(const Ray& ray, Interval interval, double tolerance, double guess,
                      double guess_reach, bool doubles_first, double& piece_reach) const;
    RestrictionBall segment_ball(const Ray& ray, double a, double b) const;
    // The same in double-double (LineRestrictor::restrict_with_double_double_bounds).
    RestrictionBall segment_ball_precise(const Ray& ray, double a, double b) const;
    RootResult narrow(const Ray& ray, const Piece& piece, double tolerance, int work,
                      bool doubles_first = true) const;
    RootResult exact(const Ray& ray, Interval interval, int work) const;

    const algebra::CompiledPolynomial* f_;
    LineRestrictor restrictor_;
    double coefficient_error_;
};

}  // namespace locus::render
