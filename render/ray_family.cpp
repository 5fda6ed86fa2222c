#include "render/ray_family.h"

#include <algorithm>
#include <cmath>

namespace locus::render {

RayFamily::RayFamily(const algebra::CompiledPolynomial& f, const Camera& camera, const Vec3& center,
                     int width, int height)
    : camera_(&camera),
      restrictor_(f.terms()),
      chebyshev_(restrictor_.degree()),
      plane_t_(glm::dot(center - camera.eye(), camera.forward())),
      center_x_(0.5 * width),
      half_width_(0.5 * width),
      center_y_(0.5 * height),
      half_height_(0.5 * height) {
    const int nodes = restrictor_.degree() + 1;
    if (restrictor_.degree() < 0 || restrictor_.degree() > kMaxFamilyDegree) {
        return;  // above kMaxFamilyDegree rows are expanded directly (if at all)
    }
    // Rows at the Chebyshev nodes in v, then each coefficient interpolated in v.
    const auto n_nodes = static_cast<std::size_t>(nodes);
    std::vector<RowExpansion> rows(n_nodes);
    for (int j = 0; j < nodes; ++j) {
        expand_row_directly(center_y_ + chebyshev_.node(j) * half_height_,
                            rows[static_cast<std::size_t>(j)]);
    }
    by_v_.assign(n_nodes * n_nodes * n_nodes, 0.0);
    for (int k = 0; k < nodes; ++k) {
        for (int i = 0; i < nodes; ++i) {
            chebyshev_.interpolate(
                [&](int j) { return rows[static_cast<std::size_t>(j)].row[k][i]; },
                by_v_.data() + (static_cast<std::size_t>(k) * n_nodes + i) * n_nodes);
        }
    }
}

void RayFamily::expand_row(double y, RowExpansion& out) const {
    const int n = restrictor_.degree();
    if (by_v_.empty()) {
        expand_row_directly(y, out);
        return;
    }
    out.degree = n;
    out.center_x = center_x_;
    out.inverse_half_width = 1.0 / half_width_;
    const double v = (y - center_y_) / half_height_;
    const auto n_nodes = static_cast<std::size_t>(n + 1);
    for (int k = 0; k <= n; ++k) {
        for (int i = 0; i <= n; ++i) {
            const double* power =
                by_v_.data() + (static_cast<std::size_t>(k) * n_nodes + i) * n_nodes;
            double value = power[n];
            for (int m = n - 1; m >= 0; --m) {
                value = value * v + power[m];
            }
            out.row[k][i] = value;
        }
    }
}

void RayFamily::expand_row_directly(double y, RowExpansion& out) const {
    const int n = restrictor_.degree();
    out.degree = n;
    out.center_x = center_x_;
    out.inverse_half_width = 1.0 / half_width_;
    // values[j]: the restriction along the ray at node u_j.
    std::array<RayPolynomial, kMaxDegree + 1> values;
    for (int j = 0; j <= n; ++j) {
        const Vec3 d = camera_->direction(center_x_ + chebyshev_.node(j) * half_width_, y);
        values[j] = restrictor_.restrict_to(camera_->eye() + plane_t_ * d, d);
    }
    for (int k = 0; k <= n; ++k) {
        chebyshev_.interpolate([&](int j) { return values[static_cast<std::size_t>(j)].c[k]; },
                               out.row[k].data());
    }
}

RayPolynomial RayFamily::restriction(const RowExpansion& row, double x) {
    RayPolynomial result;
    restriction(row, x, result);
    return result;
}

void RayFamily::restriction(const RowExpansion& row, double x, RayPolynomial& result) {
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
}

}  // namespace locus::render
