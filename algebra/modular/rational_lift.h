// Lifting rational numbers from their images modulo primes — Chinese remaindering and rational
// reconstruction (Wang; FLINT's fmpq_reconstruct_fmpz) — the one lifting machinery of the
// modular Gröbner route (modular_groebner.cpp) and of implicitization by interpolation
// (implicit/detail/modular_lifting.h).
//
// How, and why so (measured on the modular route): the residues of a number are kept, one per
// prime, and combined only when a reconstruction is attempted, all at once by a product tree
// (fmpz_multi_CRT_ui) — folding every prime into a GMP integer as it came (fmpz_CRT_ui) cost a
// multiprecision step per number and prime, 1.1 of katsura-10's 13 s. A value, once found, is
// checked against the primes that come after (n ≡ d·r mod p, in words) instead of being
// reconstructed again: 0.6 s more there. Attempts come after every prime up to 64 primes and
// then after 1/32 more: reconstruction of n words costs O(n²), and attempting after every prime
// made lifting quadratic in the primes (1813 primes for the atlas' explode_rational_lex took
// 33 s of lifting); the spacing costs at most 3 % more primes than needed.
//
// The coefficients of one polynomial usually share most of their denominator: given it, each
// is an integer over it (or over it times a small factor), which needs about half the primes of
// the rational; simultaneous reconstruction of a few numbers finds it (Attempt's
// common_denominator and reconstruct with a denominator; the Gröbner route uses them per
// element: cyclic-8 44 → 27 primes).
//
// A lift is a candidate, not a result: a value reconstructed from k primes and agreeing with a
// prime it was not made from is `confirmed` (the interpolation's stopping rule), and callers
// prove what they accept (substitution, or the Gröbner route's certification).
#pragma once

#include <flint/flint.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "algebra/modular/modular_polynomial.h"
#include "algebra/rational.h"

namespace locus::algebra::modular {

// Distinct primes for a lift. `small` ones (below 2³¹: F4's 32-bit data) come down from a
// random point in [2³¹ − 2²⁸, 2³¹), `wide` ones (above 2⁶²: 64-bit kernels, half as many primes
// for the same bits) go up from a random point in [2⁶², 2⁶² + 2⁵⁸), `unreduced` ones (below
// 2²⁴, where F4's row reductions sum products without reducing them on matrices of up to
// 65 535 rows) come down from a random point in [2²⁴ − 2²¹, 2²⁴). Random, because with a fixed
// sequence an input can be made on which the first primes are unlucky together (a coefficient
// equal to the product of the first two, found by a review of the Gröbner route). `forced`
// primes come first (tests); no prime is given twice, since a repeated prime would agree with
// itself.
class PrimeSequence {
  public:
    enum class Width { small, wide, unreduced };
    explicit PrimeSequence(Width width, std::vector<std::uint64_t> forced = {});
    std::uint64_t next();

  private:
    Width width_;
    std::vector<std::uint64_t> forced_;
    std::size_t position_ = 0;
    std::uint64_t last_;
};

// One rational number being lifted.
struct LiftedNumber {
    // Its residues modulo the lift's primes, in their order (a caller whose image lacks the
    // number for a prime stores 0 there).
    std::vector<mp_limb_t> residues;
    Rational value;
    std::size_t value_primes = 0;  // the value agrees with the first value_primes residues
    std::size_t found_with = 0;    // the number of primes the value was reconstructed from
    // A later prime agrees with the value.
    bool confirmed() const { return value_primes > found_with; }
};

// The primes of a lift, their product, and when to attempt the next reconstruction.
class RationalLift {
  public:
    // Primes must be distinct (a repeated prime would agree with itself).
    void add_prime(mp_limb_t p);
    std::size_t primes() const { return primes_.size(); }
    const std::vector<mp_limb_t>& prime_list() const { return primes_; }
    const Integer& modulus() const { return modulus_; }

    // Whether a reconstruction should be attempted now; a true answer moves the schedule on.
    bool attempt_due();

    // One attempt: the product tree of the current primes, for any number of reconstructions.
    class Attempt {
      public:
        // `lattices`: whether common_denominator may reduce lattices in this attempt (a
        // caller's budget: see modular_groebner.cpp's reconstruct).
        explicit Attempt(const RationalLift& lift, bool lattices = true);
        ~Attempt();
        Attempt(const Attempt&) = delete;
        Attempt& operator=(const Attempt&) = delete;
        // The number's value from all the lift's primes: kept when it agrees with the residues
        // it has not been checked against, else reconstructed (0 when every residue is 0).
        // False when no rational within the modulus' bounds has these residues.
        // With a `denominator` D that goes with the number (one its element's coefficients
        // share), D·r (mod M) is first taken as a/b with |a| < M/2^(kMarginBits +
        // kExtraDenominatorBits + 1) and b < 2^kExtraDenominatorBits, the value being a/(b·D):
        // an integer over D, or over D times a small factor that D lacks, needs about half the
        // primes of a rational with D's digits in it. The bounds leave a margin, so that a
        // residue its primes do not determine yet passes with probability about
        // 2^−kMarginBits.
        bool reconstruct(LiftedNumber& number, const Integer* denominator = nullptr);
        // A denominator shared by these numbers (at least two; their values are not looked
        // at), by simultaneous rational reconstruction: the first vector of the LLL-reduced
        // lattice of (D, D·r₁ mod M, …, D·r_k mod M), when it is too short to be an accident
        // (every entry 2^kMarginBits below M^(k/(k+1)), the size of a random lattice's
        // shortest vector, and below the second reduced vector's by as much). With k numbers of
        // numerators below N and a common denominator D this needs about
        // log N + log max(N, D)/k bits where rational reconstruction of any one of them needs
        // log N + log D (cyclic-8: 1 334 bits for the latter, about 840 for k = 4, 760 for k = 8).
        // Nothing when there is no such vector, nothing past kLatticeBits of modulus, and
        // nothing when the attempt was made without lattices.
        std::optional<Integer> common_denominator(std::span<LiftedNumber* const> numbers);
        // The time this attempt spent reducing lattices.
        double lattice_seconds() const { return lattice_seconds_; }
        // One of a group of numbers that share most of a denominator (the coefficients of one
        // polynomial): first over `denominator` (the group's, as far as known), then as a
        // plain rational, then over `hint` (the last denominator the caller found, often
        // shared between groups), and last over a denominator found by common_denominator()
        // of the number with `companions()` (a few more of its group, see companions_near;
        // asked only then, and not past kLatticeBits). The group's denominator takes in, by
        // lcm, only what is reliable: the hint when a value is found over it, the lattice's
        // denominators, and the denominators of values a later prime confirmed (a rational
        // reconstruction from too few primes can succeed by accident, and its denominator
        // would make every integer of the group too large).
        bool reconstruct_sharing(LiftedNumber& number, Integer& denominator, Integer& hint,
                                 const std::function<std::vector<LiftedNumber*>()>& companions);

      private:
        // residue_ ← the number's residues combined, in [0, M).
        void combine(const LiftedNumber& number);
        // The number's value from residue_ over `denominator` (see reconstruct), without
        // marking it found.
        bool over_denominator(LiftedNumber& number, const Integer& denominator);

        const RationalLift& lift_;
        bool lattices_;
        double lattice_seconds_ = 0.0;
        fmpz_comb_t comb_;
        fmpz_comb_temp_t temp_;
        Integer residue_, scaled_, numerator_bound_, denominator_bound_;
    };

    // The safety margin, in bits, of reconstructions whose acceptance is a size test.
    static constexpr flint_bitcnt_t kMarginBits = 32;
    // The largest factor, in bits, that a number's denominator may have beyond the one given.
    static constexpr flint_bitcnt_t kExtraDenominatorBits = 64;
    // No lattices past this modulus: their reduction grows with the square of the entries'
    // size, and an attempt whose numbers are not ready may try one that fails (an integer of
    // 36 000 digits, 5 000 primes: 5.1 → 12.4 s of lifting with no limit; katsura-6 with x0
    // scaled by a 5 000-bit rational, whose denominators are not shared: 0.03 → 0.44 s at
    // 16 384 bits, 0.25 s at this limit). The Gröbner route's lifts stay below it (cyclic-8:
    // about 850 bits, katsura-12 1 100). Spacing a group's failed lattices by two primes
    // instead cost cyclic-8 two primes more (0.3 s) to save that case 0.06 s.
    static constexpr flint_bitcnt_t kLatticeBits = 4096;

  private:
    std::vector<mp_limb_t> primes_;
    std::vector<PrimeField> fields_;  // one per prime: the checks of found values use them
    Integer modulus_{1};
    std::size_t next_attempt_ = 0;
};

// Up to `count` numbers of a group of `size` near position t (after it first, then before
// it), for common_denominator: not t itself, not `skip` (a number known to be 1, such as a
// monic polynomial's leading coefficient, whose residues say nothing), and none whose residues
// are all zero (a zero says nothing of a denominator). `number_at(u)` is the u-th number.
template <typename NumberAt>
std::vector<LiftedNumber*> companions_near(std::size_t t, std::size_t size, std::size_t count,
                                           std::size_t skip, NumberAt number_at) {
    std::vector<LiftedNumber*> out;
    const auto consider = [&](std::size_t u) {
        if (u == t || u == skip || out.size() >= count) {
            return;
        }
        LiftedNumber& n = number_at(u);
        if (std::any_of(n.residues.begin(), n.residues.end(), [](mp_limb_t r) { return r != 0; })) {
            out.push_back(&n);
        }
    };
    for (std::size_t u = t + 1; u < size && out.size() < count; ++u) {
        consider(u);
    }
    for (std::size_t u = t; u-- > 0 && out.size() < count;) {
        consider(u);
    }
    return out;
}

}  // namespace locus::algebra::modular
