// Polynomials with coefficients modulo a word-size prime, in the packed monomials of a PolyRing
// (the same layout, hence the same order, as the rational polynomials), and the arithmetic of
// Z/pZ: the library's one modular polynomial type and one mod-p idiom — the F4 and
// multi-modular Gröbner code (algebra/modular/, primes below 2³¹ in 32-bit coefficients) and
// implicitization by interpolation (primes above 2⁶² in 64-bit ones) both use them.
//
// p < 2³¹ keeps a product of two residues below 2⁶², so F4's row reductions can accumulate
// several products in 64 bits before reducing (f4_linear_algebra.cpp).
#pragma once

#include <flint/fmpq.h>
#include <flint/ulong_extras.h>

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "algebra/polynomial.h"

namespace locus::algebra::modular {

// Arithmetic in Z/pZ for a prime p < 2⁶⁴: FLINT's multiplication by a precomputed inverse
// (n_mulmod2_preinv), which needs no 128-bit division.
class PrimeField {
  public:
    // Implicit: a prime names its field ({p} where a field is asked for).
    PrimeField(std::uint64_t prime)  // NOLINT(google-explicit-constructor)
        : p(prime), inverse_limb_(n_preinvert_limb(prime)) {}

    std::uint64_t p;

    std::uint64_t add(std::uint64_t a, std::uint64_t b) const { return n_addmod(a, b, p); }
    std::uint64_t negate(std::uint64_t a) const { return a == 0 ? 0 : p - a; }
    std::uint64_t multiply(std::uint64_t a, std::uint64_t b) const {
        return n_mulmod2_preinv(a, b, p, inverse_limb_);
    }
    std::uint64_t power(std::uint64_t a, std::uint64_t e) const {
        return n_powmod2_preinv(a, e, p, inverse_limb_);
    }
    std::uint64_t inverse(std::uint64_t a) const { return n_invmod(a, p); }  // a ≠ 0 mod p
    // The residue of a rational number, or nothing when p divides its denominator.
    std::optional<std::uint64_t> residue(const fmpq* q) const;

  private:
    std::uint64_t inverse_limb_;
};

// The largest prime below `bound` (bound ≤ 2³¹).
std::uint32_t previous_prime(std::uint32_t bound);

// Terms strictly descending under the ring's order, coefficients in [1, p).
template <typename Coefficient>
struct BasicModularPolynomial {
    std::vector<std::uint64_t> monomials;  // words per term: the ring's layout
    std::vector<Coefficient> coefficients;
    std::size_t size() const { return coefficients.size(); }
    bool is_zero() const { return coefficients.empty(); }
    const std::uint64_t* monomial(std::size_t i, std::size_t words) const {
        return monomials.data() + i * words;
    }
};
// Primes below 2³¹: the Gröbner code's data.
using ModularPolynomial = BasicModularPolynomial<std::uint32_t>;
// Any word-size prime.
using WideModularPolynomial = BasicModularPolynomial<std::uint64_t>;

// f mod p, or nothing when p divides a denominator of f. Coefficient: std::uint32_t (the
// default) needs p < 2³².
template <typename Coefficient = std::uint32_t>
std::optional<BasicModularPolynomial<Coefficient>> reduce_modulo(const Polynomial& f,
                                                                 const PrimeField& field);

}  // namespace locus::algebra::modular
