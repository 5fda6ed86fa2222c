// Polynomials with coefficients modulo a word-size prime p < 2³¹, in the packed monomials of a
// PolyRing (the same layout, hence the same order, as the rational polynomials): the data of
// the F4 and multi-modular Gröbner code (algebra/modular/).
//
// p < 2³¹ keeps a product of two residues below 2⁶², so row reductions can accumulate several
// products in 64 bits before reducing (f4.cpp).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "algebra/polynomial.h"

namespace locus::algebra::modular {

// Arithmetic in Z/pZ.
struct PrimeField {
    std::uint64_t p;
    std::uint64_t add(std::uint64_t a, std::uint64_t b) const {
        const std::uint64_t s = a + b;
        return s >= p ? s - p : s;
    }
    std::uint64_t negate(std::uint64_t a) const { return a == 0 ? 0 : p - a; }
    std::uint64_t multiply(std::uint64_t a, std::uint64_t b) const { return a * b % p; }
    std::uint64_t inverse(std::uint64_t a) const;  // precondition: a ≠ 0 mod p
};

// The largest prime below `bound` (bound ≤ 2³¹).
std::uint32_t previous_prime(std::uint32_t bound);

// Terms strictly descending under the ring's order, coefficients in [1, p).
struct ModularPolynomial {
    std::vector<std::uint64_t> monomials;  // words per term: the ring's layout
    std::vector<std::uint32_t> coefficients;
    std::size_t size() const { return coefficients.size(); }
    bool is_zero() const { return coefficients.empty(); }
    const std::uint64_t* monomial(std::size_t i, std::size_t words) const {
        return monomials.data() + i * words;
    }
};

// f mod p, or nothing when p divides a denominator of f.
std::optional<ModularPolynomial> reduce_modulo(const Polynomial& f, const PrimeField& field);

}  // namespace locus::algebra::modular
