#include "render/certified_isolation.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "render/detail/fixed_degree.h"
#include "render/detail/uninitialized_array.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace locus::render {

namespace {

// The set bits of x, inline: the baseline x86-64 has no popcnt instruction, and std::popcount
// there is a call into libgcc (2 % of a degree-8 frame).
constexpr int bit_count(std::uint64_t x) {
    x = x - ((x >> 1) & 0x5555555555555555ULL);
    x = (x & 0x3333333333333333ULL) + ((x >> 2) & 0x3333333333333333ULL);
    x = (x + (x >> 4)) & 0x0f0f0f0f0f0f0f0fULL;
    return static_cast<int>((x * 0x0101010101010101ULL) >> 56);
}
static_assert(bit_count(0) == 0 && bit_count(~0ULL) == 64 && bit_count(0x8000000000000001ULL) == 2);

// The sign changes of the coefficients when every sign is certain, −1 otherwise, for degree
// ≤ 62: a bit a coefficient for "certainly positive" and one for "certainly negative", two
// coefficients per SSE2 comparison (movmskpd), then the changes are the bits where the positive
// mask differs from its neighbour — no chain of dependent tests through the coefficients.
// Unrolled for a degree known at compile time (`Fixed` ≥ 0; −1 reads the ball's).
template <int Fixed>
int certain_sign_changes(const BernsteinBall& g) {
    const int n = Fixed >= 0 ? Fixed : g.degree;
    std::uint64_t positive = 0, negative = 0;
    int i = 0;
#if defined(__SSE2__)
    const __m128d zero = _mm_setzero_pd();
#pragma GCC unroll 8
    for (; i + 1 <= n; i += 2) {
        const __m128d b = _mm_loadu_pd(&g.b[static_cast<std::size_t>(i)]);
        const __m128d r = _mm_loadu_pd(&g.r[static_cast<std::size_t>(i)]);
        positive |=
            static_cast<std::uint64_t>(_mm_movemask_pd(_mm_cmpgt_pd(_mm_sub_pd(b, r), zero))) << i;
        negative |=
            static_cast<std::uint64_t>(_mm_movemask_pd(_mm_cmplt_pd(_mm_add_pd(b, r), zero))) << i;
    }
#endif
    for (; i <= n; ++i) {
        const auto k = static_cast<std::size_t>(i);
        positive |= static_cast<std::uint64_t>(g.b[k] - g.r[k] > 0.0) << i;
        negative |= static_cast<std::uint64_t>(g.b[k] + g.r[k] < 0.0) << i;
    }
    const std::uint64_t every = (std::uint64_t{2} << n) - 1;
    if ((positive | negative) != every) {
        return -1;
    }
    return bit_count((positive ^ (positive >> 1)) & (every >> 1));
}

// A ball's degree and coefficients 0..degree, the only ones ever read: a whole ball is 1 KB,
// and copying it whole was a tenth of isolate_into's time.
void copy_ball(const BernsteinBall& from, BernsteinBall& to) {
    to.degree = from.degree;
    const auto count = static_cast<std::size_t>(std::max(from.degree + 1, 0));
    std::copy_n(from.b.begin(), count, to.b.begin());
    std::copy_n(from.r.begin(), count, to.r.begin());
}

}  // namespace

int most_sign_changes(const BernsteinBall& g) {
    // Most pieces have every sign certain: the changes are then counted as they are.
    // (Degree −1, the zero polynomial, and degrees past the masks' 62 take the search below.)
    const int changes =
        g.degree >= 0 && g.degree <= 62
            ? detail::with_fixed_degree(
                  g.degree,
                  [&](auto fixed) { return certain_sign_changes<decltype(fixed)::value>(g); })
            : -1;
    if (changes >= 0) {
        return changes;
    }
    // The most changes of a choice of signs for coefficients 0..i that ends negative (or
    // positive); −1 when coefficient i cannot have that sign.
    int negative = -1, positive = -1;
    for (int i = 0; i <= g.degree; ++i) {
        const int s = g.sign(i);
        const int from_negative = negative, from_positive = positive;
        if (i == 0) {
            negative = s <= 0 ? 0 : -1;
            positive = s >= 0 ? 0 : -1;
            continue;
        }
        negative =
            s <= 0 ? std::max(from_negative, from_positive >= 0 ? from_positive + 1 : -1) : -1;
        positive =
            s >= 0 ? std::max(from_positive, from_negative >= 0 ? from_negative + 1 : -1) : -1;
    }
    return std::max(negative, positive);
}

namespace {

// isolate_first_root into an Isolation the caller owns (a ball is 0.6 KB: the guided search
// returns the one it was given rather than copies).
void isolate_into(const BernsteinBall& g, int max_depth, double end, Isolation& out) {
    out.kind = Isolation::Kind::no_root;
    out.lo = 0.0;
    out.hi = 1.0;
    out.sign_at_lo = 0;
    out.work = 0;
    max_depth = std::clamp(max_depth, 0, 52);
    if (g.degree < 0) {
        out.kind = Isolation::Kind::undecided;  // the zero polynomial: every point is a root
        copy_ball(g, out.piece);
        return;
    }
    // Pending right halves, innermost last; the piece being examined is [a, a + 2^-depth], in
    // `g`, `left` or the stack (no copies: a split may write over the piece it splits). The
    // stack is left uninitialised: a ball's default degree, stored for all 53 at every call,
    // was a tenth of this function's time.
    detail::UninitializedArray<BernsteinBall, 53> stack;
    std::array<double, 53> stack_a;
    std::array<int, 53> stack_depth;
    int top = 0;
    BernsteinBall left;
    const BernsteinBall* piece = &g;
    double a = 0.0;
    int depth = 0;
    for (;;) {
        ++out.work;
        // A piece past the end of the search, and every piece after it, is not looked at.
        const int changes = a > end ? 0 : most_sign_changes(*piece);
        if (a > end) {
            top = 0;
        }
        const double width = 1.0 / static_cast<double>(std::uint64_t{1} << depth);  // exact
        const int first = piece->sign(0);
        const int last = piece->sign(piece->degree);
        if (changes == 1 && first != 0 && last != 0 && first != last) {
            out.kind = Isolation::Kind::one_root;
            out.lo = a;
            out.hi = a + width;
            out.sign_at_lo = first;
            copy_ball(*piece, out.piece);
            return;
        }
        if (changes != 0) {
            if (depth >= max_depth) {
                out.kind = Isolation::Kind::undecided;
                out.lo = a;
                out.hi = a + width;
                copy_ball(*piece, out.piece);
                return;
            }
            ++depth;
            stack_a[top] = a + 0.5 * width;
            stack_depth[top] = depth;
            split_half(*piece, left, stack[top]);
            piece = &left;
            ++top;
            continue;
        }
        if (top == 0) {
            out.kind = Isolation::Kind::no_root;
            return;
        }
        --top;
        piece = &stack[top];
        a = stack_a[top];
        depth = stack_depth[top];
    }
}

}  // namespace

Isolation isolate_first_root(const BernsteinBall& g, int max_depth, double end) {
    Isolation out;
    isolate_into(g, max_depth, end, out);
    return out;
}

// A search that ends before this point of its piece is cut at its end first: bisection up to
// the end splits every piece that straddles it and shows a root past it (the surface beyond
// the clip sphere) or a near one. The cut is rounded up (by 8u: its quotient rounds twice,
// its use once more), so that the piece holds the whole search, and a root it finds past the
// end is the caller's to check, as when a piece reaches past it (first_hit_from).
constexpr double kCutEnd = 0.75;
constexpr double kRoundUp = 1.0 + 8.0 * 0x1.0p-53;

Isolation isolate_first_root_near(const BernsteinBall& g, int max_depth, double start, double end,
                                  double guess, double reach) {
    max_depth = std::clamp(max_depth, 0, 52);
    // A piece [base, base + scale] of g searched alone: pieces narrower than 2^-max_depth of g
    // are still not split (ilogb(scale) ≤ log2(scale)), and its ends map back to g's σ.
    const auto depth_within = [&](double scale) {
        return std::max(0, max_depth + std::ilogb(scale));
    };
    Isolation out;  // every path returns this one (no copies)
    int work = 0;
    const auto map_back = [&](double base, double scale) {
        out.lo = base + out.lo * scale;
        out.hi = out.hi == 1.0 ? base + scale : base + out.hi * scale;
        out.work += work;
    };
    const double a = guess - reach, b = guess + reach;
    // A window reaching the end of a search to the end: [a, 1] (a caller that cut its segment
    // at the window's end, to spare the cut).
    const bool window_to_end = b >= 1.0 - 0x1.0p-30 && end >= 1.0;
    if (g.degree < 1 || !(a > start) || !(window_to_end || b < std::min(end, 1.0)) || !(b > a)) {
        // No usable guess: cut at `start` (and at `end`, kCutEnd), bisect what is between.
        if (!(start > 0.0) && !(end < kCutEnd)) {
            isolate_into(g, max_depth, end, out);
            return out;
        }
        BernsteinBall skipped, rest;
        const BernsteinBall* searched = &g;
        double scale = 1.0;
        if (start > 0.0) {
            split_at(g, start, skipped, rest);
            searched = &rest;
            ++work;
            scale = 1.0 - start;
        }
        const double rest_end = (end - std::max(start, 0.0)) / scale;
        const bool cut = rest_end > 0.0 && rest_end < kCutEnd;
        if (cut) {
            split_at(*searched, rest_end * kRoundUp, rest, skipped);
            searched = &rest;
            ++work;
            scale *= rest_end * kRoundUp;
        }
        isolate_into(*searched, depth_within(scale), cut ? 1.0 : rest_end, out);
        map_back(std::max(start, 0.0), scale);
        return out;
    }
    // [0, a] whole first — the stretch before `start` too: a piece certainly of one sign
    // throughout (the common case) costs one cut; otherwise [start, a] is cut from it.
    BernsteinBall before, after;
    split_at(g, a, before, after);
    ++work;
    if (most_sign_changes(before) != 0) {
        double base = 0.0, scale = a;
        if (start > 0.0) {
            // [a·c, a] with a·c ≤ start: the cut rounded down so that no root after `start` is
            // skipped. A root this finds in the sliver before `start` (within a few roundings of
            // it) is before the interval, which the caller checks (first_hit_from).
            const double cut = start / a * (1.0 - 8.0 * 0x1.0p-53);
            BernsteinBall skipped;
            split_at(before, cut, skipped, before);
            ++work;
            base = a * cut;
            scale = a - base;
        }
        isolate_into(before, depth_within(scale), 1.0, out);
        if (out.kind != Isolation::Kind::no_root) {
            map_back(base, scale);
            return out;
        }
        work += out.work;
    }
    // The window [a, h], h = a + τ·(1 − a) ≈ b, then [h, 1].
    const double rest = 1.0 - a;
    if (window_to_end) {
        isolate_into(after, depth_within(rest), 1.0, out);
        map_back(a, rest);
        return out;
    }
    const double tau = (b - a) / rest;
    BernsteinBall window, beyond;
    split_at(after, tau, window, beyond);
    ++work;
    const double window_width = tau * rest;
    isolate_into(window, depth_within(window_width), 1.0, out);
    if (out.kind != Isolation::Kind::no_root) {
        map_back(a, window_width);
        return out;
    }
    work += out.work;
    const double h = a + window_width;
    double beyond_width = 1.0 - h;
    const double beyond_end = (end - h) / beyond_width;
    // h is itself within a few u of the piece's exact start: the cut goes 4u past `end`.
    const double end_cut = (end + 4.0 * 0x1.0p-53 - h) / beyond_width * kRoundUp;
    const bool cut = beyond_end > 0.0 && end_cut < kCutEnd;
    if (cut) {
        BernsteinBall skipped;
        split_at(beyond, end_cut, beyond, skipped);
        ++work;
        beyond_width *= end_cut;
    }
    isolate_into(beyond, depth_within(beyond_width), cut ? 1.0 : beyond_end, out);
    map_back(h, beyond_width);
    return out;
}

Bracket narrow_root(const BernsteinBall& piece, const MidpointPolynomial& midpoint,
                    int sign_at_zero, double width) {
    Bracket out;
    double a = 0.0, b = 1.0;  // G(a) has sign_at_zero, G(b) the opposite, both certified
    const auto sign_at = [&](double p) {
        ++out.work;
        return midpoint.enclose(p).sign();  // O(n); evaluate() is O(n²)
    };
    // The root of the midpoint polynomial by safeguarded Newton (a Newton step that leaves the
    // bracket of the midpoint polynomial's own signs, or does not halve it, is replaced by
    // bisection): the estimate, and whether the radii leave any hope of placing the root to
    // `width`. Past the radii's own blur (noise over slope) more steps only polish a guess the
    // radii cannot confirm; a caller that must place the root better takes it from there.
    double noise = 0.0;
    for (int i = 0; i <= piece.degree; ++i) {
        noise = std::max(noise, piece.r[i]);
    }
    double slope = 0.0;
    {
        double lo = 0.0, hi = 1.0, x = 0.5;
        // The start: where the control polygon crosses zero (its vertices are (i/n, b_i)),
        // nearer the root than the chord between the end values, and its slope there.
        const int n = piece.degree;
        for (int i = 0; i < n; ++i) {
            const double here = piece.b[i], next = piece.b[i + 1];
            if ((here > 0.0) != (next > 0.0) && here != next && std::isfinite(here - next)) {
                x = std::clamp((i + here / (here - next)) / n, 0.0, 1.0);
                slope = n * (next - here);  // until Newton has its own
                break;
            }
        }
        double previous_step = 1.0;
        const auto resolved = [&](double step) {
            return step <= 1e-3 * width || step * std::abs(slope) <= noise;
        };
        for (int step = 0; step < 100 && !resolved(hi - lo) && !resolved(previous_step); ++step) {
            const ValueSlope e = midpoint.at(x);
            ++out.newton_steps;
            slope = e.slope;
            if (e.value == 0.0) {
                break;
            }
            if ((e.value > 0.0) == (sign_at_zero > 0)) {
                lo = x;
            } else {
                hi = x;
            }
            double next = x - e.value / e.slope;
            // A Newton step already below the resolution: x is the estimate. Without this, a
            // value that rounding gives the wrong sign at the root (±1e-16) made the next step
            // leave the bracket it had just closed on x, and bisection threw the estimate back
            // to the middle of the bracket: 13 % of the Whitney umbrella's roots took 14 to
            // 100 steps instead of 4–5.
            if (resolved(std::abs(next - x))) {
                if (next > lo && next < hi) {
                    x = next;
                }
                break;
            }
            if (!(next > lo && next < hi) || std::abs(next - x) > 0.5 * previous_step) {
                next = 0.5 * (lo + hi);
            }
            previous_step = std::abs(next - x);
            x = next;
        }
        out.estimate = x;
        out.slope = slope;
        out.noise = noise;
        if (!(noise < 0.25 * width * std::abs(slope))) {
            return out;
        }
    }
    // The last Newton step was then below 1e-3·width or below noise/|slope| < 0.25·width, and
    // the estimate's error far below the step (Newton converges quadratically): the estimate is
    // the first proposal, without recomputing it.
    bool proposed = true;
    bool bisect = false;
    for (int iteration = 0; iteration < 200 && b - a > width; ++iteration) {
        // A proposal from the midpoint polynomial: regula falsi between a and b, then Newton;
        // the midpoint of [a, b] after a proposal that did not halve the bracket.
        double x = 0.5 * (a + b);
        if (proposed) {
            x = out.estimate;
            proposed = false;
        } else if (!bisect) {
            const ValueSlope at_a = midpoint.at(a), at_b = midpoint.at(b);
            if (at_a.value != at_b.value && std::isfinite(at_a.value) &&
                std::isfinite(at_b.value)) {
                const double secant = a - at_a.value * (b - a) / (at_b.value - at_a.value);
                if (secant > a && secant < b) {
                    x = secant;
                }
            }
            for (int step = 0; step < 8; ++step) {
                const ValueSlope e = midpoint.at(x);
                const double next = x - e.value / e.slope;
                if (!(next > a && next < b)) {
                    break;
                }
                const bool converged = std::abs(next - x) <= 0.0625 * width;
                x = next;
                if (converged) {
                    break;
                }
            }
        }
        // Certified signs either side of x, a quarter width away, and 8, 64, … times farther
        // while the radii hide the sign: each certain sign moves an end of the bracket.
        const double before = b - a;
        bool hidden_left = false, hidden_right = false;
        for (double h = 0.25 * width;; h *= 8.0) {
            const double p = x - h;
            if (!(p > a)) {
                break;
            }
            const int s = sign_at(p);
            if (s != 0) {
                (s == sign_at_zero ? a : b) = p;
                break;
            }
            hidden_left = hidden_left || h == 0.25 * width;
        }
        for (double h = 0.25 * width;; h *= 8.0) {
            const double p = x + h;
            if (!(p < b) || !(p > a)) {
                break;
            }
            const int s = sign_at(p);
            if (s != 0) {
                (s == sign_at_zero ? a : b) = p;
                break;
            }
            hidden_right = hidden_right || h == 0.25 * width;
        }
        if (b - a > 0.5 * before) {
            // Both signs next to x hidden by the radii: the root's position is not resolved at
            // this width. Otherwise the proposal was poor: bisect next.
            if (hidden_left && hidden_right) {
                break;
            }
            bisect = true;
        } else {
            bisect = false;
        }
    }
    out.lo = a;
    out.hi = b;
    out.certified = b - a <= width;
    out.estimate = std::clamp(out.estimate, a, b);
    return out;
}

RootRange mean_value_bracket(const MidpointPolynomial& midpoint, const SlopeBounds& slopes,
                             int sign_at_zero, double sigma, double blur, double value,
                             double error) {
    constexpr double lo = 0.0, hi = 1.0;  // where σ* is known to lie
    RootRange out{lo, hi};
    constexpr double kUnit = 0x1.0p-53;
    constexpr double kSlack = 1.0 + 8.0 * kUnit;  // a few roundings of a product or quotient
    const double slope = std::abs(midpoint.at(sigma).slope);
    const double size = (std::abs(value) + error) * kSlack;  // ≥ |G(s)|
    if (!(sigma >= 0.0 && sigma <= 1.0) || !(blur >= 0.0) || !std::isfinite(size) ||
        !(slope > 0.0) || !std::isfinite(slope)) {
        return out;
    }
    // The bound on |G'(ξ) − slope| when |ξ − s| ≤ ρ (so |ξ − σ| ≤ ρ + blur); below half the
    // slope, slope − e is within 2u of exact.
    const auto slope_error = [&](double reach) {
        return (slopes.point_error + slopes.curvature * (reach + blur)) * kSlack;
    };
    // A first bound ρ on |σ* − s|: the bracket's; the hull's when G' keeps one sign on [0, 1]
    // (|σ* − s| ≤ |G(s)|/min|G'|); or, for ρ = four Newton distances with [s − ρ, s + ρ] inside
    // [0, 1]: when |G'| ≥ L > |G(s)|/ρ there, G is monotone on that interval and takes both signs
    // at its ends, so its root there is σ*, the only one in [0, 1].
    double reach = std::max(sigma + blur - lo, hi - sigma + blur) * kSlack;
    const double hull_gap =
        slopes.hull_lo > 0.0 ? slopes.hull_lo : (slopes.hull_hi < 0.0 ? -slopes.hull_hi : 0.0);
    if (hull_gap > 0.0) {
        reach = std::min(reach, size / hull_gap * kSlack);
    }
    const double candidate = 4.0 * size / slope;
    if (candidate < reach && sigma - blur - candidate >= 4.0 * kUnit &&
        sigma + blur + candidate <= 1.0 - 4.0 * kUnit) {
        const double e = slope_error(candidate);
        if (e < 0.5 * slope && size / (slope - e) * kSlack < candidate) {
            reach = candidate;
        }
    }
    // Each bound ρ gives |σ* − s| ≤ |G(s)|/(slope − e(ρ)), smaller once ρ is small.
    double error_bound = INFINITY;  // e(ρ) for the last ρ that gave a bound
    for (int i = 0; i < 4; ++i) {
        const double e = slope_error(reach);
        if (!(e < 0.5 * slope)) {
            break;
        }
        error_bound = e;
        const double next = size / (slope - e) * kSlack;
        if (!(next < reach)) {
            break;
        }
        reach = next;
    }
    if (!(error_bound < INFINITY)) {
        return out;
    }
    double below = sigma - blur - reach, above = sigma + blur + reach;
    if (std::abs(value) > error * (1.0 + 0x1.0p-50)) {
        // G(s)'s sign is certain: σ* is on the side where G has the other sign, at least
        // |G(s)|/max|G'| from s (|value| − error rounded down).
        const double certain = std::abs(value) - error - 2.0 * kUnit * (std::abs(value) + error);
        const double least = std::max(0.0, certain) / (slope + error_bound) / kSlack;
        if ((value > 0.0) == (sign_at_zero > 0)) {
            below = sigma - blur + least;
        } else {
            above = sigma + blur - least;
        }
    }
    // The sums above round by at most u of the larger magnitude, ≤ 2.
    out.lo = std::max(lo, below - 4.0 * kUnit);
    out.hi = std::min(hi, above + 4.0 * kUnit);
    if (!(out.lo <= out.hi)) {
        out = RootRange{lo, hi};  // only rounding can get here: keep what is known
    }
    return out;
}

}  // namespace locus::render
