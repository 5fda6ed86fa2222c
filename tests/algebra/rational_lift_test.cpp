// The one lifting machinery (algebra/modular/rational_lift.h) against numbers chosen here:
// residues are computed with FLINT's integer division and inverse (no lifting code), and the
// lift must give back the rational — small, huge (hundreds of digits), negative, zero — once
// enough primes are in, never a wrong value reported as confirmed, and it must notice a number
// whose residues change (an unlucky prime).
#include <gtest/gtest.h>

#include <flint/fmpq.h>
#include <flint/fmpz.h>
#include <flint/ulong_extras.h>

#include <algorithm>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "algebra/modular/rational_lift.h"

namespace locus::algebra::modular {
namespace {

mp_limb_t residue_of(const Rational& q, mp_limb_t p) {
    const ulong n = fmpz_fdiv_ui(fmpq_numref(q.get()), p);
    const ulong d = fmpz_fdiv_ui(fmpq_denref(q.get()), p);
    return n_mulmod2_preinv(n, n_invmod(d, p), p, n_preinvert_limb(p));
}

// The largest prime below p (odd p > 3).
mp_limb_t prime_below(mp_limb_t p) {
    do {
        p -= 2;
    } while (!n_is_prime(p));
    return p;
}

Rational random_rational(std::mt19937_64& random, int digits) {
    std::string numerator = random() % 2 == 0 ? "-" : "";
    numerator += std::to_string(1 + random() % 9);
    for (int i = 1; i < digits; ++i) {
        numerator += std::to_string(random() % 10);
    }
    std::string denominator = std::to_string(1 + random() % 9);
    for (int i = 1; i < digits / 2; ++i) {
        denominator += std::to_string(random() % 10);
    }
    Rational q;
    fmpq_set_str(q.get(), (numerator + "/" + denominator).c_str(), 10);
    fmpq_canonicalise(q.get());
    return q;
}

// A positive integer of `digits` random decimal digits.
Integer random_integer(std::mt19937_64& random, int digits) {
    std::string text = std::to_string(1 + random() % 9);
    for (int i = 1; i < digits; ++i) {
        text += std::to_string(random() % 10);
    }
    Integer value;
    fmpz_set_str(value.get(), text.c_str(), 10);
    return value;
}

// Moves p to the next prime below it, gives every number its residue there (`residue(i, p)`)
// and adds p to the lift.
template <typename Residue>
void add_next_prime(RationalLift& lift, mp_limb_t& p, std::vector<LiftedNumber>& numbers,
                    Residue residue) {
    p = prime_below(p);
    for (std::size_t i = 0; i < numbers.size(); ++i) {
        numbers[i].residues.push_back(residue(i, p));
    }
    lift.add_prime(p);
}

std::vector<LiftedNumber*> pointers_to(std::vector<LiftedNumber>& numbers) {
    std::vector<LiftedNumber*> out;
    for (LiftedNumber& n : numbers) {
        out.push_back(&n);
    }
    return out;
}

TEST(RationalLift, GivesBackRationalsOfEverySize) {
    std::mt19937_64 random(3);
    for (const bool wide_primes : {false, true}) {
        for (const int digits : {1, 5, 40, 300}) {
            std::vector<Rational> truth;
            for (int i = 0; i < 20; ++i) {
                truth.push_back(i == 0 ? Rational() : random_rational(random, digits));
            }
            std::vector<LiftedNumber> numbers(truth.size());
            RationalLift lift;
            // Distinct primes: above 2^62 upwards (the interpolation's) or below 2^31
            // downwards (the Gröbner route's).
            mp_limb_t p = wide_primes ? n_nextprime(UWORD(1) << 62, 1) : (1u << 31) + 1;
            bool done = false;
            for (int k = 0; k < 400 && !done; ++k) {
                p = wide_primes ? n_nextprime(p, 1) : prime_below(p);
                for (std::size_t i = 0; i < truth.size(); ++i) {
                    numbers[i].residues.push_back(residue_of(truth[i], p));
                }
                lift.add_prime(p);
                if (!lift.attempt_due()) {
                    continue;
                }
                RationalLift::Attempt attempt(lift);
                done = true;
                for (LiftedNumber& number : numbers) {
                    done = attempt.reconstruct(number) && number.confirmed() && done;
                }
            }
            ASSERT_TRUE(done) << digits << " digits";
            for (std::size_t i = 0; i < truth.size(); ++i) {
                EXPECT_TRUE(fmpq_equal(numbers[i].value.get(), truth[i].get()))
                    << digits << " digits, number " << i;
            }
            // Enough primes and not many more: about 2·(digits + digits/2)·log2(10) bits.
            const double bits_needed = 2.0 * 1.5 * digits * 3.33;
            const double bits_per_prime = wide_primes ? 62.0 : 31.0;
            EXPECT_LE(static_cast<double>(lift.primes()), bits_needed / bits_per_prime * 1.1 + 4);
        }
    }
}

TEST(RationalLift, AValueStopsBeingConfirmedWhenAPrimeDisagrees) {
    // A number whose first two primes' residues are those of 1/3 and the later ones those of
    // 5/7 (an unlucky pair of primes, then the true residues): 1/3 is confirmed by the second
    // prime, and never again once a prime disagrees — the mixed residues have no confirmed
    // value at all (the callers keep unlucky primes out: groups by leading monomials, kernels
    // of the wrong dimension).
    const Rational third(1, 3), other(5, 7);
    LiftedNumber number;
    RationalLift lift;
    mp_limb_t p = (1u << 31) + 1;
    for (int k = 0; k < 8; ++k) {
        p = prime_below(p);
        number.residues.push_back(residue_of(k < 2 ? third : other, p));
        lift.add_prime(p);
        RationalLift::Attempt attempt(lift);
        const bool confirmed = attempt.reconstruct(number) && number.confirmed();
        if (k == 1) {
            EXPECT_TRUE(confirmed);
            EXPECT_TRUE(fmpq_equal(number.value.get(), third.get()));
        }
        if (k >= 2) {
            EXPECT_FALSE(confirmed) << "after " << k + 1 << " primes";
        }
    }
}

// Numbers sharing a large denominator (as the coefficients of one element of a reduced basis
// over Q do): four of them give it back by simultaneous reconstruction with about
// log N + log max(N, D)/4 bits, where rational reconstruction of any one needs log N + log D;
// then every number of the group comes back as an integer over it, including one whose
// denominator has a small factor more. Random residues give no denominator (no accident).
TEST(RationalLift, SharedDenominatorsNeedAboutHalfThePrimes) {
    std::mt19937_64 random(11);
    const auto big = [&](int digits) { return random_integer(random, digits); };
    const Integer denominator = big(150);  // about 500 bits; numerators too
    std::vector<Rational> truth;
    for (int i = 0; i < 12; ++i) {
        Rational q;
        fmpz_set(fmpq_numref(q.get()), big(150).get());
        if (i % 2 == 1) {
            fmpz_neg(fmpq_numref(q.get()), fmpq_numref(q.get()));
        }
        fmpz_set(fmpq_denref(q.get()), denominator.get());
        if (i == 5) {  // a small factor more than the others
            fmpz_mul_ui(fmpq_denref(q.get()), fmpq_denref(q.get()), 1000003);
        }
        fmpq_canonicalise(q.get());
        truth.push_back(q);
    }
    std::vector<LiftedNumber> numbers(truth.size());
    RationalLift lift;
    mp_limb_t p = (1u << 31) + 1;
    std::optional<Integer> found;
    std::size_t primes_at_found = 0;
    const auto residue_of_truth = [&](std::size_t i, mp_limb_t q) {
        return residue_of(truth[i], q);
    };
    for (int k = 0; k < 60 && !found; ++k) {
        add_next_prime(lift, p, numbers, residue_of_truth);
        RationalLift::Attempt attempt(lift);
        std::vector<LiftedNumber*> four{&numbers[0], &numbers[1], &numbers[2], &numbers[3]};
        found = attempt.common_denominator(four);
        primes_at_found = lift.primes();
    }
    ASSERT_TRUE(found.has_value());
    EXPECT_TRUE(fmpz_divisible(found->get(), denominator.get()) &&
                fmpz_divisible(denominator.get(), found->get()));
    // Rational reconstruction of one number needs about 1000 bits (33 primes); four together
    // about 500 · 5/4 + 32 bits.
    EXPECT_LE(primes_at_found, 24u);
    EXPECT_GE(primes_at_found, 20u);
    {
        // An attempt made without lattices (a caller's budget spent) reduces none, with the
        // same primes, and says it spent no time on them; with them it timed its reduction.
        std::vector<LiftedNumber*> four{&numbers[0], &numbers[1], &numbers[2], &numbers[3]};
        RationalLift::Attempt without(lift, false);
        EXPECT_FALSE(without.common_denominator(four).has_value());
        Integer group_denominator(1), hint(1);
        LiftedNumber copy;
        copy.residues = numbers[0].residues;
        EXPECT_FALSE(without.reconstruct_sharing(copy, group_denominator, hint, [&] {
            return std::vector<LiftedNumber*>{&numbers[1], &numbers[2], &numbers[3]};
        }));
        EXPECT_EQ(without.lattice_seconds(), 0.0);
        RationalLift::Attempt with(lift, true);
        EXPECT_TRUE(with.reconstruct_sharing(copy, group_denominator, hint, [&] {
            return std::vector<LiftedNumber*>{&numbers[1], &numbers[2], &numbers[3]};
        }));
        EXPECT_TRUE(fmpq_equal(copy.value.get(), truth[0].get()));
        EXPECT_GT(with.lattice_seconds(), 0.0);
    }
    RationalLift::Attempt attempt(lift);
    for (std::size_t i = 0; i < truth.size(); ++i) {
        ASSERT_TRUE(attempt.reconstruct(numbers[i], &*found)) << i;
        EXPECT_TRUE(fmpq_equal(numbers[i].value.get(), truth[i].get())) << i;
        LiftedNumber alone;
        alone.residues = numbers[i].residues;
        // Too few primes for the number alone: rational reconstruction cannot give it back
        // (it may give another rational, as it does for most residues).
        EXPECT_FALSE(attempt.reconstruct(alone) && fmpq_equal(alone.value.get(), truth[i].get()))
            << i;
    }
    // Residues of nothing in particular: no common denominator at any number of primes.
    std::vector<LiftedNumber> noise(4);
    RationalLift noise_lift;
    p = (1u << 31) + 1;
    for (int k = 0; k < 40; ++k) {
        add_next_prime(noise_lift, p, noise,
                       [&](std::size_t, mp_limb_t q) { return random() % q; });
        RationalLift::Attempt noise_attempt(noise_lift);
        EXPECT_FALSE(noise_attempt.common_denominator(pointers_to(noise)).has_value())
            << k + 1 << " primes";
    }
}

// Lattices whose entries pass the range of doubles (2^1024): numbers sharing a 1 300-bit
// denominator, with numerators as large, need a modulus of about 1 600 bits for eight of them
// together. The lattice reduction in doubles with exact dot products (fmpz_lll_d_heuristic)
// either copes with such entries or says it failed, and the full reduction then takes over:
// either way the denominator is found, with no more primes than eight numbers need.
TEST(RationalLift, SharedDenominatorPastTheRangeOfDoubles) {
    std::mt19937_64 random(23);
    const Integer denominator = random_integer(random, 390);  // about 1 300 bits
    std::vector<Rational> truth;
    for (int i = 0; i < 8; ++i) {
        truth.emplace_back();
        fmpq_set_fmpz_frac(truth.back().get(), random_integer(random, 390).get(),
                           denominator.get());
    }
    std::vector<LiftedNumber> numbers(truth.size());
    RationalLift lift;
    mp_limb_t p = (1u << 31) + 1;
    std::optional<Integer> found;
    while (!found && lift.primes() < 100) {
        add_next_prime(lift, p, numbers,
                       [&](std::size_t i, mp_limb_t q) { return residue_of(truth[i], q); });
        RationalLift::Attempt attempt(lift);
        found = attempt.common_denominator(pointers_to(numbers));
    }
    ASSERT_TRUE(found.has_value());
    EXPECT_TRUE(fmpz_divisible(found->get(), denominator.get()) &&
                fmpz_divisible(denominator.get(), found->get()));
    // log N + log max(N, D)/8 + 32 ≈ 1 300 + 163 + 32 bits: 49 primes; one alone needs 84.
    EXPECT_LE(lift.primes(), 52u);
    EXPECT_GT(fmpz_bits(lift.modulus().get()), 1024u);
    RationalLift::Attempt attempt(lift);
    for (std::size_t i = 0; i < truth.size(); ++i) {
        ASSERT_TRUE(attempt.reconstruct(numbers[i], &*found)) << i;
        EXPECT_TRUE(fmpq_equal(numbers[i].value.get(), truth[i].get())) << i;
    }
}

// The lattice's second test (its first vector well below the second): three numbers already
// determined by the primes (small numerators over a small denominator) and one that is not (a
// random residue) make a lattice whose two shortest vectors are alike and short enough for the
// first test — and a multiplier chosen from the random residue itself, over which any value
// would pass a size margin. No denominator may come out of it, at any number of primes.
TEST(RationalLift, NoDenominatorFromDeterminedCompanionsAndOneUndeterminedNumber) {
    std::mt19937_64 random(5);
    const Rational a(12345, 977), b(-4321, 977), c(999, 977);
    std::vector<LiftedNumber> numbers(4);
    RationalLift lift;
    mp_limb_t p = (1u << 31) + 1;
    const Rational* determined[] = {nullptr, &a, &b, &c};
    for (int k = 0; k < 30; ++k) {
        add_next_prime(lift, p, numbers, [&](std::size_t i, mp_limb_t q) {
            return i == 0 ? random() % q : residue_of(*determined[i], q);
        });
        RationalLift::Attempt attempt(lift);
        EXPECT_FALSE(attempt.common_denominator(pointers_to(numbers)).has_value())
            << k + 1 << " primes";
    }
}

// Sharing through reconstruct_sharing: a group whose numbers share a 300-bit denominator finds
// it by a lattice of a number and its companions (companions_near, which leaves out the zero),
// and takes the others as integers over it — every value exact and confirmed by a later prime
// with fewer primes than rational reconstruction of one of them needs.
TEST(RationalLift, ReconstructSharingFindsTheGroupsDenominator) {
    std::mt19937_64 random(17);
    const auto big = [&](int digits) { return random_integer(random, digits); };
    const Integer denominator = big(90);  // about 300 bits, numerators too
    std::vector<Rational> truth;
    for (int i = 0; i < 10; ++i) {
        Rational q;
        if (i == 3) {  // a zero, which no lattice takes as a companion
            truth.push_back(q);
            continue;
        }
        fmpz_set(fmpq_numref(q.get()), big(90).get());
        fmpz_set(fmpq_denref(q.get()), denominator.get());
        fmpq_canonicalise(q.get());
        truth.push_back(q);
    }
    std::vector<LiftedNumber> numbers(truth.size());
    RationalLift lift;
    Integer group_denominator(1), hint(1);
    mp_limb_t p = (1u << 31) + 1;
    bool all = false;
    for (int k = 0; k < 40 && !all; ++k) {
        add_next_prime(lift, p, numbers,
                       [&](std::size_t i, mp_limb_t q) { return residue_of(truth[i], q); });
        RationalLift::Attempt attempt(lift);
        all = true;
        for (std::size_t t = 0; t < numbers.size(); ++t) {
            const bool found =
                attempt.reconstruct_sharing(numbers[t], group_denominator, hint, [&] {
                    const std::vector<LiftedNumber*> near =
                        companions_near(t, numbers.size(), 7, numbers.size(),
                                        [&](std::size_t u) -> LiftedNumber& { return numbers[u]; });
                    for (const LiftedNumber* n : near) {
                        EXPECT_NE(n, &numbers[3]);  // the zero is no companion
                        EXPECT_NE(n, &numbers[t]);
                    }
                    return near;
                });
            all = found && numbers[t].confirmed() && all;
        }
    }
    ASSERT_TRUE(all);
    for (std::size_t i = 0; i < truth.size(); ++i) {
        EXPECT_TRUE(fmpq_equal(numbers[i].value.get(), truth[i].get())) << i;
    }
    EXPECT_TRUE(fmpz_divisible(group_denominator.get(), denominator.get()));
    EXPECT_TRUE(hint == group_denominator);
    // Rational reconstruction of one number needs about 600 bits (20 primes).
    EXPECT_LE(lift.primes(), 16u);
}

TEST(RationalLift, AttemptsAfterEveryPrimeThenSpacedOut) {
    RationalLift lift;
    std::vector<std::size_t> attempts;
    mp_limb_t p = (1u << 31) + 1;
    for (int k = 0; k < 200; ++k) {
        p = prime_below(p);
        lift.add_prime(p);
        if (lift.attempt_due()) {
            attempts.push_back(lift.primes());
        }
    }
    // 1 … 64, then every 1/32 more: 66, 68, … (at 64 + 64/32 = 66).
    ASSERT_GE(attempts.size(), 64u);
    for (std::size_t i = 0; i < 64; ++i) {
        EXPECT_EQ(attempts[i], i + 1);
    }
    EXPECT_EQ(attempts[64], 66u);
    EXPECT_LT(attempts.size(), 120u);
}

TEST(PrimeSequence, DistinctPrimesOfEitherWidthForcedOnesFirst) {
    for (const auto width : {PrimeSequence::Width::small, PrimeSequence::Width::wide}) {
        PrimeSequence primes(width, {65521, 65521, 2147483647});
        std::vector<std::uint64_t> seen = {primes.next(), primes.next()};
        EXPECT_EQ(seen[0], 65521u);
        EXPECT_EQ(seen[1], 2147483647u);  // the repeated forced prime is skipped
        for (int k = 0; k < 300; ++k) {
            const std::uint64_t p = primes.next();
            EXPECT_TRUE(n_is_prime(p)) << p;
            if (width == PrimeSequence::Width::small) {
                EXPECT_LT(p, UWORD(1) << 31);
                EXPECT_GT(p, (UWORD(1) << 31) - (UWORD(1) << 29));
            } else {
                EXPECT_GT(p, UWORD(1) << 62);
                EXPECT_LT(p, (UWORD(1) << 62) + (UWORD(1) << 59));
            }
            EXPECT_EQ(std::find(seen.begin(), seen.end(), p), seen.end()) << p;
            seen.push_back(p);
        }
        // From a random point: two sequences start apart (equal with probability about 1e-7).
        EXPECT_NE(PrimeSequence(width).next(), PrimeSequence(width).next());
    }
}

}  // namespace
}  // namespace locus::algebra::modular
