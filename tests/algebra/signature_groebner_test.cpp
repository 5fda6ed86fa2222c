// The signature-based algorithm (signature_groebner.h) against the same data as Buchberger's:
// every literature basis (tests/data/known) and every Singular oracle basis
// (tests/data/oracle/random.txt, all order kinds) under both signature orders; random ideals
// against Buchberger with the generators shuffled. Its criteria are checked by what they must
// achieve: on a homogeneous regular sequence nothing reduces to zero under position-over-term
// (Faugère's F5 theorem), and on the suite's eco-7 most of Buchberger's zero reductions are gone.
#include "algebra/groebner/signature_groebner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <random>
#include <sstream>

#include "algebra/error.h"
#include "algebra/groebner/verify.h"
#include "algebra/parse.h"
#include "algebra/print.h"
#include "tests/support/ideal_cases.h"

namespace locus::algebra {
namespace {

std::string normalized(const std::vector<Polynomial>& basis, const PolyRing& ring) {
    return format_polynomials(basis, ring, OutputFormat::normalized);
}

const char* order_name(SignatureOrder order) {
    return order == SignatureOrder::schreyer ? "schreyer" : "position_over_term";
}

constexpr SignatureOrder kOrders[] = {SignatureOrder::schreyer, SignatureOrder::position_over_term};

class SignatureKnown : public ::testing::TestWithParam<std::string> {};

// The tests reach the batches of two threads from the first step (signature_groebner's last
// argument), on systems far smaller than the default threshold lets through.
GroebnerOptions on_threads(int threads) {
    GroebnerOptions options;
    options.threads = threads;
    return options;
}

TEST_P(SignatureKnown, MatchesExpectedBasisUnderBothOrdersOnOneAndTwoThreads) {
    const std::string base = test::source_dir() + "/tests/data/known/" + GetParam();
    const IdealFile ideal = parse_ideal_file(test::read_text(base + ".ideal"));
    for (const SignatureOrder order : kOrders) {
        for (const int threads : {1, 2}) {
            SCOPED_TRACE(std::string(order_name(order)) + ", threads " + std::to_string(threads));
            const GroebnerResult r =
                signature_groebner(ideal.generators, on_threads(threads), order, 0);
            ASSERT_EQ(r.outcome, GroebnerOutcome::complete);
            EXPECT_EQ(normalized(r.basis, *ideal.ring), test::read_text(base + ".expected"));
            EXPECT_TRUE(is_reduced(r.basis));
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Literature, SignatureKnown, ::testing::ValuesIn(test::known_case_names()),
                         [](const auto& param_info) { return param_info.param; });

TEST(SignatureOracle, AgreesWithSingularOnRandomIdealsUnderBothOrdersOnOneAndTwoThreads) {
    const auto cases = test::oracle_cases();
    ASSERT_GE(cases.size(), 200u);
    for (const auto& c : cases) {
        SCOPED_TRACE("oracle case " + c.number);
        const IdealFile file = parse_ideal_file(c.ideal);
        for (const SignatureOrder order : kOrders) {
            for (const int threads : {1, 2}) {
                SCOPED_TRACE(std::string(order_name(order)) + ", threads " +
                             std::to_string(threads));
                const GroebnerResult r =
                    signature_groebner(file.generators, on_threads(threads), order, 0);
                EXPECT_EQ(r.outcome, GroebnerOutcome::complete);
                EXPECT_EQ(normalized(r.basis, *file.ring), c.expected);
            }
        }
    }
}

// n random dense homogeneous polynomials in n variables, of degrees 2 and 3 alternately, with
// random coefficients: a regular sequence with probability one.
std::vector<Polynomial> random_regular_sequence(const RingPtr& ring, std::mt19937_64& rng) {
    const std::size_t n = ring->num_vars();
    std::uniform_int_distribution<long> coefficient(-50, 50);
    std::vector<Polynomial> f;
    for (std::size_t k = 0; k < n; ++k) {
        const unsigned degree = k % 2 == 0 ? 2 : 3;
        std::vector<std::pair<Rational, std::vector<std::uint32_t>>> terms;
        std::vector<std::uint32_t> e(n, 0);
        // Every exponent vector of total degree `degree`, by counting in base degree + 1.
        while (true) {
            std::uint32_t sum = 0;
            for (auto x : e) {
                sum += x;
            }
            if (sum == degree) {
                long c = 0;
                while (c == 0) {
                    c = coefficient(rng);
                }
                terms.emplace_back(Rational(c), e);
            }
            std::size_t i = 0;
            while (i < n && e[i] == degree) {
                e[i++] = 0;
            }
            if (i == n) {
                break;
            }
            ++e[i];
        }
        f.push_back(Polynomial::from_terms(ring, std::move(terms)));
    }
    return f;
}

TEST(SignatureCriteria, NothingReducesToZeroOnRegularSequencesUnderPositionOverTerm) {
    for (int seed = 0; seed < test::seed_count(6); ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        std::mt19937_64 rng(static_cast<unsigned>(seed));
        const RingPtr ring = PolyRing::make({"x", "y", "z", "w"}, MonomialOrder::grevlex(4));
        const std::vector<Polynomial> f = random_regular_sequence(ring, rng);
        const GroebnerResult by_buchberger = buchberger(f);
        const GroebnerResult r = signature_groebner(f, {}, SignatureOrder::position_over_term);
        EXPECT_EQ(r.basis, by_buchberger.basis);
        EXPECT_EQ(r.stats.zero_reductions, 0u);
        // The statement has content: Buchberger's criteria leave many zero reductions here.
        EXPECT_GE(by_buchberger.stats.zero_reductions, 10u);
        EXPECT_GT(r.stats.removed_by_syzygy, 0u);
    }
}

TEST(SignatureCriteria, RemoveMostOfBuchbergersZeroReductionsOnEco7) {
    const IdealFile ideal =
        parse_ideal_file(test::read_text(test::source_dir() + "/bench/data/eco7.ideal"));
    const GroebnerResult by_buchberger = buchberger(ideal.generators);
    const GroebnerResult r = signature_groebner(ideal.generators);
    EXPECT_EQ(r.basis, by_buchberger.basis);
    // 114 zero reductions and 7997 steps for Buchberger; 26 and about 2 800 here.
    EXPECT_LT(4 * r.stats.zero_reductions, by_buchberger.stats.zero_reductions);
    EXPECT_LT(2 * r.stats.reduction_steps, by_buchberger.stats.reduction_steps);
    EXPECT_GT(r.stats.removed_by_rewriting, 0u);
}

TEST(SignatureProperties, EqualsBuchbergerWhateverTheGeneratorOrder) {
    int compared = 0;
    for (int seed = 0; seed < test::seed_count(60); ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        std::mt19937_64 rng(5000 + static_cast<unsigned>(seed));
        const IdealFile ideal = test::random_ideal(rng, seed);
        GroebnerOptions limited;
        limited.max_basis_size = 40;
        const GroebnerResult expected = buchberger(ideal.generators, limited);
        if (expected.outcome != GroebnerOutcome::complete) {
            continue;
        }
        std::vector<Polynomial> shuffled = ideal.generators;
        std::shuffle(shuffled.begin(), shuffled.end(), rng);
        shuffled.push_back(shuffled.front());  // a repeated generator is a syzygy at once
        for (const SignatureOrder order : kOrders) {
            for (const int threads : {1, 2}) {
                SCOPED_TRACE(std::string(order_name(order)) + ", threads " +
                             std::to_string(threads));
                const GroebnerResult r =
                    signature_groebner(shuffled, on_threads(threads), order, 0);
                ASSERT_EQ(r.outcome, GroebnerOutcome::complete);
                EXPECT_EQ(r.basis, expected.basis);
            }
        }
        ++compared;
    }
    EXPECT_GE(compared, test::seed_count(60) * 9 / 10);
}

// With two threads the signatures of a degree are attempted side by side on the basis before
// them, then checked again and their reductions continued in order (signature_groebner.h).
// Every decision is then the sequential one: the same signatures are skipped by each criterion,
// the same ones reduced and to zero, and the elements have the same leading monomials (so the
// same S-pairs are queued), which the statistics show. Only the work differs: attempts later
// found skipped, and continued reductions. Runs with two threads do not differ from each other.
// Under a degree order no element of a batch divides another's signature (same degree); under
// lex (the batches share the first variable's exponent) the batch's elements do change which
// element's multiple is taken: 14 times on katsura5_lex, 23 on cyclic5_lex.
TEST(SignatureParallel, MakesTheSequentialDecisionsOnTwoThreads) {
    for (const std::string name : {"eco7.ideal", "katsura7.ideal", "cyclic6.ideal", "noon5.ideal",
                                   "katsura5_lex.ideal", "cyclic5_lex.ideal"}) {
        SCOPED_TRACE(name);
        const IdealFile ideal =
            parse_ideal_file(test::read_text(test::source_dir() + "/bench/data/" + name));
        for (const SignatureOrder order : kOrders) {
            SCOPED_TRACE(order_name(order));
            const GroebnerResult one =
                signature_groebner(ideal.generators, on_threads(1), order, 0);
            const GroebnerResult two =
                signature_groebner(ideal.generators, on_threads(2), order, 0);
            const GroebnerResult again =
                signature_groebner(ideal.generators, on_threads(2), order, 0);
            ASSERT_EQ(one.outcome, GroebnerOutcome::complete);
            ASSERT_EQ(two.outcome, GroebnerOutcome::complete);
            EXPECT_EQ(two.basis, one.basis);
            EXPECT_EQ(two.stats.pairs_created, one.stats.pairs_created);
            EXPECT_EQ(two.stats.removed_by_syzygy, one.stats.removed_by_syzygy);
            EXPECT_EQ(two.stats.removed_by_rewriting, one.stats.removed_by_rewriting);
            EXPECT_EQ(two.stats.reductions, one.stats.reductions);
            EXPECT_EQ(two.stats.zero_reductions, one.stats.zero_reductions);
            EXPECT_EQ(two.stats.max_basis_size, one.stats.max_basis_size);
            EXPECT_GT(two.stats.batched_signatures, 0u);  // the batches ran
            EXPECT_EQ(again.basis, two.basis);
            EXPECT_EQ(again.stats.reduction_steps, two.stats.reduction_steps);
        }
    }
}

// By default a run takes the batches only after kStepsBeforeBatches steps: eco7 (about 2 700)
// runs on one thread; noon7 (about 47 000) reaches them.
TEST(SignatureParallel, SmallRunsStayOnOneThreadByDefault) {
    for (const std::string name : {"eco7.ideal", "noon7.ideal"}) {
        SCOPED_TRACE(name);
        const IdealFile ideal =
            parse_ideal_file(test::read_text(test::source_dir() + "/bench/data/" + name));
        const GroebnerResult one = signature_groebner(ideal.generators, on_threads(1));
        const GroebnerResult two = signature_groebner(ideal.generators, on_threads(2));
        EXPECT_EQ(two.basis, one.basis);
        EXPECT_EQ(one.stats.batched_signatures, 0u);
        EXPECT_EQ(two.stats.batched_signatures > 0,
                  one.stats.reduction_steps >= kStepsBeforeBatches);
        EXPECT_EQ(two.stats.batched_signatures > 0, name == "noon7.ideal");
    }
    // Forced from the first step, eco7 takes batches too.
    const IdealFile eco7 =
        parse_ideal_file(test::read_text(test::source_dir() + "/bench/data/eco7.ideal"));
    EXPECT_GT(signature_groebner(eco7.generators, on_threads(2), SignatureOrder::schreyer, 0)
                  .stats.batched_signatures,
              0u);
}

// A deadline stops a run on two threads promptly, in the batches attempted side by side (most
// of cyclic-7's time: about 1.4 s in all) as in the loop that takes them in order.
TEST(SignatureParallel, DeadlineStopsTheRunOnTwoThreads) {
    const IdealFile ideal =
        parse_ideal_file(test::read_text(test::source_dir() + "/bench/data/cyclic7.ideal"));
    for (const int milliseconds : {100, 300}) {
        GroebnerOptions options = on_threads(2);
        options.deadline =
            std::chrono::steady_clock::now() + std::chrono::milliseconds(milliseconds);
        const auto start = std::chrono::steady_clock::now();
        const GroebnerResult r = signature_groebner(ideal.generators, options);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        EXPECT_EQ(r.outcome, GroebnerOutcome::stopped_timeout);
        EXPECT_LT(seconds, milliseconds / 1000.0 + 0.5);
        // The partial result keeps every generator beside the elements so far.
        EXPECT_GT(r.basis.size(), ideal.generators.size());
    }
}

// Generators that share their leading monomial, and zero generators among them: the Schreyer
// order then breaks ties between signatures by the generators' numbers.
TEST(Signature, EqualLeadingMonomialsAndZeroGenerators) {
    const RingPtr r = PolyRing::make({"x", "y", "z"}, MonomialOrder::grevlex(3));
    const std::vector<Polynomial> f = {Polynomial(r), parse_polynomial("x^2*y+y^3-z", r),
                                       parse_polynomial("x^2*y+x*z+2", r), Polynomial(r),
                                       parse_polynomial("x^2*y-y*z^2+x", r)};
    const std::vector<Polynomial> expected = buchberger(f).basis;
    for (const SignatureOrder order : kOrders) {
        SCOPED_TRACE(order_name(order));
        EXPECT_EQ(signature_groebner(f, {}, order).basis, expected);
    }
}

TEST(Signature, EdgeCases) {
    const RingPtr r = PolyRing::make({"x", "y"}, MonomialOrder::grevlex(2));
    EXPECT_TRUE(signature_groebner(std::vector<Polynomial>{}).basis.empty());
    const std::vector<Polynomial> zeros = {Polynomial(r), Polynomial(r)};
    EXPECT_TRUE(signature_groebner(zeros).basis.empty());
    // The unit ideal, from a constant generator and from a computation.
    const std::vector<Polynomial> constant = {parse_polynomial("x^2-y", r),
                                              parse_polynomial("-3", r)};
    EXPECT_EQ(normalized(signature_groebner(constant).basis, *r), "1\n");
    const std::vector<Polynomial> unit = {parse_polynomial("x*y-1", r), parse_polynomial("x", r)};
    EXPECT_EQ(normalized(signature_groebner(unit).basis, *r), "1\n");
    const std::vector<Polynomial> single = {parse_polynomial("3*x*y-6", r)};
    EXPECT_EQ(normalized(signature_groebner(single).basis, *r), "x*y-2\n");
}

TEST(Signature, StopsWithAGeneratingSetOnTimeoutAndSize) {
    const IdealFile ideal =
        parse_ideal_file(test::read_text(test::source_dir() + "/bench/data/katsura6.ideal"));
    const std::vector<Polynomial> expected = buchberger(ideal.generators).basis;
    GroebnerOptions timeout;
    timeout.deadline = std::chrono::steady_clock::now();
    GroebnerOptions size;
    size.max_basis_size = 5;
    for (const GroebnerOptions& options : {timeout, size}) {
        const GroebnerResult r = signature_groebner(ideal.generators, options);
        EXPECT_NE(r.outcome, GroebnerOutcome::complete);
        // What is returned generates the ideal: its basis is the same.
        EXPECT_EQ(buchberger(r.basis).basis, expected);
    }
    EXPECT_EQ(signature_groebner(ideal.generators, timeout).outcome,
              GroebnerOutcome::stopped_timeout);
    EXPECT_EQ(signature_groebner(ideal.generators, size).outcome, GroebnerOutcome::stopped_size);
}

// A deadline that passes during a reduction stops it within 16 steps, not at the next signature:
// x^2000 - 1 is reduced by x - y in 2000 steps. (A machine that stalls for 20 ms before the
// second signature stops at the loop's check instead, with fewer steps still.)
TEST(Signature, DeadlineInterruptsALongReduction) {
    const RingPtr ring = PolyRing::make({"x", "y"}, MonomialOrder::grevlex(2));
    const std::vector<Polynomial> f = {parse_polynomial("x-y", ring),
                                       parse_polynomial("x^2000-1", ring)};
    const GroebnerResult full = signature_groebner(f);
    ASSERT_GE(full.stats.reduction_steps, 2000u);
    // The deadline is 20 ms ahead; the progress call of the second signature (that of
    // x^2000 - 1) waits it out, after the loop has checked it and before the reduction starts.
    GroebnerOptions options;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(20);
    options.deadline = deadline;
    options.progress = [&](const GroebnerProgress& p) {
        if (p.pairs_done == 2) {
            while (std::chrono::steady_clock::now() <= deadline) {
            }
        }
    };
    const GroebnerResult r = signature_groebner(f, options);
    EXPECT_EQ(r.outcome, GroebnerOutcome::stopped_timeout);
    EXPECT_LE(r.stats.reduction_steps, 32u);
    EXPECT_EQ(buchberger(r.basis).basis, full.basis);
}

// Progress reports one call per signature taken, in order, and ends with nothing queued.
TEST(Signature, ProgressCountsSignatures) {
    const IdealFile ideal =
        parse_ideal_file(test::read_text(test::source_dir() + "/bench/data/katsura5.ideal"));
    std::vector<GroebnerProgress> calls;
    GroebnerOptions options;
    options.progress = [&](const GroebnerProgress& p) { calls.push_back(p); };
    const GroebnerResult r = signature_groebner(ideal.generators, options);
    ASSERT_FALSE(calls.empty());
    for (std::size_t k = 0; k < calls.size(); ++k) {
        EXPECT_EQ(calls[k].pairs_done, k + 1);
        if (k > 0) {
            EXPECT_GE(calls[k].basis_size, calls[k - 1].basis_size);
        }
    }
    EXPECT_EQ(calls.back().pairs_left, 0u);
    // Every reduction follows its own call; the rest were skipped by a criterion.
    EXPECT_GE(calls.size(), r.stats.reductions);
    EXPECT_GE(r.stats.reductions, ideal.generators.size());
}

// Signatures can exceed the polynomials' degrees: under weights(16000,1), where x^2 alone has
// weight 32000, the signatures of these ideals' elements leave the packed range (32767) while
// Buchberger's lcms stay inside it (x^2*y: 32001). signature_groebner reports the overflow; the
// fallback answers with Buchberger's basis.
TEST(Signature, FallsBackToBuchbergerWhenASignatureOverflows) {
    const RingPtr r =
        PolyRing::make({"x", "y"}, MonomialOrder::weighted(std::vector<std::int64_t>{16000, 1}));
    const std::vector<std::vector<Polynomial>> ideals = {
        {parse_polynomial("x^2-y", r), parse_polynomial("x*y-1", r)},
        {parse_polynomial("x^2+y", r), parse_polynomial("x^2+y^2", r),
         parse_polynomial("x*y+1", r)}};
    for (const auto& f : ideals) {
        EXPECT_THROW(signature_groebner(f), locus::ExponentOverflow);
        EXPECT_EQ(signature_groebner_or_buchberger(f).basis, buchberger(f).basis);
    }
    EXPECT_EQ(normalized(signature_groebner_or_buchberger(ideals[0]).basis, *r), "y^3-1\nx-y^2\n");
    // Where nothing overflows, the signature algorithm answers.
    const RingPtr g = PolyRing::make({"x", "y"}, MonomialOrder::grevlex(2));
    const std::vector<Polynomial> h = {parse_polynomial("x^2-y", g), parse_polynomial("x*y-1", g)};
    EXPECT_EQ(signature_groebner_or_buchberger(h).stats.removed_by_syzygy,
              signature_groebner(h).stats.removed_by_syzygy);
    EXPECT_GT(signature_groebner(h).stats.removed_by_syzygy, 0u);
}

TEST(Signature, RejectsMixedRings) {
    const RingPtr a = PolyRing::make({"x", "y"}, MonomialOrder::grevlex(2));
    const RingPtr b = PolyRing::make({"x", "y"}, MonomialOrder::lex(2));
    const std::vector<Polynomial> mixed = {parse_polynomial("x-y", a), parse_polynomial("x", b)};
    EXPECT_THROW(signature_groebner(mixed), locus::MixedRings);
}

}  // namespace
}  // namespace locus::algebra
