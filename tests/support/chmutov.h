// Chmutov's surface T_n(x) + T_n(y) + T_n(z) = 0 as equation text (Chebyshev polynomials of the
// first kind, integer coefficients from T_k = 2t·T_{k−1} − T_{k−2}): the high-degree surfaces of
// the renderer's tests. scripts/chmutov prints the same equations.
#pragma once

#include <string>
#include <vector>

namespace locus::test {

// In 128-bit integers: T_64's coefficients reach 2^63 and beyond (their magnitudes sum to about
// 1.2·10^24), past a long long; for n ≤ 64 they stay far below 2^127.
inline std::string chmutov_equation(int n) {
    __extension__ using Int128 = __int128;  // GCC's and Clang's (not ISO C++)
    const auto text_of = [](Int128 v) {
        const bool negative = v < 0;
        std::string digits;
        do {
            const int digit = static_cast<int>(v % 10);
            digits.insert(digits.begin(), static_cast<char>('0' + (digit < 0 ? -digit : digit)));
            v /= 10;
        } while (v != 0);
        return negative ? "-" + digits : digits;
    };
    std::vector<std::vector<Int128>> t{{1}, {0, 1}};
    for (int k = 2; k <= n; ++k) {
        std::vector<Int128> next(static_cast<std::size_t>(k) + 1, 0);
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
            const Int128 c = t[static_cast<std::size_t>(n)][i];
            if (c != 0) {
                text += "+(" + text_of(c) + ")*" + v + "^" + std::to_string(i);
            }
        }
    }
    return text;
}

}  // namespace locus::test
