#include "render/certified_ray_family.h"

#include <algorithm>
#include <cmath>

#include "algebra/double_double.h"
#include "render/certified_isolation.h"
#include "render/detail/chebyshev_interpolation.h"
#include "render/ray_restriction.h"

namespace locus::render {

namespace {

constexpr double kUnit = 0x1.0p-53;

double gamma(int k) {
    return k * kUnit / (1.0 - k * kUnit);
}

// |computed − exact| for Camera::direction(x, y) = (base + x·U) + y·V in doubles, four
// roundings: at most 3u·(|base| + |x||U| + |y||V|) componentwise (3.1u with room).
Vec3 direction_rounding(const Camera& camera, double x, double y) {
    return 3.1 * kUnit *
           (glm::abs(camera.base()) + std::abs(x) * glm::abs(camera.per_column()) +
            std::abs(y) * glm::abs(camera.per_row()));
}

// The reference ray of image point (x, y) is e + (D + s·R)·d(x, y) with the exact
// d = base + x·U + y·V; as a line in s ∈ [−1, 1] its origin is e + D·d and its direction R·d.
// Its restriction in the Bernstein basis, with rigorous radii for d given within `d_error`
// (componentwise) of the exact direction.
BernsteinBall line_ball(const LineRestrictor& restrictor, const algebra::CompiledPolynomial& f,
                        const Camera& camera, double plane_t, double radius, const Vec3& d,
                        const Vec3& d_error) {
    const Vec3& eye = camera.eye();
    Vec3 origin, direction;
    LineError error;
    for (int i = 0; i < 3; ++i) {
        origin[i] = std::fma(plane_t, d[i], eye[i]);
        direction[i] = radius * d[i];
        error.origin[i] = 1.01 * kUnit * std::abs(origin[i]) + std::abs(plane_t) * d_error[i];
        error.direction[i] = 1.01 * kUnit * std::abs(direction[i]) + radius * d_error[i];
    }
    return to_bernstein(
        restrictor.restrict_with_bounds(origin, direction, error, f.coefficient_error()));
}

// The reference ray of the node at image point (cx + u·hw, cy + v·hh) (u, v doubles),
// restricted in double-double: the image point, the direction d, the line's origin e + D·d and
// direction R·d are formed in double-double, each operation within kOperationError of its
// result (algebra/double_double.h), and the restriction carries those errors and its own. In
// doubles the image point and the direction were rounded eight times (about 10u of their
// magnitude) and the restriction's roundings added u·Σ|terms|: that was most of the nodes'
// radii, which the interpolation multiplies by Λ² for every pixel of the frame.
BernsteinBall node_ball(const LineRestrictor& restrictor, const algebra::CompiledPolynomial& f,
                        const Camera& camera, double plane_t, double radius, double cx, double u,
                        double hw, double cy, double v, double hh) {
    using algebra::DoubleDouble;
    const DoubleDouble x = algebra::two_product(u, hw) + cx;
    const DoubleDouble y = algebra::two_product(v, hh) + cy;
    DoubleDoubleLine line;
    LineError error;
    constexpr double kError = algebra::kOperationError * (1.0 + 0x1.0p-50);
    for (int i = 0; i < 3; ++i) {
        const DoubleDouble d = x * algebra::from_double(camera.per_column()[i]) +
                               y * algebra::from_double(camera.per_row()[i]) + camera.base()[i];
        // d within 4·kError·M of exact (M = |base| + |x||U| + |y||V|), 8 with room.
        const double d_error =
            8.0 * kError *
                (std::abs(camera.base()[i]) + std::abs(x.hi) * std::abs(camera.per_column()[i]) +
                 std::abs(y.hi) * std::abs(camera.per_row()[i])) +
            0x1.0p-1070;
        // origin e + D·d and direction R·d, one product and one sum, each within kError of
        // its result, besides d's own error times |D| and R.
        const DoubleDouble start = d * algebra::from_double(plane_t);
        const DoubleDouble origin = start + camera.eye()[i];
        const DoubleDouble direction = d * algebra::from_double(radius);
        line.origin_hi[i] = origin.hi;
        line.origin_lo[i] = origin.lo;
        line.direction_hi[i] = direction.hi;
        line.direction_lo[i] = direction.lo;
        error.origin[i] = kError * (std::abs(start.hi) + std::abs(origin.hi)) * 2.0 +
                          std::abs(plane_t) * d_error + 0x1.0p-1070;
        error.direction[i] =
            2.0 * kError * std::abs(direction.hi) + std::abs(radius) * d_error + 0x1.0p-1070;
    }
    return to_bernstein(restrictor.restrict_with_double_double_bounds(
        line, error, f.double_double_coefficient_error()));
}

}  // namespace

bool CertifiedRayFamily::worth_building(const algebra::CompiledPolynomial& f, const Camera& camera,
                                        const Vec3& center, double radius, const ImageRect& rect,
                                        int grid, int depth, double fraction) {
    if (grid < 1 || f.degree() < 0 || f.degree() > kMaxDegree || !(radius > 0.0)) {
        return false;
    }
    const LineRestrictor restrictor(f.terms());
    const double plane_t = glm::dot(center - camera.eye(), camera.forward());
    // A family's radius for coefficient i is at least Λ² (the tensor Lebesgue constant) times
    // the largest node's, for every pixel: the samples are searched with that radius.
    const double lebesgue = detail::ChebyshevInterpolation(f.degree()).lebesgue_bound();
    std::vector<BernsteinBall> balls;
    std::array<double, kMaxDegree + 1> largest{};
    for (int j = 0; j < grid; ++j) {
        for (int i = 0; i < grid; ++i) {
            const double x = rect.x0 + (rect.x1 - rect.x0) * (i + 0.5) / grid;
            const double y = rect.y0 + (rect.y1 - rect.y0) * (j + 0.5) / grid;
            balls.push_back(line_ball(restrictor, f, camera, plane_t, radius,
                                      camera.direction(x, y), direction_rounding(camera, x, y)));
            for (int k = 0; k <= f.degree(); ++k) {
                largest[k] = std::max(largest[k], balls.back().r[k]);
            }
        }
    }
    // Rays whose ball is of one sign throughout (far from the surface) are decided by any ball
    // and say nothing: the fraction is of the others. A sample of only those: build.
    int decided = 0, searched = 0;
    for (BernsteinBall& ball : balls) {
        for (int k = 0; k <= f.degree(); ++k) {
            ball.r[k] = lebesgue * lebesgue * largest[k];
        }
        if (most_sign_changes(ball) == 0) {
            continue;
        }
        ++searched;
        decided += isolate_first_root(ball, depth).kind != Isolation::Kind::undecided ? 1 : 0;
    }
    return searched == 0 || decided >= fraction * searched;
}

CertifiedRayFamily::CertifiedRayFamily(const algebra::CompiledPolynomial& f, const Camera& camera,
                                       const Vec3& center, double radius, const ImageRect& rect)
    : degree_(f.degree()),
      center_x_(0.5 * (rect.x0 + rect.x1)),
      half_width_(0.5 * (rect.x1 - rect.x0)),
      center_y_(0.5 * (rect.y0 + rect.y1)),
      half_height_(0.5 * (rect.y1 - rect.y0)) {
    const int n = degree_;
    // The bounds below take image coordinates as non-negative (|x| ≤ center + half-width).
    if (n < 0 || n > kMaxDegree || !(radius > 0.0) || !(rect.x0 >= 0.0) || !(rect.y0 >= 0.0) ||
        !(half_width_ > 0.0) || !(half_height_ > 0.0)) {
        return;
    }
    const auto nodes = static_cast<std::size_t>(n + 1);
    const LineRestrictor restrictor(f.terms());
    const LineRestrictor precise_restrictor(f.terms(), f.low_words());
    const detail::ChebyshevInterpolation chebyshev(n);
    const Vec3& eye = camera.eye();
    const double plane_t = glm::dot(center - eye, camera.forward());
    t_start_ = plane_t - radius;
    t_width_ = 2.0 * radius;
    // The nodes' balls: node (j, k) at u_j, v_k (node_ball).
    std::vector<BernsteinBall> balls(nodes * nodes);
    for (std::size_t j = 0; j < nodes; ++j) {
        for (std::size_t k = 0; k < nodes; ++k) {
            BernsteinBall& ball = balls[j * nodes + k];
            ball = node_ball(precise_restrictor, f, camera, plane_t, radius, center_x_,
                             chebyshev.node(static_cast<int>(j)), half_width_, center_y_,
                             chebyshev.node(static_cast<int>(k)), half_height_);
            for (int i = 0; i <= n; ++i) {
                if (!std::isfinite(ball.b[i]) || !std::isfinite(ball.r[i])) {
                    return;
                }
            }
        }
    }

    // Interpolation: in u for every node row v_k, then each coefficient in v.
    by_uv_.assign(nodes * nodes * nodes, 0.0);
    std::vector<double> in_u(nodes * nodes);  // [k·(n + 1) + a] for the current i
    for (int i = 0; i <= n; ++i) {
        for (std::size_t k = 0; k < nodes; ++k) {
            chebyshev.interpolate(
                [&](int j) { return balls[static_cast<std::size_t>(j) * nodes + k].b[i]; },
                in_u.data() + k * nodes);
        }
        for (std::size_t a = 0; a < nodes; ++a) {
            chebyshev.interpolate(
                [&](int k) { return in_u[static_cast<std::size_t>(k) * nodes + a]; },
                by_uv_.data() + (static_cast<std::size_t>(i) * nodes + a) * nodes);
        }
    }

    // How far a pixel's computed ray may be from its reference: the direction's rounding, and
    // the rounding of u = (x − cx)/hw and v (within 4.1u·(|x| + cx) of the pixel, times |U|).
    // (|x| ≤ cx + hw in the rectangle, so |x| + cx ≤ 2·(cx + hw).)
    const double largest_x = center_x_ + half_width_, largest_y = center_y_ + half_height_;
    const Vec3 pixel_error = direction_rounding(camera, largest_x, largest_y) +
                             4.1 * kUnit *
                                 (2.0 * largest_x * glm::abs(camera.per_column()) +
                                  2.0 * largest_y * glm::abs(camera.per_row())) +
                             direction_rounding(camera, center_x_, center_y_);
    LineError pixel_line;
    pixel_line.origin = std::abs(plane_t) * pixel_error;
    pixel_line.direction = radius * pixel_error;
    // What that distance can change in the restriction, over one tile of the rectangle at a
    // time: the bound grows with the largest magnitudes of the reference lines' origins and
    // directions, affine in u and v (at most the tile centre's magnitude plus the two slopes'),
    // and over a whole frame those are far above any one ray's (a 64-pixel tile at the centre
    // of a 512² frame of barth_decic: 1e-4 of the frame's bound). The tiles are widened by a
    // pixel, for pixels that rounding assigns to a neighbour (ball_at). The computed centre's
    // own rounding is added to the slope: over a narrow tile far from the image's left edge
    // the slopes are too small for the 1e-12 factor to absorb it.
    tiles_x_ =
        std::clamp(static_cast<int>(std::ceil(2.0 * half_width_ / kTilePixels)), 1, kMostTiles);
    tiles_y_ =
        std::clamp(static_cast<int>(std::ceil(2.0 * half_height_ / kTilePixels)), 1, kMostTiles);
    tile_width_ = 2.0 * half_width_ / tiles_x_;
    tile_height_ = 2.0 * half_height_ / tiles_y_;
    const auto tile_growth = [&](int column, int row) {
        const double tx = rect.x0 + (column + 0.5) * tile_width_;
        const double ty = rect.y0 + (row + 0.5) * tile_height_;
        const Vec3 d_center = camera.direction(tx, ty);
        const Vec3 slope_u = (0.5 * tile_width_ + 1.0) * glm::abs(camera.per_column()) +
                             direction_rounding(camera, tx, ty);
        const Vec3 slope_v = (0.5 * tile_height_ + 1.0) * glm::abs(camera.per_row());
        const Vec3 largest_origin =
            (glm::abs(eye + plane_t * d_center) + std::abs(plane_t) * (slope_u + slope_v)) *
                (1.0 + 1e-12) +
            4.0 * kUnit * (glm::abs(eye) + std::abs(plane_t) * glm::abs(d_center));
        const Vec3 largest_direction =
            radius * (glm::abs(d_center) + slope_u + slope_v) * (1.0 + 1e-12);
        RestrictionBall growth;
        growth.polynomial.degree = n;
        growth.radius = restrictor.growth_bound(largest_origin, largest_direction, pixel_line);
        return to_bernstein(growth);
    };

    // The radius of every coefficient, for every pixel.
    const double lebesgue = chebyshev.lebesgue_bound();
    std::vector<double> interpolation_radius(nodes);
    std::vector<double> node_values(nodes * nodes);
    for (int i = 0; i <= n; ++i) {
        const double* p = by_uv_.data() + static_cast<std::size_t>(i) * nodes * nodes;
        double total = 0.0;  // Σ|p_ab|, which bounds |B_i| on [−1, 1]²
        for (std::size_t ab = 0; ab < nodes * nodes; ++ab) {
            total += std::abs(p[ab]);
        }
        // Evaluating the interpolant in doubles (by v, then by u) errs by at most
        // γ_{2n+4}·Σ|p_ab| on [−1, 1]²: at the nodes here, and at every row and pixel.
        const double evaluation = gamma(2 * n + 4) * total * 1.01;
        double at_nodes = 0.0;
        for (std::size_t j = 0; j < nodes; ++j) {
            const double u = chebyshev.node(static_cast<int>(j));
            for (std::size_t k = 0; k < nodes; ++k) {
                const double v = chebyshev.node(static_cast<int>(k));
                double value = 0.0;
                for (int a = n; a >= 0; --a) {
                    const double* in_v = p + static_cast<std::size_t>(a) * nodes;
                    double coefficient = in_v[n];
                    for (int b = n - 1; b >= 0; --b) {
                        coefficient = coefficient * v + in_v[b];
                    }
                    value = value * u + coefficient;
                }
                const BernsteinBall& ball = balls[j * nodes + k];
                at_nodes = std::max(at_nodes, std::abs(ball.b[i] - value) + ball.r[i]);
            }
        }
        // sup |B_i − interpolant| ≤ Λ²·max at the nodes (both of degree ≤ n in u and in v),
        // plus the evaluations' rounding (and, per tile, below, the pixel rays' distance from
        // their references).
        interpolation_radius[static_cast<std::size_t>(i)] =
            (at_nodes * (1.0 + 4.0 * kUnit) + evaluation) * lebesgue * lebesgue + evaluation;
    }
    tile_radius_.assign(static_cast<std::size_t>(tiles_x_ * tiles_y_) * nodes, 0.0);
    certified_ = true;
    for (int row = 0; row < tiles_y_; ++row) {
        for (int column = 0; column < tiles_x_; ++column) {
            const BernsteinBall growth = tile_growth(column, row);
            double* radius_of =
                tile_radius_.data() + static_cast<std::size_t>(row * tiles_x_ + column) * nodes;
            for (int i = 0; i <= n; ++i) {
                radius_of[i] = (interpolation_radius[static_cast<std::size_t>(i)] + growth.r[i]) *
                               (1.0 + 1e-12);
                certified_ = certified_ && std::isfinite(radius_of[i]);
            }
        }
    }
}

void CertifiedRayFamily::expand_row(double y, Row& out) const {
    const int n = degree_;
    out.degree = n;
    if (!certified_) {
        return;
    }
    const auto nodes = static_cast<std::size_t>(n + 1);
    const double v = std::clamp((y - center_y_) / half_height_, -1.0, 1.0);
    out.tile_row =
        std::clamp(static_cast<int>(std::floor((y - (center_y_ - half_height_)) / tile_height_)), 0,
                   tiles_y_ - 1);
    for (int i = 0; i <= n; ++i) {
        for (int a = 0; a <= n; ++a) {
            const double* in_v = by_uv_.data() + (static_cast<std::size_t>(i) * nodes + a) * nodes;
            double value = in_v[n];
            for (int b = n - 1; b >= 0; --b) {
                value = value * v + in_v[b];
            }
            out.by_u[a][i] = value;
        }
    }
}

void CertifiedRayFamily::ball_at(const Row& row, double x, BernsteinBall& out) const {
    const int n = row.degree;
    out.degree = n;
    if (n < 0) {
        return;
    }
    const double u = std::clamp((x - center_x_) / half_width_, -1.0, 1.0);
    const int tile_column =
        std::clamp(static_cast<int>(std::floor((x - (center_x_ - half_width_)) / tile_width_)), 0,
                   tiles_x_ - 1);
    const double* radius_of =
        tile_radius_.data() + static_cast<std::size_t>(row.tile_row * tiles_x_ + tile_column) *
                                  static_cast<std::size_t>(n + 1);
    // Horner in u for every B_i at once.
    for (int i = 0; i <= n; ++i) {
        out.b[i] = row.by_u[n][i];
        out.r[i] = radius_of[i];
    }
    for (int a = n - 1; a >= 0; --a) {
        const auto& in_u = row.by_u[a];
        for (int i = 0; i <= n; ++i) {
            out.b[i] = out.b[i] * u + in_u[i];
        }
    }
}

bool CertifiedRayFamily::decides_often(int grid, int depth, double fraction) const {
    if (!certified_ || grid < 1) {
        return false;
    }
    const int samples = grid * grid;
    const auto needed = static_cast<int>(std::ceil(fraction * samples));
    Row row;
    BernsteinBall ball;
    int decided = 0, undecided = 0;
    for (int j = 0; j < grid; ++j) {
        const double y = center_y_ + half_height_ * ((2.0 * j + 1.0) / grid - 1.0);
        expand_row(y, row);
        for (int i = 0; i < grid; ++i) {
            ball_at(row, center_x_ + half_width_ * ((2.0 * i + 1.0) / grid - 1.0), ball);
            if (isolate_first_root(ball, depth).kind == Isolation::Kind::undecided) {
                ++undecided;
            } else {
                ++decided;
            }
            if (decided >= needed) {
                return true;
            }
            if (samples - undecided < needed) {
                return false;
            }
        }
    }
    return decided >= needed;
}

}  // namespace locus::render
