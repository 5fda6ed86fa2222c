// Verification of implicit equations by substitution: does f vanish identically on a
// parametrization? Two checks that share only the polynomial arithmetic:
//   * vanishes_on, on the rational map (after the tangent half-angle substitution for angles),
//     by exact evaluation on a grid large enough to be a proof (see the .cpp);
//   * vanishes_on_map_as_written, on the map as the user wrote it: for angles, f of the map is
//     a polynomial in the parameters and in sin u, cos u, and it must reduce to zero modulo
//     sin(u)^2 + cos(u)^2 − 1 — which is exactly vanishing for every real angle (the circle is
//     Zariski-dense in the complex conic), with no substitution involved.
#pragma once

#include <optional>

#include "algebra/polynomial.h"
#include "implicit/parametrization.h"

namespace locus::implicit {

struct ImplicitResult;  // implicitize.h

// Does f vanish identically on the (rational) parametrization? f(x) with xᵢ = pᵢ/qᵢ
// substituted, times the denominators' powers, must be the zero polynomial. Exact: a proof by
// evaluation modulo primes past a coefficient bound, checked on `threads` threads.
bool vanishes_on(const algebra::Polynomial& f, const Parametrization& map, int threads = 1);

// Does f vanish identically on the map as written (the same as vanishes_on for rational maps;
// for angles, on sin u and cos u themselves)? Exact.
bool vanishes_on_map_as_written(const algebra::Polynomial& f, const Parametrization& map);

// Whether every polynomial `result` gives (its equation, or its generators) vanishes on the map
// as written: the check every caller runs before it reports a result. The substitution is
// skipped only where the route already proved the equation on this very map (rational maps
// implicitized by interpolation or Dixon). Empty when all vanish, else the first polynomial
// that does not.
std::optional<algebra::Polynomial> first_not_vanishing(const ImplicitResult& result,
                                                       const Parametrization& map);

}  // namespace locus::implicit
