// Interpolation of a polynomial of degree ≤ n on [−1, 1] from its values at the n + 1
// Chebyshev nodes u_j = cos(π(j + ½)/(n + 1)), into powers of u — the step both ray families
// (render/ray_family.h, render/certified_ray_family.h) use to expand a row of rays from a few.
//
// Two steps, kept apart rather than fused into one node-to-power matrix: the discrete cosine
// transform to Chebyshev coefficients c_m, then Σ c_m·T_m in powers. Summing c_m·T_m lets the
// small high-order c_m meet the large coefficients of T_m, while the fused matrix sums large
// terms of both signs (20× the distance error at degree 12).
#pragma once

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "render/root_finder.h"

namespace locus::render::detail {

class ChebyshevInterpolation {
  public:
    explicit ChebyshevInterpolation(int degree) : degree_(std::max(degree, 0)) {
        const int nodes = degree_ + 1;
        chebyshev_powers_.resize(static_cast<std::size_t>(nodes));
        cosines_.resize(static_cast<std::size_t>(nodes));
        for (int m = 0; m < nodes; ++m) {
            auto& t = chebyshev_powers_[static_cast<std::size_t>(m)];
            t.fill(0.0);
            if (m <= 1) {
                t[static_cast<std::size_t>(m)] = 1.0;  // T_0 = 1, T_1 = u
            } else {
                // T_m = 2u·T_{m−1} − T_{m−2}.
                const auto& t1 = chebyshev_powers_[static_cast<std::size_t>(m - 1)];
                const auto& t2 = chebyshev_powers_[static_cast<std::size_t>(m - 2)];
                for (int i = 0; i <= m; ++i) {
                    t[i] = (i > 0 ? 2.0 * t1[i - 1] : 0.0) - t2[i];
                }
            }
            for (int j = 0; j < nodes; ++j) {
                cosines_[static_cast<std::size_t>(m)][j] =
                    std::cos(std::numbers::pi * m * (j + 0.5) / nodes);
            }
        }
    }

    int degree() const { return degree_; }

    // Node j in [−1, 1] (0 for degree 0).
    double node(int j) const {
        return degree_ > 0 ? cosines_[1][static_cast<std::size_t>(j)] : 0.0;
    }

    // power[0..n]: the coefficients, in powers of u, of the polynomial of degree ≤ n through
    // value_at_node(j) at the n + 1 nodes.
    template <class ValueAtNode>
    void interpolate(ValueAtNode value_at_node, double* power) const {
        const int nodes = degree_ + 1;
        std::fill_n(power, nodes, 0.0);
        for (int m = 0; m < nodes; ++m) {
            const auto& cosine = cosines_[static_cast<std::size_t>(m)];
            double chebyshev = 0.0;
            for (int j = 0; j < nodes; ++j) {
                chebyshev += value_at_node(j) * cosine[j];
            }
            chebyshev *= (m == 0 ? 1.0 : 2.0) / nodes;
            const auto& t = chebyshev_powers_[static_cast<std::size_t>(m)];
            for (int e = 0; e <= m; ++e) {
                power[e] += chebyshev * t[e];
            }
        }
    }

    // An upper bound of the Lebesgue constant of the nodes: for every polynomial p of degree
    // ≤ n, max over [−1, 1] of |p| ≤ lebesgue_bound()·max over the nodes of |p|. Rivlin's
    // bound (2/π)·ln(n + 1) + 1 holds for the exact nodes; the doubles stand for nodes moved by
    // at most 1e-16, which changes each Lagrange basis polynomial by a relative 1e-12 at most
    // (n ≤ 40: factors (u − u_i)/(u_j − u_i) with node gaps above 1e-3), and 0.01 covers that.
    double lebesgue_bound() const {
        return 2.0 / std::numbers::pi * std::log(degree_ + 1.0) + 1.01;
    }

  private:
    int degree_;
    // cosines_[m][j] = cos(π·m·(j + ½)/(n + 1)) for the discrete cosine transform to Chebyshev
    // coefficients c_m, and chebyshev_powers_[m][i], the coefficient of u^i in T_m.
    std::vector<std::array<double, kMaxDegree + 1>> cosines_;
    std::vector<std::array<double, kMaxDegree + 1>> chebyshev_powers_;
};

}  // namespace locus::render::detail
