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

const std::array<std::uint8_t, kSumTableSize> kSumTable = [] {
    std::array<std::uint8_t, kSumTableSize> t{};
    for (std::size_t d = 0; d < kSumTableSize; ++d) {
        const double exact =
            kPerBit * std::log2(1.0 + std::exp2(-static_cast<double>(d) / kPerBit));
        t[d] = static_cast<std::uint8_t>(std::max(1.0, std::ceil(exact + kMargin)));
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
