// Laguerre's method for all complex roots of F with deflation, then Newton polishing of the
// (nearly) real ones on the original F and the smallest in [lo, hi].
//
// Follows Numerical Recipes (Press, Teukolsky, Vetterling & Flannery, 3rd ed., §9.5.3, `laguer`
// and `zroots`): each root is found from 0 with the Laguerre step, stopping at the rounding
// level of the evaluation (or when the step falls below the spacing of doubles: rounding can
// make the iterate alternate between neighbours) and breaking limit cycles with fractional
// steps every kCycle iterations; roots are then divided out, the smallest first, which keeps
// forward deflation stable. Because F is real, a root whose imaginary part exceeds
// detail::kRealImaginary·(|x| + 1) is deflated together with its conjugate by a real quadratic
// factor, so the deflated polynomial stays real and half the roots come for free. Every root
// with a small imaginary part is a candidate (detail::polish_real_root): a double root of F
// perturbed by rounding becomes a pair r ± iδ with δ ~ √ε, which must still be a hit.
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>

#include "render/root_finder.h"
#include "render/root_finders/detail/univariate.h"

namespace locus::render {
namespace {

using Complex = std::complex<double>;
using detail::Coefficients;

constexpr int kCycle = 10;                  // a fractional step every kCycle iterations
constexpr int kMaxIterations = 4 * kCycle;  // per start
constexpr int kStarts = 5;                  // 0, then points on the circle of the root moduli

// One root of the real polynomial a (degree m ≥ 2) by Laguerre's method from x; returns false
// when kMaxIterations pass without convergence. Adds iterations to `work`.
bool laguerre_from(const double* a, int m, Complex& x, int& work) {
    static constexpr double kFractions[] = {0.5, 0.25, 0.75, 0.13};
    for (int iteration = 1; iteration <= kMaxIterations; ++iteration) {
        ++work;
        // p(x), p'(x) and p''(x)/2 by Horner, with the rounding bound of p(x).
        Complex p = a[m];
        Complex dp = 0.0;
        Complex half_ddp = 0.0;
        const double abs_x = std::abs(x);
        double bound = std::abs(p);
        for (int j = m - 1; j >= 0; --j) {
            half_ddp = x * half_ddp + dp;
            dp = x * dp + p;
            p = x * p + a[j];
            bound = std::abs(p) + abs_x * bound;
        }
        if (std::abs(p) <= bound * detail::kEpsilon) {
            return true;
        }
        const Complex g = dp / p;
        const Complex g2 = g * g;
        const Complex h = g2 - 2.0 * half_ddp / p;
        const Complex root =
            std::sqrt(static_cast<double>(m - 1) * (static_cast<double>(m) * h - g2));
        const Complex plus = g + root;
        const Complex minus = g - root;
        const double largest = std::max(std::abs(plus), std::abs(minus));
        const Complex step =
            largest > 0.0
                ? static_cast<double>(m) / (std::abs(plus) >= std::abs(minus) ? plus : minus)
                : std::polar(1.0 + abs_x, static_cast<double>(iteration));
        const Complex next = x - step;
        if (std::abs(step) <= 2.0 * detail::kEpsilon * abs_x) {
            return true;  // converged to rounding (possibly alternating between neighbours)
        }
        x = iteration % kCycle != 0 ? next : x - kFractions[iteration / kCycle - 1] * step;
    }
    return false;
}

// One root of a (degree m ≥ 2), from 0 first as Numerical Recipes does, so that the smallest
// roots come first. Where F is very flat at 0 (F ≈ a₀ + a_m·x^m) the Laguerre step from 0 is
// huge and the iterate can bounce between 0 and far away forever; the later starts lie on the
// circle |x| = |a₀/a_m|^(1/m), the geometric mean of the root moduli, at spread-out angles.
bool laguerre(const double* a, int m, Complex& x, int& work) {
    const double radius = std::pow(std::abs(a[0] / a[m]), 1.0 / m);
    for (int start = 0; start < kStarts; ++start) {
        x = start == 0 ? Complex(0.0) : std::polar(radius, 0.7 + 2.1 * start);
        if (laguerre_from(a, m, x, work)) {
            return true;
        }
    }
    return false;
}

}  // namespace

RootResult LaguerreRootFinder::first_root(const RayPolynomial& f, double lo, double hi) const {
    const detail::Screening screening = detail::screen(f, lo, hi);
    if (screening.done) {
        return screening.result;
    }
    const int n = screening.degree;
    // Deflation works on a copy scaled by a power of two (exact) to keep 1e±30 in range.
    double largest = 0.0;
    for (int k = 0; k <= n; ++k) {
        largest = std::max(largest, std::abs(f.c[k]));
    }
    int exponent = 0;
    std::frexp(largest, &exponent);
    Coefficients original;
    Coefficients a;  // deflated in place
    const double prescale = std::ldexp(1.0, -exponent);
    for (int k = 0; k <= n; ++k) {
        original[k] = f.c[k] * prescale;
        a[k] = original[k];
    }
    Coefficients original_derivative;
    detail::derivative(original.data(), n, original_derivative.data());
    const double slack = detail::end_slack(lo, hi);
    double best = HUGE_VAL;
    int work = 0;
    int polish_work = 0;  // not counted: `work` is Laguerre iterations
    const auto consider = [&](Complex z) {
        double t;
        if (detail::polish_real_root(original.data(), original_derivative.data(), n, z.real(),
                                     z.imag(), polish_work, t) &&
            t >= lo - slack && t <= hi + slack) {
            best = std::min(best, std::clamp(t, lo, hi));
        }
    };
    int m = n;
    while (m > 0) {
        if (m == 1) {
            consider(-a[0] / a[1]);
            break;
        }
        Complex x = 0.0;
        if (!laguerre(a.data(), m, x, work)) {
            return detail::unknown("laguerre iteration limit reached", work);
        }
        consider(x);
        if (std::abs(x.imag()) <= detail::kRealImaginary * (std::abs(x) + 1.0)) {
            // Divide by (t − r).
            const double r = x.real();
            double carry = a[m];
            for (int k = m - 1; k >= 0; --k) {
                const double next = a[k] + r * carry;
                a[k] = carry;
                carry = next;
            }
            --m;
        } else {
            // Divide by t² + p·t + q, the factor of x and its conjugate.
            const double p = -2.0 * x.real();
            const double q = std::norm(x);
            double b1 = a[m];
            double b2 = 0.0;
            for (int k = m - 1; k >= 1; --k) {
                const double b0 = a[k] - p * b1 - q * b2;
                a[k + 1] = b1;
                b2 = b1;
                b1 = b0;
            }
            // a[2..m] now hold the quotient shifted by two; move it down.
            for (int k = 0; k <= m - 2; ++k) {
                a[k] = a[k + 2];
            }
            m -= 2;
        }
    }
    if (best != HUGE_VAL) {
        return detail::hit(best, work);
    }
    return detail::is_zero_within_rounding(f.c.data(), n, hi) ? detail::hit(hi, work)
                                                              : detail::miss(work);
}

}  // namespace locus::render
