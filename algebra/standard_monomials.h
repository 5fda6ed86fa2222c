// Counting the standard monomials of a zero-dimensional monomial ideal: dim_Q Q[x]/I when the
// ideal is the leading-term ideal of a Gröbner basis of I (Cox–Little–O'Shea, IVA ch. 5 §3).
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <vector>

#include "algebra/rational.h"

namespace locus::algebra {

using ExponentVector = std::vector<std::uint32_t>;

// Whether finitely many monomials in n variables escape the generators: some generator is 1,
// or every variable has a pure power among them (CLO ch. 5 §3, Theorem 6, for the leading
// monomials of a Gröbner basis: the ideal is zero-dimensional or the unit ideal).
bool has_finitely_many_standard_monomials(const std::vector<ExponentVector>& generators,
                                          std::size_t n);

// The number of monomials in n variables that no generator divides; InputError unless
// has_finitely_many_standard_monomials. Splits on a
// variable x of a mixed generator, N(M) = N(M + ⟨x⟩) + N(M : x) (Bigatti's pivot recursion for
// Hilbert series, with the pivot a variable): the monomials outside M either avoid x or are x
// times one outside M : x. A box of pure powers alone is a product, so 12⁸ points cost
// nothing, where walking them took minutes. Throws Timeout once `deadline` has passed.
Integer count_standard_monomials(
    std::vector<ExponentVector> generators, std::size_t n,
    std::optional<std::chrono::steady_clock::time_point> deadline = std::nullopt);

}  // namespace locus::algebra
