#include "render/surface_extent.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "algebra/deadline.h"
#include "algebra/error.h"
#include "render/ray_restriction.h"
#include "render/surface_tracer.h"

namespace locus::render {

namespace {

using TimePoint = std::chrono::steady_clock::time_point;

// Evenly spread unit vectors (the Fibonacci lattice on the sphere).
std::vector<Vec3> sphere_directions(int count) {
    std::vector<Vec3> directions;
    directions.reserve(count);
    const double golden_angle = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < count; ++i) {
        const double z = 1.0 - (2.0 * i + 1.0) / count;
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        const double phi = golden_angle * i;
        directions.push_back({r * std::cos(phi), r * std::sin(phi), z});
    }
    return directions;
}

// Two unit vectors completing u to an orthonormal basis.
std::pair<Vec3, Vec3> tangent_basis(const Vec3& u) {
    const Vec3 other = std::abs(u.x) < 0.6 ? Vec3{1.0, 0.0, 0.0} : Vec3{0.0, 1.0, 0.0};
    const Vec3 first = glm::normalize(glm::cross(u, other));
    return {first, glm::cross(u, first)};
}

// Fujiwara's bound on the moduli of the roots of F (leading coefficient non-zero):
// 2·max(|a_{d−1}/a_d|, |a_{d−2}/a_d|^{1/2}, …, |a_0/(2·a_d)|^{1/d}).
double root_modulus_bound(const RayPolynomial& f) {
    const int d = f.degree;
    double bound = 0.0;
    for (int k = 1; k <= d; ++k) {
        double ratio = std::abs(f.c[d - k] / f.c[d]);
        if (k == d) {
            ratio *= 0.5;
        }
        bound = std::max(bound, std::pow(ratio, 1.0 / k));
    }
    return 2.0 * bound;
}

// The top-degree form f_d of f and its gradient, from the compiled terms of degree d.
class TopForm {
  public:
    explicit TopForm(const algebra::CompiledPolynomial& f) {
        for (const algebra::CompiledTerm& term : f.terms()) {
            if (term.ex + term.ey + term.ez == f.degree()) {
                terms_.push_back(term);
            }
        }
    }

    // +1 or −1 when f_d is certainly of that sign away from the origin because of its terms'
    // form alone: every term an even power product with a coefficient of that sign, and the
    // pure power x_i^d of each variable among them; 0 otherwise. Then sign·f_d(u) ≥
    // Σ_i |c_i|·u_i^d > 0 on the unit sphere, however small that least value is: the sampled
    // test below asks for 1e-6 of the largest, which x⁴⁰ + y⁴⁰ + z⁴⁰ (3⁻¹⁹ at the diagonal) and
    // Chmutov's T₃₀ surfaces miss. The coefficients' signs are the rational ones (a
    // coefficient rounded to zero fails the test).
    int even_power_sign(int degree) const {
        int sign = 0;
        bool pure[3] = {false, false, false};
        for (const algebra::CompiledTerm& t : terms_) {
            const int term_sign = t.coefficient > 0.0 ? 1 : (t.coefficient < 0.0 ? -1 : 0);
            if (term_sign == 0 || (sign != 0 && term_sign != sign) || t.ex % 2 != 0 ||
                t.ey % 2 != 0 || t.ez % 2 != 0) {
                return 0;
            }
            sign = term_sign;
            pure[0] = pure[0] || t.ex == degree;
            pure[1] = pure[1] || t.ey == degree;
            pure[2] = pure[2] || t.ez == degree;
        }
        return pure[0] && pure[1] && pure[2] ? sign : 0;
    }

    double value(const Vec3& u) const {
        double sum = 0.0;
        for (const algebra::CompiledTerm& t : terms_) {
            sum += t.coefficient * std::pow(u.x, t.ex) * std::pow(u.y, t.ey) * std::pow(u.z, t.ez);
        }
        return sum;
    }

    Vec3 gradient(const Vec3& u) const {
        Vec3 g(0.0);
        for (const algebra::CompiledTerm& t : terms_) {
            const double px = std::pow(u.x, t.ex), py = std::pow(u.y, t.ey),
                         pz = std::pow(u.z, t.ez);
            if (t.ex > 0) {
                g.x += t.coefficient * t.ex * std::pow(u.x, t.ex - 1) * py * pz;
            }
            if (t.ey > 0) {
                g.y += t.coefficient * t.ey * px * std::pow(u.y, t.ey - 1) * pz;
            }
            if (t.ez > 0) {
                g.z += t.coefficient * t.ez * px * py * std::pow(u.z, t.ez - 1);
            }
        }
        return g;
    }

    // The smallest value of sign·f_d on the unit sphere near `start`: projected gradient
    // descent with backtracking, which walks into a zero of f_d that the lattice only
    // approaches (the pole of x² + y², where the lattice's smallest value is about 2/N).
    double local_minimum(Vec3 u, int sign) const {
        double value_at_u = sign * value(u);
        double step = 0.1;
        for (int iteration = 0; iteration < 200 && step > 1e-12 && value_at_u > 0.0; ++iteration) {
            const Vec3 g = double(sign) * gradient(u);
            const Vec3 tangent = g - glm::dot(g, u) * u;
            const double length = glm::length(tangent);
            if (!(length > 0.0)) {
                break;
            }
            const Vec3 next = glm::normalize(u - step * tangent / length);
            const double value_at_next = sign * value(next);
            if (value_at_next < value_at_u) {
                u = next;
                value_at_u = value_at_next;
                step *= 1.5;
            } else {
                step *= 0.5;
            }
        }
        return value_at_u;
    }

  private:
    std::vector<algebra::CompiledTerm> terms_;
};

class ExtentSearch {
  public:
    ExtentSearch(const algebra::CompiledPolynomial& f, int directions,
                 std::optional<TimePoint> deadline)
        : f_(f),
          restrictor_(f.terms()),
          directions_(sphere_directions(directions)),
          deadline_(deadline) {}

    // Whether f_d keeps one sign on the sphere: certainly so by its terms' form
    // (TopForm::even_power_sign), or else when it stays above 1e-6 of its largest size there
    // at the lattice's values and at local minima from its eight smallest.
    bool top_form_is_definite() const {
        if (f_.degree() % 2 != 0) {
            return false;
        }
        const TopForm top(f_);
        if (top.even_power_sign(f_.degree()) != 0) {
            return true;
        }
        std::vector<std::pair<double, Vec3>> values;
        values.reserve(directions_.size());
        int sign = 0;
        double largest = 0.0;
        for (const Vec3& u : directions_) {
            const double value = top.value(u);
            const int value_sign = value > 0.0 ? 1 : (value < 0.0 ? -1 : 0);
            if (value_sign == 0 || (sign != 0 && value_sign != sign) || !std::isfinite(value)) {
                return false;
            }
            sign = value_sign;
            largest = std::max(largest, std::abs(value));
            values.emplace_back(std::abs(value), u);
        }
        const std::size_t starts = std::min<std::size_t>(8, values.size());
        std::partial_sort(values.begin(), values.begin() + starts, values.end(),
                          [](const auto& a, const auto& b) { return a.first < b.first; });
        for (std::size_t i = 0; i < starts; ++i) {
            if (!(top.local_minimum(values[i].second, sign) > 1e-6 * largest)) {
                return false;
            }
        }
        return true;
    }

    // The Fujiwara bound of f's roots on the line through `centre` along u, with 1 % and an
    // absolute margin for the rounding of the restriction's coefficients.
    double root_bound(const Vec3& centre, const Vec3& u) const {
        RayPolynomial restriction = restrictor_.restrict_to(centre, u);
        restriction.degree = f_.degree();
        return root_modulus_bound(restriction) * 1.01 + 1e-9;
    }

    // The outermost point of the surface on the line through `centre` along u, traced inwards
    // from centre + reach·u, and with a region only inside it.
    std::optional<Vec3> outermost_point(const SurfaceTracer& tracer, const Vec3& centre,
                                        const Vec3& u, double reach,
                                        const ClipRegion* region) const {
        if (!std::isfinite(reach)) {
            return std::nullopt;
        }
        const Ray inwards{centre + reach * u, -u};
        Interval interval{0.0, reach};
        if (region != nullptr) {
            interval = clip(*region, inwards, interval);
            if (interval.is_empty()) {
                return std::nullopt;
            }
        }
        const RootResult hit = tracer.first_hit(inwards, interval);
        if (hit.status != RootStatus::hit) {
            return std::nullopt;
        }
        return inwards.at(hit.t);
    }

    // The surface's point nearest `centre` on the rays from it along the lattice's directions
    // (which cover the whole sphere), each traced outwards over the Fujiwara bound of its roots
    // (a ray along which f_d vanishes has none and is skipped); nothing when no ray meets it.
    std::optional<Vec3> nearest_point(const Vec3& centre) const {
        std::vector<double> reaches(directions_.size()), nearest(directions_.size(), INFINITY);
        for (std::size_t i = 0; i < directions_.size(); ++i) {
            reaches[i] = root_bound(centre, directions_[i]);
        }
        trace_lattice(reaches, [&](const SurfaceTracer& tracer, std::size_t i) {
            const RootResult hit = tracer.first_hit(Ray{centre, directions_[i]}, {0.0, reaches[i]});
            if (hit.status == RootStatus::hit) {
                nearest[i] = hit.t;
            }
        });
        const auto closest = std::min_element(nearest.begin(), nearest.end());
        if (!std::isfinite(*closest)) {
            return std::nullopt;
        }
        return centre + *closest * directions_[static_cast<std::size_t>(closest - nearest.begin())];
    }

    // The outermost point along every lattice direction through `centre` (nothing where none
    // was found), reached as reach(u) says.
    template <class Reach>
    std::vector<std::optional<Vec3>> outermost_points(const Vec3& centre, const Reach& reach,
                                                      const ClipRegion* region, int& lines) const {
        std::vector<std::optional<Vec3>> points(directions_.size());
        std::vector<double> reaches(directions_.size());
        for (std::size_t i = 0; i < directions_.size(); ++i) {
            reaches[i] = reach(directions_[i]);
        }
        if (trace_lattice(reaches, [&](const SurfaceTracer& tracer, std::size_t i) {
                points[i] = outermost_point(tracer, centre, directions_[i], reaches[i], region);
            })) {
            lines += static_cast<int>(directions_.size());
        }
        return points;
    }

    // Pushes each face of `box` outwards: from the lattice direction through `centre` whose
    // outermost point is farthest along the face's axis, a pattern search over nearby
    // directions, the step doubled after a move and halved after none, from half the lattice
    // spacing down to 1e-4 of it (1 % stopped short on the ridges of elongated ellipsoids).
    // The lattice alone left 3 % of an elongated ellipsoid's width outside the box.
    void refine_faces(const Vec3& centre, std::span<const std::optional<Vec3>> points, ClipBox& box,
                      int& lines) const {
        const SurfaceTracer tracer(f_, TraceMethod::certified,
                                   glm::length(box.max - box.min) + glm::length(centre));
        const double spacing = std::sqrt(4.0 * std::numbers::pi / directions_.size());
        for (int axis = 0; axis < 3; ++axis) {
            for (const double side : {-1.0, 1.0}) {
                const auto extent_of = [&](const Vec3& u) -> std::optional<double> {
                    if (++lines % 16 == 0) {
                        check_deadline(0);
                    }
                    const auto point =
                        outermost_point(tracer, centre, u, root_bound(centre, u), nullptr);
                    return point ? std::optional<double>(side * (*point)[axis]) : std::nullopt;
                };
                Vec3 best_u(0.0);
                double best = -INFINITY;
                for (std::size_t i = 0; i < points.size(); ++i) {
                    if (points[i] && side * (*points[i])[axis] > best) {
                        best = side * (*points[i])[axis];
                        best_u = directions_[i];
                    }
                }
                if (!(best > -INFINITY)) {
                    continue;
                }
                check_deadline(0);
                int evaluations = 0;
                for (double step = 0.5 * spacing; step > 1e-4 * spacing && evaluations < 400;) {
                    const auto [e1, e2] = tangent_basis(best_u);
                    bool moved = false;
                    for (const Vec3& offset : {e1, -e1, e2, -e2}) {
                        const Vec3 u = glm::normalize(best_u + step * offset);
                        ++evaluations;
                        if (const auto value = extent_of(u); value && *value > best) {
                            best = *value;
                            best_u = u;
                            moved = true;
                            break;
                        }
                    }
                    step *= moved ? 2.0 : 0.5;
                }
                if (side > 0.0) {
                    box.max[axis] = std::max(box.max[axis], best);
                } else {
                    box.min[axis] = std::min(box.min[axis], -best);
                }
            }
        }
    }

  private:
    // Calls trace(tracer, i) for every lattice direction i with a finite reach, in chunks of 64
    // on threads (each checks the deadline once), with one certified tracer whose tolerance is
    // relative to the largest reach (the scene's size). False, tracing nothing, when no reach
    // is positive and finite.
    template <class Trace>
    bool trace_lattice(const std::vector<double>& reaches, const Trace& trace) const {
        double largest = 0.0;
        for (const double reach : reaches) {
            if (std::isfinite(reach)) {
                largest = std::max(largest, reach);
            }
        }
        if (!(largest > 0.0)) {
            return false;
        }
        const SurfaceTracer tracer(f_, TraceMethod::certified, largest);
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, reaches.size(), 64),
                          [&](const tbb::blocked_range<std::size_t>& range) {
                              check_deadline(0);
                              for (std::size_t i = range.begin(); i < range.end(); ++i) {
                                  if (std::isfinite(reaches[i])) {
                                      trace(tracer, i);
                                  }
                              }
                          });
        return true;
    }

    void check_deadline(std::size_t i) const {
        if (i % 64 == 0 && deadline_passed(deadline_)) {
            throw Timeout("estimating the surface's extent");
        }
    }

    const algebra::CompiledPolynomial& f_;
    LineRestrictor restrictor_;
    std::vector<Vec3> directions_;
    std::optional<TimePoint> deadline_;
};

// A point near the surface reached from `start` by Newton's steps along the gradient,
// x ← x − f(x)·∇f(x)/|∇f(x)|² (the least step that zeroes f's linearisation), or nothing when
// they stall (a critical point, no real point near) or leave the doubles. A guess only: it
// serves as a centre for lines, and only the tracer's points on them count. Far from a small
// or distant component the steps shrink the distance geometrically (a unit sphere 10⁵ away
// is met in about twenty steps from the origin), where the lattice of lines through the origin,
// 0.11 rad apart, passes beside it. Across an elongated component far away the steps can
// zigzag without settling (3 of 200 random far ellipsoids in the tests): when they stop there,
// near f = 0 by their own measure (the last step, |f|/|∇f| where it was taken, under 5 % of
// the way come, and |f| there under 1 % of its value at the start), the last point is
// returned all the same, for its lines to decide. (x³⁰ + y³⁰ + z³⁰ + 1, with no real point,
// drifts slowly towards the origin and fails the second test: no lines are spent on it.)
std::optional<Vec3> newton_projection(const algebra::CompiledPolynomial& f, Vec3 x) {
    const Vec3 start = x;
    double last_step = INFINITY, start_value = NAN, last_value = NAN;
    constexpr int kSteps = 200;
    for (int step = 0; step < kSteps; ++step) {
        const algebra::ValueGradient vg = f.value_gradient({x.x, x.y, x.z});
        const Vec3 g{vg.gradient[0], vg.gradient[1], vg.gradient[2]};
        // |∇f|² computed on the gradient scaled to its largest component: far out, its square
        // overflows the doubles (|∇f| above 1e154) where ∇f itself does not.
        const double scale = std::max({std::abs(g.x), std::abs(g.y), std::abs(g.z)});
        if (!std::isfinite(vg.value) || !std::isfinite(scale) || !(scale > 0.0)) {
            return std::nullopt;
        }
        if (step == 0) {
            start_value = vg.value;
        }
        last_value = vg.value;
        const Vec3 unit = g / scale;
        const Vec3 move = (vg.value / scale / glm::dot(unit, unit)) * unit;
        x -= move;
        last_step = glm::length(move);
        if (!std::isfinite(x.x) || !std::isfinite(x.y) || !std::isfinite(x.z)) {
            return std::nullopt;
        }
        // Converged to the doubles' resolution of where it stands, and onto a zero: |f| within
        // a factor 10⁶ of its evaluation's error bound there (far out, where f/|∇f| is small
        // beside |x| without f being near zero, the steps also stop moving).
        if (glm::length(move) <= 1e-12 * std::max(1.0, glm::length(x))) {
            const algebra::ValueEnclosure e =
                f.enclose_on_line({x.x, x.y, x.z}, {0.0, 0.0, 0.0}, 0.0,
                                  algebra::CompiledPolynomial::Precision::double_precision);
            if (std::abs(e.value) <= 1e6 * e.radius) {
                return x;
            }
            return std::nullopt;
        }
    }
    if (last_step <= 0.05 * glm::length(x - start) &&
        std::abs(last_value) <= 0.01 * std::abs(start_value)) {
        return x;
    }
    return std::nullopt;
}

// Grows `box` to hold the points found; returns whether there was one.
bool add_to_box(std::span<const std::optional<Vec3>> points, ClipBox& box) {
    bool found = false;
    for (const std::optional<Vec3>& point : points) {
        if (point) {
            box.min = glm::min(box.min, *point);
            box.max = glm::max(box.max, *point);
            found = true;
        }
    }
    return found;
}

}  // namespace

SurfaceExtent estimate_extent(const algebra::CompiledPolynomial& f, int directions,
                              std::optional<TimePoint> deadline) {
    SurfaceExtent extent;
    const ExtentSearch search(f, directions, deadline);
    if (!search.top_form_is_definite()) {
        extent.kind = SurfaceExtent::Kind::unbounded;
        return extent;
    }
    const auto reach_from = [&search](const Vec3& centre) {
        return [&search, centre](const Vec3& u) { return search.root_bound(centre, u); };
    };
    ClipBox box{Vec3(INFINITY), Vec3(-INFINITY)};
    Vec3 centre(0.0);
    auto points = search.outermost_points(centre, reach_from(centre), nullptr, extent.lines);
    if (!add_to_box(points, box)) {
        // Nothing on the lines through the origin: a component too small or too far to be
        // met by them. Lines through the point Newton's steps reach from the origin (and,
        // failing that, from the corners of a unit cube) meet it when it is there.
        bool found = false;
        for (const Vec3& start : {Vec3(0.0), Vec3(1.0, 1.0, 1.0), Vec3(-1.0, 1.0, -1.0),
                                  Vec3(1.0, -1.0, -1.0), Vec3(-1.0, -1.0, 1.0)}) {
            const std::optional<Vec3> seed = newton_projection(f, start);
            if (!seed) {
                continue;
            }
            centre = *seed;
            ++extent.newton_points;
            points = search.outermost_points(centre, reach_from(centre), nullptr, extent.lines);
            if (add_to_box(points, box)) {
                found = true;
                break;
            }
        }
        if (!found) {
            extent.kind = SurfaceExtent::Kind::none_found;
            return extent;
        }
    }
    // A surface away from the origin is seen again from the middle of what was found, where
    // the lines meet the whole of it rather than its far side.
    if (glm::length(box.max + box.min) > 0.1 * glm::length(box.max - box.min)) {
        centre = (box.min + box.max) * 0.5;
        points = search.outermost_points(centre, reach_from(centre), nullptr, extent.lines);
        add_to_box(points, box);
    }
    search.refine_faces(centre, points, box, extent.lines);
    extent.kind = SurfaceExtent::Kind::bounded;
    extent.low = box.min;
    extent.high = box.max;
    return extent;
}

std::optional<ClipBox> box_in_region(const algebra::CompiledPolynomial& f, const ClipRegion& region,
                                     int directions, std::optional<TimePoint> deadline) {
    const ExtentSearch search(f, directions, deadline);
    const ClipSphere around = bounding_sphere(region);
    // Slightly beyond the region, so that a surface on its boundary is met inside it.
    const double reach = around.radius * 1.001;
    ClipBox box{Vec3(INFINITY), Vec3(-INFINITY)};
    int lines = 0;
    if (!add_to_box(search.outermost_points(
                        around.center, [reach](const Vec3&) { return reach; }, &region, lines),
                    box)) {
        return std::nullopt;
    }
    return box;
}

std::optional<Vec3> nearest_point_on_lines(const algebra::CompiledPolynomial& f, const Vec3& centre,
                                           int directions, std::optional<TimePoint> deadline) {
    return ExtentSearch(f, directions, deadline).nearest_point(centre);
}

std::optional<ClipSphere> fitted_clip_sphere(const SurfaceExtent& extent) {
    if (extent.kind != SurfaceExtent::Kind::bounded) {
        return std::nullopt;
    }
    const double half_diagonal = glm::length(extent.high - extent.low) * 0.5;
    // 5 % more than the box; 10⁻³ for a surface that is a point (a sphere of radius 10⁻⁴
    // filled a tenth of the picture when 10⁻³ was added to every box).
    return ClipSphere{(extent.low + extent.high) * 0.5,
                      half_diagonal > 0.0 ? half_diagonal * 1.05 : 1e-3};
}

}  // namespace locus::render
