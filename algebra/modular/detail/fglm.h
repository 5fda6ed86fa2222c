// FGLM (Faugère, Gianni, Lazard, Mora, JSC 16, 1993) modulo a prime: the reduced Gröbner basis
// of a zero-dimensional ideal under any target order, from its reduced basis under another
// order. Lex bases are hard to compute directly (F4 must go one pair at a time, Buchberger
// wanders through high degrees) and cheap to convert: the quotient has finite dimension D and
// the conversion is linear algebra on D-vectors of normal forms.
#pragma once

#include <chrono>
#include <optional>
#include <vector>

#include "algebra/modular/modular_polynomial.h"

namespace locus::algebra::modular {

// `basis`: the monic reduced basis under `from` (terms descending under it). Returns the monic
// reduced basis under `to`, sorted by ascending leading monomial, or nothing when the ideal is
// not zero-dimensional or its quotient has more than `max_dimension` standard monomials.
std::optional<std::vector<ModularPolynomial>> fglm(
    const std::vector<ModularPolynomial>& basis, const MonomialLayout& from,
    const MonomialLayout& to, const PrimeField& field, std::size_t max_dimension = 3000,
    std::optional<std::chrono::steady_clock::time_point> deadline = std::nullopt);

}  // namespace locus::algebra::modular
