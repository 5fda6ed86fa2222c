#include "algebra/modular/rational_lift.h"

#include <flint/fmpq.h>
#include <flint/fmpz.h>
#include <flint/ulong_extras.h>

#include <algorithm>
#include <random>
#include <utility>

namespace locus::algebra::modular {

PrimeSequence::PrimeSequence(Width width, std::vector<std::uint64_t> forced)
    : width_(width), forced_(std::move(forced)) {
    std::random_device entropy;
    const std::uint64_t random = (static_cast<std::uint64_t>(entropy()) << 32) | entropy();
    last_ = width == Width::small ? (UWORD(1) << 31) - random % (UWORD(1) << 28)
                                  : (UWORD(1) << 62) + random % (UWORD(1) << 58);
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
        if (width_ == Width::small) {
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

RationalLift::Attempt::Attempt(const RationalLift& lift) : lift_(lift) {
    fmpz_comb_init(comb_, lift.primes_.data(), static_cast<slong>(lift.primes_.size()));
    fmpz_comb_temp_init(temp_, comb_);
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

bool RationalLift::Attempt::reconstruct(LiftedNumber& number) {
    if (number.value_primes > 0 && value_agrees(number, lift_.fields_)) {
        return true;
    }
    fmpz_multi_CRT_ui(residue_.get(), number.residues.data(), comb_, temp_, 0);  // in [0, M)
    if (fmpz_is_zero(residue_.get())) {
        fmpq_zero(number.value.get());
    } else if (fmpq_reconstruct_fmpz(number.value.get(), residue_.get(), lift_.modulus_.get()) ==
               0) {
        return false;
    }
    number.value_primes = number.found_with = lift_.primes_.size();
    return true;
}

}  // namespace locus::algebra::modular
