// Internal to the Gröbner code: a residue number system on K lanes (residue_lanes.h), for
// integers known to lie in (−M/4, M/4) where M is the product of the first K − 1 primes. The
// last prime q is redundant: it makes the Chinese remainder reconstruction exact without
// multiprecision arithmetic (Shenoy and Kumaresan, "Fast base extension using a redundant
// modulus in RNS", IEEE Trans. Computers 38 (1989)), which is what lets the certification
// (zero_reducer.h) learn, from the residues alone, whether a value is divisible by a basis
// element's leading coefficient L — a remainder modulo L computed from K words — and rebuild a
// value in full when it has to divide out a content.
//
// With y_i = v·(M/p_i)⁻¹ mod p_i, v = Σ y_i·(M/p_i) − α·M for an integer 0 ≤ α < K, and the
// residue of v modulo q gives α exactly.
#pragma once

#include <cstdint>
#include <vector>

#include <flint/fmpz.h>
#include <gmp.h>

#include "algebra/groebner/detail/log_bound.h"
#include "algebra/groebner/detail/residue_lanes.h"

namespace locus::algebra::detail {

class ResidueSystem {
  public:
    explicit ResidueSystem(LanePrimes primes);
    ~ResidueSystem();
    ResidueSystem(const ResidueSystem&) = delete;
    ResidueSystem& operator=(const ResidueSystem&) = delete;

    const LanePrimes& primes() const { return primes_; }
    std::size_t lanes() const { return primes_.size(); }
    // The largest bound (log_bound units) of a value the residues determine: M/4.
    log_bound::Units capacity() const { return capacity_; }

    // Residues of c on every lane, plain or in Montgomery form.
    void residues(const fmpz_t c, std::uint32_t* out, bool montgomery);
    void residues(mpz_srcptr c, std::uint32_t* out, bool montgomery);

    // Per lane, the Montgomery form of the factor that turns a value's residues into
    // reconstruction digits: (M/p_i)⁻¹ on the first K − 1 lanes and 1 on the last.
    const std::uint32_t* digit_factors() const { return digit_factors_.data(); }

    // A modulus L > 1 prepared for remainders: (M/p_i) mod L and L − (M mod L).
    struct Divisor {
        std::vector<mp_limb_t> limbs;          // L
        std::vector<mp_limb_t> cofactors;      // (M/p_i) mod L, `limbs.size()` limbs each
        std::vector<mp_limb_t> minus_modulus;  // L − (M mod L)
    };
    Divisor divisor(mpz_srcptr l) const;

    // From `digits` (a value's residues times digit_factors(), lane by lane): the value
    // modulo d, as d.limbs.size() limbs.
    void remainder(const std::uint32_t* digits, const Divisor& d, mp_limb_t* out);
    // From `digits`: the value itself.
    void reconstruct(const std::uint32_t* digits, mpz_t out) const;

  private:
    std::uint32_t alpha(const std::uint32_t* digits) const;
    void ensure_powers(std::size_t halves);

    LanePrimes primes_;
    log_bound::Units capacity_;
    std::vector<std::uint32_t> digit_factors_;
    std::vector<std::uint32_t> cofactors_mod_q_;  // (M/p_i) mod q
    std::uint32_t modulus_inverse_mod_q_;         // M⁻¹ mod q
    std::vector<__mpz_struct> cofactors_;         // M/p_i
    mpz_t modulus_;                               // M
    // Row i: 2^(32·(i + 1)) mod p on every lane (Montgomery form of 2^(32·i)).
    std::vector<std::uint32_t> powers_;
    std::vector<std::uint32_t> halves_;
    std::vector<mp_limb_t> sum_;
};

}  // namespace locus::algebra::detail
