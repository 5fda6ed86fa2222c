// Critical pairs and the Gebauer–Möller installation of Buchberger's criteria
// (Gebauer & Möller, "On an installation of Buchberger's algorithm", JSC 6, 1988; the UPDATE
// procedure of Becker–Weispfenning, "Gröbner Bases", 1993, p. 230).
//
// When a new element h joins the basis: new pairs (h, g) whose lcm is a proper multiple of
// another new pair's lcm are dropped (chain criterion, "M" and "F" steps), then pairs with
// coprime leading monomials are dropped (product criterion); old pairs (g1, g2) with
// lm(h) | lcm(g1, g2) and lcm(gi, h) ≠ lcm(g1, g2) for both i are dropped (chain criterion,
// "B" step); old elements whose leading monomial lm(h) divides become redundant (they stay as
// pair partners of already created pairs, but get no new pairs).
#pragma once

#include <cstdint>
#include <vector>

#include "algebra/groebner/detail/integer_polynomial.h"
#include "algebra/monomial.h"

namespace locus::algebra::detail {

struct CriticalPair {
    std::size_t first, second;       // basis indices, first < second
    std::vector<std::uint64_t> lcm;  // lcm of the leading monomials (packed)
    std::uint32_t sugar = 0;         // sugar degree of the S-polynomial
    std::uint32_t lcm_degree = 0;
};

struct BasisElement {
    IntegerPolynomial poly;
    bool redundant = false;  // its leading monomial is divisible by a later element's
};

struct CriteriaCounts {
    std::size_t pairs_created = 0;
    std::size_t removed_by_product = 0;
    std::size_t removed_by_chain = 0;
};

// Adds the pairs of basis[new_index] (already appended) to `pairs`, applying the criteria above,
// and marks old elements redundant. Counts go to `counts`.
void gebauer_moller_update(std::vector<BasisElement>& basis, std::vector<CriticalPair>& pairs,
                           std::size_t new_index, const MonomialLayout& layout,
                           CriteriaCounts& counts);

}  // namespace locus::algebra::detail
