#include "render/ray_restriction.h"

#include <algorithm>
#include <map>

namespace locus::render {

LineRestrictor::LineRestrictor(std::span<const algebra::CompiledTerm> terms) {
    std::map<int, std::map<int, std::vector<ZTerm>>> grouped;
    for (const algebra::CompiledTerm& term : terms) {
        grouped[term.ex][term.ey].push_back({term.ez, term.coefficient});
        degree_ = std::max(degree_, term.ex + term.ey + term.ez);
        max_exponent_ = std::max({max_exponent_, term.ex, term.ey, term.ez});
    }
    for (auto& [ex, by_y] : grouped) {
        XGroup x_group{ex, 0, {}};
        for (auto& [ey, z_terms] : by_y) {
            YGroup y_group{ey, 0, std::move(z_terms)};
            for (const ZTerm& z : y_group.z_terms) {
                y_group.max_ez = std::max(y_group.max_ez, z.ez);
            }
            x_group.max_yz = std::max(x_group.max_yz, ey + y_group.max_ez);
            x_group.y_groups.push_back(std::move(y_group));
        }
        x_groups_.push_back(std::move(x_group));
    }
}

namespace {

// Powers (o + t·d)^k for k ≤ n as coefficient rows: row k has k + 1 coefficients.
using PowerTable = std::array<std::array<double, kMaxDegree + 1>, kMaxDegree + 1>;

void fill_powers(PowerTable& table, int n, double o, double d) {
    table[0][0] = 1.0;
    for (int k = 1; k <= n; ++k) {
        const auto& previous = table[k - 1];
        auto& row = table[k];
        row[0] = previous[0] * o;
        for (int j = 1; j < k; ++j) {
            row[j] = previous[j] * o + previous[j - 1] * d;
        }
        row[k] = previous[k - 1] * d;
    }
}

}  // namespace

RayPolynomial LineRestrictor::restrict_to(const Vec3& origin, const Vec3& direction) const {
    RayPolynomial result;
    result.degree = degree_;
    if (degree_ < 0) {
        return result;
    }
    PowerTable xs, ys, zs;
    fill_powers(xs, max_exponent_, origin.x, direction.x);
    fill_powers(ys, max_exponent_, origin.y, direction.y);
    fill_powers(zs, max_exponent_, origin.z, direction.z);
    std::array<double, kMaxDegree + 1> in_z, in_yz;
    for (const XGroup& x_group : x_groups_) {
        std::fill_n(in_yz.begin(), x_group.max_yz + 1, 0.0);
        for (const YGroup& y_group : x_group.y_groups) {
            std::fill_n(in_z.begin(), y_group.max_ez + 1, 0.0);
            for (const ZTerm& z : y_group.z_terms) {
                const auto& power = zs[z.ez];
                for (int j = 0; j <= z.ez; ++j) {
                    in_z[j] += z.coefficient * power[j];
                }
            }
            const auto& y_power = ys[y_group.ey];
            for (int i = 0; i <= y_group.ey; ++i) {
                for (int j = 0; j <= y_group.max_ez; ++j) {
                    in_yz[i + j] += y_power[i] * in_z[j];
                }
            }
        }
        const auto& x_power = xs[x_group.ex];
        for (int i = 0; i <= x_group.ex; ++i) {
            for (int j = 0; j <= x_group.max_yz; ++j) {
                result.c[i + j] += x_power[i] * in_yz[j];
            }
        }
    }
    return result;
}

}  // namespace locus::render
