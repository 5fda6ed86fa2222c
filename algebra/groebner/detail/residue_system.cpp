#include "algebra/groebner/detail/residue_system.h"

#include <cstring>

#include <flint/ulong_extras.h>

#include "algebra/error.h"

namespace locus::algebra::detail {

namespace {

__extension__ using Wide = unsigned __int128;

}  // namespace

ResidueSystem::ResidueSystem(LanePrimes primes) : primes_(std::move(primes)) {
    const std::size_t lanes = primes_.size(), digits = lanes - 1;
    const std::uint32_t q = primes_.prime(digits);
    mpz_init_set_ui(modulus_, 1);
    for (std::size_t i = 0; i < digits; ++i) {
        mpz_mul_ui(modulus_, modulus_, primes_.prime(i));
    }
    capacity_ = log_bound::lower(modulus_) - 2 * log_bound::kPerBit;  // M/4
    cofactors_.resize(digits);
    digit_factors_.resize(lanes);
    cofactors_mod_q_.resize(digits);
    for (std::size_t i = 0; i < digits; ++i) {
        const std::uint32_t p = primes_.prime(i);
        mpz_init(&cofactors_[i]);
        mpz_divexact_ui(&cofactors_[i], modulus_, p);
        const ulong inverse = n_invmod(mpz_fdiv_ui(&cofactors_[i], p), p);
        digit_factors_[i] = primes_.to_montgomery(i, static_cast<std::uint32_t>(inverse));
        cofactors_mod_q_[i] = static_cast<std::uint32_t>(mpz_fdiv_ui(&cofactors_[i], q));
    }
    digit_factors_[digits] = primes_.to_montgomery(digits, 1);
    modulus_inverse_mod_q_ = static_cast<std::uint32_t>(n_invmod(mpz_fdiv_ui(modulus_, q), q));
    ensure_powers(8);
}

ResidueSystem::~ResidueSystem() {
    for (__mpz_struct& z : cofactors_) {
        mpz_clear(&z);
    }
    mpz_clear(modulus_);
}

void ResidueSystem::ensure_powers(std::size_t halves) {
    const std::size_t lanes = primes_.size();
    std::size_t rows = powers_.size() / lanes;
    if (rows >= halves + 1) {
        return;
    }
    powers_.resize((halves + 1) * lanes);
    for (; rows < halves + 1; ++rows) {
        for (std::size_t l = 0; l < lanes; ++l) {
            const std::uint64_t previous = rows == 0 ? 1 : powers_[(rows - 1) * lanes + l];
            powers_[rows * lanes + l] =
                static_cast<std::uint32_t>((previous << 32) % primes_.prime(l));
        }
    }
}

void ResidueSystem::residues(mpz_srcptr c, std::uint32_t* out, bool montgomery) {
    const std::size_t limbs = mpz_size(c);
    std::size_t count = 2 * limbs;
    halves_.resize(count);
    if (limbs > 0) {
        std::memcpy(halves_.data(), mpz_limbs_read(c), limbs * sizeof(mp_limb_t));
    }
    static_assert(sizeof(mp_limb_t) == 2 * sizeof(std::uint32_t));
    while (count > 0 && halves_[count - 1] == 0) {
        --count;
    }
    ensure_powers(count);
    lanes::combine_digits(out, halves_.data(), count,
                          powers_.data() + (montgomery ? primes_.size() : 0), primes_);
    if (mpz_sgn(c) < 0) {
        lanes::negate(out, primes_);
    }
}

void ResidueSystem::residues(const fmpz_t c, std::uint32_t* out, bool montgomery) {
    if (!COEFF_IS_MPZ(*c)) {
        const slong v = *c;
        const auto magnitude = static_cast<std::uint64_t>(v < 0 ? -v : v);
        const std::uint32_t halves[2] = {static_cast<std::uint32_t>(magnitude),
                                         static_cast<std::uint32_t>(magnitude >> 32)};
        const std::size_t count = halves[1] != 0 ? 2 : (halves[0] != 0 ? 1 : 0);
        lanes::combine_digits(out, halves, count,
                              powers_.data() + (montgomery ? primes_.size() : 0), primes_);
        if (v < 0) {
            lanes::negate(out, primes_);
        }
        return;
    }
    mpz_t z;
    mpz_init(z);
    fmpz_get_mpz(z, c);
    residues(z, out, montgomery);
    mpz_clear(z);
}

std::uint32_t ResidueSystem::alpha(const std::uint32_t* digits) const {
    const std::size_t count = primes_.size() - 1;
    const std::uint32_t q = primes_.prime(count);
    Wide sum = 0;
    for (std::size_t i = 0; i < count; ++i) {
        sum += static_cast<std::uint64_t>(digits[i]) * cofactors_mod_q_[i];
    }
    const auto s = static_cast<std::uint64_t>(sum % q);
    const std::uint64_t difference = (s + q - digits[count]) % q;
    const auto a = static_cast<std::uint32_t>(difference * modulus_inverse_mod_q_ % q);
    if (a >= primes_.size()) {
        // The value was outside (−M/2, M/2): a bound was wrong, and the residues mean nothing.
        // A bug, reported as an error (never a certificate, never a crash).
        throw Error("internal error: a residue value outside the range its bound promised");
    }
    return a;
}

ResidueSystem::Divisor ResidueSystem::divisor(mpz_srcptr l) const {
    Divisor d;
    const std::size_t n = mpz_size(l);
    d.limbs.assign(mpz_limbs_read(l), mpz_limbs_read(l) + n);
    mpz_t r;
    mpz_init(r);
    const auto append = [&](mpz_srcptr v, std::vector<mp_limb_t>& to) {
        const std::size_t size = mpz_size(v);
        to.insert(to.end(), mpz_limbs_read(v), mpz_limbs_read(v) + size);
        to.insert(to.end(), n - size, 0);
    };
    for (const __mpz_struct& cofactor : cofactors_) {
        mpz_fdiv_r(r, &cofactor, l);
        append(r, d.cofactors);
    }
    mpz_fdiv_r(r, modulus_, l);
    mpz_sub(r, l, r);
    append(r, d.minus_modulus);
    mpz_clear(r);
    return d;
}

void ResidueSystem::remainder(const std::uint32_t* digits, const Divisor& d, mp_limb_t* out) {
    const std::size_t n = d.limbs.size(), count = primes_.size() - 1;
    const std::uint64_t a = alpha(digits);
    // Σ y_i·((M/p_i) mod L) + α·(L − M mod L) ≡ Σ y_i·(M/p_i) − α·M = v (mod L), accumulated
    // a limb at a time: each column sum stays below 2^(64 + 31 + 8) for the at most 256 lanes
    // (kMostLanes), well inside the 128-bit accumulator.
    sum_.resize(n + 1);
    Wide carry = 0;
    for (std::size_t j = 0; j < n; ++j) {
        Wide column = carry + static_cast<Wide>(a) * d.minus_modulus[j];
        const mp_limb_t* cofactor = d.cofactors.data() + j;
        for (std::size_t i = 0; i < count; ++i) {
            column += static_cast<Wide>(digits[i]) * cofactor[i * n];
        }
        sum_[j] = static_cast<mp_limb_t>(column);
        carry = column >> 64;
    }
    sum_[n] = static_cast<mp_limb_t>(carry);
    if (n == 1) {
        out[0] = mpn_mod_1(sum_.data(), 2, d.limbs[0]);
        return;
    }
    mp_limb_t quotient[2];
    mpn_tdiv_qr(quotient, out, 0, sum_.data(), static_cast<mp_size_t>(n + 1), d.limbs.data(),
                static_cast<mp_size_t>(n));
}

void ResidueSystem::reconstruct(const std::uint32_t* digits, mpz_t out) const {
    const std::size_t count = primes_.size() - 1;
    mpz_set_ui(out, 0);
    for (std::size_t i = 0; i < count; ++i) {
        mpz_addmul_ui(out, &cofactors_[i], digits[i]);
    }
    mpz_submul_ui(out, modulus_, alpha(digits));
}

}  // namespace locus::algebra::detail
