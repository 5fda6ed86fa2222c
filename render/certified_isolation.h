// Certified isolation of the first root of a polynomial known up to its Bernstein coefficients'
// radii (render/bernstein_ball.h), and certified narrowing of an isolated root. Every decision
// holds for every polynomial inside the ball — so for the exact restriction of the exact
// surface, whenever the ball's radii are rigorous — or is not taken: the answer is then
// "undecided" and the caller escalates (a tighter expansion, double-double, exact arithmetic).
//
// The rule: on a piece, let V be the number of sign changes of the exact Bernstein
// coefficients. The number of roots in the piece is at most V and has its parity (Lane &
// Riesenfeld 1981). With uncertain signs V is not known, but V_max — the most sign changes any
// choice of the uncertain signs gives — bounds it. V_max = 0: no root (every coefficient
// certainly of one sign). V_max = 1 with end coefficients (the values at the ends) certainly of
// opposite signs: V = 1, exactly one root, simple. Otherwise split at the middle, left first.
#pragma once

#include "render/bernstein_ball.h"

namespace locus::render {

struct Isolation {
    enum class Kind {
        no_root,    // no root in [0, 1]
        one_root,   // exactly one root in [lo, hi], none in [0, lo); G(lo) has sign `sign_at_lo`
        undecided,  // no root in [0, lo); [lo, hi] could not be decided at the depth limit
    };
    Kind kind = Kind::no_root;
    double lo = 0.0, hi = 1.0;  // dyadic, exact
    int sign_at_lo = 0;
    BernsteinBall piece;  // the ball on [lo, hi], mapped to [0, 1]
    int work = 0;         // pieces examined
};

// Pieces narrower than 2^-max_depth are not split (max_depth ≤ 52). Pieces that start after
// `end` are not looked at (a search that ends there): `no_root` then means none in [0, end],
// and a `one_root` piece may reach past `end`, with its root on either side.
Isolation isolate_first_root(const BernsteinBall& g, int max_depth, double end = 1.0);

// The same search over [start, 1] only (up to `end`), guided by a guess: the first root is
// expected in [guess − reach, guess + reach] (the neighbouring pixel's root and the width that
// isolated it). The piece before that window is tested whole first (from 0: one cut when it is
// certainly of one sign), then the window, then the rest — where bisection from `start` takes
// a cut for every level down to the root. A wrong guess costs those cuts, never the answer.
// A window reaching 1 (within 2^-30, when `end` is 1) is [a, 1]: one cut in all. Without a
// usable window (not inside (start, min(end, 1)), or NaN) the search is
// isolate_first_root's on [start, 1]. A search that ends well before 1 (the rest after the
// window, or the whole without one) is cut just past `end` first. The ends of a `one_root` or
// `undecided` piece are in g's σ and not dyadic: each is within 8u of the exact end of its
// piece.
Isolation isolate_first_root_near(const BernsteinBall& g, int max_depth, double start, double end,
                                  double guess, double reach);

// What one value of G places about its root, by the mean value theorem. `g` has exactly one
// root σ* in [0, 1], G of sign `sign_at_zero` before it and of the other sign after;
// G(s) ∈ [value − error, value + error] at some s ∈ [0, 1] within `blur` of the double
// `sigma` ∈ [0, 1]. Then σ* − s = −G(s)/G'(ξ) for some ξ between s and σ*, and `slopes` bounds
// G'(ξ) about the midpoint polynomial's slope at `sigma` (slope_bounds(g)). The result is a
// bracket of σ* within [0, 1] — [0, 1] itself when the bounds cannot tell (G' may vanish near
// σ*, or G(s) is too uncertain). From a point a ball's blur away from σ*, it
// places σ* to far below that blur: one evaluation where signs either side of σ* take two.
struct RootRange {
    double lo = 0.0, hi = 1.0;
};
RootRange mean_value_bracket(const MidpointPolynomial& midpoint, const SlopeBounds& slopes,
                             int sign_at_zero, double sigma, double blur, double value,
                             double error);

// The most sign changes of any choice of signs for the coefficients the ball leaves uncertain.
int most_sign_changes(const BernsteinBall& g);

// Narrows the one root of `piece` (G(0) of sign `sign_at_zero`, G(1) of the opposite sign) to a
// certified bracket [lo, hi] ⊆ [0, 1] of width ≤ `width`. `certified` is false when the ball's
// radii hide the root's position at that width (the caller needs more precision); lo and hi
// are then still a certified bracket, only wider. When the radii are plainly too wide for the
// width (largest radius over the slope at the estimate above a quarter of it), no probe is
// spent: the bracket is [0, 1] with the estimate.
struct Bracket {
    double lo = 0.0, hi = 1.0;
    bool certified = false;
    int work = 0;           // certified evaluations (MidpointPolynomial::enclose)
    int newton_steps = 0;   // evaluations of the midpoint polynomial that placed the estimate
    double estimate = 0.5;  // the root as the midpoint polynomial places it, in [lo, hi]
    double slope = 0.0;     // the midpoint polynomial's slope there (per unit of σ)
    double noise = 0.0;     // the largest radius: the root is within ≈ noise/|slope| of it
};
// `midpoint` is MidpointPolynomial(piece), which the caller may use again.
Bracket narrow_root(const BernsteinBall& piece, const MidpointPolynomial& midpoint,
                    int sign_at_zero, double width);

}  // namespace locus::render
