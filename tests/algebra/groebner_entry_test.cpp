// The library's entry point (algebra/groebner.h): every algorithm over Q gives the basis of the
// literature case, over GF(p) the basis F4 gives modulo p, and every way of not answering is an
// outcome with a reason, not an exception.
#include "algebra/groebner.h"

#include "algebra/groebner/signature_groebner.h"
#include "algebra/modular/modular_groebner.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <thread>

#include "algebra/deadline.h"
#include "algebra/error.h"
#include "algebra/parse.h"
#include "algebra/print.h"
#include "tests/support/ideal_cases.h"

namespace locus::algebra {
namespace {

std::string normalized(const std::vector<Polynomial>& basis, const PolyRing& ring) {
    return format_polynomials(basis, ring, OutputFormat::normalized);
}

IdealFile read_case(const std::string& relative) {
    return parse_ideal_file(test::read_text(test::source_dir() + "/" + relative));
}

TEST(GroebnerEntry, EveryAlgorithmOverQGivesTheKnownBasis) {
    const IdealFile ideal = read_case("tests/data/known/cyclic4_grevlex.ideal");
    const std::string expected =
        test::read_text(test::source_dir() + "/tests/data/known/cyclic4_grevlex.expected");
    for (const Algorithm algorithm :
         {Algorithm::automatic, Algorithm::buchberger, Algorithm::signature, Algorithm::modular}) {
        GroebnerRequest request;
        request.algorithm = algorithm;
        const GroebnerAnswer answer = groebner(ideal.generators, request);
        ASSERT_EQ(answer.outcome, GroebnerOutcome::complete) << algorithm_name(algorithm);
        EXPECT_EQ(normalized(answer.basis, *ideal.ring), expected) << algorithm_name(algorithm);
        EXPECT_TRUE(answer.certified) << algorithm_name(algorithm);
        EXPECT_TRUE(answer.reason.empty());
        EXPECT_EQ(answer.characteristic, 0u);
        EXPECT_NE(answer.algorithm, Algorithm::automatic);
        if (algorithm != Algorithm::automatic) {
            EXPECT_EQ(answer.algorithm, algorithm);
        }
        EXPECT_EQ(answer.modular.has_value(), answer.algorithm == Algorithm::modular);
    }
}

TEST(GroebnerEntry, WithoutCertificationTheModularAnswerSaysSo) {
    const IdealFile ideal = read_case("bench/data/katsura4.ideal");
    GroebnerRequest request;
    request.algorithm = Algorithm::modular;
    request.certify = false;
    const GroebnerAnswer answer = groebner(ideal.generators, request);
    ASSERT_EQ(answer.outcome, GroebnerOutcome::complete);
    EXPECT_FALSE(answer.certified);
    request.certify = true;
    EXPECT_EQ(groebner(ideal.generators, request).basis, answer.basis);
}

// Over GF(p) the answer is F4's modulo p, whatever route is asked for that can give it.
TEST(GroebnerEntry, APrimeCharacteristicComputesModuloIt) {
    const IdealFile ideal = read_case("bench/data/katsura4.ideal");
    GroebnerRequest request;
    request.characteristic = 101;
    for (const Algorithm algorithm : {Algorithm::automatic, Algorithm::modular}) {
        request.algorithm = algorithm;
        const GroebnerAnswer answer = groebner(ideal.generators, request);
        ASSERT_EQ(answer.outcome, GroebnerOutcome::complete);
        EXPECT_EQ(answer.basis, groebner_modulo(ideal.generators, 101));
        EXPECT_EQ(answer.characteristic, 101u);
        EXPECT_TRUE(answer.f4.has_value());
        EXPECT_FALSE(answer.certified);  // nothing lifted, nothing to certify
    }
    for (const Algorithm algorithm : {Algorithm::buchberger, Algorithm::signature}) {
        request.algorithm = algorithm;
        EXPECT_THROW(groebner(ideal.generators, request), InputError);
    }
    request.algorithm = Algorithm::automatic;
    request.characteristic = 100;
    EXPECT_THROW(groebner(ideal.generators, request), InputError);
}

TEST(GroebnerEntry, APassedDeadlineIsAnOutcomeForEveryRoute) {
    const IdealFile ideal = read_case("bench/data/katsura7.ideal");
    for (const std::uint32_t p : {0u, 65521u}) {
        for (const Algorithm algorithm : {Algorithm::automatic, Algorithm::buchberger,
                                          Algorithm::signature, Algorithm::modular}) {
            if (p != 0 &&
                (algorithm == Algorithm::buchberger || algorithm == Algorithm::signature)) {
                continue;
            }
            GroebnerRequest request;
            request.algorithm = algorithm;
            request.characteristic = p;
            request.deadline = std::chrono::steady_clock::now() - std::chrono::seconds(1);
            GroebnerAnswer answer;
            ASSERT_NO_THROW(answer = groebner(ideal.generators, request));
            EXPECT_EQ(answer.outcome, GroebnerOutcome::stopped_timeout)
                << algorithm_name(algorithm) << " p=" << p;
            EXPECT_FALSE(answer.reason.empty());
            EXPECT_FALSE(answer.basis.empty());  // still generators of the ideal
            EXPECT_FALSE(answer.certified);
        }
    }
}

TEST(GroebnerEntry, AlgorithmNamesRoundTrip) {
    for (const Algorithm algorithm :
         {Algorithm::automatic, Algorithm::buchberger, Algorithm::signature, Algorithm::modular}) {
        EXPECT_EQ(parse_algorithm(algorithm_name(algorithm)), algorithm);
    }
    EXPECT_EQ(parse_algorithm("f4"), Algorithm::modular);
    EXPECT_FALSE(parse_algorithm("groebner").has_value());
    EXPECT_FALSE(parse_algorithm("").has_value());
}

}  // namespace
}  // namespace locus::algebra

namespace locus::algebra {
namespace {

// With two threads the probe attempts signatures side by side and the modular route runs its
// primes side by side: the route, and so the answer, are the probe's to decide as on one thread
// (noon-7: signatures; cyclic-7: modular), and a caller's budget still stops it.
TEST(GroebnerEntry, AutomaticRouteIsTheSameOnTwoThreads) {
    for (const std::string name : {"noon7.ideal", "cyclic7.ideal"}) {
        const IdealFile ideal =
            parse_ideal_file(test::read_text(test::source_dir() + "/bench/data/" + name));
        GroebnerOptions one, two;
        two.threads = 2;
        bool modular_one = false, modular_two = false;
        const GroebnerResult a = groebner_automatic(ideal.generators, one, nullptr, &modular_one);
        ModularStats stats;
        const GroebnerResult b = groebner_automatic(ideal.generators, two, &stats, &modular_two);
        ASSERT_EQ(a.outcome, GroebnerOutcome::complete) << name;
        ASSERT_EQ(b.outcome, GroebnerOutcome::complete) << name;
        EXPECT_EQ(modular_one, modular_two) << name;
        EXPECT_EQ(modular_two, name == "cyclic7.ideal");
        EXPECT_EQ(a.basis, b.basis) << name;
        if (modular_two) {
            EXPECT_TRUE(stats.certified) << name;  // the stats are the route's that answered
            EXPECT_GT(stats.primes_used.size(), 1u) << name;
        }
    }
    const IdealFile k10 =
        parse_ideal_file(test::read_text(test::source_dir() + "/bench/data/katsura10.ideal"));
    GroebnerOptions callers;
    callers.max_reduction_steps = 100;
    callers.threads = 2;
    bool modular = true;
    const GroebnerResult limited = groebner_automatic(k10.generators, callers, nullptr, &modular);
    EXPECT_EQ(limited.outcome, GroebnerOutcome::stopped_size);
    EXPECT_FALSE(modular);
}

// A cancellation of the caller's deadline (what the Python bindings do on Ctrl-C) stops the
// modular route after the probe has handed over to it: cyclic-8 hands over within 0.05 s and
// the route then runs for seconds.
TEST(GroebnerEntry, CancellingTheCallersDeadlineStopsTheModularRoute) {
    const IdealFile c8 =
        parse_ideal_file(test::read_text(test::source_dir() + "/bench/data/cyclic8.ideal"));
    std::atomic<bool> cancelled{false};
    const auto deadline =
        cancellable_deadline(std::chrono::steady_clock::now() + std::chrono::hours(1), &cancelled);
    GroebnerOptions options;
    options.threads = 2;
    options.deadline = deadline;
    std::thread canceller([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(1200));
        cancelled = true;
    });
    const auto start = std::chrono::steady_clock::now();
    bool stopped = false;
    try {
        stopped =
            groebner_automatic(c8.generators, options).outcome == GroebnerOutcome::stopped_timeout;
    } catch (const Timeout&) {
        stopped = true;
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    canceller.join();
    forget_cancellable_deadline(deadline);
    EXPECT_TRUE(stopped);
    EXPECT_LT(seconds, 3.0);  // the whole computation takes 8 s on two threads
}

// `auto` takes its route from the input's shape, a budget of reduction steps and the growth of
// coefficients, never from the clock: the same route on every run (the wall-clock probe sent
// katsura-9 either way by the machine's load), and the small lex cases finish by signatures
// while the larger ones go through the modular algorithm.
TEST(GroebnerEntry, AutomaticRouteIsDecidedByShapeAndWork) {
    const auto route = [](const std::string& name) {
        const IdealFile ideal =
            parse_ideal_file(test::read_text(test::source_dir() + "/bench/data/" + name));
        bool modular = false;
        const GroebnerResult r = groebner_automatic(ideal.generators, {}, nullptr, &modular);
        EXPECT_EQ(r.outcome, GroebnerOutcome::complete) << name;
        return modular;
    };
    for (int run = 0; run < 3; ++run) {
        EXPECT_FALSE(route("katsura4_lex.ideal"));
        EXPECT_FALSE(route("cyclic4_lex.ideal"));
        EXPECT_TRUE(route("cyclic5_lex.ideal"));
        EXPECT_TRUE(route("katsura5_lex.ideal"));
        EXPECT_FALSE(route("katsura8.ideal"));
    }
    // Large by Bézout's bound (times the variables, above 4500): the signature algorithm until
    // coefficients of b ≥ 32 bits appear in a basis of fewer than 4·b elements.
    EXPECT_TRUE(route("cyclic7.ideal"));    // 33 bits with 86 elements
    EXPECT_FALSE(route("noon7.ideal"));     // 40 bits at the end
    EXPECT_FALSE(route("henrion5.ideal"));  // Bézout 120 · 6: below the shape, signatures
    // The growth rule itself: katsura-10's coefficients pass 128 bits within its first 40
    // elements, a few hundred reduction steps in.
    const IdealFile k10 =
        parse_ideal_file(test::read_text(test::source_dir() + "/bench/data/katsura10.ideal"));
    GroebnerOptions growth;
    growth.growth_bits = 128;
    growth.growth_basis = 512;
    const GroebnerResult grown = signature_groebner(k10.generators, growth);
    EXPECT_EQ(grown.outcome, GroebnerOutcome::stopped_size);
    EXPECT_NE(grown.reason.find(" bits in a basis of "), std::string::npos) << grown.reason;
    EXPECT_LT(grown.stats.reduction_steps, 5000u);
    // The rule is a rate: b ≥ 32 bits within fewer than 4·b elements (auto's setting). Cyclic-7
    // crosses it (33 bits with 86 elements); eco-10 never does (32 bits with 319 elements, 101
    // with 477 at its end) and completes.
    GroebnerOptions rate;
    rate.growth_bits = 32;
    rate.growth_basis = 128;
    const IdealFile c7 =
        parse_ideal_file(test::read_text(test::source_dir() + "/bench/data/cyclic7.ideal"));
    const GroebnerResult crossed = signature_groebner(c7.generators, rate);
    ASSERT_EQ(crossed.outcome, GroebnerOutcome::stopped_size);
    std::size_t bits = 0, elements = 0;
    ASSERT_EQ(std::sscanf(crossed.reason.c_str(), "coefficients of %zu bits in a basis of %zu",
                          &bits, &elements),
              2)
        << crossed.reason;
    EXPECT_GE(bits, 32u);
    EXPECT_LT(elements, 4 * bits);
    const IdealFile e10 =
        parse_ideal_file(test::read_text(test::source_dir() + "/bench/data/eco10.ideal"));
    EXPECT_EQ(signature_groebner(e10.generators, rate).outcome, GroebnerOutcome::complete);
    // A caller's own budget of steps is the caller's: `auto` stops there rather than handing
    // the ideal to the modular algorithm.
    GroebnerOptions callers;
    callers.max_reduction_steps = 100;
    bool modular = true;
    const GroebnerResult limited = groebner_automatic(k10.generators, callers, nullptr, &modular);
    EXPECT_EQ(limited.outcome, GroebnerOutcome::stopped_size);
    EXPECT_FALSE(modular);
    // A budget of steps stops Buchberger and the signature algorithm alike, as stopped_size.
    const IdealFile k =
        parse_ideal_file(test::read_text(test::source_dir() + "/bench/data/katsura7.ideal"));
    GroebnerOptions budget;
    budget.max_reduction_steps = 100;
    for (const bool signature : {false, true}) {
        const GroebnerResult r =
            signature ? signature_groebner(k.generators, budget) : buchberger(k.generators, budget);
        EXPECT_EQ(r.outcome, GroebnerOutcome::stopped_size);
        EXPECT_GE(r.stats.reduction_steps, 100u);
        EXPECT_LT(r.stats.reduction_steps, 2000u);  // stopped at the next pair, not at the end
    }
}

}  // namespace
}  // namespace locus::algebra
