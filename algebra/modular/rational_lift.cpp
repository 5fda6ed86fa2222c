#include "algebra/modular/rational_lift.h"

#include <flint/fmpq.h>
#include <flint/fmpz.h>
#include <flint/fmpz_lll.h>
#include <flint/fmpz_mat.h>
#include <flint/ulong_extras.h>

#include <algorithm>
#include <chrono>
#include <random>
#include <utility>

namespace locus::algebra::modular {

PrimeSequence::PrimeSequence(Width width, std::vector<std::uint64_t> forced)
    : width_(width), forced_(std::move(forced)) {
    std::random_device entropy;
    const std::uint64_t random = (static_cast<std::uint64_t>(entropy()) << 32) | entropy();
    switch (width) {
    case Width::small:
        last_ = (UWORD(1) << 31) - random % (UWORD(1) << 28);
        break;
    case Width::wide:
        last_ = (UWORD(1) << 62) + random % (UWORD(1) << 58);
        break;
    case Width::unreduced:
        last_ = (UWORD(1) << 24) - random % (UWORD(1) << 21);
        break;
    }
}

std::uint64_t PrimeSequence::next() {
    const auto forced_before = [&](std::size_t end, std::uint64_t p) {
        return std::find(forced_.begin(), forced_.begin() + static_cast<std::ptrdiff_t>(end), p) !=
               forced_.begin() + static_cast<std::ptrdiff_t>(end);
    };
    while (position_ < forced_.size()) {
        const std::uint64_t p = forced_[position_++];
        if (!forced_before(position_ - 1, p)) {
            return p;
        }
    }
    do {
        if (width_ != Width::wide) {
            last_ = previous_prime(static_cast<std::uint32_t>(last_));
        } else {
            last_ = n_nextprime(last_, 1);
        }
    } while (forced_before(forced_.size(), last_));
    return last_;
}

void RationalLift::add_prime(mp_limb_t p) {
    fmpz_mul_ui(modulus_.get(), modulus_.get(), p);
    primes_.push_back(p);
    fields_.emplace_back(p);
}

bool RationalLift::attempt_due() {
    const std::size_t k = primes_.size();
    if (k < next_attempt_) {
        return false;
    }
    next_attempt_ = k + (k < 64 ? 1 : k / 32);
    return true;
}

RationalLift::Attempt::Attempt(const RationalLift& lift, bool lattices)
    : lift_(lift), lattices_(lattices) {
    fmpz_comb_init(comb_, lift.primes_.data(), static_cast<slong>(lift.primes_.size()));
    fmpz_comb_temp_init(temp_, comb_);
    // over_denominator's bounds, the same for every number of the attempt.
    fmpz_fdiv_q_2exp(numerator_bound_.get(), lift.modulus_.get(),
                     kMarginBits + kExtraDenominatorBits + 1);
    fmpz_one(denominator_bound_.get());
    fmpz_mul_2exp(denominator_bound_.get(), denominator_bound_.get(), kExtraDenominatorBits);
}

RationalLift::Attempt::~Attempt() {
    fmpz_comb_temp_clear(temp_);
    fmpz_comb_clear(comb_);
}

namespace {

// Whether the value n/d agrees with the residues from value_primes on: n ≡ d·r (mod p), p ∤ d.
bool value_agrees(LiftedNumber& number, const std::vector<PrimeField>& fields) {
    for (std::size_t i = number.value_primes; i < fields.size(); ++i) {
        const PrimeField& field = fields[i];
        const ulong n = fmpz_fdiv_ui(fmpq_numref(number.value.get()), field.p);
        const ulong d = fmpz_fdiv_ui(fmpq_denref(number.value.get()), field.p);
        if (d == 0 || n != field.multiply(d, number.residues[i])) {
            number.value_primes = 0;
            return false;
        }
    }
    number.value_primes = fields.size();
    return true;
}

}  // namespace

void RationalLift::Attempt::combine(const LiftedNumber& number) {
    fmpz_multi_CRT_ui(residue_.get(), number.residues.data(), comb_, temp_, 0);  // in [0, M)
}

bool RationalLift::Attempt::reconstruct(LiftedNumber& number, const Integer* denominator) {
    if (number.value_primes > 0 && value_agrees(number, lift_.fields_)) {
        return true;
    }
    combine(number);
    if (fmpz_is_zero(residue_.get())) {
        fmpq_zero(number.value.get());
    } else if ((denominator == nullptr || !over_denominator(number, *denominator)) &&
               fmpq_reconstruct_fmpz(number.value.get(), residue_.get(), lift_.modulus_.get()) ==
                   0) {
        return false;
    }
    number.value_primes = number.found_with = lift_.primes_.size();
    return true;
}

bool RationalLift::Attempt::over_denominator(LiftedNumber& number, const Integer& denominator) {
    // D·r as a rational a/b with |a| < M/2^(margin + extra + 1) and b < 2^extra: an integer
    // over D, or one over D times a small factor D lacks.
    const fmpz* modulus = lift_.modulus_.get();
    const flint_bitcnt_t bits = fmpz_bits(modulus);
    if (bits <= kMarginBits + kExtraDenominatorBits + 2) {
        return false;
    }
    fmpz_mul(scaled_.get(), residue_.get(), denominator.get());
    fmpz_mod(scaled_.get(), scaled_.get(), modulus);
    if (fmpq_reconstruct_fmpz_2(number.value.get(), scaled_.get(), modulus, numerator_bound_.get(),
                                denominator_bound_.get()) == 0) {
        return false;
    }
    fmpq_div_fmpz(number.value.get(), number.value.get(), denominator.get());
    return true;
}

std::optional<Integer> RationalLift::Attempt::common_denominator(
    std::span<LiftedNumber* const> numbers) {
    const auto k = static_cast<slong>(numbers.size());
    const fmpz* modulus = lift_.modulus_.get();
    if (!lattices_ || k < 2 || fmpz_bits(modulus) > kLatticeBits) {
        return std::nullopt;
    }
    const auto start = std::chrono::steady_clock::now();
    // Rows: (1, r₁, …, r_k) and M·e_i; every lattice vector is (D, D·r_i − a_i·M).
    fmpz_mat_t lattice;
    fmpz_mat_init(lattice, k + 1, k + 1);
    fmpz_one(fmpz_mat_entry(lattice, 0, 0));
    for (slong i = 0; i < k; ++i) {
        combine(*numbers[static_cast<std::size_t>(i)]);
        fmpz_set(fmpz_mat_entry(lattice, 0, i + 1), residue_.get());
        fmpz_set(fmpz_mat_entry(lattice, i + 1, i + 1), modulus);
    }
    fmpz_lll_t context;
    fmpz_lll_context_init_default(context);
    // Doubles with exact dot products where they suffice (the full reduction, fmpz_lll, runs a
    // truncating loop and then proves the basis reduced in MPFR: 4 % of katsura-10's run, 0.26
    // s of a katsura-6 with a 5 000-bit coefficient, against 0.7 % and 0.04 s). A basis only
    // proposes a denominator: the tests below and the later primes decide.
    if (fmpz_lll_d_heuristic(lattice, nullptr, context) == -1) {
        fmpz_lll(lattice, nullptr, context);
    }
    // No accident: the first vector short against the lattice's ordinary shortest vector
    // (about M^(k/(k+1))) and against the second reduced vector (a planted short vector leaves
    // the others about (M^k/|v|)^(1/k); a random lattice's are all alike). The second test is
    // the one that matters in practice: when the companions are determined and the number is
    // not, the lattice holds a two-dimensional part whose minima are both about √(M·P) for
    // companions of P bits — short enough for the first test, and a multiplier chosen from
    // this very residue, so the value over it would pass any size margin. Its two minima are
    // alike, which the second test refuses (tested).
    const auto longest_entry = [&](slong row) {
        flint_bitcnt_t bits = 0;
        for (slong j = 0; j <= k; ++j) {
            bits = std::max(bits, fmpz_bits(fmpz_mat_entry(lattice, row, j)));
        }
        return static_cast<slong>(bits);
    };
    const auto margin = static_cast<slong>(kMarginBits);
    const slong first = longest_entry(0);
    std::optional<Integer> found;
    const fmpz* d = fmpz_mat_entry(lattice, 0, 0);
    if (!fmpz_is_zero(d)) {
        const bool short_enough =
            first <= static_cast<slong>(fmpz_bits(modulus)) * k / (k + 1) - margin &&
            first + margin <= longest_entry(1);
        if (short_enough) {
            found.emplace();
            fmpz_abs(found->get(), d);
        }
    }
    fmpz_mat_clear(lattice);
    lattice_seconds_ +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return found;
}

bool RationalLift::Attempt::reconstruct_sharing(
    LiftedNumber& number, Integer& denominator, Integer& hint,
    const std::function<std::vector<LiftedNumber*>()>& companions) {
    // A value's denominator joins the group's once, when a later prime first confirms it.
    const bool was_confirmed = number.confirmed();
    if (reconstruct(number, &denominator)) {
        const fmpz* d = fmpq_denref(number.value.get());
        if (!was_confirmed && number.confirmed() && !fmpz_is_one(d)) {
            fmpz_lcm(denominator.get(), denominator.get(), d);
        }
        return true;
    }
    // reconstruct() failed past its check of a kept value: residue_ is the number's, and
    // rational reconstruction of it has failed; only other denominators are left to try.
    const auto found_over = [&](const Integer& d) {
        if (!over_denominator(number, d)) {
            return false;
        }
        number.value_primes = number.found_with = lift_.primes_.size();
        return true;
    };
    if (!(hint == denominator) && found_over(hint)) {
        fmpz_lcm(denominator.get(), denominator.get(), hint.get());
        return true;
    }
    if (!lattices_ || fmpz_bits(lift_.modulus_.get()) > kLatticeBits) {
        return false;
    }
    std::vector<LiftedNumber*> together{&number};
    for (LiftedNumber* other : companions()) {
        together.push_back(other);
    }
    const std::optional<Integer> common = common_denominator(together);
    if (!common) {
        return false;
    }
    fmpz_lcm(denominator.get(), denominator.get(), common->get());
    hint = denominator;
    combine(number);  // the lattice combined the companions' residues since
    return found_over(denominator);
}

}  // namespace locus::algebra::modular
