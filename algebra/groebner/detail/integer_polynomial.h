// Internal to the Gröbner code: a polynomial with integer coefficients (FLINT fmpz) for
// fraction-free reduction, with the sugar degree and the divisibility mask of its leading
// monomial. Terms strictly descending, no zero coefficient; same packed layout as Polynomial.
//
// Why integers: over Q every reduction step would normalize fractions (two gcds per
// coefficient); over Z one step is a·p − b·m·g with a, b the cofactors of the leading
// coefficients' gcd, and the content is divided out once per reduced polynomial (Singular's
// p_Cleardenom / p_Content route for characteristic 0).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "algebra/polynomial.h"

namespace locus::algebra::detail {

struct IntegerPolynomial {
    std::vector<std::uint64_t> monomials;  // `words` words per term
    std::vector<Integer> coefficients;
    std::uint32_t sugar = 0;
    std::uint64_t leading_mask = 0;  // MonomialLayout::divisibility_mask of the leading monomial

    std::size_t size() const { return coefficients.size(); }
    bool empty() const { return coefficients.empty(); }
    const std::uint64_t* monomial(std::size_t i, std::size_t words) const {
        return monomials.data() + i * words;
    }
};

// Clears denominators and divides by the content; leading coefficient made positive.
IntegerPolynomial to_integer_polynomial(const Polynomial& f);
// The non-zero generators as integer polynomials (to_integer_polynomial), leading monomials
// ascending: the order in which the Gröbner algorithms take them (small elements first make
// better reducers). Throws MixedRings unless all share one ring.
std::vector<IntegerPolynomial> sorted_integer_generators(std::span<const Polynomial> generators);
// Back to Q, made monic.
Polynomial to_monic_polynomial(const IntegerPolynomial& f, const RingPtr& ring);
// Back to Q with the integer coefficients as they are (primitive, as every basis element and
// generator is): no division, so its cost is a copy whatever their size. For bases returned
// after a deadline, where making monic (a gcd per coefficient) took seconds on coefficients of
// 10⁵ digits and more.
Polynomial to_primitive_polynomial(const IntegerPolynomial& f, const RingPtr& ring);
// Divides by the gcd of the coefficients and makes the leading coefficient positive.
void make_primitive(IntegerPolynomial& f);

}  // namespace locus::algebra::detail
