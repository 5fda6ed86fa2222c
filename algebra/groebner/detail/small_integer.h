// Internal to the Gröbner code: inline fast paths for FLINT's fmpz when every operand is an
// immediate (a word, not a GMP integer) and so is the result; otherwise FLINT's own function
// runs. The results are the same either way.
//
// Why: on small coefficients FLINT's calls cost far more than the arithmetic. In eco-7's
// Buchberger run (callgrind) fmpz_submul took about 100 instructions a call and fmpz_mul about
// 40, and together with fmpz_add they were a sixth of all instructions.
#pragma once

#include <flint/fmpz.h>

namespace locus::algebra::detail {

// Immediate fmpz values are the words in [COEFF_MIN, COEFF_MAX]; anything else is a pointer.
inline bool fits_immediate(slong v) {
    return v >= COEFF_MIN && v <= COEFF_MAX;
}

// c −= a·b.
inline void submul(fmpz_t c, const fmpz_t a, const fmpz_t b) {
    const slong x = *c, y = *a, z = *b;
    if (!COEFF_IS_MPZ(x) && !COEFF_IS_MPZ(y) && !COEFF_IS_MPZ(z)) {
        slong product, result;
        if (!__builtin_mul_overflow(y, z, &product) &&
            !__builtin_sub_overflow(x, product, &result) && fits_immediate(result)) {
            *c = result;
            return;
        }
    }
    fmpz_submul(c, a, b);
}

// c = a·b.
inline void mul(fmpz_t c, const fmpz_t a, const fmpz_t b) {
    const slong x = *c, y = *a, z = *b;
    if (!COEFF_IS_MPZ(x) && !COEFF_IS_MPZ(y) && !COEFF_IS_MPZ(z)) {
        slong product;
        if (!__builtin_mul_overflow(y, z, &product) && fits_immediate(product)) {
            *c = product;
            return;
        }
    }
    fmpz_mul(c, a, b);
}

// c += a.
inline void add(fmpz_t c, const fmpz_t a) {
    const slong x = *c, y = *a;
    if (!COEFF_IS_MPZ(x) && !COEFF_IS_MPZ(y)) {
        // Two immediates sum to at most 2·COEFF_MAX < 2^63: no overflow.
        const slong sum = x + y;
        if (fits_immediate(sum)) {
            *c = sum;
            return;
        }
    }
    fmpz_add(c, c, a);
}

}  // namespace locus::algebra::detail
