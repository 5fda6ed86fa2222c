// Steps shared by the univariate root finders of render/root_finder.h: screening of degenerate
// restrictions, the map of [lo, hi] onto [0, 1] (with the choice, point by point, between that
// basis and the original one), bracketed regula falsi refinement, Newton polishing, and the
// tests for "a root within rounding" and "a tangent". Internal to render/root_finders; this is
// per-ray code, so everything is inline and works on stack arrays only.
//
// Tolerances are stated once here so that every method agrees on what "a root at lo", "a
// negligible leading coefficient", "touches zero" and "accurate enough" mean.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "render/root_finder.h"

namespace locus::render::detail {

inline constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// A leading coefficient whose term is below this fraction of the largest term on the interval
// is rounding noise (Horner's own error is several times larger) and is dropped.
inline constexpr double kNegligibleLeading = 1e-15;

// Root accuracy asked of the refinement, relative to max(1, hi − lo); the interface promises
// 1e-10, the margin covers the conditioning of the evaluation.
inline constexpr double kRootTolerance = 2e-11;

// Coefficients of a polynomial of degree ≤ kMaxDegree.
using Coefficients = std::array<double, kMaxDegree + 1>;

inline double horner(const double* c, int degree, double x) {
    double value = c[degree];
    for (int k = degree - 1; k >= 0; --k) {
        value = value * x + c[k];
    }
    return value;
}

// Σ|c_k||t|^k ≥ |F(t)|, the scale of Horner's rounding error at t (Higham, "Accuracy and
// Stability of Numerical Algorithms", 2nd ed., §5.1: |error| ≤ γ_2n · Σ|c_k||t|^k); returns F(t).
inline double horner_with_magnitude(const double* c, int degree, double t, double& magnitude) {
    double value = c[degree];
    magnitude = std::abs(c[degree]);
    const double abs_t = std::abs(t);
    for (int k = degree - 1; k >= 0; --k) {
        value = value * t + c[k];
        magnitude = magnitude * abs_t + std::abs(c[k]);
    }
    return value;
}

// |F(t)| is within the rounding error of Horner's rule at t, so t counts as a root.
inline bool is_zero_within_rounding(const double* c, int degree, double t) {
    double magnitude;
    const double value = horner_with_magnitude(c, degree, t, magnitude);
    return std::abs(value) <= 4.0 * (degree + 1) * kEpsilon * magnitude;
}

// Margin over the rounding error of F, per unit of degree, within which the minimum of |F| at a
// critical point counts as touching zero: a root of even multiplicity (a tangent ray), which
// rounding of the coefficients may have turned into a pair of close real roots or a complex
// pair r ± iδ with δ ~ √ε. A larger margin turns more near-tangent misses into hits.
inline constexpr double kTouchFactor = 16.0;

inline bool touches_zero(const double* c, int degree, double t) {
    double magnitude;
    const double value = horner_with_magnitude(c, degree, t, magnitude);
    return std::abs(value) <= kTouchFactor * (degree + 1) * kEpsilon * magnitude;
}

// Coefficients of F'.
inline void derivative(const double* c, int degree, double* d) {
    for (int k = 1; k <= degree; ++k) {
        d[k - 1] = k * c[k];
    }
}

inline RootResult hit(double t, int work) {
    return RootResult{RootStatus::hit, t, work, ""};
}
inline RootResult miss(int work) {
    return RootResult{RootStatus::miss, 0.0, work, ""};
}
inline RootResult unknown(const char* reason, int work) {
    return RootResult{RootStatus::unknown, 0.0, work, reason};
}

// The outcome of screening F before any method runs: either a final result (degenerate input,
// constant F, a root at lo) or the effective degree ≥ 1 to work with.
struct Screening {
    bool done = false;
    RootResult result;
    int degree = 0;
};

// Rejects invalid intervals and non-finite or zero coefficients, drops leading coefficients
// whose terms are negligible on [lo, hi] (|c_n|·R^n ≤ kNegligibleLeading · max_k |c_k|·R^k with
// R = max(1, |lo|, |hi|)), and answers constants and roots at lo.
inline Screening screen(const RayPolynomial& f, double lo, double hi) {
    Screening s;
    s.done = true;
    if (!(std::isfinite(lo) && std::isfinite(hi) && lo <= hi && std::isfinite(hi - lo))) {
        s.result = unknown("invalid interval", 0);
        return s;
    }
    if (f.degree > kMaxDegree) {
        s.result = unknown("degree above kMaxDegree", 0);
        return s;
    }
    int n = f.degree;
    bool all_zero = true;
    for (int k = 0; k <= n; ++k) {
        if (!std::isfinite(f.c[k])) {
            s.result = unknown("non-finite coefficient", 0);
            return s;
        }
        all_zero = all_zero && f.c[k] == 0.0;
    }
    if (all_zero) {
        // The segment lies in the surface (a line through two of Cayley's nodes): it meets
        // the surface at once, as the exact method says (stability atlas, cayley_line).
        s.result = hit(lo, 0);
        return s;
    }
    const double inverse_radius = 1.0 / std::max({1.0, std::abs(lo), std::abs(hi)});
    while (n > 0) {
        // Largest lower term relative to the leading one: |c_k|·R^(k−n) ≤ |c_k|.
        double largest = 0.0;
        double power = 1.0;
        for (int k = n - 1; k >= 0; --k) {
            power *= inverse_radius;
            largest = std::max(largest, std::abs(f.c[k]) * power);
        }
        if (std::abs(f.c[n]) > kNegligibleLeading * largest) {
            break;
        }
        --n;
    }
    if (n == 0) {
        s.result = miss(0);
        return s;
    }
    if (is_zero_within_rounding(f.c.data(), n, lo)) {
        s.result = hit(lo, 0);
        return s;
    }
    if (lo == hi) {
        s.result = miss(0);
        return s;
    }
    s.done = false;
    s.degree = n;
    return s;
}

// F on [lo, hi] in two bases: its own coefficients in t, and G(s) = κ·F(lo + w·s) on s ∈ [0, 1]
// with w = hi − lo and κ > 0 chosen so that max |g_k| = 1.
struct UnitRestriction {
    const double* f = nullptr;
    int f_degree = 0;
    double lo = 0.0;
    double hi = 0.0;
    double w = 0.0;
    double kappa = 1.0;
    int degree = 0;  // of G; lower than f_degree when leading terms are negligible on [lo, hi]
    Coefficients g;
};

// Computes G: a Taylor shift by lo (repeated synthetic division, n²/2 multiply-adds) and a
// scaling by w^k; leading coefficients negligible on [0, 1] are dropped. Working on [0, 1] makes
// the later tolerances absolute and improves conditioning when the interval is far from 0.
// Returns false when the coefficients overflow.
inline bool map_to_unit_interval(const RayPolynomial& f, int degree, double lo, double hi,
                                 UnitRestriction& u) {
    u.f = f.c.data();
    u.f_degree = degree;
    u.lo = lo;
    u.hi = hi;
    u.w = hi - lo;
    Coefficients& g = u.g;
    double largest = 0.0;
    for (int k = 0; k <= degree; ++k) {
        largest = std::max(largest, std::abs(f.c[k]));
    }
    // Exact power-of-two prescaling keeps extreme coefficients away from overflow in the shift.
    double prescale = 1.0;
    if (largest > 1e100 || largest < 1e-100) {
        int exponent = 0;
        std::frexp(largest, &exponent);
        prescale = std::ldexp(1.0, -exponent);
    }
    for (int k = 0; k <= degree; ++k) {
        g[k] = f.c[k] * prescale;
    }
    if (lo != 0.0) {
        for (int j = 0; j < degree; ++j) {
            for (int k = degree - 1; k >= j; --k) {
                g[k] += lo * g[k + 1];
            }
        }
    }
    double power = u.w;
    for (int k = 1; k <= degree; ++k) {
        g[k] *= power;
        power *= u.w;
    }
    largest = 0.0;
    for (int k = 0; k <= degree; ++k) {
        largest = std::max(largest, std::abs(g[k]));
    }
    if (!std::isfinite(largest)) {
        return false;
    }
    int n = degree;
    while (n > 0 && std::abs(g[n]) <= kNegligibleLeading * largest) {
        --n;
    }
    const double inverse = 1.0 / largest;
    for (int k = 0; k <= n; ++k) {
        g[k] *= inverse;
    }
    u.degree = n;
    u.kappa = inverse * prescale;
    return true;
}

// 1 / C(n, k) for n, k ≤ kMaxDegree (C(40, 20) ≈ 1.4e11 is exact in a double).
inline constexpr auto kInverseBinomial = [] {
    std::array<std::array<double, kMaxDegree + 1>, kMaxDegree + 1> table{};
    for (int n = 0; n <= kMaxDegree; ++n) {
        double c = 1.0;
        for (int k = 0; k <= n; ++k) {
            table[n][k] = 1.0 / c;
            c = c * (n - k) / (k + 1);
        }
    }
    return table;
}();

// Bernstein coefficients on [0, 1] from power coefficients: b_i = Σ_{k≤i} C(i,k)/C(n,k) g_k,
// computed with n²/2 additions after scaling by 1/C(n, k).
inline void to_bernstein(const Coefficients& g, int n, Coefficients& b) {
    for (int k = 0; k <= n; ++k) {
        b[k] = g[k] * kInverseBinomial[n][k];
    }
    for (int j = 0; j < n; ++j) {
        for (int i = n; i > j; --i) {
            b[i] += b[i - 1];
        }
    }
}

// De Casteljau at s ∈ (0, 1): the piece `left` (Bernstein coefficients on some [a, b]) becomes
// its part on [a, a + s·(b − a)] and `right` the rest.
inline void split_at(Coefficients& left, Coefficients& right, int n, double s) {
    std::copy(left.begin(), left.begin() + n + 1, right.begin());
    for (int k = 1; k <= n; ++k) {
        for (int i = 0; i <= n - k; ++i) {
            right[i] += s * (right[i + 1] - right[i]);
        }
        left[k] = right[0];
    }
}

// Required width of the final bracket in s ∈ [0, 1] for an interval of width w.
inline double unit_tolerance(double w) {
    return std::max(kRootTolerance * std::max(1.0, w) / w, 8.0 * kEpsilon);
}

// Back from s ∈ [0, 1] to t ∈ [lo, hi], exact at both ends.
inline double from_unit(double s, double lo, double hi) {
    if (s <= 0.0) {
        return lo;
    }
    if (s >= 1.0) {
        return hi;
    }
    return std::clamp(lo + (hi - lo) * s, lo, hi);
}

// The root of G in [a, b] given G(a)·G(b) < 0: regula falsi of the Illinois family. When the
// same end is kept twice its value is scaled down, by the Anderson–Björck factor 1 − G(x)/G(x₋)
// (Anderson & Björck, BIT 13 (1973) 253–264), or by the Illinois factor 1/2 (Dowell & Jarratt,
// BIT 11 (1971) 168–174) when that factor is not positive. Measured on random cubics from a
// bracket of width ~0.1 to 2e-11: 4.7 evaluations on average against 5.8 for Illinois. Steps
// are kept at least tol/2 inside the bracket so that it collapses once the iterate has
// converged, and four steps in a row that fail to halve the bracket force a bisection. Stops
// when b − a ≤ tol; adds evaluations to `work`.
inline double regula_falsi(const double* g, int degree, double a, double b, double ga, double gb,
                           double tol, int& work) {
    int kept = 0;  // +1: b was kept by the last step, −1: a was kept, 0: neither
    int slow = 0;
    for (int iteration = 0; iteration < 200 && b - a > tol; ++iteration) {
        const double width = b - a;
        double x;
        if (slow >= 4) {
            x = 0.5 * (a + b);
            slow = 0;
        } else {
            x = a - ga * (width / (gb - ga));
            x = std::clamp(x, a + 0.5 * tol, b - 0.5 * tol);
        }
        const double gx = horner(g, degree, x);
        ++work;
        if (gx == 0.0) {
            return x;
        }
        if ((gx < 0.0) == (ga < 0.0)) {
            if (kept == 1) {
                const double m = 1.0 - gx / ga;
                gb *= m > 0.0 ? m : 0.5;
            }
            a = x;
            ga = gx;
            kept = 1;
        } else {
            if (kept == -1) {
                const double m = 1.0 - gx / gb;
                ga *= m > 0.0 ? m : 0.5;
            }
            b = x;
            gb = gx;
            kept = -1;
        }
        slow = (b - a > 0.5 * width) ? slow + 1 : 0;
    }
    return 0.5 * (a + b);
}

// F(x), F'(x) and F''(x)/2 by one Horner pass (the three recurrences are independent, so this
// costs about the latency of F alone).
inline double horner_with_derivatives(const double* c, int degree, double x, double& derivative,
                                      double& half_second) {
    double value = c[degree];
    derivative = 0.0;
    half_second = 0.0;
    for (int k = degree - 1; k >= 0; --k) {
        half_second = half_second * x + derivative;
        derivative = derivative * x + value;
        value = value * x + c[k];
    }
    return value;
}

// The root of G in [a, b] given G(a)·G(b) < 0, like regula_falsi, for a bracket known to hold a
// single root (Sturm isolation): Halley steps x − G·G'/(G'² − G·G''/2) from the midpoint, kept
// inside the bracket, which every evaluation shrinks by the sign of G. A step that leaves the
// bracket or did not halve |G| is replaced by the secant point of the bracket, or by its
// midpoint right after such a secant step or before any Halley step, so that two fallback
// steps in a row at least halve the bracket. Once the Newton error estimate |G''/2G'|·step² (an
// upper bound for Halley's) is below tol/4, the points x ± tol/2 are evaluated (one pass, two
// independent recurrences) and, when they straddle the root, x is returned: a bracket of width tol,
// the guarantee of regula_falsi. Anything else (a step cap) hands the current bracket to
// regula_falsi. Measured on the restrictions of the render suite (256² primary rays, degree
// 4–12): 4.5–5.2 evaluations of G, G', G'' per root against 7.9–9.7 evaluations of G for
// regula_falsi, and with three independent recurrences one evaluation costs about as much as one of
// G. Newton steps instead of Halley's took about 0.5 more evaluations per root, and the secant
// point as the start about 0.4 more.
inline double halley_bracketed(const double* g, int degree, double a, double b, double ga,
                               double gb, double tol, int& work) {
    double x = 0.5 * (a + b);
    double previous = std::numeric_limits<double>::infinity();
    bool bisect_next = true;
    for (int iteration = 0; iteration < 60 && b - a > tol; ++iteration) {
        x = std::clamp(x, a + 0.5 * tol, b - 0.5 * tol);
        double derivative;
        double half_second;
        const double gx = horner_with_derivatives(g, degree, x, derivative, half_second);
        ++work;
        if (gx == 0.0) {
            return x;
        }
        if ((gx < 0.0) == (ga < 0.0)) {
            a = x;
            ga = gx;
        } else {
            b = x;
            gb = gx;
        }
        const double step = gx * derivative / (derivative * derivative - gx * half_second);
        const double next = x - step;
        if (next > a && next < b && std::abs(gx) <= 0.5 * previous) {
            previous = std::abs(gx);
            bisect_next = false;
            if (std::abs(half_second / derivative) * step * step <= 0.25 * tol) {
                // Converged: confirm by a bracket of width tol around the iterate.
                const double left = std::max(a, next - 0.5 * tol);
                const double right = std::min(b, next + 0.5 * tol);
                double gl = g[degree];
                double gr = g[degree];
                for (int k = degree - 1; k >= 0; --k) {
                    gl = gl * left + g[k];
                    gr = gr * right + g[k];
                }
                ++work;
                if (gl == 0.0) {
                    return left;
                }
                if (gr == 0.0) {
                    return right;
                }
                if ((gl < 0.0) != (gr < 0.0)) {
                    return next;
                }
                if ((gl < 0.0) == (ga < 0.0)) {
                    a = left;
                    ga = gl;
                } else {
                    b = right;
                    gb = gr;
                }
                break;
            }
            x = next;
        } else {
            previous = std::abs(gx);
            x = bisect_next ? 0.5 * (a + b) : a - ga * ((b - a) / (gb - ga));
            bisect_next = !bisect_next;
        }
    }
    return regula_falsi(g, degree, a, b, ga, gb, tol, work);
}

// Which polynomial a bracket holds a root of: the restriction or its derivative.
enum class RootOf { value, derivative };

// F and G, or F' and G' for RootOf::derivative, ready to evaluate.
struct BothBases {
    const double* f;  // in t
    int f_degree;
    const double* g;  // in s; g = scale·(f at t = lo + w·s)
    int g_degree;
    double scale;
    Coefficients f_storage;
    Coefficients g_storage;
};

inline void make_bases(const UnitRestriction& u, RootOf of, BothBases& b) {
    b.f = u.f;
    b.f_degree = u.f_degree;
    b.g = u.g.data();
    b.g_degree = u.degree;
    b.scale = u.kappa;
    if (of == RootOf::derivative) {
        derivative(u.f, u.f_degree, b.f_storage.data());
        derivative(u.g.data(), u.degree, b.g_storage.data());
        b.f = b.f_storage.data();
        b.g = b.g_storage.data();
        --b.f_degree;
        --b.g_degree;
        b.scale *= u.w;
    }
}

// Whether the original basis rounds less than G near s: G is better when [lo, hi] is far from
// 0 and narrow, the original when the interval contains 0 or is wide (the Taylor shift then
// inflates the coefficients). The Horner rounding scales Σ|c_k||x|^k, in the same units, decide.
inline bool original_rounds_less(const BothBases& b, const UnitRestriction& u, double s) {
    double f_scale;
    double g_scale;
    horner_with_magnitude(b.f, b.f_degree, u.lo + u.w * s, f_scale);
    horner_with_magnitude(b.g, b.g_degree, s, g_scale);
    return f_scale * b.scale < g_scale;
}

// A bracket [a, b] ⊂ [0, 1] in s with the values ga, gb of G (or G') at its ends, of opposite
// signs.
struct SignChange {
    double a, b, ga, gb;
};

// How far and by which iteration refine_root goes.
struct Refinement {
    double coarse_s = 0.0;     // > 0: stop at a bracket this wide in s, not at the tolerance
    bool single_root = false;  // the bracket holds one root (Sturm isolation): halley_bracketed
};

// The root, as t, of G (or of G') in `bracket`, refined by regula falsi in the basis that
// rounds less, to the root tolerance or to `how.coarse_s`. NaN when that basis sees no sign
// change at the ends: the one in G was rounding noise.
inline double refine_root(const UnitRestriction& u, RootOf of, const SignChange& bracket, int& work,
                          Refinement how = {}) {
    const auto [a, b, ga, gb] = bracket;
    const auto solve = how.single_root ? halley_bracketed : regula_falsi;
    BothBases bases;
    make_bases(u, of, bases);
    const double tol_s = std::max(unit_tolerance(u.w), how.coarse_s);
    // With lo = 0 the two bases differ only by the scaling of the coefficients.
    if (u.lo != 0.0 && original_rounds_less(bases, u, 0.5 * (a + b))) {
        const double ta = from_unit(a, u.lo, u.hi);
        const double tb = from_unit(b, u.lo, u.hi);
        const double fa = horner(bases.f, bases.f_degree, ta);
        const double fb = horner(bases.f, bases.f_degree, tb);
        if (fa != 0.0 && fb != 0.0 && (fa < 0.0) != (fb < 0.0)) {
            const double tol =
                std::max(tol_s * u.w, 8.0 * kEpsilon * std::max(std::abs(ta), std::abs(tb)));
            return solve(bases.f, bases.f_degree, ta, tb, fa, fb, tol, work);
        }
        return std::numeric_limits<double>::quiet_NaN();
    }
    const double s = solve(bases.g, bases.g_degree, a, b, ga, gb, tol_s, work);
    return from_unit(s, u.lo, u.hi);
}

// F(t) for t ∈ [lo, hi], evaluated in the basis that rounds less there, and the uncertainty of
// F(t) that comes with the data: the coefficients of F are doubles, so F(t) is only known to
// about ε·Σ|c_k||t|^k whichever basis evaluates it.
inline double value_with_uncertainty(const UnitRestriction& u, double t, double& uncertainty) {
    double f_scale;
    const double f_value = horner_with_magnitude(u.f, u.f_degree, t, f_scale);
    uncertainty = (u.f_degree + 1) * kEpsilon * f_scale;
    const double s = std::clamp((t - u.lo) / u.w, 0.0, 1.0);
    double g_scale;
    const double g_value = horner_with_magnitude(u.g.data(), u.degree, s, g_scale);
    return f_scale * u.kappa <= g_scale ? f_value : g_value / u.kappa;
}

// F vanishes at t within the uncertainty of the data (see value_with_uncertainty).
inline bool is_root_within_rounding(const UnitRestriction& u, double t) {
    double uncertainty;
    const double value = value_with_uncertainty(u, t, uncertainty);
    return std::abs(value) <= 4.0 * uncertainty;
}

// F touches zero at the critical point t: within kTouchFactor times the uncertainty of the
// data (a root of even multiplicity that rounding of the coefficients may have split or lifted
// off the axis), allowing for t itself being known only to the root tolerance τ, which moves
// F by up to |F''(t)|·τ²/2 (without it, F = t²·H with a tangent at exactly 0 never touches:
// F and its rounding scale shrink together).
// `slack` (in units of F) widens the test for a t known less precisely.
inline bool touches_zero(const UnitRestriction& u, double t, double slack = 0.0) {
    double uncertainty;
    const double value = value_with_uncertainty(u, t, uncertainty);
    double second = 0.0;
    for (int k = u.f_degree; k >= 2; --k) {
        second = second * t + k * (k - 1) * u.f[k];
    }
    const double tau = kRootTolerance * std::max(1.0, u.w);
    return std::abs(value) <=
           kTouchFactor * uncertainty + 0.5 * std::abs(second) * tau * tau + slack;
}

// Newton steps used to polish a root or a critical point.
inline constexpr int kPolishSteps = 8;

// A few Newton steps on F from x, each accepted only while |F| decreases (so a step cannot jump
// to another root); adds steps to `work`. Used to polish roots of a deflated or eigenvalue
// problem on the original F.
inline double newton_polish(const double* c, int degree, double x, int max_steps, int& work) {
    // Value and derivative of F at x by one Horner pass.
    const auto evaluate = [&](double at, double& value, double& derivative) {
        value = c[degree];
        derivative = 0.0;
        for (int k = degree - 1; k >= 0; --k) {
            derivative = derivative * at + value;
            value = value * at + c[k];
        }
    };
    double value;
    double derivative;
    evaluate(x, value, derivative);
    for (int step = 0; step < max_steps; ++step) {
        if (value == 0.0 || derivative == 0.0 || !std::isfinite(derivative)) {
            break;
        }
        const double next = x - value / derivative;
        double next_value;
        double next_derivative;
        evaluate(next, next_value, next_derivative);
        ++work;
        if (!(std::abs(next_value) < std::abs(value))) {
            break;
        }
        const bool converged = std::abs(next - x) <= 4.0 * kEpsilon * std::abs(x);
        x = next;
        value = next_value;
        derivative = next_derivative;
        if (converged) {
            break;
        }
    }
    return x;
}

// The critical point of F next to s (Newton on F' in the basis that rounds less), as t; may lie
// outside [lo, hi].
inline double critical_point_near(const UnitRestriction& u, double s, int& work) {
    BothBases bases;
    make_bases(u, RootOf::derivative, bases);
    if (original_rounds_less(bases, u, s)) {
        return newton_polish(bases.f, bases.f_degree, u.lo + u.w * s, kPolishSteps, work);
    }
    return u.lo + u.w * newton_polish(bases.g, bases.g_degree, s, kPolishSteps, work);
}

// Root estimates of the global methods (Laguerre, companion eigenvalues) whose imaginary part
// is below this fraction of (|z| + 1) are examined as possible real roots or tangents.
inline constexpr double kNearReal = 1e-3;
// ... and below this fraction they are real whatever the polishing says.
inline constexpr double kRealImaginary = 1e-7;

// Turns a root estimate z = re + i·im of a global method into a real root t of F, polished on
// the original coefficients c (degree ≥ 1; dc holds F'). A simple root is polished by Newton on
// F until F vanishes within rounding; otherwise z may be one of a pair that rounding split off a
// double root (a tangent), which Newton on F' locates as the critical point where F touches
// zero. Returns false when z is not real. Adds Newton steps to `work`.
inline bool polish_real_root(const double* c, const double* dc, int degree, double re, double im,
                             int& work, double& t) {
    const double size = std::abs(re) + std::abs(im) + 1.0;
    if (std::abs(im) > kNearReal * size) {
        return false;
    }
    const double x = newton_polish(c, degree, re, kPolishSteps, work);
    if (is_zero_within_rounding(c, degree, x)) {
        t = x;
        return true;
    }
    if (degree >= 2) {
        const double y = newton_polish(dc, degree - 1, re, kPolishSteps, work);
        if (touches_zero(c, degree, y)) {
            t = y;
            return true;
        }
    }
    if (std::abs(im) <= kRealImaginary * size) {
        t = x;
        return true;
    }
    return false;
}

// Largest distance outside [lo, hi] at which a polished root still counts as a root at the end
// point; below the accuracy the interface promises.
inline double end_slack(double lo, double hi) {
    return 0.1 * kRootTolerance * std::max(1.0, hi - lo);
}

}  // namespace locus::render::detail
