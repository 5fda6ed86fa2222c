#include "algebra/groebner/detail/log_bound.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace locus::algebra::detail::log_bound {

namespace {

// The safety margin on every rounding: far above the error of a double's log2 (about 1e-13
// here), far below a unit.
constexpr double kMargin = 1e-4;

}  // namespace

const std::array<std::int32_t, kSumTableSize / kSumNodeStep + 1> kSumNodes = [] {
    std::array<std::int32_t, kSumTableSize / kSumNodeStep + 1> n{};
    for (std::size_t i = 0; i < n.size(); ++i) {
        const double d = static_cast<double>(i * kSumNodeStep);
        const double exact = kPerBit * std::log2(1.0 + std::exp2(-d / kPerBit));
        n[i] = static_cast<std::int32_t>(std::max(1.0, std::ceil(exact + kMargin)));
    }
    return n;
}();

const std::array<std::uint8_t, kSumTableSize> kSumTable = [] {
    std::array<std::uint8_t, kSumTableSize> t{};
    constexpr auto step = static_cast<std::int32_t>(kSumNodeStep);
    for (std::size_t d = 0; d < kSumTableSize; ++d) {
        const std::int32_t low = kSumNodes[d / kSumNodeStep];
        const std::int32_t high = kSumNodes[d / kSumNodeStep + 1];
        const auto r = static_cast<std::int32_t>(d % kSumNodeStep);
        // Non-negative: the nodes decrease and the chord stays above the lower one.
        t[d] = static_cast<std::uint8_t>((step * low + (high - low) * r + step - 1) / step);
    }
    return t;
}();

Units upper(mpz_srcptr v) {
    if (mpz_sgn(v) == 0) {
        return kZero;
    }
    // |v| = d·2^e with d in [0.5, 1), truncated: the true mantissa is below |d| + 2^−53.
    long exponent = 0;
    const double d = std::fabs(mpz_get_d_2exp(&exponent, v));
    const double fraction = kPerBit * std::log2(d + std::ldexp(1.0, -52));
    return static_cast<Units>(exponent) * kPerBit +
           static_cast<Units>(std::ceil(fraction + kMargin));
}

Units upper(const fmpz_t v) {
    if (fmpz_is_zero(v)) {
        return kZero;
    }
    mpz_t z;
    mpz_init(z);
    fmpz_get_mpz(z, v);
    const Units u = upper(z);
    mpz_clear(z);
    return u;
}

Units lower(mpz_srcptr v) {
    long exponent = 0;
    const double d = std::fabs(mpz_get_d_2exp(&exponent, v));  // truncated: ≤ the true mantissa
    const double fraction = kPerBit * std::log2(d);
    return static_cast<Units>(exponent) * kPerBit +
           static_cast<Units>(std::floor(fraction - kMargin));
}

}  // namespace locus::algebra::detail::log_bound
