// The exact restriction F(t) = f(o + t·d) of a polynomial over Q in x, y, z to a line whose
// origin and direction are doubles — the first step of the certified renderer's exact tier
// (exact_first_root in compiled.h), internal to algebra/.
//
// Why not FLINT's fmpq_mpoly_compose_fmpq_poly: it computes over Q, so every product and sum
// is brought to lowest terms with a gcd; at degree 30 that took 1.4 ms a ray, half of a
// Chmutov T₃₀ frame. Here the six doubles are integers times one power of two, f's
// coefficients are integers over one denominator, and the line is a pair of integers per axis:
// F is computed in integers alone, as 2^(n·s)·D·F(t) for D > 0 and s ≥ 0, by Horner's scheme in
// x, then y, then z, where every step multiplies by a linear polynomial. The positive factor
// changes neither the roots of F nor its signs.
#pragma once

#include <flint/fmpz.h>
#include <flint/fmpz_poly.h>

#include <array>
#include <vector>

#include "algebra/rational.h"

namespace locus::algebra {

class Polynomial;

namespace detail {

// An integer polynomial that clears itself (the exact tier's polynomials: here, in
// real_roots.cpp and in exact_first_root).
struct FmpzPoly {
    fmpz_poly_t p;
    FmpzPoly() { fmpz_poly_init(p); }
    FmpzPoly(const FmpzPoly& o) {
        fmpz_poly_init(p);
        fmpz_poly_set(p, o.p);
    }
    FmpzPoly& operator=(const FmpzPoly&) = delete;
    ~FmpzPoly() { fmpz_poly_clear(p); }
};

class ExactLineRestriction {
  public:
    // f in a ring whose variables are x, y, z in that order (compile_surface's ring).
    explicit ExactLineRestriction(const Polynomial& f);

    // out = c·f(o + t·d) for some rational c > 0; o and d finite doubles, read exactly.
    void restrict(const std::array<double, 3>& origin, const std::array<double, 3>& direction,
                  fmpz_poly_t out) const;

  private:
    // Terms by exponents of x, then y, then z, descending; coefficients times the common
    // denominator (integers).
    struct Term {
        int ex, ey, ez;
    };
    std::vector<Term> terms_;
    std::vector<Integer> coefficients_;
    int degree_ = 0;
};

// out = d^n·p((a + b·s)/d) for an integer polynomial p of degree n, integers a, b and d > 0:
// the same computation in one variable (first_real_root maps its interval to [0, 1] with it,
// where FLINT's fmpq_poly_compose took a third of the exact tier's time at degree 30).
void compose_with_line(fmpz_poly_t out, const fmpz_poly_t p, const fmpz_t a, const fmpz_t b,
                       const fmpz_t d);

}  // namespace detail
}  // namespace locus::algebra
