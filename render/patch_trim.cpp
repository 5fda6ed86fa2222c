#include "render/patch_trim.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace locus::render {
namespace {

constexpr int kSamples = 9;         // domain samples per direction for the starting points
constexpr std::size_t kStarts = 4;  // starting points, at most
constexpr int kIterations = 40;     // Gauss–Newton steps from a start
constexpr double kDomainSlack = 1e-7;
// Powers kept on the stack by evaluate; higher exponents (a `.param` of high degree) use the
// heap. Bézier patches of the .bpt format stay far below (bicubic: 3).
constexpr int kInlinePowers = 24;

}  // namespace

struct PatchTrim::Preimage {
    double s = 0.0, t = 0.0, distance = std::numeric_limits<double>::infinity();
};

PatchTrim::PatchTrim(std::array<std::vector<BivariateTerm>, 4> map, Domain domain, Box box)
    : map_(std::move(map)), domain_(domain), box_(box) {
    for (const auto& component : map_) {
        for (const BivariateTerm& term : component) {
            highest_exponent_ = std::max({highest_exponent_, term.es, term.et});
        }
    }
    for (int i = 0; i < kSamples; ++i) {
        for (int j = 0; j < kSamples; ++j) {
            const double u = i / (kSamples - 1.0), v = j / (kSamples - 1.0);
            if (domain_ == Domain::triangle && u + v > 1.0 + 1e-12) {
                continue;
            }
            const double s = box_.s0 + u * (box_.s1 - box_.s0),
                         t = box_.t0 + v * (box_.t1 - box_.t0);
            samples_.push_back({s, t, evaluate(s, t, false).point});
        }
    }
}

// P/W at (s, t), with its partial derivatives when `derivatives`.
PatchTrim::Value PatchTrim::evaluate(double s, double t, bool derivatives) const {
    const auto count = static_cast<std::size_t>(highest_exponent_ + 1);
    std::array<double, 2 * kInlinePowers> inline_powers;
    std::vector<double> heap_powers;
    double* ps = inline_powers.data();
    if (count > kInlinePowers) {
        heap_powers.resize(2 * count);
        ps = heap_powers.data();
    }
    double* pt = ps + count;
    ps[0] = pt[0] = 1.0;
    for (std::size_t e = 1; e < count; ++e) {
        ps[e] = ps[e - 1] * s;
        pt[e] = pt[e - 1] * t;
    }
    std::array<double, 4> v{}, vs{}, vt{};
    for (std::size_t c = 0; c < 4; ++c) {
        for (const BivariateTerm& term : map_[c]) {
            v[c] += term.coefficient * ps[term.es] * pt[term.et];
            if (derivatives) {
                if (term.es > 0) {
                    vs[c] += term.coefficient * term.es * ps[term.es - 1] * pt[term.et];
                }
                if (term.et > 0) {
                    vt[c] += term.coefficient * term.et * ps[term.es] * pt[term.et - 1];
                }
            }
        }
    }
    Value r;
    const double w = v[3];
    r.point = Vec3(v[0], v[1], v[2]) / w;
    if (derivatives) {
        // d(P/W) = (dP·W − P·dW) / W²
        r.ds = (Vec3(vs[0], vs[1], vs[2]) * w - Vec3(v[0], v[1], v[2]) * vs[3]) / (w * w);
        r.dt = (Vec3(vt[0], vt[1], vt[2]) * w - Vec3(v[0], v[1], v[2]) * vt[3]) / (w * w);
    }
    return r;
}

bool PatchTrim::in_domain(double s, double t) const {
    if (domain_ == Domain::triangle) {
        return s >= -kDomainSlack && t >= -kDomainSlack && s + t <= 1.0 + kDomainSlack;
    }
    const double ds = kDomainSlack * (box_.s1 - box_.s0), dt = kDomainSlack * (box_.t1 - box_.t0);
    return s >= box_.s0 - ds && s <= box_.s1 + ds && t >= box_.t0 - dt && t <= box_.t1 + dt;
}

// Gauss–Newton on |P(s,t)/W − p|² from (s, t), with a Levenberg term for rank-deficient
// Jacobians (a collapsed edge). Stops once the distance is at most `close_enough` (then (s, t)
// is within about that distance over the Jacobian's size of the preimage).
PatchTrim::Preimage PatchTrim::refine(const Vec3& p, double s, double t,
                                      double close_enough) const {
    Preimage best;
    // Iterations in a row whose linear model cannot close even half the distance: p is off
    // the patch there (the residual is normal to the patch), and the search stops.
    int stalled = 0;
    double previous = std::numeric_limits<double>::infinity();
    for (int i = 0; i < kIterations && stalled < 3; ++i) {
        const Value m = evaluate(s, t, true);
        const Vec3 r = m.point - p;
        const double distance = glm::length(r);
        if (!(distance < best.distance)) {
            if (!std::isfinite(distance)) {
                break;
            }
        } else {
            best = {s, t, distance};
            if (distance <= close_enough) {
                break;
            }
        }
        const double a = glm::dot(m.ds, m.ds), b = glm::dot(m.ds, m.dt), c = glm::dot(m.dt, m.dt);
        const double gs = glm::dot(m.ds, r), gt = glm::dot(m.dt, r);
        const double damping = 1e-12 * (a + c) + 1e-300;
        const double det = (a + damping) * (c + damping) - b * b;
        if (!(det > 0.0)) {
            break;
        }
        const double step_s = -((c + damping) * gs - b * gt) / det;
        const double step_t = -((a + damping) * gt - b * gs) / det;
        // A stall: the linear model cannot halve the distance and the distance itself stopped
        // shrinking (it stayed above 0.9 of the best so far).
        const double predicted = glm::length(r + step_s * m.ds + step_t * m.dt);
        stalled = predicted > 0.5 * distance && distance > 0.9 * previous ? stalled + 1 : 0;
        previous = std::min(previous, distance);
        s += step_s;
        t += step_t;
        if (std::abs(step_s) + std::abs(step_t) < 1e-15) {
            break;
        }
    }
    return best;
}

// The preimage in the domain closest to p among those refined from the starting points, or the
// closest outside it when none is inside; `good_enough` stops the search early. The starting
// points are the domain samples closest to p, at least two sample steps apart, so that every
// fold of a patch that passes near p gets a start of its own; each is chosen only when the
// ones before have not found a preimage good enough (usually the first does).
PatchTrim::Preimage PatchTrim::find_preimage(const Vec3& p, double good_enough) const {
    std::array<double, kSamples * kSamples> distance;
    const std::size_t count = samples_.size();
    for (std::size_t i = 0; i < count; ++i) {
        const double d = glm::length(samples_[i].point - p);
        distance[i] = std::isnan(d) ? INFINITY : d;
    }
    const double separation = 2.0 / (kSamples - 1.0) - 1e-12;
    std::array<std::size_t, kStarts> starts;
    std::size_t chosen = 0;
    Preimage inside, outside;
    while (chosen < kStarts) {
        std::size_t next = count;
        for (std::size_t i = 0; i < count; ++i) {
            if (!std::isfinite(distance[i]) || (next < count && !(distance[i] < distance[next]))) {
                continue;
            }
            bool apart = true;
            for (std::size_t k = 0; k < chosen && apart; ++k) {
                const Sample& start = samples_[starts[k]];
                apart =
                    std::max(std::abs(start.s - samples_[i].s) / (box_.s1 - box_.s0),
                             std::abs(start.t - samples_[i].t) / (box_.t1 - box_.t0)) >= separation;
            }
            if (apart) {
                next = i;
            }
        }
        if (next == count) {
            break;
        }
        starts[chosen++] = next;
        // Refined well past good_enough, so that (s, t) is accurate for the domain test.
        const Preimage found = refine(p, samples_[next].s, samples_[next].t, 1e-3 * good_enough);
        Preimage& slot = in_domain(found.s, found.t) ? inside : outside;
        if (found.distance < slot.distance) {
            slot = found;
        }
        if (inside.distance <= good_enough) {
            break;
        }
    }
    return std::isfinite(inside.distance) ? inside : outside;
}

bool PatchTrim::contains(const Vec3& p, double tolerance) const {
    const Preimage found = find_preimage(p, tolerance);
    return found.distance <= tolerance && in_domain(found.s, found.t);
}

std::array<double, 2> PatchTrim::preimage(const Vec3& p) const {
    const Preimage found = find_preimage(p, 0.0);
    return {found.s, found.t};
}

Vec3 PatchTrim::at(double s, double t) const {
    return evaluate(s, t, false).point;
}

}  // namespace locus::render
