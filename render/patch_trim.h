// Trimming an implicit surface to the parametric patch it came from. A Bézier patch's implicit
// equation describes the whole algebraic surface — sheets beyond the patch's edges, and for a
// degenerate map further pieces — while CAD means only the image of the parameter domain (the
// unit square, or the triangle s, t ≥ 0, s + t ≤ 1; for a parametrization, the box of its
// `domain:` line). A hit of the implicit surface counts only
// when some preimage of the hit point lies in the domain; otherwise the ray goes on to the next
// root (first_hit_trimmed).
//
// The preimage is found numerically: the closest of a grid of domain samples starts
// Gauss–Newton iterations on |P(s,t)/W(s,t) − p|², and the hit is on the patch when the
// residual is below a distance tolerance and (s, t) lies in the domain up to 1e-7 of its size. This
// is a floating-point decision, not a certified one: a hit within the tolerance of the patch's edge
// may go either way.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "render/certified_tracer.h"
#include "render/root_finder.h"
#include "render/vec3.h"

namespace locus::render {

// The distance, relative to the scene's size, within which a hit counts as on the patch.
inline constexpr double kTrimTolerance = 1e-6;

struct BivariateTerm {
    double coefficient;
    int es, et;  // exponents of s and t
};

// A box [s0, s1] × [t0, t1] of parameters (the unit square for tensor-product patches, the
// user's `domain:` for .param files).
struct ParameterBox {
    double s0 = 0.0, s1 = 1.0, t0 = 0.0, t1 = 1.0;
};

class PatchTrim {
  public:
    // A triangular domain is s, t ≥ 0, s + t ≤ 1, whatever the box.
    enum class Domain { box, triangle };
    using Box = ParameterBox;
    // `map`: X, Y, Z and the common denominator W (the constant 1 for polynomial patches).
    PatchTrim(std::array<std::vector<BivariateTerm>, 4> map, Domain domain, Box box = {});

    // Is p the image of a point of the domain, within `tolerance` (a distance)?
    bool contains(const Vec3& p, double tolerance) const;
    // The preimage found for p (meaningful when contains(p) is true), for tests.
    std::array<double, 2> preimage(const Vec3& p) const;
    // The patch's point at (s, t).
    Vec3 at(double s, double t) const;

    Domain domain() const { return domain_; }
    const Box& box() const { return box_; }

    // The map's point at (s, t) and its partial derivatives.
    struct Value {
        Vec3 point{0.0};
        Vec3 ds{0.0}, dt{0.0};
    };
    // A domain sample: the grid of starting points for the preimage search, computed once.
    struct Sample {
        double s, t;
        Vec3 point;
    };

  private:
    struct Preimage;
    Value evaluate(double s, double t, bool derivatives) const;
    bool in_domain(double s, double t) const;
    Preimage refine(const Vec3& p, double s, double t, double close_enough) const;
    Preimage find_preimage(const Vec3& p, double good_enough) const;

    std::array<std::vector<BivariateTerm>, 4> map_;
    Domain domain_;
    Box box_;
    int highest_exponent_ = 0;  // of s or t in the map: the table of powers evaluate needs
    std::vector<Sample> samples_;
};

// The first root in `interval` whose point is on the patch: `first_hit(interval)` is asked
// again past every root off the patch, at most `max_roots` times (a line meets a surface of
// degree d at most d times); the work adds up. Without a trim, first_hit(interval) itself.
// When the roots run out of the budget the answer is RootStatus::unknown, never a guess.
// Intervals go by reference on the per-ray path: by value, GCC carried the pair through the
// stack in two 8-byte stores and one 16-byte load, a store-forwarding stall at every call
// (passing them by reference here and to first_hit_from took a sphere's frames from 25.5 to 29.9
// a second on one thread).
template <class FirstHit>
RootResult first_hit_trimmed(const PatchTrim* trim, const Ray& ray, const Interval& whole,
                             double tolerance, int max_roots, FirstHit&& first_hit) {
    RootResult hit = first_hit(whole);
    if (trim == nullptr) {
        return hit;
    }
    Interval interval = whole;
    int work = hit.work;
    for (int roots = 0; hit.status == RootStatus::hit; ++roots) {
        if (trim->contains(ray.at(hit.t), tolerance)) {
            break;
        }
        if (roots >= max_roots) {
            hit.status = RootStatus::unknown;
            hit.reason = "more roots off the patch than the degree allows";
            break;
        }
        // Past this root: ten times the renderer's hit tolerance (kRenderTolerance, relative),
        // so that the same root is not found again; roots closer than that are one point in a
        // picture.
        interval.lo = hit.t + 10.0 * kRenderTolerance * std::max(1.0, std::abs(hit.t));
        if (interval.is_empty()) {
            hit = RootResult{};
            break;
        }
        hit = first_hit(interval);
        work += hit.work;
    }
    hit.work = work;
    return hit;
}

}  // namespace locus::render
