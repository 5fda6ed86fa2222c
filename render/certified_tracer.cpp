#include "render/certified_tracer.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "algebra/double_double.h"
#include "render/certified_isolation.h"

namespace locus::render {

namespace {

constexpr double kUnit = 0x1.0p-53;
// What a subnormal result may lose, added to bounds that are otherwise relative.
constexpr double kTiny = 0x1.0p-1070;

// Subdivision depth of one segment's ball before its undecided piece is expanded afresh (the
// piece is then 64 times narrower than the segment, and its terms no larger than its own).
constexpr int kSegmentDepth = 6;
// Segments a ray may expand before the exact method decides.
constexpr int kMaxSegments = 16;

RootResult miss(int work) {
    RootResult r;
    r.status = RootStatus::miss;
    r.work = work;
    return r;
}

RootResult hit(double t, int work, Decision decided_by) {
    RootResult r;
    r.status = RootStatus::hit;
    r.t = t;
    r.work = work;
    r.decided_by = decided_by;
    return r;
}

// The hint's doubles_rest after a ray: a rest begins when the doubles were tried and a hit took
// double-double, and counts down while it lasts.
int next_doubles_rest(const NeighbourHint& before, bool doubles_first, const RootResult& result) {
    if (!doubles_first) {
        return before.doubles_rest - 1;
    }
    const bool fell_short =
        result.status == RootStatus::hit && result.decided_by == Decision::double_double;
    return fell_short ? kDoublesRest : 0;
}

// max(1, |t|) over [lo, hi]'s smallest magnitude: the scale of the tolerance there.
double tolerance_scale(double lo, double hi) {
    if (lo <= 0.0 && hi >= 0.0) {
        return 1.0;
    }
    return std::max(1.0, std::min(std::abs(lo), std::abs(hi)));
}

}  // namespace

// An isolated root: exactly one root of F in the exact t-range whose computed ends are t_lo and
// t_hi (each within `margin` of exact), none before it in the interval searched, and F(t_lo) of
// sign `sign_at_lo`. `ball` is the restriction on that range, mapped to [0, 1].
struct CertifiedTracer::Piece {
    const BernsteinBall& ball;
    int sign_at_lo = 0;
    double t_lo = 0.0, t_hi = 0.0;
    double margin = 0.0;
};

CertifiedTracer::CertifiedTracer(const algebra::CompiledPolynomial& f)
    : f_(&f), restrictor_(f.terms(), f.low_words()), coefficient_error_(f.coefficient_error()) {}

RestrictionBall CertifiedTracer::segment_ball(const Ray& ray, double a, double b) const {
    // The segment [a, b] about its middle, x ∈ [−1, 1]: the exact line is
    // m + x·h with m = o + a·d + h and h = (b − a)·d/2. o + a·d is rounded once (an FMA:
    // within u of exact, relative), h twice (b − a, then the product; halving is exact), and
    // m once more, with an error of its own that the restriction's balls carry.
    const double half_width = 0.5 * (b - a);
    Vec3 middle, half;
    LineError error;
    for (int i = 0; i < 3; ++i) {
        const double start = std::fma(a, ray.direction[i], ray.origin[i]);
        half[i] = half_width * ray.direction[i];
        middle[i] = start + half[i];
        error.direction[i] = std::abs(half[i]) * (2.03 * kUnit) + kTiny;
        error.origin[i] = std::abs(start) * (1.01 * kUnit) + error.direction[i] +
                          std::abs(middle[i]) * (1.01 * kUnit) + kTiny;
    }
    return restrictor_.restrict_with_bounds(middle, half, error, coefficient_error_);
}

RestrictionBall CertifiedTracer::segment_ball_precise(const Ray& ray, double a, double b) const {
    // The same line in double-double: b − a exactly (TwoSum, halved exactly), a·d exactly
    // (TwoProduct), then the start o + a·d, the half-width h and the middle m = start + h, each
    // a double-double operation within 5u² of its result (u = 2^-53).
    using algebra::DoubleDouble;
    const DoubleDouble width = algebra::two_sum(b, -a);
    const DoubleDouble half_width{0.5 * width.hi, 0.5 * width.lo};
    constexpr double kError = algebra::kOperationError * (1.0 + 0x1.0p-50);
    DoubleDoubleLine line;
    LineError error;
    for (int i = 0; i < 3; ++i) {
        const DoubleDouble start =
            algebra::from_double(ray.origin[i]) + algebra::two_product(a, ray.direction[i]);
        const DoubleDouble half = half_width * algebra::from_double(ray.direction[i]);
        const DoubleDouble middle = start + half;
        line.origin_hi[i] = middle.hi;
        line.origin_lo[i] = middle.lo;
        line.direction_hi[i] = half.hi;
        line.direction_lo[i] = half.lo;
        error.direction[i] = kError * std::abs(half.hi) + kTiny;
        error.origin[i] =
            kError * (std::abs(start.hi) + std::abs(half.hi) + std::abs(middle.hi)) + 3.0 * kTiny;
    }
    return restrictor_.restrict_with_double_double_bounds(line, error,
                                                          f_->double_double_coefficient_error());
}

RootResult CertifiedTracer::exact(const Ray& ray, Interval interval, int work) const {
    const algebra::ExactRoot root = algebra::exact_first_root(
        *f_, to_point(ray.origin), to_point(ray.direction), interval.lo, interval.hi, true);
    // A ray lying in the surface meets it everywhere: the start of the interval is reported.
    return root.status == algebra::ExactRoot::Status::miss
               ? [&] {
                     RootResult r = miss(work + 1);
                     r.decided_by = Decision::exact;
                     return r;
                 }()
               : hit(root.t, work + 1, Decision::exact);
}

RootResult CertifiedTracer::narrow(const Ray& ray, const Piece& piece, double tolerance, int work,
                                   bool doubles_first) const {
    // Tiers 1–2: the ball itself (in doubles or double-double). A bracket of σ-width w maps
    // to t-width w·(t_hi − t_lo), within m of exact at either end (the two ends' margins, and
    // the rounding of the map).
    const double span = piece.t_hi - piece.t_lo;
    const double m = 2.0 * piece.margin +
                     4.0 * kUnit * std::max(std::abs(piece.t_lo), std::abs(piece.t_hi)) + kTiny;
    const double allowed = tolerance * tolerance_scale(piece.t_lo, piece.t_hi);
    const auto at = [&](double sigma) { return piece.t_lo + sigma * span; };
    const MidpointPolynomial midpoint(piece.ball);
    const Bracket bracket =
        narrow_root(piece.ball, midpoint, piece.sign_at_lo, 0.5 * allowed / span);
    work += bracket.work;
    const double lower = at(bracket.lo) - m, upper = at(bracket.hi) + m;
    if (bracket.certified || upper - lower <= allowed) {
        // Any point of the bracket keeps the contract; the midpoint polynomial's root is the
        // one nearest the true root (and prints as `exact` does on a well-conditioned ray).
        return hit(std::clamp(at(bracket.estimate), at(bracket.lo), at(bracket.hi)), work,
                   Decision::floating);
    }
    // Tier 3: signs of F at points of the ray, evaluated from f at the point with a running
    // error bound in doubles — the error of the point's own terms, far below the ball's where
    // the ball covers a long segment or a whole frame — and then in double-double. The root is
    // the only one in the exact range [lower, upper]; a point left of it has sign_at_lo, right
    // of it the other. `left`/`right` are the tightest ends known so far; a point whose sign
    // the arithmetic cannot tell leaves them as they are.
    double left = lower, right = upper;
    double probe_lo = at(bracket.lo) + m, probe_hi = at(bracket.hi) - m;
    // The mean value theorem then places the root from one point (mean_value_bracket), in σ
    // of the piece: a probe at p is G at σ(p), within the map's error of the σ p rounds to.
    const SlopeBounds slopes = slope_bounds(piece.ball);
    const bool map_is_sharp = m < 0.01 * span;  // else the point's σ is too blurred to use
    const auto mean_value_step = [&](double p, const algebra::ValueEnclosure& e) {
        if (!map_is_sharp) {
            return;
        }
        const double sigma = std::clamp((p - piece.t_lo) / span, 0.0, 1.0);
        const double blur =
            (std::abs(at(sigma) - p) * (1.0 + 4.0 * kUnit) + m + 2.0 * kUnit * std::abs(p)) / span *
            (1.0 + 4.0 * m / span + 4.0 * kUnit);
        const RootRange range = mean_value_bracket(midpoint, slopes, piece.sign_at_lo, sigma, blur,
                                                   e.value, std::abs(e.value_low) + e.radius);
        left = std::max(left, at(range.lo) - m);
        right = std::min(right, at(range.hi) + m);
        probe_lo = std::max(probe_lo, left);
        probe_hi = std::min(probe_hi, right);
    };
    using Precision = algebra::CompiledPolynomial::Precision;
    for (const Precision precision : {Precision::double_precision, Precision::double_double}) {
        if (precision == Precision::double_precision && !doubles_first) {
            continue;
        }
        // Set when this precision's error bound exceeds what f reaches near the root
        // (4·|slope|·h, with room for a poor slope): its signs a quarter tolerance from the root
        // cannot be certain, and the pass ends (at degree 30 the doubles' bound often is).
        bool hopeless = false;
        double h = 0.0, slope = 0.0;
        // Evaluates at p; a certain sign moves an end of the bracket.
        const auto probe = [&](double p) {
            ++work;
            const algebra::ValueEnclosure e =
                f_->enclose_on_line(to_point(ray.origin), to_point(ray.direction), p, precision);
            hopeless = hopeless || !(e.radius < 4.0 * std::abs(slope) * h);
            if (p >= probe_lo && p <= probe_hi) {
                if (e.sign() == piece.sign_at_lo) {
                    left = probe_lo = p;
                } else if (e.sign() == -piece.sign_at_lo) {
                    right = probe_hi = p;
                }
                mean_value_step(p, e);
            }
            return e.value + e.value_low;
        };
        const auto done = [&] { return right - left <= tolerance * tolerance_scale(left, right); };
        const auto stop = [&] { return hopeless || done(); };
        // Newton steps on the point values from the ball's estimate, with the ball's slope
        // (proposals only), then certified signs a quarter tolerance either side, and
        // farther out while the arithmetic cannot tell.
        double x = std::clamp(at(bracket.estimate), probe_lo, probe_hi);
        h = 0.25 * tolerance * std::max(1.0, std::abs(x));
        slope = bracket.slope / span;
        // Where the ball places the root to within δ ≤ 1.8h (its radii over its slope, with a
        // quarter to spare), certain signs at x ± δ close the bracket at once: two probes,
        // where a Newton probe first needs three.
        const double blur = 1.25 * bracket.noise / std::abs(bracket.slope) * span;
        if (precision == Precision::double_precision && blur <= 1.8 * h) {
            probe(x - blur);
            probe(x + blur);
        }
        for (int step = 0; step < 6 && !stop(); ++step) {
            const double value = probe(x);
            const double next = std::clamp(x - value / slope, probe_lo, probe_hi);
            if (!std::isfinite(next)) {
                break;
            }
            // A step from the ball's estimate (off by about its blur, a few h) with the
            // ball's slope lands within a fraction of h: its error is the step times the
            // slope's relative error. Probing there again would only confirm it.
            const bool converged = std::abs(next - x) <= 16.0 * h;
            x = next;
            if (converged) {
                break;
            }
        }
        // The farther end first: after a Newton probe the nearer end is often close enough.
        const int farther = x - left <= right - x ? 1 : -1;
        for (int side : {farther, -farther}) {
            for (double step = h; !stop(); step *= 8.0) {
                const double p = x + side * step;
                if (!(p > probe_lo && p < probe_hi)) {
                    break;
                }
                const double before = right - left;
                probe(p);
                if (right - left < before) {
                    break;
                }
            }
        }
        // What is left: bisection on certain signs, while they stay certain.
        for (int iteration = 0; iteration < 80 && !stop(); ++iteration) {
            const double before = right - left;
            probe(0.5 * (probe_lo + probe_hi));
            if (!(right - left < before)) {
                break;
            }
        }
        if (done()) {
            return hit(std::clamp(x, left, right), work,
                       precision == Precision::double_double ? Decision::double_double
                                                             : Decision::floating);
        }
    }
    // Tier 4: exact arithmetic on the range that holds the root (and nothing before it).
    return exact(ray, {std::nextafter(lower, -INFINITY), std::nextafter(upper, INFINITY)}, work);
}

RootResult CertifiedTracer::first_hit(const Ray& ray, Interval interval, double tolerance,
                                      NeighbourHint* hint) const {
    if (hint == nullptr) {
        double unused = 0.0;
        return search(ray, interval, tolerance, NAN, 0.0, true, unused);
    }
    // For the next ray: this one's root, and the half-width of the piece that isolated it (a
    // root found otherwise — exact arithmetic — leaves that of the finest segment piece).
    double reach = 0.0;
    const bool doubles_first = hint->doubles_rest == 0;
    const RootResult result =
        search(ray, interval, tolerance, hint->t, hint->reach, doubles_first, reach);
    const bool hit = result.status == RootStatus::hit;
    hint->t = hit ? result.t : NAN;
    hint->doubles_rest = next_doubles_rest(*hint, doubles_first, result);
    hint->reach =
        !hit ? 0.0 : (reach > 0.0 ? reach : std::ldexp(interval.hi - interval.lo, -kSegmentDepth));
    return result;
}

RootResult CertifiedTracer::search(const Ray& ray, Interval interval, double tolerance,
                                   double guess, double guess_reach, bool doubles_first,
                                   double& piece_reach) const {
    const double lo = interval.lo, hi = interval.hi;
    if (!(hi > lo)) {
        return miss(0);
    }
    bool finite = std::isfinite(lo) && std::isfinite(hi);
    for (int i = 0; i < 3; ++i) {
        finite = finite && std::isfinite(ray.origin[i]) && std::isfinite(ray.direction[i]);
    }
    if (!finite) {
        RootResult r;
        r.status = RootStatus::unknown;
        r.reason = "a ray or interval that is not finite";
        return r;
    }
    // `precise`: restricted in double-double, for pieces doubles could not decide.
    struct Segment {
        double a, b;
        bool precise = false;
    };
    std::array<Segment, kMaxSegments + 2> stack;
    int top = 0;
    // With a guess, the first segment ends where the guess's window does: the root is then found
    // in the window's piece of one cut, and the ray's rest is only expanded when it is not.
    const double window_end = guess + guess_reach;
    const bool cut_at_window =
        std::isfinite(window_end) && guess > lo && window_end > guess && window_end < hi;
    if (cut_at_window) {
        stack[top++] = {window_end, hi, false};
        stack[top++] = {lo, window_end, false};
    } else {
        stack[top++] = {lo, hi, false};
    }
    int work = 0;
    int segments = 0;
    bool doubles_at_floor = false;
    while (top > 0) {
        const Segment segment = stack[--top];
        if (++segments > kMaxSegments) {
            return exact(ray, interval, work);
        }
        const double a = segment.a, b = segment.b;
        // A ray whose doubles have reached their floor somewhere (below) is expanded in
        // double-double from then on: its later segments are the rest of the same stretch, where
        // the doubles would only cut off a sliver each time before the segments run out.
        const bool precise = segment.precise || doubles_at_floor;
        const RestrictionBall power =
            precise ? segment_ball_precise(ray, a, b) : segment_ball(ray, a, b);
        if (!power.certified) {
            // Overflow over a very long segment: bound the roots first (Cauchy's bound on the
            // restriction about a, when its leading coefficient is certainly not zero).
            if (segments == 1) {
                const RestrictionBall about_a = segment_ball(ray, a, a + 1.0);
                const int n = about_a.polynomial.degree;
                const double lead =
                    n >= 0 ? std::abs(about_a.polynomial.c[n]) - about_a.radius[n] : 0.0;
                if (about_a.certified && lead > 0.0) {
                    double largest = 0.0;
                    for (int k = 0; k < n; ++k) {
                        largest = std::max(largest,
                                           std::abs(about_a.polynomial.c[k]) + about_a.radius[k]);
                    }
                    const double reach = (1.0 + largest / lead) * (1.0 + 1e-9) + 1.0;
                    if (std::isfinite(reach) && a + reach < b) {
                        stack[top++] = {a, a + reach, false};
                        ++work;
                        continue;
                    }
                }
            }
            return exact(ray, interval, work);
        }
        const BernsteinBall ball = to_bernstein(power);
        // The first segment is searched near the previous ray's root first: on a row of a
        // degree-30 frame that skips the bisection down to the first root (a third of the
        // pieces examined).
        const bool guided = segments == 1 && std::isfinite(guess) && guess > a && guess < b;
        const Isolation isolation =
            guided ? isolate_first_root_near(ball, kSegmentDepth, 0.0, 1.0, (guess - a) / (b - a),
                                             guess_reach / (b - a))
                   : isolate_first_root(ball, kSegmentDepth);
        work += isolation.work;
        // The map σ → t rounds (4u of the larger end); a guided search's piece ends are not
        // dyadic and are themselves within 8u of exact in σ (isolate_first_root_near), so 8u of
        // the segment more — without it an undecided piece's re-search could start past its
        // exact start, leaving a sliver no piece had shown free of roots.
        const double margin = 4.0 * kUnit * std::max(std::abs(a), std::abs(b)) +
                              (guided ? 9.0 * kUnit * (b - a) : 0.0) + kTiny;
        const auto t_at = [&](double sigma) { return a + sigma * (b - a); };
        if (isolation.kind == Isolation::Kind::no_root) {
            continue;
        }
        if (isolation.kind == Isolation::Kind::one_root) {
            const Piece piece{isolation.piece, isolation.sign_at_lo, t_at(isolation.lo),
                              t_at(isolation.hi), margin};
            piece_reach = 0.5 * (piece.t_hi - piece.t_lo);
            return narrow(ray, piece, tolerance, work, doubles_first);
        }
        // Expanding about a narrower piece shrinks the radii of the powers of t (they scale
        // with the piece's width), not the constant term's: the rounding of f at the middle,
        // u·Σ|terms| there. Once that floor is most of the radius (degree 34 and up, near
        // |x| = 1), doubles cannot decide however narrow the piece: when such a segment leaves
        // a piece undecided, every later segment of the ray is expanded in double-double.
        if (!precise) {
            double power_radii = 0.0;
            for (int k = 1; k <= power.polynomial.degree; ++k) {
                power_radii += power.radius[k];
            }
            doubles_at_floor = !(power_radii > power.radius[0]);
        }
        const double piece_a = std::max(a, t_at(isolation.lo) - margin);
        const double piece_b = std::min(b, t_at(isolation.hi) + margin);
        const double rest_a = std::max(a, t_at(isolation.hi) - margin);
        if (top + 2 > static_cast<int>(stack.size())) {
            return exact(ray, interval, work);
        }
        // Undecided at the very start: F(lo) may be zero (a ray starting on the surface, or
        // the surface crossing the clip sphere where the ray enters it), or smaller than the
        // doubles' radii (degree 30). The undecided piece is expanded again in double-double;
        // what that cannot decide either, exact arithmetic decides on the piece alone — a short
        // interval, with few roots to isolate — and the search goes on past it when it holds
        // none.
        if (isolation.lo == 0.0 && a == lo && ball.sign(0) == 0) {
            if (!(piece_b > lo && piece_b < hi)) {
                return exact(ray, interval, work);
            }
            if (!precise) {
                if (piece_b < b) {
                    stack[top++] = {piece_b, b, false};
                }
                stack[top++] = {lo, piece_b, true};
                continue;
            }
            const RootResult near_start = exact(ray, {lo, piece_b}, work);
            if (near_start.status == RootStatus::hit) {
                return near_start;
            }
            work = near_start.work;
            if (piece_b < b) {
                stack[top++] = {piece_b, b, true};
            }
            continue;
        }
        // Undecided elsewhere: a piece less than half the segment is expanded again about
        // itself, where its terms are smaller; one that is not (a cluster of roots, or radii
        // above F's values throughout) is expanded again in double-double, and what that
        // cannot decide goes to exact arithmetic.
        const bool shrinks = piece_b - piece_a < 0.5 * (b - a);
        if (!shrinks && precise) {
            return exact(ray, interval, work);
        }
        if (isolation.hi < 1.0) {
            stack[top++] = {rest_a, b, precise};
        }
        stack[top++] = {piece_a, piece_b, precise || !shrinks};
    }
    return miss(work);
}

RootResult CertifiedTracer::first_hit_from(const BernsteinBall& ball, double t0, double width,
                                           const Ray& ray, const Interval& interval,
                                           double tolerance, NeighbourHint* hint) const {
    NeighbourHint unused;
    NeighbourHint& next = hint != nullptr ? *hint : unused;
    const NeighbourHint guess = next;
    next = NeighbourHint{};
    next.family_failures = guess.family_failures;
    next.doubles_rest = guess.doubles_rest;
    if (!(interval.hi > interval.lo)) {
        next.family_rest = guess.family_rest;
        return miss(0);
    }
    if (guess.family_rest > 0) {
        next.family_rest = guess.family_rest - 1;
        return first_hit(ray, interval, tolerance);
    }
    // The ball is the restriction to [T0, T0 + width] for the exact T0 that t0 rounds (within
    // u·|t0|; a family's width is exact). An interval reaching within the roundings of the
    // range's ends is traced alone rather than searched in part.
    const double range_error = 2.0 * kUnit * (std::abs(t0) + std::abs(t0 + width)) + kTiny;
    if (!(interval.hi > interval.lo) || interval.lo < t0 + range_error ||
        interval.hi > t0 + width - range_error) {
        return first_hit(ray, interval, tolerance);
    }
    // The interval in σ: an end t is at σ = (t − T0)/width, computed from t0 with two roundings
    // more, so within (u·|t0| + 2u·(|t| + |t0|))/width + 2u of its exact σ. The search is
    // widened by twice that at both ends, so that no root inside the interval falls in a
    // sliver before s0 or past s_hi (isolate_first_root_near cuts its search at both); a root
    // the widening lets in from outside is checked below, as one a piece reaching past the
    // interval would be.
    const double sigma_error =
        4.0 * kUnit * (std::abs(t0) + std::abs(interval.lo) + std::abs(interval.hi)) / width +
        4.0 * kUnit;
    const double s0 = std::max(0.0, (interval.lo - t0) / width - sigma_error);
    const double s_hi = std::min(1.0, (interval.hi - t0) / width + sigma_error);
    if (!(s_hi > s0)) {
        return first_hit(ray, interval, tolerance);
    }
    // The neighbour's root and reach in σ (NaN when it had none: no guess).
    const Isolation isolation = isolate_first_root_near(
        ball, kFamilyDepth, s0, s_hi, (guess.t - t0) / width, guess.reach / width);
    next.family_failures =
        isolation.kind == Isolation::Kind::undecided ? guess.family_failures + 1 : 0;
    if (next.family_failures == kFamilyFailuresBeforeRest) {
        next.family_failures = 0;
        next.family_rest = kFamilyRest;
    }
    if (isolation.kind == Isolation::Kind::no_root) {
        return miss(isolation.work);
    }
    if (isolation.kind == Isolation::Kind::undecided) {
        RootResult alone = first_hit(ray, interval, tolerance);
        alone.work += isolation.work;
        return alone;
    }
    // t = t0 + σ·width, exact up to the rounding of the map and of the piece's ends (within 8u
    // of exact).
    const double margin = 16.0 * kUnit * (std::abs(t0) + std::abs(width)) + kTiny;
    const auto t_at = [&](double sigma) { return t0 + sigma * width; };
    const Piece found{isolation.piece, isolation.sign_at_lo, t_at(isolation.lo), t_at(isolation.hi),
                      margin};
    const bool doubles_first = guess.doubles_rest == 0;
    RootResult result = narrow(ray, found, tolerance, isolation.work, doubles_first);
    next.doubles_rest = next_doubles_rest(guess, doubles_first, result);
    // The piece may reach past the interval: its one root is then the first in the interval
    // only if it comes before the end. A hit placed outside the interval but within the
    // tolerance of an end may be a root just inside it (or, at the start, one the cut's
    // rounding let in from just before): exact arithmetic decides those.
    if (result.status == RootStatus::hit && (result.t > interval.hi || result.t < interval.lo)) {
        const double slack = 1.01 * tolerance * std::max(1.0, std::abs(result.t));
        if (result.t > interval.hi && result.t - slack > interval.hi) {
            RootResult none = miss(result.work);
            none.decided_by = result.decided_by;
            return none;
        }
        return exact(ray, interval, result.work);
    }
    if (result.status == RootStatus::hit) {
        next.t = result.t;
        next.reach = 0.5 * (found.t_hi - found.t_lo);
    }
    return result;
}

}  // namespace locus::render
