// The certification's arithmetic: the residue lanes against scalar modular arithmetic
// done another way (64-bit products and remainders, a modular inverse of 2^32 in place of
// Montgomery's reduction);
// the size bounds against exact powers; the residue system's reconstructions and remainders
// against GMP; and the residue reducer against the GMP reducer, which must make the same
// steps on the same integers and reach the same verdicts, on bases from the bench suite, on
// corrupted ones, and on lanes so narrow that reductions start again and rebuild their values.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <flint/ulong_extras.h>

#include "algebra/groebner/detail/exact_zero_reducer.h"
#include "algebra/groebner/detail/log_bound.h"
#include "algebra/groebner/detail/pair_criteria.h"
#include "algebra/groebner/detail/residue_lanes.h"
#include "algebra/groebner/detail/residue_system.h"
#include "algebra/groebner/detail/residue_zero_reducer.h"
#include "algebra/groebner/verify.h"
#include "algebra/modular/modular_groebner.h"
#include "algebra/parse.h"
#include "tests/support/ideal_cases.h"
#include "tests/support/test_data.h"

namespace locus::algebra::detail {
namespace {

namespace lb = log_bound;

LanePrimes primes_for(std::size_t lanes) {
    return LanePrimes(lanes, [](std::uint32_t) { return true; });
}

// x·y·2^−32 mod p, computed as x·y·(2^32)⁻¹ with a modular inverse.
std::uint32_t reference_montgomery(std::uint32_t x, std::uint32_t y, std::uint32_t p) {
    const std::uint64_t r_inverse = n_invmod((std::uint64_t{1} << 32) % p, p);
    const std::uint64_t xy = (static_cast<std::uint64_t>(x) % p) * (y % p) % p;
    return static_cast<std::uint32_t>(xy * r_inverse % p);
}

// Restores the best kernels when a test that selected others ends.
struct KernelGuard {
    ~KernelGuard() { lanes::select_kernels(lanes::supported_kernels().back()); }
};

TEST(ResidueLanes, EveryKernelAgreesWithScalarArithmetic) {
    KernelGuard guard;
    std::mt19937_64 rng(7);
    for (const std::string& kernel : lanes::supported_kernels()) {
        lanes::select_kernels(kernel);
        EXPECT_EQ(kernel, lanes::kernel_name());
        // 72, 104 and 128 lanes: past the widths the AVX-512 kernels are specialised for, done
        // in chunks of 64 and a tail of 8, 40 or 64.
        for (const std::size_t width : {8u, 16u, 24u, 40u, 72u, 104u, 128u}) {
            const LanePrimes primes = primes_for(width);
            std::vector<std::uint32_t> x(width), y(width), out(width);
            const auto random_residues = [&](std::vector<std::uint32_t>& v, bool below_p) {
                for (std::size_t l = 0; l < v.size(); ++l) {
                    v[l] = static_cast<std::uint32_t>(
                        rng() % (below_p ? primes.prime(l % width) : (1ull << 32)));
                }
            };
            random_residues(x, true);
            random_residues(y, true);
            lanes::multiply(out.data(), x.data(), y.data(), primes);
            for (std::size_t l = 0; l < width; ++l) {
                ASSERT_EQ(out[l], reference_montgomery(x[l], y[l], primes.prime(l)))
                    << kernel << " lanes " << width << " lane " << l;
            }
            // A table of 50 columns; a row of 20 terms lands on 20 distinct ones.
            std::vector<std::uint32_t> table(50 * width), rows(20 * width), b(width);
            random_residues(table, true);
            random_residues(rows, true);
            random_residues(b, true);
            // The extremes of the multiplier, where the floating-point estimate is nearest 2^32
            // or exact.
            b[0] = primes.prime(0) - 1;
            b[1] = 0;
            b[2] = 1;
            std::vector<std::uint32_t> columns(50);
            for (std::uint32_t c = 0; c < 50; ++c) {
                columns[c] = c;
            }
            std::shuffle(columns.begin(), columns.end(), rng);
            columns.resize(20);
            std::vector<std::uint32_t> expected = table;
            for (std::size_t t = 0; t < 20; ++t) {
                for (std::size_t l = 0; l < width; ++l) {
                    const std::uint64_t p = primes.prime(l);
                    std::uint32_t& v = expected[columns[t] * width + l];
                    v = static_cast<std::uint32_t>(
                        (v + static_cast<std::uint64_t>(b[l]) * rows[t * width + l] % p) % p);
                }
            }
            std::vector<std::uint32_t> quotients(width);
            lanes::shoup_quotients(quotients.data(), b.data(), primes);
            for (std::size_t l = 0; l < width; ++l) {
                ASSERT_EQ(quotients[l], (static_cast<std::uint64_t>(b[l]) << 32) / primes.prime(l));
            }
            lanes::add_scaled_rows(table.data(), columns.data(), 20, rows.data(), b.data(),
                                   quotients.data(), primes);
            ASSERT_EQ(table, expected) << kernel << " lanes " << width;
            // No terms and no rows at all (a reducer without a tail): the table is unchanged
            // (the sanitizers of the debug and fuzz builds also see no null pointer offset).
            lanes::add_scaled_rows(table.data(), columns.data(), 0, nullptr, b.data(),
                                   quotients.data(), primes);
            ASSERT_EQ(table, expected) << kernel << " lanes " << width;
            // The kernel of reductions done together: slots 0, 2, 3, 5 and 7 of a shared table,
            // each with its multiplier; every touched slot's residues, its bound raised by the
            // term (log_bound's sum) and its highest, and the columns not pending before listed
            // per slot in term order and marked. Slots not taking the step are left alone.
            const unsigned slots = 0b10101101;
            std::vector<std::uint32_t> shared(50 * lanes::kSlots * width);
            std::vector<std::uint32_t> multipliers(lanes::kSlots * width),
                slot_quotients(lanes::kSlots * width);
            for (std::size_t k = 0; k < shared.size(); ++k) {
                shared[k] = static_cast<std::uint32_t>(rng() % primes.prime(k % width));
            }
            for (std::size_t sl = 0; sl < lanes::kSlots; ++sl) {
                for (std::size_t l = 0; l < width; ++l) {
                    multipliers[sl * width + l] =
                        static_cast<std::uint32_t>(rng() % primes.prime(l));
                }
                lanes::shoup_quotients(slot_quotients.data() + sl * width,
                                       multipliers.data() + sl * width, primes);
            }
            std::vector<std::int64_t> bound(50 * lanes::kSlots), term(20);
            std::vector<std::uint8_t> pending(50 * lanes::kSlots);
            for (std::size_t k = 0; k < bound.size(); ++k) {
                bound[k] = k % 7 == 0 ? lb::kZero : static_cast<std::int64_t>(rng() % 40000);
                pending[k] = static_cast<std::uint8_t>(rng() % 2);
            }
            for (std::int64_t& u : term) {
                u = static_cast<std::int64_t>(rng() % 30000);
            }
            std::array<std::int64_t, lanes::kSlots> offsets{}, highest{};
            for (std::size_t sl = 0; sl < lanes::kSlots; ++sl) {
                offsets[sl] = static_cast<std::int64_t>(rng() % 3000);
                highest[sl] = static_cast<std::int64_t>(rng() % 40000);
            }
            std::vector<std::uint32_t> expected_shared = shared;
            std::vector<std::int64_t> expected_bound = bound;
            std::vector<std::uint8_t> expected_pending = pending;
            std::array<std::int64_t, lanes::kSlots> expected_highest = highest;
            std::vector<std::vector<std::uint32_t>> expected_fresh(lanes::kSlots);
            for (std::size_t t = 0; t < 20; ++t) {
                const std::uint32_t c = columns[t];
                for (std::size_t sl = 0; sl < lanes::kSlots; ++sl) {
                    if ((slots >> sl & 1u) == 0) {
                        continue;
                    }
                    const std::size_t at = c * lanes::kSlots + sl;
                    expected_bound[at] = lb::of_sum(expected_bound[at], offsets[sl] + term[t]);
                    expected_highest[sl] = std::max(expected_highest[sl], expected_bound[at]);
                    if (expected_pending[at] == 0) {
                        expected_pending[at] = 1;
                        expected_fresh[sl].push_back(c);
                    }
                    for (std::size_t l = 0; l < width; ++l) {
                        const std::uint64_t p = primes.prime(l);
                        std::uint32_t& v = expected_shared[at * width + l];
                        v = static_cast<std::uint32_t>(
                            (v + static_cast<std::uint64_t>(multipliers[sl * width + l]) *
                                     rows[t * width + l] % p) %
                            p);
                    }
                }
            }
            std::vector<std::uint32_t> fresh(20 * lanes::kSlots);
            std::array<std::size_t, lanes::kSlots> fresh_counts{};
            lanes::SlotBounds bounds{bound.data(),   term.data(),  offsets.data(),
                                     pending.data(), fresh.data(), fresh_counts.data(),
                                     highest.data()};
            lanes::add_scaled_rows_together(shared.data(), columns.data(), 20, rows.data(), slots,
                                            multipliers.data(), slot_quotients.data(), primes,
                                            bounds);
            ASSERT_EQ(shared, expected_shared) << kernel << " lanes " << width;
            ASSERT_EQ(bound, expected_bound) << kernel << " lanes " << width;
            ASSERT_EQ(pending, expected_pending) << kernel << " lanes " << width;
            ASSERT_EQ(highest, expected_highest) << kernel << " lanes " << width;
            for (std::size_t sl = 0; sl < lanes::kSlots; ++sl) {
                const std::vector<std::uint32_t> listed(fresh.begin() + sl * 20,
                                                        fresh.begin() + sl * 20 + fresh_counts[sl]);
                ASSERT_EQ(listed, expected_fresh[sl])
                    << kernel << " lanes " << width << " slot " << sl;
            }
            // Digits of any 32 bits, powers below p.
            std::vector<std::uint32_t> halves(6), powers(6 * width);
            random_residues(halves, false);
            random_residues(powers, true);
            lanes::combine_digits(out.data(), halves.data(), 6, powers.data(), primes);
            for (std::size_t l = 0; l < width; ++l) {
                const std::uint32_t p = primes.prime(l);
                std::uint64_t sum = 0;
                for (std::size_t i = 0; i < 6; ++i) {
                    sum = (sum + reference_montgomery(halves[i], powers[i * width + l], p)) % p;
                }
                ASSERT_EQ(out[l], sum) << kernel << " lanes " << width << " lane " << l;
            }
        }
    }
}

TEST(ResidueLanes, PrimesAreTheLargestUsableOnes) {
    const LanePrimes all = primes_for(8);
    EXPECT_EQ(all.prime(0), 2147483647u);  // 2^31 − 1
    // Skipping the first: the next eight are the others shifted by one.
    const LanePrimes skipping(8, [](std::uint32_t p) { return p != 2147483647u; });
    for (std::size_t l = 0; l + 1 < 8; ++l) {
        EXPECT_EQ(skipping.prime(l), all.prime(l + 1));
    }
    EXPECT_THROW(LanePrimes(12, [](std::uint32_t) { return true; }), std::invalid_argument);
}

// A random integer of up to `bits` bits, of either sign.
void random_integer(mpz_t out, std::size_t bits, std::mt19937_64& rng) {
    mpz_set_ui(out, 0);
    const std::size_t length = 1 + rng() % bits;
    for (std::size_t done = 0; done < length; done += 32) {
        mpz_mul_2exp(out, out, 32);
        mpz_add_ui(out, out, rng() & 0xFFFFFFFFu);
    }
    mpz_fdiv_q_2exp(out, out, (length + 31) / 32 * 32 - length);
    if (rng() % 2 == 0) {
        mpz_neg(out, out);
    }
}

TEST(LogBound, UpperAndLowerBoundTheSizeExactly) {
    std::mt19937_64 rng(11);
    mpz_t v, power, two_power;
    mpz_inits(v, power, two_power, nullptr);
    for (int k = 0; k < test::seed_count(300); ++k) {
        random_integer(v, 1 + rng() % 1500, rng);
        if (mpz_sgn(v) == 0) {
            continue;
        }
        // |v| ≤ 2^(u/64) ⟺ |v|^64 ≤ 2^u.
        mpz_abs(power, v);
        mpz_pow_ui(power, power, lb::kPerBit);
        const lb::Units upper = lb::upper(v), lower = lb::lower(v);
        ASSERT_GE(upper, 0);
        mpz_set_ui(two_power, 1);
        mpz_mul_2exp(two_power, two_power, static_cast<mp_bitcnt_t>(upper));
        EXPECT_LE(mpz_cmp(power, two_power), 0) << "upper bound too small";
        mpz_set_ui(two_power, 1);
        mpz_mul_2exp(two_power, two_power, static_cast<mp_bitcnt_t>(std::max<lb::Units>(0, lower)));
        EXPECT_GE(mpz_cmp(power, two_power), 0) << "lower bound too large";
        EXPECT_LE(upper - lower, 2) << "bounds within a unit of the truth on each side";
    }
    mpz_set_ui(v, 0);
    EXPECT_TRUE(lb::is_zero(lb::upper(v)));
    mpz_clears(v, power, two_power, nullptr);
}

TEST(LogBound, SumBoundCoversBothSummands) {
    std::mt19937_64 rng(13);
    for (int k = 0; k < test::seed_count(20000); ++k) {
        const auto x = static_cast<lb::Units>(rng() % 200000);
        const auto y = static_cast<lb::Units>(x - static_cast<lb::Units>(rng() % 3000));
        const lb::Units s = lb::of_sum(x, y);
        // 2^(x/64) + 2^(y/64) ≤ 2^(s/64), divided through by 2^(s/64).
        const long double total = std::exp2(static_cast<long double>(x - s) / lb::kPerBit) +
                                  std::exp2(static_cast<long double>(y - s) / lb::kPerBit);
        ASSERT_LE(total, 1.0L + 1e-15L) << x << " " << y << " " << s;
        ASSERT_LE(s - std::max(x, y), lb::kPerBit + 1) << "a bit and a rounding unit at most";
    }
    EXPECT_EQ(lb::of_sum(lb::kZero, 640), 641);  // zero adds the smallest unit
}

// Every entry of the sum table (chords between nodes, which the AVX-512 kernel evaluates) is at
// or above the exact 64·log2(1 + 2^(−d/64)), computed here in long double, and at most 2 units
// above that value rounded up (log_bound.h documents 2.11 units above the exact one).
TEST(LogBound, EverySumTableEntryBoundsTheExactValue) {
    for (std::size_t d = 0; d < lb::kSumTableSize; ++d) {
        const long double exact =
            lb::kPerBit * std::log2(1.0L + std::exp2(-static_cast<long double>(d) / lb::kPerBit));
        ASSERT_GE(static_cast<long double>(lb::kSumTable[d]), exact) << d;
        ASSERT_LE(static_cast<long double>(lb::kSumTable[d]), exact + 2.12L) << d;
        ASSERT_LE(static_cast<long double>(lb::kSumTable[d]),
                  std::max(1.0L, std::ceil(exact)) + 2.0L)
            << d;
    }
}

TEST(ResidueSystem, ReconstructsValuesAndTheirRemainders) {
    std::mt19937_64 rng(17);
    mpz_t v, back, l, expected;
    mpz_inits(v, back, l, expected, nullptr);
    for (const std::size_t width : {8u, 24u, 40u}) {
        ResidueSystem system(primes_for(width));
        const auto capacity_bits = static_cast<std::size_t>(system.capacity() / lb::kPerBit);
        std::vector<std::uint32_t> residues(width), digits(width);
        for (int k = 0; k < test::seed_count(200); ++k) {
            random_integer(v, capacity_bits, rng);
            system.residues(v, residues.data(), false);
            lanes::multiply(digits.data(), residues.data(), system.digit_factors(),
                            system.primes());
            system.reconstruct(digits.data(), back);
            ASSERT_EQ(mpz_cmp(v, back), 0) << "lanes " << width;
            // Remainders modulo divisors of one to five limbs.
            random_integer(l, 1 + rng() % 300, rng);
            mpz_abs(l, l);
            if (mpz_cmp_ui(l, 2) < 0) {
                continue;
            }
            const ResidueSystem::Divisor d = system.divisor(l);
            std::vector<mp_limb_t> remainder(d.limbs.size());
            system.remainder(digits.data(), d, remainder.data());
            mpz_fdiv_r(expected, v, l);
            mpz_set_ui(back, 0);
            for (std::size_t i = remainder.size(); i-- > 0;) {
                mpz_mul_2exp(back, back, 64);
                mpz_add_ui(back, back, remainder[i]);
            }
            ASSERT_EQ(mpz_cmp(back, expected), 0) << "lanes " << width;
        }
        // The Montgomery form is the value times 2^32.
        mpz_set_si(v, -123456789);
        system.residues(v, residues.data(), true);
        for (std::size_t lane = 0; lane < width; ++lane) {
            const std::uint32_t p = system.primes().prime(lane);
            const std::uint64_t plain = static_cast<std::uint64_t>(p - 123456789 % p) % p;
            EXPECT_EQ(residues[lane], plain * ((std::uint64_t{1} << 32) % p) % p);
        }
    }
    mpz_clears(v, back, l, expected, nullptr);
}

// The basis and the Gebauer–Möller pairs, as certify_groebner_basis builds them.
struct Certification {
    RingPtr ring;
    std::vector<BasisElement> elements;
    std::vector<CriticalPair> pairs;
    std::vector<IntegerPolynomial> generators;
};

Certification certification_of(const std::vector<Polynomial>& basis,
                               const std::vector<Polynomial>& generators) {
    Certification c;
    c.ring = basis.front().ring();
    CriteriaCounts counts;
    for (const Polynomial& g : basis) {
        c.elements.push_back({to_integer_polynomial(g), false});
        gebauer_moller_update(c.elements, c.pairs, c.elements.size() - 1, c.ring->layout(), counts);
    }
    for (const Polynomial& f : generators) {
        c.generators.push_back(to_integer_polynomial(f));
    }
    return c;
}

// Every generator and pair through both reducers: the same verdicts after the same number of
// steps. The residue reducer takes the jobs `group` at a time (reduce_together), the GMP one
// alone. Returns how many were not zero.
std::size_t compare_reducers(const Certification& c, std::size_t lanes, const std::string& what,
                             ResidueZeroReducer::Statistics* statistics = nullptr,
                             std::size_t group = 1) {
    const MonomialLayout& layout = c.ring->layout();
    // Forced lanes are kept for every reduction: narrow ones then start again and rebuild often.
    ResidueZeroReducer residue(layout, c.elements, lanes, lanes == 0);
    ExactZeroReducer exact(layout, c.elements);
    std::vector<ResidueZeroReducer::Job> jobs;
    for (const IntegerPolynomial& g : c.generators) {
        jobs.push_back({&g, 0, 0, nullptr});
    }
    for (const CriticalPair& pair : c.pairs) {
        jobs.push_back({nullptr, pair.first, pair.second, pair.lcm.data()});
    }
    std::size_t nonzero = 0;
    for (std::size_t from = 0; from < jobs.size(); from += group) {
        const std::size_t n = std::min(group, jobs.size() - from);
        std::vector<ResidueZeroReducer::Verdict> verdicts(n);
        std::vector<ReductionCounts> counts(n);
        residue.reduce_together(std::span(jobs.data() + from, n), verdicts, counts);
        for (std::size_t k = 0; k < n; ++k) {
            const ResidueZeroReducer::Job& job = jobs[from + k];
            ReductionCounts e;
            const bool by_gmp =
                job.polynomial != nullptr
                    ? exact.reduces_to_zero(*job.polynomial, e)
                    : exact.s_polynomial_reduces_to_zero(job.first, job.second, job.lcm, e);
            EXPECT_NE(verdicts[k], ResidueZeroReducer::Verdict::too_wide) << what;
            const bool by_residues = verdicts[k] == ResidueZeroReducer::Verdict::zero;
            EXPECT_EQ(by_residues, by_gmp) << what << " job " << from + k;
            EXPECT_EQ(counts[k].steps, e.steps) << what << " job " << from + k;
            nonzero += by_residues ? 0 : 1;
        }
    }
    if (statistics != nullptr) {
        *statistics = residue.statistics();
    }
    return nonzero;
}

std::vector<Polynomial> with_coefficient_changed(std::vector<Polynomial> basis, std::size_t e) {
    Polynomial& g = basis[e];
    Polynomial changed(g.ring());
    for (std::size_t i = 0; i < g.num_terms(); ++i) {
        Rational c = g.coefficient(i);
        if (i + 1 == g.num_terms()) {
            c = c == Rational(-1, 7) ? Rational(1, 7) : c + Rational(1, 7);  // never zero
        }
        changed.push_back_term(c, g.monomial(i));
    }
    g = changed;
    return basis;
}

// Three dense quadrics with six-digit coefficients: the basis' own coefficients (hundreds of
// bits) do not fit 8 lanes, so reductions on 8 must start again on more.
Certification dense_quadrics() {
    std::mt19937_64 rng(19);
    std::string text = "vars: x,y,z\norder: grevlex\n";
    for (int f = 0; f < 3; ++f) {
        for (const char* m : {"x^2", "x*y", "x*z", "y^2", "y*z", "z^2", "x", "y", "z", "1"}) {
            // Appended piece by piece: GCC 12 warns (-Wrestrict) on the chained operator+.
            text.append("+").append(std::to_string(100000 + rng() % 900000)).append("*").append(m);
        }
        text += "\n";
    }
    const IdealFile dense = parse_ideal_file(text);
    return certification_of(modular_groebner(dense.generators).basis, dense.generators);
}

TEST(ZeroReducers, ResidueAndGmpReducersMakeTheSameSteps) {
    std::size_t rebuilds = 0;
    for (const char* name : {"cyclic5", "katsura6", "eco6", "noon4", "katsura7", "cyclic6"}) {
        const IdealFile ideal = parse_ideal_file(
            test::read_text(test::source_dir() + "/bench/data/" + name + ".ideal"));
        const GroebnerResult r = modular_groebner(ideal.generators);
        const Certification good = certification_of(r.basis, ideal.generators);
        EXPECT_EQ(compare_reducers(good, 0, name), 0u) << name;
        // A corrupted element: some reductions are no longer zero, the same ones in both.
        const Certification bad = certification_of(
            with_coefficient_changed(r.basis, r.basis.size() / 2), ideal.generators);
        EXPECT_GT(compare_reducers(bad, 0, std::string(name) + " corrupted"), 0u) << name;
        {
            // Eight lanes for every reduction, narrower than many values grow: reductions
            // start again on more, and values are rebuilt in full, with the same steps and
            // verdicts.
            ResidueZeroReducer::Statistics narrow;
            EXPECT_EQ(compare_reducers(good, 8, std::string(name) + " on 8 lanes", &narrow), 0u);
            rebuilds += narrow.rebuilds;
            EXPECT_GT(compare_reducers(bad, 8, std::string(name) + " corrupted, 8 lanes"), 0u);
        }
    }
    EXPECT_GT(rebuilds, 0u);
    const Certification c = dense_quadrics();
    ASSERT_GT(ResidueZeroReducer::initial_lanes(c.elements), 8u);
    ResidueZeroReducer::Statistics narrow;
    EXPECT_EQ(compare_reducers(c, 8, "dense quadrics on 8 lanes", &narrow), 0u);
    EXPECT_GT(narrow.restarts, 0u);
    EXPECT_GT(narrow.lanes, 8u);
}

// Jobs reduced together make each its own steps, the same as alone and as on GMP integers,
// including those that rebuild their values or must start again on more lanes while the others
// go on; and they share reducer rows.
TEST(ZeroReducers, JobsReducedTogetherMakeTheirOwnSteps) {
    std::size_t rebuilds = 0;
    for (const char* name : {"cyclic5", "katsura6", "eco6", "noon4", "katsura7"}) {
        const IdealFile ideal = parse_ideal_file(
            test::read_text(test::source_dir() + "/bench/data/" + name + ".ideal"));
        const GroebnerResult r = modular_groebner(ideal.generators);
        const Certification good = certification_of(r.basis, ideal.generators);
        const Certification bad = certification_of(
            with_coefficient_changed(r.basis, r.basis.size() / 2), ideal.generators);
        for (const std::size_t group : {std::size_t{5}, std::size_t{8}}) {
            const std::string what = std::string(name) + " in groups of " + std::to_string(group);
            ResidueZeroReducer::Statistics shared;
            EXPECT_EQ(compare_reducers(good, 0, what, &shared, group), 0u);
            EXPECT_LT(shared.row_terms, shared.reducer_terms) << what;
            EXPECT_GT(compare_reducers(bad, 0, what + ", corrupted", nullptr, group), 0u);
            ResidueZeroReducer::Statistics narrow;
            EXPECT_EQ(compare_reducers(good, 8, what + " on 8 lanes", &narrow, group), 0u);
            rebuilds += narrow.rebuilds;
            EXPECT_GT(compare_reducers(bad, 8, what + " on 8 lanes, corrupted", nullptr, group),
                      0u);
        }
    }
    EXPECT_GT(rebuilds, 0u);
    ResidueZeroReducer::Statistics narrow;
    EXPECT_EQ(compare_reducers(dense_quadrics(), 8, "dense quadrics on 8 lanes in groups of 3",
                               &narrow, 3),
              0u);
    EXPECT_GT(narrow.restarts, 0u);
}

// The same on inputs nobody chose: random ideals under every order the generator picks, their
// bases from the multi-modular route, intact and with one coefficient changed, in groups of 8
// on their own lanes and on 8.
TEST(ZeroReducers, JobsReducedTogetherMatchGmpOnRandomIdeals) {
    std::mt19937_64 rng(23);
    std::size_t jobs = 0, corrupted_nonzero = 0;
    for (int seed = 0; seed < test::seed_count(120); ++seed) {
        const IdealFile ideal = test::random_ideal(rng, seed);
        const GroebnerResult r = modular_groebner(ideal.generators);
        if (r.basis.empty() || r.basis.front().is_constant()) {
            continue;  // the unit ideal: no pairs
        }
        const std::string what = "random ideal " + std::to_string(seed);
        const Certification good = certification_of(r.basis, ideal.generators);
        jobs += good.generators.size() + good.pairs.size();
        EXPECT_EQ(compare_reducers(good, 0, what, nullptr, 8), 0u);
        EXPECT_EQ(compare_reducers(good, 8, what + " on 8 lanes", nullptr, 8), 0u);
        const Certification bad = certification_of(
            with_coefficient_changed(r.basis, r.basis.size() / 2), ideal.generators);
        corrupted_nonzero += compare_reducers(bad, 0, what + ", corrupted", nullptr, 8);
        compare_reducers(bad, 8, what + ", corrupted, on 8 lanes", nullptr, 8);
    }
    EXPECT_GT(jobs, 500u);
    EXPECT_GT(corrupted_nonzero, 0u);
}

// The work counts the certification reports (`locus groebner --stats`): the same steps on
// 32 and on 64 lanes go through the same reducer terms, each counted once a lane, and number
// the same columns.
TEST(ZeroReducers, TermCountsDoNotDependOnTheLanes) {
    const IdealFile ideal =
        parse_ideal_file(test::read_text(test::source_dir() + "/bench/data/katsura6.ideal"));
    const Certification c =
        certification_of(modular_groebner(ideal.generators).basis, ideal.generators);
    ResidueZeroReducer::Statistics on32, on64;
    EXPECT_EQ(compare_reducers(c, 32, "katsura6 on 32 lanes", &on32), 0u);
    EXPECT_EQ(compare_reducers(c, 64, "katsura6 on 64 lanes", &on64), 0u);
    ASSERT_EQ(on32.restarts + on64.restarts, 0u);
    EXPECT_GT(on32.reducer_terms, 0u);
    EXPECT_EQ(on32.reducer_terms, on64.reducer_terms);
    EXPECT_EQ(on32.lane_terms, 32 * on32.reducer_terms);
    EXPECT_EQ(on64.lane_terms, 64 * on64.reducer_terms);
    EXPECT_GT(on32.columns, 0u);
    EXPECT_EQ(on32.columns, on64.columns);
}

TEST(ZeroReducers, EveryKernelCertifiesTheSameWay) {
    KernelGuard guard;
    const IdealFile ideal =
        parse_ideal_file(test::read_text(test::source_dir() + "/bench/data/katsura6.ideal"));
    const GroebnerResult r = modular_groebner(ideal.generators);
    std::vector<std::size_t> steps;
    for (const std::string& kernel : lanes::supported_kernels()) {
        lanes::select_kernels(kernel);
        const BasisCheck check = certify_groebner_basis(r.basis, ideal.generators);
        EXPECT_TRUE(check.ok) << kernel;
        EXPECT_GT(check.work.lanes, 0u) << kernel;
        steps.push_back(check.work.reduction_steps);
    }
    EXPECT_EQ(std::count(steps.begin(), steps.end(), steps.front()),
              static_cast<long>(steps.size()));
}

TEST(ZeroReducers, HugeCoefficientsAreLeftToGmpIntegers) {
    // Two constants of about 9 000 bits: the basis' coefficients need more lanes than the
    // residue reducer takes on.
    std::string a = "1", b = "3";
    for (int k = 0; k < 2700; ++k) {
        a += static_cast<char>('0' + (k * 7 + 3) % 10);
        b += static_cast<char>('0' + (k * 3 + 1) % 10);
    }
    const IdealFile ideal =
        parse_ideal_file("vars: x,y\norder: grevlex\nx^2-" + a + "*y\n" + "x*y-" + b + "\n");
    const GroebnerResult r = buchberger(ideal.generators);
    const BasisCheck check = certify_groebner_basis(r.basis, ideal.generators);
    EXPECT_TRUE(check.ok);
    EXPECT_TRUE(check.work.exact_fallback);
    EXPECT_EQ(check.work.lanes, 0u);
    const BasisCheck corrupted =
        certify_groebner_basis(with_coefficient_changed(r.basis, 0), ideal.generators);
    EXPECT_FALSE(corrupted.ok);
}

// Constants of about 6 600 bits: the basis fits the residues at first (fewer than kMostLanes
// lanes, checked), but its reductions outgrow them; the certification goes on on GMP integers
// in the middle of a group, with the same verdicts, and says it used both (it reported 0 lanes
// when it had given the residues up).
TEST(ZeroReducers, ReductionsThatOutgrowTheLanesGoOnOnGmpIntegers) {
    std::string a = "1", b = "3";
    for (int k = 0; k < 2000; ++k) {
        a += static_cast<char>('0' + (k * 7 + 3) % 10);
        b += static_cast<char>('0' + (k * 3 + 1) % 10);
    }
    const IdealFile ideal = parse_ideal_file("vars: x,y,z\norder: grevlex\nx^2-" + a +
                                             "*y*z\nx*y-" + b + "*z\ny^2-x*z\n");
    const GroebnerResult r = buchberger(ideal.generators);
    const Certification c = certification_of(r.basis, ideal.generators);
    ASSERT_LE(ResidueZeroReducer::initial_lanes(c.elements), ResidueZeroReducer::kMostLanes);
    const BasisCheck check = certify_groebner_basis(r.basis, ideal.generators);
    EXPECT_TRUE(check.ok);
    EXPECT_TRUE(check.work.exact_fallback);
    EXPECT_GT(check.work.lanes, 0u);
    EXPECT_GT(check.work.lane_restarts, 0u);
    const BasisCheck corrupted =
        certify_groebner_basis(with_coefficient_changed(r.basis, 0), ideal.generators);
    EXPECT_FALSE(corrupted.ok);
}

}  // namespace
}  // namespace locus::algebra::detail
