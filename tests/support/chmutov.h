// Chmutov's surface T_n(x) + T_n(y) + T_n(z) = 0 as equation text (Chebyshev polynomials of the
// first kind, integer coefficients from T_k = 2t·T_{k−1} − T_{k−2}): the degree-30 surface of the
// renderer's high-degree tests. scripts/chmutov prints the same equations.
#pragma once

#include <string>
#include <vector>

namespace locus::test {

inline std::string chmutov_equation(int n) {
    std::vector<std::vector<long long>> t{{1}, {0, 1}};
    for (int k = 2; k <= n; ++k) {
        std::vector<long long> next(static_cast<std::size_t>(k) + 1, 0);
        for (std::size_t i = 0; i < t[k - 1].size(); ++i) {
            next[i + 1] += 2 * t[k - 1][i];
        }
        for (std::size_t i = 0; i < t[k - 2].size(); ++i) {
            next[i] -= t[k - 2][i];
        }
        t.push_back(next);
    }
    std::string text;
    for (const char* v : {"x", "y", "z"}) {
        for (std::size_t i = 0; i < t[static_cast<std::size_t>(n)].size(); ++i) {
            const long long c = t[static_cast<std::size_t>(n)][i];
            if (c != 0) {
                text += "+(" + std::to_string(c) + ")*" + v + "^" + std::to_string(i);
            }
        }
    }
    return text;
}

}  // namespace locus::test
