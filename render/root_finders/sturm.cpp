// Sturm sequence isolation of the first root of F on [lo, hi], then bracketed Halley refinement.
//
// F is first mapped to G(s) = F(lo + (hi − lo)·s) on s ∈ [0, 1] (detail/univariate.h). The
// sequence p₀ = G, p₁ = G', p_{i+1} = −rem(p_{i−1}, p_i) is built in doubles; a remainder whose
// coefficients are all below kRemainderZero of the division's scale counts as zero and ends the
// sequence. Ending at a
// near-common factor of G and G' is deliberate: the number of sign changes V(a) − V(b) then
// counts the *distinct* roots of G in (a, b] (the generalised Sturm theorem, e.g. Basu, Pollack
// & Roy, "Algorithms in Real Algebraic Geometry", 2nd ed., Thm 2.50), so a double root — a
// tangent ray — is one root, and a pair of roots closer than about √kRemainderZero merges into
// one such root. Bisection on counts isolates the first root; a bracket with a sign change is
// refined by detail::halley_bracketed, one without by even_root, which confirms a
// tangent by value (G' = 0 where G touches zero within rounding) or finds the sign change the
// counts hid, and otherwise goes on after the bracket. Double roots whose remainder noise
// exceeds kRemainderZero are caught through kRemainderSuspect.
// Reference for the method in ray tracing: Hook & McAree, "Using Sturm sequences to bracket real
// roots of polynomial equations", Graphics Gems I (1990) 416–422.
#include <algorithm>
#include <array>
#include <cmath>

#include "render/root_finder.h"
#include "render/root_finders/detail/univariate.h"

namespace locus::render {
namespace {

using detail::Coefficients;

// A remainder whose coefficients are all below kRemainderZero times the scale of its division
// (the largest of the dividend's coefficients and the quotient's times the divisor's) is zero: a
// few hundred ε, so that only a genuine near-common factor of G and G' ends the chain (a larger
// threshold, 1e-11 was tried, also cut chains where a member with a tiny leading coefficient makes
// the next two nearly proportional, and the counts went wrong). It separates close roots down to
// ~1e-7 (a pair r ± δ leaves a remainder of relative size ~δ²). Most double roots leave more
// rounding than that in their remainder, and are found through kRemainderSuspect instead.
constexpr double kRemainderZero = 1e-13;

// A remainder below this relative size marks its divisor as a suspected near-common factor: a
// double root that rounding turned into a complex pair r ± iδ has no sign change and the counts
// miss it, so the roots of that divisor are checked as tangent points (G' = 0 and G touches
// zero within rounding). The check is by value, so a large threshold costs time, not accuracy.
constexpr double kRemainderSuspect = 1e-5;

// Restrictions of this degree and above always get a second opinion (see first_root).
constexpr int kCrossCheckDegree = 16;

// Effort allowed per ray (bisections on counts and refinement steps) before the method gives
// up with RootStatus::unknown; one isolation exhausts the unit interval in doubles in ~50.
constexpr int kMaxWork = 200;

// |G| at the critical point next to a claimed near-common factor (G has max |g_k| = 1) up to
// which the claim is plausible.
constexpr double kFactorSmallValue = 1e-6;

// Tries of the root of G' as the tangent point of an even-multiplicity root, and how far (in s)
// the last try may move from the bracket found by counts.
constexpr int kMaxTangentAttempts = 3;
constexpr double kTangentReach = 1e-4;

// The Sturm sequence of G on [0, 1]: member i has degree degree[i], coefficients
// coefficients[offset[i] .. offset[i] + degree[i]] and largest coefficient magnitude
// largest[i]. Members are not normalised (to max |coefficient| 1, as they once were): that put
// a division and a pass over the coefficients between one remainder and the next on the
// critical path of build_sequence, a chain of dependent operations; without it degree 8–12 rays
// were about 10% faster (root finder alone, render suite). Thresholds are relative to
// largest[] instead, the same tests up to rounding.
struct SturmSequence {
    std::array<double, (kMaxDegree + 1) * (kMaxDegree + 2) / 2> coefficients;
    std::array<int, kMaxDegree + 3> offset;
    std::array<int, kMaxDegree + 2> degree;
    std::array<double, kMaxDegree + 2> largest;
    int size = 0;
    int suspect = -1;  // a member suspected to be a near-common factor, see kRemainderSuspect

    const double* member(int i) const { return coefficients.data() + offset[i]; }
    double* member(int i) { return coefficients.data() + offset[i]; }
};

// Largest |p[k]| for k < count. Four independent maxima: a single running maximum is a serial
// chain of dependent max operations.
double largest_magnitude(const double* p, int count) {
    double m0 = 0.0;
    double m1 = 0.0;
    double m2 = 0.0;
    double m3 = 0.0;
    int k = 0;
    for (; k + 4 <= count; k += 4) {
        m0 = std::max(m0, std::abs(p[k]));
        m1 = std::max(m1, std::abs(p[k + 1]));
        m2 = std::max(m2, std::abs(p[k + 2]));
        m3 = std::max(m3, std::abs(p[k + 3]));
    }
    for (; k < count; ++k) {
        m0 = std::max(m0, std::abs(p[k]));
    }
    return std::max(std::max(m0, m1), std::max(m2, m3));
}

// Unnormalised members keep away from overflow and underflow by exact power-of-two rescaling
// once their largest coefficient leaves [2^−kRescaleExponent, 2^kRescaleExponent].
constexpr int kRescaleExponent = 300;

// Makes the coefficients already written at member `size` (degree d, largest magnitude
// `largest`) a member.
void push_member(SturmSequence& s, int d, double largest) {
    double* p = s.member(s.size);
    if (largest > std::ldexp(1.0, kRescaleExponent) ||
        largest < std::ldexp(1.0, -kRescaleExponent)) {
        int exponent = 0;
        std::frexp(largest, &exponent);
        for (int k = 0; k <= d; ++k) {
            p[k] = std::ldexp(p[k], -exponent);
        }
        largest = std::ldexp(largest, -exponent);
    }
    s.degree[s.size] = d;
    s.largest[s.size] = largest;
    ++s.size;
    s.offset[s.size] = s.offset[s.size - 1] + d + 1;
}

void build_sequence(const Coefficients& g, int n, SturmSequence& s) {
    s.size = 0;
    s.suspect = -1;
    s.offset[0] = 0;
    double* p = s.member(0);
    std::copy(g.begin(), g.begin() + n + 1, p);
    push_member(s, n, largest_magnitude(p, n + 1));
    p = s.member(1);
    for (int k = 1; k <= n; ++k) {
        p[k - 1] = k * g[k];
    }
    push_member(s, n - 1, largest_magnitude(p, n));
    double smallest_remainder = kRemainderSuspect;
    Coefficients scratch;
    while (s.degree[s.size - 1] > 0) {
        const double* previous = s.member(s.size - 2);
        const double* divisor = s.member(s.size - 1);
        const int d1 = s.degree[s.size - 2];
        const int d2 = s.degree[s.size - 1];
        double* r = s.member(s.size);  // −remainder is written in place of the next member
        const double inverse_lead = 1.0 / divisor[d2];
        double largest_quotient = 0.0;
        if (d1 == d2 + 1) {
            // The usual case, a linear quotient q₁x + q₀: one fused pass.
            const double q1 = previous[d1] * inverse_lead;
            const double q0 = (previous[d2] - q1 * divisor[d2 - 1]) * inverse_lead;
            largest_quotient = std::max(std::abs(q1), std::abs(q0));
            r[0] = -(previous[0] - q0 * divisor[0]);
            for (int j = 1; j < d2; ++j) {
                r[j] = -(previous[j] - q1 * divisor[j - 1] - q0 * divisor[j]);
            }
        } else {
            std::copy(previous, previous + d1 + 1, scratch.begin());
            for (int k = d1; k >= d2; --k) {
                const double q = scratch[k] * inverse_lead;
                largest_quotient = std::max(largest_quotient, std::abs(q));
                for (int j = 0; j < d2; ++j) {
                    scratch[k - d2 + j] -= q * divisor[j];
                }
            }
            for (int j = 0; j < d2; ++j) {
                r[j] = -scratch[j];
            }
        }
        // The scale of the division: its terms are at most the larger of the dividend and
        // quotient × divisor (for normalised members, max(1, largest quotient coefficient)).
        const double scale =
            std::max(s.largest[s.size - 2], largest_quotient * s.largest[s.size - 1]);
        const double zero = kRemainderZero * scale;
        int d = d2 - 1;
        while (d >= 0 && std::abs(r[d]) <= zero) {
            --d;
        }
        if (d < 0) {
            break;  // a (near) common factor: the sequence ends at the divisor
        }
        const double largest = largest_magnitude(r, d + 1);
        if (largest < smallest_remainder * scale) {
            smallest_remainder = largest / scale;
            s.suspect = s.size - 1;
        }
        push_member(s, d, largest);
    }
}

// Number of sign changes of values[0 .. count) (zeros skipped). Without zeros, the usual case,
// a branch-free sum: signs along a chain look random to the branch predictor, and the general
// loop's branches held about half of the samples of sign_changes (perf, degree 12).
int count_sign_changes(const double* values, int count) {
    int changes = 0;
    bool zero = values[0] == 0.0;
    for (int i = 1; i < count; ++i) {
        changes += (values[i] < 0.0) != (values[i - 1] < 0.0) ? 1 : 0;
        zero = zero || values[i] == 0.0;
    }
    if (!zero) {
        return changes;
    }
    changes = 0;
    double previous = 0.0;
    for (int i = 0; i < count; ++i) {
        const double v = values[i];
        if (v != 0.0) {
            changes += (previous != 0.0 && (v < 0.0) != (previous < 0.0)) ? 1 : 0;
            previous = v;
        }
    }
    return changes;
}

// Number of sign changes of the sequence at s (zeros skipped).
int sign_changes(const SturmSequence& seq, double s) {
    // Two members per Horner loop: member by member, each loop ends in a branch that the
    // processor cannot see past, so the latency of every member's recurrence adds up; paired,
    // two independent recurrences share the loop (5–7% faster rays at degree 12, root finder
    // alone; the values are unchanged). Four members per loop measured the same as two. Consecutive
    // members have decreasing degrees.
    std::array<double, kMaxDegree + 2> values;
    int i = 0;
    for (; i + 1 < seq.size; i += 2) {
        const double* p = seq.member(i);
        const double* q = seq.member(i + 1);
        const int dp = seq.degree[i];
        const int dq = seq.degree[i + 1];
        double vp = p[dp];
        int k = dp - 1;
        for (; k >= dq; --k) {
            vp = vp * s + p[k];
        }
        double vq = q[dq];
        for (; k >= 0; --k) {
            vp = vp * s + p[k];
            vq = vq * s + q[k];
        }
        values[i] = vp;
        values[i + 1] = vq;
    }
    if (i < seq.size) {
        values[i] = detail::horner(seq.member(i), seq.degree[i], s);
    }
    return count_sign_changes(values.data(), seq.size);
}

int sign_changes_at_zero(const SturmSequence& seq) {
    std::array<double, kMaxDegree + 2> values;
    for (int i = 0; i < seq.size; ++i) {
        values[i] = seq.member(i)[0];
    }
    return count_sign_changes(values.data(), seq.size);
}

// The root counted on [a, b] (va sign changes at a) when G has the same sign at both ends: a
// root of even multiplicity, which is a simple root of G' — or counts spoiled by rounding (a
// member with a small leading coefficient amplifies it) that hide two close simple roots or
// merge a close complex pair into a "root". Bisect on counts; whenever G' changes sign on the
// bracket, look at its root c: G(c) of the other sign than G(a) reveals a sign change in
// [a, c], and G touching zero at c is the tangent, far better conditioned than the counts near
// it. Returns t, or NaN when neither is found.
double even_root(const SturmSequence& seq, const detail::UnitRestriction& u, double a, double b,
                 int va, int& work) {
    const Coefficients& g = u.g;
    const int n = u.degree;
    const double tol = detail::unit_tolerance(u.w);
    Coefficients dg;
    detail::derivative(g.data(), n, dg.data());
    int attempts = 0;
    while (b - a > tol && work < kMaxWork) {
        const double da = detail::horner(dg.data(), n - 1, a);
        const double db = detail::horner(dg.data(), n - 1, b);
        if (attempts < kMaxTangentAttempts && da != 0.0 && db != 0.0 && (da < 0.0) != (db < 0.0)) {
            ++attempts;
            const double t =
                detail::refine_root(u, detail::RootOf::derivative, {a, b, da, db}, work);
            if (!std::isnan(t)) {
                const double c = std::clamp((t - u.lo) / u.w, a, b);
                const double ga = detail::horner(g.data(), n, a);
                const double gc = detail::horner(g.data(), n, c);
                if (ga != 0.0 && gc != 0.0 && (ga < 0.0) != (gc < 0.0)) {
                    const double root =
                        detail::refine_root(u, detail::RootOf::value, {a, c, ga, gc}, work);
                    if (!std::isnan(root)) {
                        return root;
                    }
                }
                if (detail::touches_zero(u, t)) {
                    return t;
                }
            }
        }
        const double m = 0.5 * (a + b);
        const int vm = sign_changes(seq, m);
        ++work;
        if (va - vm >= 1) {
            b = m;
        } else {
            a = m;
            va = vm;
        }
    }
    // Counts near a tangent are noise-limited; the critical point next to the bracket is not.
    const double m = 0.5 * (a + b);
    const double t = detail::critical_point_near(u, m, work);
    return std::abs(t - detail::from_unit(m, u.lo, u.hi)) <= kTangentReach * u.w && t >= u.lo &&
                   t <= u.hi && detail::touches_zero(u, t)
               ? t
               : NAN;
}

// A chain that ends early claims a near-common factor of G and G', so each real root of that
// last member in [0, 1] must lie next to a critical point of G where |G| is small (a tangent,
// or the close complex pair of a near miss, which even_root tells apart). A small remainder
// can have other causes (a member with a tiny leading coefficient makes the next two nearly
// proportional), and then the counts are wrong: the method answers RootStatus::unknown rather
// than trust them. Factors of degree ≥ 3 are not checked.
bool common_factor_is_plausible(const SturmSequence& seq, const detail::UnitRestriction& u,
                                int& work) {
    const int last = seq.size - 1;
    const double* p = seq.member(last);
    std::array<double, 2> roots;
    int count = 0;
    if (seq.degree[last] == 1) {
        roots[count++] = -p[0] / p[1];
    } else if (seq.degree[last] == 2) {
        const double discriminant = p[1] * p[1] - 4.0 * p[2] * p[0];
        if (discriminant >= 0.0) {
            const double q = -0.5 * (p[1] + std::copysign(std::sqrt(discriminant), p[1]));
            roots[count++] = q / p[2];
            if (q != 0.0) {
                roots[count++] = p[0] / q;
            }
        }
    }
    for (int i = 0; i < count; ++i) {
        if (roots[i] < 0.0 || roots[i] > 1.0) {
            continue;  // does not affect the counts on [0, 1]
        }
        const double t = detail::critical_point_near(u, roots[i], work);
        if (!(std::abs(t - detail::from_unit(roots[i], u.lo, u.hi)) <= kTangentReach * u.w)) {
            return false;
        }
        const double c = std::clamp((t - u.lo) / u.w, 0.0, 1.0);
        if (!(std::abs(detail::horner(u.g.data(), u.degree, c)) <= kFactorSmallValue)) {
            return false;
        }
    }
    return true;
}

// What the counts say about the first root of G in (0, 1].
struct CountedRoot {
    double t = NAN;                 // the root, or NaN when the counts find none
    const char* failure = nullptr;  // set when the method must answer RootStatus::unknown
};

// The first root of G in (0, 1] by Sturm counts.
CountedRoot first_counted_root(const SturmSequence& seq, const detail::UnitRestriction& u,
                               int& work) {
    const Coefficients& g = u.g;
    const int n = u.degree;
    const double tol = detail::unit_tolerance(u.w);
    if (!common_factor_is_plausible(seq, u, work)) {
        return CountedRoot{NAN, "sturm sequence inconsistent (rounding)"};
    }
    double a = 0.0;
    int va = sign_changes_at_zero(seq);
    const int v_end = sign_changes(seq, 1.0);
    while (va - v_end > 0) {
        // Isolate the first distinct root in (a, 1]: keep the left half whenever it holds one.
        double b = 1.0;
        int vb = v_end;
        while (va - vb > 1) {
            if (work >= kMaxWork) {
                return CountedRoot{NAN, "sturm bisection limit reached"};
            }
            if (b - a <= tol) {
                return CountedRoot{detail::from_unit(0.5 * (a + b), u.lo, u.hi)};  // a cluster
            }
            const double m = 0.5 * (a + b);
            const int vm = sign_changes(seq, m);
            ++work;
            if (va - vm >= 1) {
                b = m;
                vb = vm;
            } else {
                a = m;
                va = vm;
            }
        }
        const double ga = detail::horner(g.data(), n, a);
        const double gb = detail::horner(g.data(), n, b);
        if (gb == 0.0) {
            return CountedRoot{detail::from_unit(b, u.lo, u.hi)};
        }
        if ((ga < 0.0) != (gb < 0.0) && ga != 0.0) {
            const double t = detail::refine_root(u, detail::RootOf::value, {a, b, ga, gb}, work,
                                                 {.single_root = true});
            if (!std::isnan(t)) {
                return CountedRoot{t};
            }
        }
        const double t = even_root(seq, u, a, b, va, work);
        if (!std::isnan(t)) {
            return CountedRoot{t};
        }
        // Nothing real on [a, b] after all: look beyond it.
        a = b;
        va = vb;
    }
    return CountedRoot{};
}

// The first tangent point t ≤ limit among the real roots of the suspected near-common factor
// (degree 1 or 2; higher degrees, three or more near-double roots at once, are not examined),
// each moved to the nearby critical point of G by Newton on G'; NaN when none touches zero.
double first_suspected_tangent(const SturmSequence& seq, const detail::UnitRestriction& u,
                               double limit, int& work) {
    const double* p = seq.member(seq.suspect);
    std::array<double, 2> candidates;
    int count = 0;
    if (seq.degree[seq.suspect] == 1) {
        candidates[count++] = -p[0] / p[1];
    } else if (seq.degree[seq.suspect] == 2) {
        // A complex pair of the factor is still a candidate through its real part.
        const double discriminant = std::max(0.0, p[1] * p[1] - 4.0 * p[2] * p[0]);
        const double q = -0.5 * (p[1] + std::copysign(std::sqrt(discriminant), p[1]));
        candidates[count++] = q / p[2];
        if (q != 0.0) {
            candidates[count++] = p[0] / q;
        }
    }
    double best = NAN;
    for (int i = 0; i < count; ++i) {
        if (!(candidates[i] >= -0.5 && candidates[i] <= 1.5)) {
            continue;
        }
        const double t = detail::critical_point_near(u, candidates[i], work);
        if (t >= u.lo && t <= limit && !(t >= best) && detail::touches_zero(u, t)) {
            best = t;
        }
    }
    return best;
}

// Half-width, in s ∈ [0, 1], of the bracket tried around a hint.
constexpr double kHintReach = 1.0 / 64.0;

// Bernstein coefficients b[0..n] all of one sign and clear of the rounding noise `touch`:
// the piece holds no root (G lies in the convex hull of its control polygon).
bool clear_of_zero(const Coefficients& b, int n, double touch) {
    for (int i = 0; i <= n; ++i) {
        if (!(std::abs(b[i]) > touch) || (b[i] < 0.0) != (b[0] < 0.0)) {
            return false;
        }
    }
    return true;
}

// Exactly one sign change among b[0..n], every coefficient clear of `touch`: exactly one root
// in the piece, a simple one (Descartes' rule of signs in the Bernstein basis bounds the roots
// counted with multiplicity).
bool one_sign_change(const Coefficients& b, int n, double touch) {
    int changes = 0;
    for (int i = 0; i <= n; ++i) {
        if (!(std::abs(b[i]) > touch)) {
            return false;
        }
        changes += i > 0 && (b[i] < 0.0) != (b[i - 1] < 0.0) ? 1 : 0;
    }
    return changes == 1;
}

// The first root of G certified around a hint h (the neighbouring pixel's root, in s) without
// the Sturm chain: with l, r = h ∓ kHintReach, G has no root on [0, l] and exactly one simple
// root on [l, r], both read off Bernstein coefficients (de Casteljau at l and r) that stay
// clear of rounding noise; then bracketed Halley on [l, r]. Neighbouring primary rays mostly
// pass (their first roots move little from pixel to pixel), and these tests cost about a third
// of building and counting the chain. NaN when a test fails: the counts decide.
double coherent_root(const detail::UnitRestriction& u, double h, int& work) {
    const int n = u.degree;
    if (!(h > kHintReach && h < 1.0 - kHintReach)) {
        return NAN;
    }
    const double l = h - kHintReach;
    const double r = h + kHintReach;
    // As in bernstein.cpp: G has max |g_k| = 1, so |G| ≤ n + 1 bounds its rounding scale.
    const double touch = detail::kTouchFactor * (n + 1) * detail::kEpsilon;
    // G(r·s) on s ∈ [0, 1] is G on [0, r]; one de Casteljau step at l / r parts [0, l] and
    // [l, r] (converting on [0, 1] and splitting twice cost half as much again).
    Coefficients before;
    Coefficients after;
    double power = 1.0;
    for (int k = 0; k <= n; ++k) {
        after[k] = u.g[k] * power;
        power *= r;
    }
    detail::to_bernstein(after, n, before);
    detail::split_at(before, after, n, l / r);  // before: [0, l]; after: [l, r]
    if (!one_sign_change(after, n, touch)) {
        return NAN;
    }
    if (!clear_of_zero(before, n, touch)) {
        // The polygon on a long [0, l] is loose where F comes close to zero without a root
        // (thin walls): halved once, it often clears.
        Coefficients second;
        detail::split_at(before, second, n, 0.5);
        if (!clear_of_zero(before, n, touch) || !clear_of_zero(second, n, touch)) {
            return NAN;
        }
    }
    const double gl = detail::horner(u.g.data(), n, l);
    const double gr = detail::horner(u.g.data(), n, r);
    if (gl == 0.0 || gr == 0.0 || (gl < 0.0) == (gr < 0.0)) {
        return NAN;
    }
    ++work;
    return detail::refine_root(u, detail::RootOf::value, {l, r, gl, gr}, work,
                               {.single_root = true});
}

}  // namespace

RootResult SturmRootFinder::first_root(const RayPolynomial& f, double lo, double hi,
                                       double hint) const {
    const detail::Screening screening = detail::screen(f, lo, hi);
    if (screening.done) {
        return screening.result;
    }
    detail::UnitRestriction u;
    if (!detail::map_to_unit_interval(f, screening.degree, lo, hi, u)) {
        return detail::unknown("coefficients overflow on the interval", 0);
    }
    int work = 0;
    double t = NAN;
    const char* flag = "";
    if (u.degree > 0 && !std::isnan(hint)) {
        t = coherent_root(u, (hint - lo) / u.w, work);
        if (!std::isnan(t)) {
            return detail::hit(t, work);
        }
    }
    if (u.degree > 0) {
        SturmSequence seq;
        build_sequence(u.g, u.degree, seq);
        // The chain ended at a near-common factor of G and G': a multiple root, or two roots
        // closer than rounding can separate. Counting on such a chain skipped the first pair of
        // two spheres 1e-6 apart and a triple root at the middle of the interval (stability
        // atlas: twin_spheres, steiner_lines, nested_rays), so the answer carries a flag that
        // lets SurfaceTracer confirm it with another method.
        // From degree 16 on, a floating chain is fragile even without a small remainder: on
        // ten nested spheres (degree 20) the count skipped a simple root while a tangent sat
        // at the middle of the interval (stability atlas, nested_rays). A small remainder
        // alone (kRemainderSuspect) is handled by first_suspected_tangent below; flagging it
        // too passed the same atlas at a few percent of the frame on singular surfaces.
        if (seq.degree[seq.size - 1] > 0) {
            flag = kNearCommonFactor;
        } else if (u.degree >= kCrossCheckDegree) {
            flag = kSecondOpinion;
        }
        const CountedRoot counted = first_counted_root(seq, u, work);
        if (counted.failure != nullptr) {
            return detail::unknown(counted.failure, work);
        }
        t = counted.t;
        if (seq.suspect >= 0) {
            // A tangent before the counted root wins; so does one just after it when the
            // counted root is not a root in the better basis (rounding noise of G around the
            // tangent produced its sign change).
            const double limit = std::isnan(t) ? hi : std::min(hi, t + kTangentReach * u.w);
            const double tangent = first_suspected_tangent(seq, u, limit, work);
            if (!std::isnan(tangent) &&
                (std::isnan(t) || tangent <= t || !detail::is_root_within_rounding(u, t))) {
                t = tangent;
            }
        }
    }
    RootResult result = !std::isnan(t) ? detail::hit(t, work)
                        : detail::is_zero_within_rounding(f.c.data(), screening.degree, hi)
                            ? detail::hit(hi, work)
                            : detail::miss(work);
    result.reason = flag;
    return result;
}

}  // namespace locus::render
