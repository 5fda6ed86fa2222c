#include "render/ray_family.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace locus::render {

RayFamily::RayFamily(const algebra::CompiledPolynomial& f, const Camera& camera, const Vec3& center,
                     int width)
    : camera_(&camera),
      restrictor_(f.terms()),
      plane_t_(glm::dot(center - camera.eye(), camera.forward())),
      center_x_(0.5 * width),
      half_width_(0.5 * width) {
    const int nodes = restrictor_.degree() + 1;
    cosines_.resize(static_cast<std::size_t>(std::max(nodes, 2)));
    for (int m = 0; m < static_cast<int>(cosines_.size()); ++m) {
        for (int j = 0; j < nodes; ++j) {
            cosines_[static_cast<std::size_t>(m)][j] =
                std::cos(std::numbers::pi * m * (j + 0.5) / nodes);
        }
    }
}

void RayFamily::expand_row(double y, RowExpansion& out) const {
    const int n = restrictor_.degree();
    out.degree = n;
    out.center_x = center_x_;
    out.inverse_half_width = 1.0 / half_width_;
    const int nodes = n + 1;
    // values[j][k]: coefficient of s^k along the ray at node u_j = cos(π(j + ½)/nodes).
    std::array<RayPolynomial, kMaxDegree + 1> values;
    for (int j = 0; j < nodes; ++j) {
        const double u = cosines_[1][j];
        const Vec3 d = camera_->direction(center_x_ + u * half_width_, y);
        values[j] = restrictor_.restrict_to(camera_->eye() + plane_t_ * d, d);
    }
    // Chebyshev coefficients of each H_k (discrete cosine transform at the nodes), then their
    // monomial form in u by the recurrence T_{m+1} = 2u·T_m − T_{m−1}.
    std::array<double, kMaxDegree + 1> chebyshev;
    std::array<double, kMaxDegree + 1> t_previous, t_current, t_next;
    for (int k = 0; k <= n; ++k) {
        for (int m = 0; m < nodes; ++m) {
            double sum = 0.0;
            for (int j = 0; j < nodes; ++j) {
                sum += values[j].c[k] * cosines_[static_cast<std::size_t>(m)][j];
            }
            chebyshev[m] = (m == 0 ? 1.0 : 2.0) * sum / nodes;
        }
        auto& monomial = out.row[k];
        std::fill_n(monomial.begin(), nodes, 0.0);
        std::fill_n(t_previous.begin(), nodes, 0.0);
        std::fill_n(t_current.begin(), nodes, 0.0);
        t_previous[0] = 1.0;  // T_0
        t_current[1] = 1.0;   // T_1
        monomial[0] += chebyshev[0];
        if (nodes > 1) {
            monomial[1] += chebyshev[1];
        }
        for (int m = 2; m < nodes; ++m) {
            t_next[0] = -t_previous[0];
            for (int i = 1; i <= m; ++i) {
                t_next[i] = 2.0 * t_current[i - 1] - (i <= m - 2 ? t_previous[i] : 0.0);
            }
            for (int i = 0; i <= m; ++i) {
                monomial[i] += chebyshev[m] * t_next[i];
            }
            t_previous = t_current;
            t_current = t_next;
        }
    }
}

RayPolynomial RayFamily::restriction(const RowExpansion& row, double x) {
    RayPolynomial result;
    result.degree = row.degree;
    const double u = (x - row.center_x) * row.inverse_half_width;
    for (int k = 0; k <= row.degree; ++k) {
        const auto& coefficients = row.row[k];
        double value = coefficients[row.degree];
        for (int j = row.degree - 1; j >= 0; --j) {
            value = value * u + coefficients[j];
        }
        result.c[k] = value;
    }
    return result;
}

}  // namespace locus::render
