// A polynomial on [0, 1] in the Bernstein basis, known up to a radius per coefficient: the
// exact coefficient i lies in [b[i] − r[i], b[i] + r[i]]. This is the object the certified root
// finder (render/certified_isolation.h) decides on, so every operation here keeps the radii
// rigorous: each computed coefficient's rounding is bounded by γ_k·Σ|terms| (Higham, "Accuracy
// and Stability of Numerical Algorithms", 2nd ed., §3.1: γ_k = k·u/(1 − k·u), u = 2^-53) and
// added to the radius, which is itself rounded up. The operations have positive weights (the
// conversion from powers on [0, 1], de Casteljau), so radii only ever add.
//
// Why Bernstein: the coefficients' signs bound the number of roots on the interval (Descartes'
// rule in the Bernstein basis, Lane & Riesenfeld, BIT 21 (1981)), the end coefficients are the
// values at the ends, and subdivision converges to the values — all three survive uncertainty
// in every coefficient, which is what a decision under rounding needs.
#pragma once

#include <array>
#include <cmath>

#include "render/ray_restriction.h"
#include "render/root_finder.h"

namespace locus::render {

// Coefficients past `degree` are never read, and are left uninitialised: balls live in
// per-ray stacks of up to 53 of them.
struct BernsteinBall {
    int degree = -1;
    std::array<double, kMaxDegree + 1> b;
    std::array<double, kMaxDegree + 1> r;

    // +1 or −1 when coefficient i is certainly of that sign, 0 when it may be zero.
    // (Without branches: which way a coefficient goes is what the search cannot predict.)
    int sign(int i) const {
        return static_cast<int>(b[i] - r[i] > 0.0) - static_cast<int>(b[i] + r[i] < 0.0);
    }
};

// The power-basis ball G(x) = Σ g_k x^k (with radii) on x ∈ [−1, 1], in the Bernstein basis
// of its degree on that interval, mapped to σ = (1 + x)/2 ∈ [0, 1]. Restrictions are expanded
// about the middle of their segment: the terms there are as small as the segment allows
// ((|p| + |d|)^k rather than (|p| + 2|d|)^k about an end: 130 times smaller at degree 12 for a
// chord through the middle of a clip sphere), and so are the roundings.
BernsteinBall to_bernstein(const RestrictionBall& g);

// De Casteljau at σ = 1/2: the halves [0, 1/2] and [1/2, 1], each mapped to [0, 1].
// `left` or `right` may be `whole` itself (it is read before either is written).
void split_half(const BernsteinBall& whole, BernsteinBall& left, BernsteinBall& right);

// De Casteljau at the double τ ∈ (0, 1): the pieces [0, τ] and [τ, 1], each mapped to [0, 1].
// `left` or `right` may be `whole` itself.
void split_at(const BernsteinBall& whole, double tau, BernsteinBall& left, BernsteinBall& right);

// The value at the double σ ∈ [0, 1] (de Casteljau, O(n²)) with a rigorous radius.
struct BallValue {
    double value = 0.0;
    double radius = 0.0;
    int sign() const { return value - radius > 0.0 ? 1 : (value + radius < 0.0 ? -1 : 0); }
};
BallValue evaluate(const BernsteinBall& g, double sigma);

// The value and derivative of the midpoint polynomial (radii ignored) at σ, in O(n): for the
// Newton steps that only propose points, which evaluate() then certifies. The binomial weights
// are applied once per ball, for the many σ a search asks about.
struct ValueSlope {
    double value = 0.0;
    double slope = 0.0;
};
class MidpointPolynomial {
  public:
    explicit MidpointPolynomial(const BernsteinBall& g);
    // For σ ∈ [0, 1]; the slope is within SlopeBounds::point_error of the exact polynomial's.
    ValueSlope at(double sigma) const;
    // The exact polynomial's value at σ ∈ [0, 1] with a rigorous radius, in O(n) where
    // evaluate() takes O(n²): the radius is the ball's largest (Σ r_i·B_i(σ) ≤ max r_i) and the
    // roundings of at() (Higham's γ on every term, whose weights sum to one), the same for every
    // σ. evaluate()'s is smaller where the radii differ from coefficient to coefficient.
    BallValue enclose(double sigma) const;

  private:
    int degree_;
    double radius_ = INFINITY;                  // enclose()'s, for every σ
    std::array<double, kMaxDegree + 1> value_;  // b_i·C(n, i)
    std::array<double, kMaxDegree + 1> slope_;  // (b_{i+1} − b_i)·C(n − 1, i)
};

// What the ball says about the derivative of the exact polynomial it holds, rigorously, for a
// mean-value step (CertifiedTracer::narrow): for every σ, σ' ∈ [0, 1],
//   * G'(σ) ∈ [hull_lo, hull_hi], the hull of the derivative's Bernstein coefficients
//     n·(β_{i+1} − β_i) (empty of 0 when G is monotone there, and certainly so);
//   * |G'(σ) − MidpointPolynomial::at(σ).slope| ≤ point_error;
//   * |G'(σ) − G'(σ')| ≤ curvature·|σ − σ'|, curvature bounding |G''| by the hull of the second
//     differences n(n − 1)·(β_{i+2} − 2β_{i+1} + β_i).
// O(n), where evaluate() on the derivative would cost O(n²): the point's slope is the midpoint
// polynomial's, which Newton's steps compute anyway.
struct SlopeBounds {
    double hull_lo = -INFINITY, hull_hi = INFINITY;
    double point_error = INFINITY;
    double curvature = INFINITY;
};
SlopeBounds slope_bounds(const BernsteinBall& g);

}  // namespace locus::render
