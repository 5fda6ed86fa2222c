// Descartes' rule of signs on Bernstein coefficients with de Casteljau subdivision, for the first
// root of F on [lo, hi].
//
// F is mapped to G(s) = F(lo + (hi − lo)·s) on [0, 1] (detail/univariate.h) and converted to
// the Bernstein basis of degree n. On a piece [a, a + h] the number V of sign changes of the
// Bernstein coefficients bounds the number of roots inside and has the same parity (Lane &
// Riesenfeld, "Bounds on a polynomial", BIT 21 (1981) 112–117): V = 0 — no root; V = 1 —
// exactly one, refined by regula falsi (detail::regula_falsi); V ≥ 2 — look at the control
// polygon of G' (differences of the coefficients): G monotone on the piece has at most one
// root, G with one critical point c at most two, found from the signs of G(a), G(c), G(b) and
// refined the same way. Only pieces where G' has several sign changes are split at the
// midpoint by de Casteljau, left half first, so the first root found is the first root. An
// explicit stack holds the pending right halves (one per level): nothing is allocated.
//
// Even-multiplicity roots never produce a sign change of G, so they are caught as critical
// points where G touches zero within rounding (detail::touches_zero), and pieces whose
// coefficients come within the rounding noise of G (kTouchFactor) are examined rather than
// dropped. A piece narrower than the root tolerance that still has to be split is a cluster
// of roots and a hit at its midpoint.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "render/root_finder.h"
#include "render/root_finders/detail/univariate.h"

namespace locus::render {
namespace {

using detail::Coefficients;

// Subdivision depth limit: the root tolerance (≥ 8ε in s) is reached by depth 50, so the limit
// only bounds the stack.
constexpr int kMaxDepth = 56;

// Width, relative to the piece, to which a critical point is located before G's sign there is
// looked at; only a possible tangent needs it to the root tolerance.
constexpr double kCoarseCritical = 1e-6;

// Total subdivisions allowed for one ray before the method gives up (RootStatus::unknown).
constexpr int kMaxSubdivisions = 2000;

// Splits the piece with coefficients `left` at its midpoint: `left` becomes the left half and
// `right` the right half (de Casteljau at s = 1/2).
void split_half(Coefficients& left, Coefficients& right, int n) {
    std::copy(left.begin(), left.begin() + n + 1, right.begin());
    for (int k = 1; k <= n; ++k) {
        for (int i = 0; i <= n - k; ++i) {
            right[i] = 0.5 * (right[i] + right[i + 1]);
        }
        left[k] = right[0];
    }
}

}  // namespace

RootResult BernsteinRootFinder::first_root(const RayPolynomial& f, double lo, double hi) const {
    const detail::Screening screening = detail::screen(f, lo, hi);
    if (screening.done) {
        return screening.result;
    }
    detail::UnitRestriction u;
    if (!detail::map_to_unit_interval(f, screening.degree, lo, hi, u)) {
        return detail::unknown("coefficients overflow on the interval", 0);
    }
    const Coefficients& g = u.g;
    const int n = u.degree;
    const double tol = detail::unit_tolerance(u.w);
    // G is normalised to max |g_k| = 1, so |G| ≤ n + 1 on [0, 1] bounds its rounding scale.
    const double touch = detail::kTouchFactor * (n + 1) * detail::kEpsilon;
    Coefficients dg;
    detail::derivative(g.data(), n, dg.data());

    int work = 0;
    const auto at = [&](double s) { return detail::hit(detail::from_unit(s, lo, hi), work); };
    // A hit at an end s of a piece of width h where F touches zero: when the touch comes from a
    // tangent within the piece's reach, the critical point is far more accurate than the end.
    const auto at_end = [&](double s, double h) {
        const double t = detail::critical_point_near(u, s, work);
        const double end = detail::from_unit(s, lo, hi);
        if (t >= lo && t <= hi && std::abs(t - end) <= h * u.w && detail::touches_zero(u, t)) {
            return detail::hit(t, work);
        }
        return detail::hit(end, work);
    };
    const auto touches_at = [&](double s) {
        return detail::touches_zero(u, detail::from_unit(s, lo, hi));
    };
    // The root in [a, b] when G(a)·G(b) < 0 (Horner values), NaN when the basis that rounds
    // less sees no sign change.
    const auto refine = [&](double a, double b, double ga, double gb) {
        return detail::refine_root(u, detail::RootOf::value, {a, b, ga, gb}, work);
    };

    // G on [a, b] (width h, values ga, gb) with at most one root: it by refinement when the ends
    // differ in sign, else a touch at an end; empty when neither settles the piece.
    const auto settle_by_ends = [&](double a, double b, double h, double ga,
                                    double gb) -> std::optional<RootResult> {
        if (ga != 0.0 && gb != 0.0 && (ga < 0.0) != (gb < 0.0)) {
            if (const double t = refine(a, b, ga, gb); !std::isnan(t)) {
                return detail::hit(t, work);
            }
        }
        if (touches_at(a)) {
            return at_end(a, h);
        }
        if (touches_at(b)) {
            return at_end(b, h);
        }
        return std::nullopt;
    };

    // G on [a, b] (width h, values ga, gb) with one critical point, located roughly at tc:
    // monotone on [a, c] and on [c, b]. A rough c is enough to bracket a root in [a, c], or to
    // rule out a tangent when |G(c)| exceeds what the error in c can hide (|G''| ≤ n²(n+1) on
    // [0, 1] as max |g_k| = 1); only a possible tangent needs c to the tolerance. Empty when
    // the piece holds neither a root nor a tangent.
    const auto unimodal = [&](double a, double b, double h, double ga, double gb, double da,
                              double db, double tc) -> std::optional<RootResult> {
        double c = std::clamp((tc - lo) / u.w, a, b);
        double gc = detail::horner(g.data(), n, c);
        const auto sign_change = [](double x, double y) {
            return x != 0.0 && y != 0.0 && (x < 0.0) != (y < 0.0);
        };
        if (sign_change(ga, gc)) {
            if (const double t = refine(a, c, ga, gc); !std::isnan(t)) {
                return detail::hit(t, work);
            }
        }
        const double coarse = kCoarseCritical * h;
        const double hidden = 0.5 * n * n * (n + 1.0) * coarse * coarse / u.kappa;
        if (gb != 0.0 && (gb < 0.0) == (gc < 0.0) && !detail::touches_zero(u, tc, hidden) &&
            !touches_at(a) && !touches_at(b)) {
            return std::nullopt;
        }
        if (const double precise =
                detail::refine_root(u, detail::RootOf::derivative, {a, b, da, db}, work);
            !std::isnan(precise)) {
            tc = precise;
            c = std::clamp((tc - lo) / u.w, a, b);
            gc = detail::horner(g.data(), n, c);
        }
        if (sign_change(ga, gc)) {
            if (const double t = refine(a, c, ga, gc); !std::isnan(t)) {
                return detail::hit(t, work);
            }
        }
        if (detail::touches_zero(u, tc)) {
            return detail::hit(tc, work);  // even multiplicity: a tangent
        }
        if (touches_at(a)) {
            return at_end(a, h);
        }
        if (sign_change(gc, gb)) {
            if (const double t = refine(c, b, gc, gb); !std::isnan(t)) {
                return detail::hit(t, work);
            }
        }
        if (touches_at(b)) {
            return at_end(b, h);
        }
        return std::nullopt;
    };

    // The piece being examined: [a, a + 2^-depth] with Bernstein coefficients `piece`; pending
    // right halves wait on the stack, innermost last.
    Coefficients piece;
    detail::to_bernstein(g, n, piece);
    double a = 0.0;
    int depth = 0;
    std::array<Coefficients, kMaxDepth> stack;
    std::array<double, kMaxDepth> stack_a;
    std::array<int, kMaxDepth> stack_depth;
    int top = 0;
    for (;;) {
        const double width = std::ldexp(1.0, -depth);
        const double b = a + width;
        int variations = 0;
        double smallest = std::abs(piece[0]);
        for (int i = 1; i <= n; ++i) {
            variations += (piece[i] < 0.0) != (piece[i - 1] < 0.0) ? 1 : 0;
            smallest = std::min(smallest, std::abs(piece[i]));
        }
        bool subdivide = false;
        if (variations == 0 && smallest > touch) {
            // The control polygon stays clear of zero: no root here.
        } else if (variations == 1) {
            // Exactly one root, a sign change of G: refine on the power form. If rounding
            // disagrees with the polygon (a root within noise of an end, or a polygon blurred
            // by rounding), a closer look settles it.
            const double ga = detail::horner(g.data(), n, a);
            const double gb = detail::horner(g.data(), n, b);
            if (const std::optional<RootResult> r = settle_by_ends(a, b, width, ga, gb)) {
                return *r;
            }
            subdivide = true;
        } else {
            // Several sign changes, or a polygon that touches zero: look at G' (coefficients
            // n·(b_{i+1} − b_i)). Monotone or unimodal G is settled without subdividing.
            int turns = 0;
            for (int i = 2; i <= n; ++i) {
                turns += (piece[i] - piece[i - 1] < 0.0) != (piece[i - 1] - piece[i - 2] < 0.0);
            }
            const double ga = detail::horner(g.data(), n, a);
            const double gb = detail::horner(g.data(), n, b);
            if (turns == 0) {
                if (const std::optional<RootResult> r = settle_by_ends(a, b, width, ga, gb)) {
                    return *r;
                }
            } else if (turns == 1) {
                const double da = detail::horner(dg.data(), n - 1, a);
                const double db = detail::horner(dg.data(), n - 1, b);
                const double tc =
                    da != 0.0 && db != 0.0 && (da < 0.0) != (db < 0.0)
                        ? detail::refine_root(u, detail::RootOf::derivative, {a, b, da, db}, work,
                                              {.coarse_s = kCoarseCritical * width})
                        : NAN;
                if (std::isnan(tc)) {
                    subdivide = true;  // rounding blurs the critical point; look closer
                } else if (const std::optional<RootResult> r =
                               unimodal(a, b, width, ga, gb, da, db, tc)) {
                    return *r;
                }
            } else {
                subdivide = true;
            }
        }
        if (subdivide) {
            if (width <= tol) {
                return at(a + 0.5 * width);  // a cluster narrower than the tolerance
            }
            if (depth >= kMaxDepth || work >= kMaxSubdivisions) {
                return detail::unknown("bernstein subdivision limit reached", work);
            }
            ++depth;
            stack_a[top] = a + std::ldexp(1.0, -depth);
            stack_depth[top] = depth;
            split_half(piece, stack[top], n);
            ++top;
            ++work;
            continue;
        }
        if (top == 0) {
            break;
        }
        --top;
        std::copy(stack[top].begin(), stack[top].begin() + n + 1, piece.begin());
        a = stack_a[top];
        depth = stack_depth[top];
    }
    return detail::is_zero_within_rounding(f.c.data(), screening.degree, hi) ? detail::hit(hi, work)
                                                                             : detail::miss(work);
}

}  // namespace locus::render
