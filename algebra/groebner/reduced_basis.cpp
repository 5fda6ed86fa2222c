// Interreduction to the reduced Gröbner basis (Cox–Little–O'Shea, IVA ch. 2 §7, Prop. 6): the
// reduced basis is unique, so reducing every tail against the *original* other elements is
// enough: leading monomials never change, and tail irreducibility depends on them only.
#include <algorithm>

#include "algebra/assert.h"
#include "algebra/groebner/buchberger.h"
#include "algebra/groebner/reduction.h"

namespace locus::algebra {
namespace detail {

std::vector<IntegerPolynomial> interreduce(std::vector<BasisElement> basis,
                                           const MonomialLayout& layout, ReductionCounts& counts) {
    const std::size_t w = layout.words();
    // Minimal basis: an element goes when another (non-removed) one's leading monomial divides
    // its own; among equal leading monomials only the first stays.
    for (std::size_t i = 0; i < basis.size(); ++i) {
        basis[i].redundant = basis[i].poly.empty();
    }
    for (std::size_t i = 0; i < basis.size(); ++i) {
        if (basis[i].redundant) {
            continue;
        }
        for (std::size_t j = 0; j < basis.size(); ++j) {
            if (i == j || basis[j].redundant) {
                continue;
            }
            const auto* lm_i = basis[i].poly.monomial(0, w);
            const auto* lm_j = basis[j].poly.monomial(0, w);
            if (layout.divides(lm_j, lm_i) && (!layout.equal(lm_i, lm_j) || j < i)) {
                basis[i].redundant = true;
                break;
            }
        }
    }
    Reducer reducer(layout);
    std::vector<IntegerPolynomial> reduced;
    for (std::size_t i = 0; i < basis.size(); ++i) {
        if (basis[i].redundant) {
            continue;
        }
        basis[i].redundant = true;  // reduce by the others only
        reduced.push_back(reducer.reduce(basis[i].poly, basis, counts));
        basis[i].redundant = false;
    }
    std::sort(reduced.begin(), reduced.end(),
              [&](const IntegerPolynomial& a, const IntegerPolynomial& b) {
                  return layout.compare(a.monomial(0, w), b.monomial(0, w)) < 0;
              });
    LOCUS_ASSERT(ascending_and_minimal(
        reduced.size(), [&](std::size_t i) { return reduced[i].monomial(0, w); }, layout));
    return reduced;
}

}  // namespace detail

std::vector<Polynomial> reduced_basis(std::span<const Polynomial> basis) {
    if (basis.empty()) {
        return {};
    }
    const RingPtr& ring = basis[0].ring();
    std::vector<detail::BasisElement> elements;
    for (const auto& g : basis) {
        require_same_ring(basis[0], g);
        if (!g.is_zero()) {
            elements.push_back({detail::to_integer_polynomial(g), false});
        }
    }
    detail::ReductionCounts counts;
    std::vector<Polynomial> out;
    for (const auto& p : detail::interreduce(std::move(elements), ring->layout(), counts)) {
        out.push_back(detail::to_monic_polynomial(p, ring));
    }
    return out;
}

}  // namespace locus::algebra
