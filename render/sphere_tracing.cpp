#include "render/sphere_tracing.h"

#include <cmath>

namespace locus::render {

namespace {
constexpr int kMaxSteps = 2000;
}  // namespace

RootResult sphere_trace_gradient(const algebra::CompiledPolynomial& f, const Ray& ray,
                                 Interval interval, double tolerance) {
    RootResult result;
    const double speed = glm::length(ray.direction);  // world distance per unit of t
    if (!(speed > 0.0)) {
        result.status = RootStatus::unknown;
        result.reason = "zero direction";
        return result;
    }
    double t = interval.lo;
    double previous_t = t;
    double previous_value = NAN;
    const double min_step = tolerance / speed;
    for (int step = 0; step < kMaxSteps; ++step) {
        result.work = step + 1;
        const algebra::ValueGradient vg = f.value_gradient(to_point(ray.at(t)));
        if (!std::isfinite(vg.value)) {
            result.status = RootStatus::unknown;
            result.reason = "non-finite value";
            return result;
        }
        if (step > 0 && vg.value != 0.0 && std::signbit(vg.value) != std::signbit(previous_value)) {
            // Overshot a sign change: bisect back within [previous_t, t].
            double lo = previous_t, hi = t, value_lo = previous_value;
            while (hi - lo > min_step && result.work < kMaxSteps) {
                const double mid = 0.5 * (lo + hi);
                const double value_mid = f.value(to_point(ray.at(mid)));
                ++result.work;
                if (std::signbit(value_mid) == std::signbit(value_lo)) {
                    lo = mid;
                    value_lo = value_mid;
                } else {
                    hi = mid;
                }
            }
            result.status = RootStatus::hit;
            result.t = 0.5 * (lo + hi);
            return result;
        }
        const double gradient_norm = std::hypot(vg.gradient[0], vg.gradient[1], vg.gradient[2]);
        const double distance = gradient_norm > 0.0 ? std::abs(vg.value) / gradient_norm : INFINITY;
        if (distance < tolerance) {
            result.status = RootStatus::hit;
            result.t = t;
            return result;
        }
        previous_t = t;
        previous_value = vg.value;
        t += std::max(distance / speed, min_step);
        if (t > interval.hi) {
            result.status = RootStatus::miss;
            return result;
        }
    }
    result.status = RootStatus::unknown;
    result.reason = "step limit";
    return result;
}

RootResult sphere_trace_lipschitz(const RayPolynomial& restriction, Interval interval,
                                  double t_tolerance) {
    RootResult result;
    const int n = restriction.degree;
    if (n < 0) {
        result.status = RootStatus::unknown;
        result.reason = "restriction is identically zero";
        return result;
    }
    double t = interval.lo;
    double window = interval.hi - interval.lo;
    std::array<double, kMaxDegree + 1> b;
    for (int step = 0; step < kMaxSteps; ++step) {
        result.work = step + 1;
        // Taylor coefficients of F at t (repeated synthetic division, O(n²)).
        for (int k = 0; k <= n; ++k) {
            b[k] = restriction.c[k];
        }
        for (int i = 0; i < n; ++i) {
            for (int k = n - 1; k >= i; --k) {
                b[k] += t * b[k + 1];
            }
        }
        const double value = std::abs(b[0]);
        if (!std::isfinite(value)) {
            result.status = RootStatus::unknown;
            result.reason = "non-finite value";
            return result;
        }
        // On the surface when |F(t)| is within the rounding of evaluating F at t; a small step
        // alone is no evidence (near-tangent rays and thin walls make |F| small, not zero).
        double magnitude = 0.0;
        for (int k = n; k >= 0; --k) {
            magnitude = magnitude * std::abs(t) + std::abs(restriction.c[k]);
        }
        if (value <= 4.0 * (n + 1) * 0x1p-52 * magnitude) {
            result.status = RootStatus::hit;
            result.t = t;
            return result;
        }
        window = std::min(window, interval.hi - t);
        // L(h) = Σ_{j≥1} j |b_j| h^(j−1), by Horner in h.
        double lipschitz = 0.0;
        for (int j = n; j >= 1; --j) {
            lipschitz = lipschitz * window + j * std::abs(b[j]);
        }
        const double step_length = lipschitz > 0.0 ? value / lipschitz : INFINITY;
        if (step_length >= window) {
            // No root in [t, t + window]: jump the whole window and try a longer one.
            if (t + window >= interval.hi) {
                result.status = RootStatus::miss;
                return result;
            }
            t += window;
            window *= 2.0;
            continue;
        }
        if (step_length < t_tolerance && window > 8.0 * t_tolerance) {
            // A tiny step from a long window says little: bound F' on a local window first.
            window = std::max(4.0 * step_length, t_tolerance);
            continue;
        }
        if (step_length < t_tolerance) {
            // Converged within the tolerance: a root if F changes sign just beyond, or if F is
            // as small as the tolerance allows (an even-multiplicity root); otherwise a thin
            // gap between two sheets, to be stepped over.
            const double beyond = restriction(t + 2.0 * t_tolerance);
            if (std::signbit(beyond) != std::signbit(b[0]) ||
                value <= lipschitz * t_tolerance * 1e-3) {
                result.status = RootStatus::hit;
                result.t = t;
                return result;
            }
        }
        t += step_length;
        // Keep the window a few steps long so that L stays a tight bound near the root.
        window = std::max(4.0 * step_length, t_tolerance);
    }
    result.status = RootStatus::unknown;
    result.reason = "step limit";
    return result;
}

}  // namespace locus::render
