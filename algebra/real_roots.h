// Exact real root isolation for univariate integer polynomials: the first root in a rational
// interval, certified. Descartes' rule of signs on the interval mapped to (0, 1) bounds the
// number of roots; bisection (Collins–Akritas, "Polynomial real root isolation using Descartes'
// rule of signs", 1976) splits until a piece has at most one sign variation, which isolates
// exactly one root of a square-free polynomial. Pieces are visited left to right, so the first
// isolated root is the first root. The `exact` method of the renderer is built on this.
#pragma once

#include <flint/fmpq.h>
#include <flint/fmpz_poly.h>

#include <optional>

namespace locus::algebra {

// The smallest root r of the square-free, non-zero polynomial p with lo ≤ r ≤ hi (lo < r with
// `lo_open`), or std::nullopt when there is none. The root is refined by regula falsi on exact
// signs (with bisection steps) until the ends of its enclosure round to the same or to adjacent
// doubles, so the result is within one ulp of r. Precondition: lo < hi.
std::optional<double> first_real_root(const fmpz_poly_t p, const fmpq_t lo, const fmpq_t hi,
                                      bool lo_open);

// out = the rational number the finite double v denotes, exactly (v = m·2^(e−53)).
void set_exact_double(fmpq_t out, double v);

// The double nearest to t, ties to even as IEEE rounds (fmpq_get_d alone may round either
// way); ±∞ beyond the range.
double nearest_double(const fmpq_t t);

}  // namespace locus::algebra
