// Multi-modular F4: every literature basis and every Singular oracle basis recomputed
// by modular_groebner equals the Buchberger result; an unlucky prime forced by construction is
// detected and set aside; the certification rejects a corrupted basis; F4 modulo one prime
// agrees with the rational basis reduced modulo that prime; a replay of the first prime's F4
// trace equals F4 on another prime, and is refused where the computation differs.
#include "algebra/modular/modular_groebner.h"

#include <flint/fmpq.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>

#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "algebra/error.h"
#include "algebra/groebner/verify.h"
#include "algebra/parse.h"
#include "algebra/print.h"
#include "tests/support/ideal_cases.h"

namespace locus::algebra {
namespace {

// The basis as text, normalized (print.h): equal bases, equal texts.
std::string normalized(const std::vector<Polynomial>& basis, const PolyRing& ring) {
    return format_polynomials(basis, ring, OutputFormat::normalized);
}

class ModularKnown : public ::testing::TestWithParam<std::string> {};

TEST_P(ModularKnown, EqualsBuchbergerAndIsCertified) {
    const std::string base = test::source_dir() + "/tests/data/known/" + GetParam();
    const IdealFile ideal = parse_ideal_file(test::read_text(base + ".ideal"));
    ModularStats stats;
    const GroebnerResult r = modular_groebner(ideal.generators, {}, &stats);
    EXPECT_EQ(normalized(r.basis, *ideal.ring), test::read_text(base + ".expected"));
    EXPECT_TRUE(stats.certified);
    EXPECT_TRUE(is_reduced(r.basis));
}

INSTANTIATE_TEST_SUITE_P(Literature, ModularKnown, ::testing::ValuesIn(test::known_case_names()),
                         [](const auto& param_info) { return param_info.param; });

TEST(Modular, AgreesWithSingularOracleOnRandomIdeals) {
    const auto cases = test::oracle_cases();
    ASSERT_GE(cases.size(), 200u);
    for (const auto& c : cases) {
        SCOPED_TRACE("oracle case " + c.number);
        const IdealFile file = parse_ideal_file(c.ideal);
        GroebnerResult r;
        try {
            r = modular_groebner(file.generators);
        } catch (const Error& e) {
            ADD_FAILURE() << e.what() << " on\n" << c.ideal;
            continue;
        }
        EXPECT_EQ(normalized(r.basis, *file.ring), c.expected);
    }
}

TEST(Modular, LexGoesThroughFglmExactlyWhenTheIdealIsZeroDimensional) {
    const std::string dir = test::source_dir() + "/bench/data/";
    for (const auto& [name, zero_dimensional] :
         std::vector<std::pair<std::string, bool>>{{"katsura5_lex", true},
                                                   {"cyclic5_lex", true},
                                                   {"cyclic4_lex", false},
                                                   {"whitney_elim", false}}) {
        SCOPED_TRACE(name);
        const IdealFile ideal = parse_ideal_file(test::read_text(dir + name + ".ideal"));
        ModularStats stats;
        const GroebnerResult r = modular_groebner(ideal.generators, {}, &stats);
        EXPECT_EQ(stats.fglm, zero_dimensional);
        EXPECT_TRUE(stats.certified);
        EXPECT_EQ(normalized(r.basis, *ideal.ring),
                  normalized(buchberger(ideal.generators).basis, *ideal.ring));
    }
}

TEST(Modular, AutomaticAgreesWithBuchbergerOnTheBenchSuite) {
    const std::string dir = test::source_dir() + "/bench/data/";
    for (const std::string name : {"cyclic5", "katsura6", "eco6", "noon4", "katsura4_lex",
                                   "tangent_surface_elim", "enneper_elim"}) {
        SCOPED_TRACE(name);
        const IdealFile ideal = parse_ideal_file(test::read_text(dir + name + ".ideal"));
        EXPECT_EQ(normalized(groebner_automatic(ideal.generators).basis, *ideal.ring),
                  normalized(buchberger(ideal.generators).basis, *ideal.ring));
    }
}

// Under lex, `auto` skips its signature probe for square systems of shape B·n ≥ 150
// (cyclic5_lex: 600, where the probe always handed over) and probes the others (cyclic4_lex: 96,
// which the probe answers; the elimination ideals, fewer generators than variables). The probe
// shows itself by reports of the pairs stage.
TEST(Modular, AutomaticSkipsTheLexProbeOnlyForLargeSquareSystems) {
    const std::string dir = test::source_dir() + "/bench/data/";
    for (const auto& [name, probed, modular] :
         std::vector<std::tuple<std::string, bool, bool>>{{"cyclic5_lex", false, true},
                                                          {"katsura5_lex", true, true},
                                                          {"cyclic4_lex", true, false},
                                                          {"enneper_elim", true, false}}) {
        SCOPED_TRACE(name);
        const IdealFile ideal = parse_ideal_file(test::read_text(dir + name + ".ideal"));
        GroebnerOptions options;
        bool pairs_reported = false;
        options.progress = [&](const GroebnerProgress& p) {
            pairs_reported = pairs_reported || p.stage == GroebnerProgress::Stage::pairs;
        };
        bool used_modular = false;
        ModularStats stats;
        const GroebnerResult r =
            groebner_automatic(ideal.generators, options, &stats, &used_modular);
        EXPECT_EQ(pairs_reported, probed);
        EXPECT_EQ(used_modular, modular);
        // The statistics say why the probe handed over (`--stats`: "auto's probe").
        if (modular) {
            EXPECT_EQ(stats.probe.rfind(probed ? "signatures stopped after " : "none: ", 0), 0u)
                << stats.probe;
        }
        EXPECT_EQ(normalized(r.basis, *ideal.ring),
                  normalized(buchberger(ideal.generators).basis, *ideal.ring));
    }
}

// Regressions from the review of the modular code.
// Coefficients beyond max_primes' reach are an outcome (unable; the CLI's exit 5), not an input
// error; the fuzzer found (2e38)^3000 (115 000 digits), which needs about 12 300 primes.
TEST(Modular, TooManyPrimesIsAnOutcomeNotAnError) {
    const IdealFile file = parse_ideal_file("vars: a,b\na^2*b-(2*10^38)^300\n");
    ModularOptions options;
    options.max_primes = 20;
    const GroebnerResult refused = modular_groebner(file.generators, options);
    EXPECT_EQ(refused.outcome, GroebnerOutcome::unable);
    EXPECT_NE(refused.reason.find("no stable lift after 20 primes"), std::string::npos);
    EXPECT_EQ(refused.basis, file.generators);  // they still generate the ideal
    options.max_primes = 10000;
    const GroebnerResult r = modular_groebner(file.generators, options);
    EXPECT_EQ(r.basis, file.generators);
}

TEST(Modular, ReviewRegressions) {
    // A coefficient equal to the product of the two largest primes below 2^31: with a fixed
    // prime sequence both primes gave the unit ideal, agreed, and "1" passed certification.
    const IdealFile product =
        parse_ideal_file("vars: x,y\norder: grevlex\nx^2+4611685975477714963*y\nx*y-1\n");
    EXPECT_EQ(normalized(modular_groebner(product.generators).basis, *product.ring),
              normalized(buchberger(product.generators).basis, *product.ring));
    // The same primes forced: the leading coefficient they divide sets them aside.
    const IdealFile lead = parse_ideal_file("vars: x\norder: grevlex\n4611685975477714963*x-1\n");
    ModularOptions forced;
    forced.primes = {2147483647u, 2147483629u};
    ModularStats stats;
    EXPECT_EQ(normalized(modular_groebner(lead.generators, forced, &stats).basis, *lead.ring),
              "x-1/4611685975477714963\n");
    EXPECT_GE(stats.unlucky_primes, 2u);
    // The same primes on a positive-dimensional input, where no proof of ideal equality applies
    // (ideal_equality.h): modulo each the input is −1, and only setting them aside keeps "1",
    // which the certificate accepts, from being the answer.
    const IdealFile curve =
        parse_ideal_file("vars: x,y\norder: grevlex\n4611685975477714963*x*y-1\n");
    ModularStats curve_stats;
    EXPECT_EQ(
        normalized(modular_groebner(curve.generators, forced, &curve_stats).basis, *curve.ring),
        "x*y-1/4611685975477714963\n");
    EXPECT_GE(curve_stats.unlucky_primes, 2u);
    // Under an elimination order, F4 one pair at a time by least lcm did not finish; by least
    // first-row sugar it takes milliseconds.
    const IdealFile elim = parse_ideal_file(
        "vars: x,y,z,w\norder: elim(x,y)\n2*w^3+x^2*z^3\n"
        "-15*x^2*z^3*w^3+57*x^2*z^2*w^3+x*y^3*z-y*z^3\n1/7*x^2*y^2*w\n"
        "y^3*z*w+2*x*y^3*z^3*w+61*z+7*w^3\n");
    EXPECT_EQ(normalized(modular_groebner(elim.generators).basis, *elim.ring),
              normalized(buchberger(elim.generators).basis, *elim.ring));
    // Certification and FGLM honour the deadline.
    const IdealFile katsura =
        parse_ideal_file(test::read_text(test::source_dir() + "/bench/data/katsura5.ideal"));
    const GroebnerResult r = modular_groebner(katsura.generators);
    EXPECT_THROW(certify_groebner_basis(r.basis, katsura.generators,
                                        std::chrono::steady_clock::now() - std::chrono::seconds(1)),
                 Timeout);
    ModularOptions past;
    past.deadline = std::chrono::steady_clock::now() - std::chrono::seconds(1);
    const IdealFile lex =
        parse_ideal_file(test::read_text(test::source_dir() + "/bench/data/katsura5_lex.ideal"));
    const GroebnerResult stopped = modular_groebner(lex.generators, past);
    EXPECT_EQ(stopped.outcome, GroebnerOutcome::stopped_timeout);
    EXPECT_EQ(stopped.basis, lex.generators);
}

// A zero-dimensional lex input of total degree 40 000 (lex packs it variable by variable): the
// detour through grevlex, whose total-degree field holds 32 767, overflowed and the route
// refused the input as bad; F4 now runs under lex itself, to Buchberger's basis.
TEST(Modular, LexInputsPastGrevlexDegreesAreComputedUnderLex) {
    const IdealFile f = parse_ideal_file("vars: x,y\norder: lex\nx^20000*y^20000-1\nx-2\n");
    ModularStats stats;
    const GroebnerResult r = modular_groebner(f.generators, {}, &stats);
    EXPECT_EQ(r.outcome, GroebnerOutcome::complete);
    EXPECT_FALSE(stats.fglm);
    EXPECT_EQ(normalized(r.basis, *f.ring), normalized(buchberger(f.generators).basis, *f.ring));
}

// A lift can agree with a fresh prime and still be wrong: both forced primes divide the
// constant 2147483647 * 2147483629, so modulo each the ideal is (x, y^2), and the lift of the
// first agrees with the second. Certification must reject it, and the run go on with more
// primes to the basis over Q.
TEST(Modular, CertificationRejectsAStableWrongLift) {
    const IdealFile f =
        parse_ideal_file("vars: x,y\norder: grevlex\nx-4611685975477714963\ny^2-x\n");
    ModularOptions forced;
    forced.primes = {2147483647u, 2147483629u};
    ModularStats stats;
    const GroebnerResult r = modular_groebner(f.generators, forced, &stats);
    EXPECT_EQ(normalized(r.basis, *f.ring), "x-4611685975477714963\ny^2-4611685975477714963\n");
    EXPECT_EQ(normalized(r.basis, *f.ring), normalized(buchberger(f.generators).basis, *f.ring));
    EXPECT_GT(stats.primes_used.size(), 2u);
    EXPECT_TRUE(stats.certified);
}

TEST(Modular, UnluckyPrimeIsDetectedAndSetAside) {
    // Modulo p the first generator loses its leading term x and the ideal becomes the unit
    // ideal: leading monomials {1} against {x, y²} over Q.
    const std::uint32_t p = 2147483629u;
    const IdealFile ideal =
        parse_ideal_file("vars: x,y\norder: lex\n" + std::to_string(p) + "*x+y\ny^2+1\n");
    ModularOptions options;
    options.primes = {p};
    ModularStats stats;
    const GroebnerResult r = modular_groebner(ideal.generators, options, &stats);
    const GroebnerResult reference = buchberger(ideal.generators);
    EXPECT_EQ(normalized(r.basis, *ideal.ring), normalized(reference.basis, *ideal.ring));
    EXPECT_EQ(stats.primes_used.front(), p);
    EXPECT_GE(stats.unlucky_primes, 1u);
    // A prime dividing a denominator is set aside too.
    const IdealFile fractions =
        parse_ideal_file("vars: x,y\norder: grevlex\nx^2-y/" + std::to_string(p) + "\nx*y-1\n");
    ModularStats fraction_stats;
    const GroebnerResult r2 = modular_groebner(fractions.generators, options, &fraction_stats);
    EXPECT_EQ(normalized(r2.basis, *fractions.ring),
              normalized(buchberger(fractions.generators).basis, *fractions.ring));
    EXPECT_GE(fraction_stats.unlucky_primes, 1u);
}

TEST(Modular, CertificationRejectsACorruptedBasis) {
    const IdealFile ideal =
        parse_ideal_file("vars: x,y,z\norder: grevlex\nx^2+y*z-2\ny^2+x*z-3\nz^2+x*y-5\n");
    const GroebnerResult r = modular_groebner(ideal.generators);
    ASSERT_TRUE(check_groebner_basis(r.basis, ideal.generators).ok);
    ASSERT_TRUE(certify_groebner_basis(r.basis, ideal.generators).ok);
    // Change one coefficient of the last element by 1/p-sized noise: still "looks" right
    // modulo most primes' reconstruction bounds, but the exact check must fail.
    std::vector<Polynomial> corrupted = r.basis;
    Polynomial& last = corrupted.back();
    ASSERT_GE(last.num_terms(), 2u);
    Polynomial fixed(last.ring());
    for (std::size_t i = 0; i < last.num_terms(); ++i) {
        Rational c = last.coefficient(i);
        if (i == last.num_terms() - 1) {
            c = c == Rational(-1, 1000003) ? Rational(1, 1000003) : c + Rational(1, 1000003);
        }
        fixed.push_back_term(c, last.monomial(i));
    }
    last = fixed;
    EXPECT_FALSE(check_groebner_basis(corrupted, ideal.generators).ok);
    // The certification the modular route runs (fraction-free, Gebauer–Möller pairs) too, and
    // on several threads it reports the same first failing pair.
    const BasisCheck single = certify_groebner_basis(corrupted, ideal.generators);
    EXPECT_FALSE(single.ok);
    const BasisCheck threaded =
        certify_groebner_basis(corrupted, ideal.generators, std::nullopt, 3);
    EXPECT_FALSE(threaded.ok);
    EXPECT_EQ(threaded.failure, single.failure);
    EXPECT_EQ(threaded.pairs_checked, single.pairs_checked);
}

// Zero elements of a candidate add nothing to its ideal: the certificate leaves them out, as the
// rational check does (it read the leading monomial of an empty polynomial before; found in a
// review: the modular route never passes one, but the function is public), and a failing
// pair is named by the elements' places in the basis as given.
TEST(Modular, CertificationLeavesZeroElementsOut) {
    const IdealFile ideal =
        parse_ideal_file("vars: x,y,z\norder: grevlex\nx^2+y*z-2\ny^2+x*z-3\nz^2+x*y-5\n");
    const GroebnerResult r = modular_groebner(ideal.generators);
    const Polynomial zero(r.basis.front().ring());
    std::vector<Polynomial> with_zeros = {zero};
    for (const Polynomial& g : r.basis) {
        with_zeros.push_back(g);
        with_zeros.push_back(zero);
    }
    for (int threads : {1, 2}) {
        const BasisCheck check =
            certify_groebner_basis(with_zeros, ideal.generators, std::nullopt, threads);
        EXPECT_TRUE(check.ok) << check.failure;
        EXPECT_EQ(check.pairs_checked,
                  certify_groebner_basis(r.basis, ideal.generators).pairs_checked);
    }
    // Only zeros: the zero ideal, which holds no generator but the zero one.
    const std::vector<Polynomial> zeros = {zero, zero};
    EXPECT_FALSE(certify_groebner_basis(zeros, ideal.generators).ok);
    EXPECT_TRUE(certify_groebner_basis(zeros, std::vector<Polynomial>{zero}).ok);
    // Not a Gröbner basis (x² + yz − 2 and xy + z² − 5 alone: their S-polynomial leads with
    // y²z), zeros between: the failing pair is named by its places among all five.
    const std::vector<Polynomial> partial = {zero, ideal.generators[0], zero, ideal.generators[2],
                                             zero};
    const BasisCheck failed = certify_groebner_basis(partial, std::vector<Polynomial>{});
    ASSERT_FALSE(failed.ok);
    EXPECT_EQ(failed.failure, "S-polynomial of elements 2 and 4 does not reduce to zero");
}

// On several threads the generators are checked beside the pairs; a generator outside the
// basis' ideal is still the failure reported, as on one thread, with no pair counted.
TEST(Modular, ThreadedCertificationReportsTheFirstGeneratorOutsideTheIdeal) {
    const IdealFile ideal =
        parse_ideal_file(test::read_text(test::source_dir() + "/bench/data/katsura6.ideal"));
    const GroebnerResult r = modular_groebner(ideal.generators);
    std::vector<Polynomial> inputs = ideal.generators;
    inputs.insert(inputs.begin() + 2,
                  r.basis.back() + Polynomial::constant(r.basis.back().ring(), Rational(1, 7)));
    const BasisCheck single = certify_groebner_basis(r.basis, inputs);
    EXPECT_FALSE(single.ok);
    EXPECT_EQ(single.generators_checked, 3u);
    EXPECT_EQ(single.pairs_checked, 0u);
    for (int threads : {2, 3}) {
        const BasisCheck threaded = certify_groebner_basis(r.basis, inputs, std::nullopt, threads);
        EXPECT_FALSE(threaded.ok);
        EXPECT_EQ(threaded.failure, single.failure);
        EXPECT_EQ(threaded.generators_checked, 3u);
        EXPECT_EQ(threaded.pairs_checked, 0u);
    }
    const BasisCheck good = certify_groebner_basis(r.basis, ideal.generators, std::nullopt, 2);
    EXPECT_TRUE(good.ok);
    EXPECT_EQ(good.generators_checked, ideal.generators.size());
}

TEST(Modular, ThreadedCertificationAgreesWithOneThread) {
    for (const char* name : {"cyclic5", "katsura6", "eco6"}) {
        const IdealFile ideal = parse_ideal_file(
            test::read_text(test::source_dir() + "/bench/data/" + name + ".ideal"));
        const GroebnerResult r = modular_groebner(ideal.generators);
        const BasisCheck single = certify_groebner_basis(r.basis, ideal.generators);
        const BasisCheck threaded =
            certify_groebner_basis(r.basis, ideal.generators, std::nullopt, 2);
        EXPECT_TRUE(single.ok) << name;
        EXPECT_TRUE(threaded.ok) << name;
        EXPECT_EQ(threaded.pairs_checked, single.pairs_checked) << name;
        // A basis missing its last element is not a Gröbner basis of the same ideal: both
        // reject it, at the same pair or generator.
        const std::vector<Polynomial> shorter(r.basis.begin(), r.basis.end() - 1);
        const BasisCheck single_short = certify_groebner_basis(shorter, ideal.generators);
        const BasisCheck threaded_short =
            certify_groebner_basis(shorter, ideal.generators, std::nullopt, 2);
        EXPECT_FALSE(single_short.ok) << name;
        EXPECT_EQ(threaded_short.failure, single_short.failure) << name;
    }
}

TEST(Modular, F4ModuloAPrimeIsTheRationalBasisReduced) {
    const IdealFile ideal =
        parse_ideal_file("vars: x,y,z\norder: grevlex\nx+y+z\nx*y+y*z+z*x\nx*y*z-1\n");  // cyclic-3
    const std::uint32_t p = 65521;
    const std::vector<Polynomial> modular = groebner_modulo(ideal.generators, p);
    const GroebnerResult rational = buchberger(ideal.generators);
    ASSERT_EQ(modular.size(), rational.basis.size());
    const modular::PrimeField field{p};
    for (std::size_t i = 0; i < modular.size(); ++i) {
        const auto a = modular::reduce_modulo(modular[i], field);
        const auto b = modular::reduce_modulo(rational.basis[i], field);
        ASSERT_TRUE(a && b);
        EXPECT_EQ(a->coefficients, b->coefficients);
        EXPECT_EQ(a->monomials, b->monomials);
    }
    EXPECT_THROW(groebner_modulo(ideal.generators, 65520), InputError);
}

// Inputs modulo p as F4 takes them.
std::vector<modular::ModularPolynomial> modulo(const std::vector<Polynomial>& polys,
                                               std::uint32_t p) {
    std::vector<modular::ModularPolynomial> out;
    for (const Polynomial& f : polys) {
        out.push_back(*modular::reduce_modulo(f, modular::PrimeField{p}));
    }
    return out;
}

// F4 frees the terms of redundant elements once no pending pair needs them (most of cyclic-6's
// elements, four fifths of cyclic-8's memory): the basis stays the one Buchberger's algorithm
// gives over Q, reduced modulo p, on designed cases — among them generators sharing a leading
// monomial (the final reduction keeps the last of them, which is never freed) — and on 60
// random small ideals under six orders. (A freed element used again would leave only its
// leading monomial, putting a monomial into the ideal: a basis that the division check of
// prime_field_test.cpp, which does not test membership in the input's ideal, would pass.)
TEST(Modular, F4FreesFinishedElementsAndKeepsTheBasis) {
    const std::uint32_t p = 2147483647u;
    const modular::PrimeField field{p};
    // The elements F4 freed; the basis checked against Buchberger's.
    auto freed = [&](const IdealFile& ideal, const std::string& what) -> std::size_t {
        modular::F4Stats stats;
        const auto basis =
            modular::f4(modulo(ideal.generators, p), ideal.ring->layout(), field, {}, &stats);
        const GroebnerResult rational = buchberger(ideal.generators);
        EXPECT_EQ(basis.size(), rational.basis.size()) << what;
        for (std::size_t i = 0; i < std::min(basis.size(), rational.basis.size()); ++i) {
            const auto expected = modular::reduce_modulo(rational.basis[i], field);
            EXPECT_TRUE(expected) << what;
            if (expected) {
                EXPECT_EQ(basis[i].monomials, expected->monomials) << what;
                EXPECT_EQ(basis[i].coefficients, expected->coefficients) << what;
            }
        }
        return stats.released_elements;
    };
    for (const std::string& text :
         {test::read_text(test::source_dir() + "/bench/data/cyclic6.ideal"),
          test::read_text(test::source_dir() + "/bench/data/cyclic5.ideal"),
          // Two generators with leading monomial x², which the basis {y, x² + z} keeps.
          std::string("vars: x,y,z\norder: grevlex\nx^2+y+z\nx^2+2*y+z\n")}) {
        EXPECT_GT(freed(parse_ideal_file(text), text), 0u) << text;
    }
    std::size_t freed_at_random = 0;
    for (int seed = 0; seed < test::seed_count(60); ++seed) {
        std::mt19937_64 rng(static_cast<std::uint64_t>(seed) + 7000);
        freed_at_random += freed(test::random_ideal(rng, seed), "seed " + std::to_string(seed));
    }
    EXPECT_GT(freed_at_random, 0u);
}

TEST(Modular, ReplayOfTheFirstPrimesTraceEqualsF4OnAnotherPrime) {
    for (const char* name : {"cyclic5", "katsura6", "eco6", "noon4"}) {
        const IdealFile ideal = parse_ideal_file(
            test::read_text(test::source_dir() + "/bench/data/" + name + ".ideal"));
        const MonomialLayout& layout = ideal.ring->layout();
        const std::uint32_t p1 = 2147483647u, p2 = 2147483629u;
        modular::F4Trace trace;
        modular::F4Stats full_stats;
        modular::f4(modulo(ideal.generators, p1), layout, {p1}, {}, &full_stats, &trace);
        const auto direct = modular::f4(modulo(ideal.generators, p2), layout, {p2});
        modular::F4Stats replay_stats;
        const auto replayed = modular::f4_replay(trace, modulo(ideal.generators, p2), layout, {p2},
                                                 {}, &replay_stats);
        ASSERT_TRUE(replayed.has_value()) << name;
        ASSERT_EQ(replayed->size(), direct.size()) << name;
        for (std::size_t i = 0; i < direct.size(); ++i) {
            EXPECT_EQ((*replayed)[i].monomials, direct[i].monomials) << name;
            EXPECT_EQ((*replayed)[i].coefficients, direct[i].coefficients) << name;
        }
        // The point of the trace: no row that reduces to zero is reduced again.
        EXPECT_GT(full_stats.zero_rows, 0u) << name;
        EXPECT_EQ(replay_stats.zero_rows, 0u) << name;
        EXPECT_LT(replay_stats.pairs_reduced, full_stats.pairs_reduced) << name;
    }
}

// The lifting on two threads (the elements merged and reconstructed side by side, handed out
// in order and none past a failure): the basis of one thread, over several attempts (katsura-7:
// 41 elements, coefficients that need about nine primes), with and without certification.
TEST(Modular, LiftingOnTwoThreadsGivesTheBasisOfOne) {
    const IdealFile ideal =
        parse_ideal_file(test::read_text(test::source_dir() + "/bench/data/katsura7.ideal"));
    ModularOptions options;
    options.certify = false;
    ModularStats one_stats, two_stats;
    options.threads = 1;
    const GroebnerResult one = modular_groebner(ideal.generators, options, &one_stats);
    options.threads = 2;
    const GroebnerResult two = modular_groebner(ideal.generators, options, &two_stats);
    ASSERT_EQ(one.basis.size(), 41u);
    EXPECT_EQ(normalized(two.basis, *ideal.ring), normalized(one.basis, *ideal.ring));
    EXPECT_GE(two_stats.primes_used.size(), 5u);
    options.certify = true;
    ModularStats certified;
    const GroebnerResult checked = modular_groebner(ideal.generators, options, &certified);
    EXPECT_TRUE(certified.certified);
    EXPECT_EQ(normalized(checked.basis, *ideal.ring), normalized(one.basis, *ideal.ring));
}

// The lift takes each element's coefficients over a denominator they share (rational_lift.h,
// modular_groebner.cpp's reconstruct_term): fewer primes than rational reconstruction of the
// largest coefficient alone could do with, which needs M > 2·|n|·d. katsura-8: its largest
// coefficient has 317 bits of numerator and denominator, about 165 over its element's
// denominator; cyclic-7: 576 and 293.
// A bench system through the modular route on one thread, with its statistics.
struct BenchRun {
    IdealFile ideal;
    GroebnerResult result;
    ModularStats stats;
};
BenchRun modular_on_bench_case(const std::string& name) {
    BenchRun run{
        parse_ideal_file(test::read_text(test::source_dir() + "/bench/data/" + name + ".ideal")),
        {},
        {}};
    ModularOptions options;
    options.threads = 1;
    run.result = modular_groebner(run.ideal.generators, options, &run.stats);
    return run;
}

TEST(Modular, LiftingNeedsFewerPrimesThanTheLargestRational) {
    for (const char* name : {"katsura8", "cyclic7"}) {
        SCOPED_TRACE(name);
        const auto [ideal, r, stats] = modular_on_bench_case(name);
        ASSERT_TRUE(stats.certified);
        std::size_t largest = 0;
        for (const Polynomial& g : r.basis) {
            for (std::size_t i = 0; i < g.num_terms(); ++i) {
                const Rational& c = g.coefficient(i);
                largest = std::max<std::size_t>(
                    largest, fmpz_bits(fmpq_numref(c.get())) + fmpz_bits(fmpq_denref(c.get())));
            }
        }
        // The primes that made the lift (the last one only confirms it), about 31 bits each.
        const std::size_t lifted = stats.primes_used.size() - 1;
        EXPECT_LT(lifted * 31, largest) << lifted << " primes, " << largest << " bits";
    }
}

// The first prime, whose F4 the others replay, is drawn below 2^24 (where the row reductions
// sum without reducing), the others below 2^31; the lift mixes them. Forced primes still come
// first (UnluckyPrimeIsDetectedAndSetAside).
TEST(Modular, TheRecordedPrimeIsBelowTwoToThe24) {
    for (const char* name : {"katsura8", "cyclic7"}) {
        SCOPED_TRACE(name);
        const auto [ideal, r, stats] = modular_on_bench_case(name);
        ASSERT_TRUE(stats.certified);
        // The same basis from a recording on a 31-bit prime (forced).
        ModularOptions forced;
        forced.threads = 1;
        forced.primes = {2147483629u};
        ModularStats forced_stats;
        EXPECT_EQ(r.basis, modular_groebner(ideal.generators, forced, &forced_stats).basis);
        EXPECT_EQ(forced_stats.primes_used.front(), 2147483629u);
        ASSERT_GE(stats.primes_used.size(), 3u);
        EXPECT_LT(stats.primes_used.front(), 1u << 24);
        EXPECT_GE(stats.primes_used.front(), (1u << 24) - (1u << 21) - 1000);
        for (std::size_t i = 1; i < stats.primes_used.size(); ++i) {
            EXPECT_GE(stats.primes_used[i], (1u << 31) - (1u << 28) - 100000);
        }
        // Every later prime replays the recording, unless its replay leaves it (a coefficient
        // of the recorded rows vanishing modulo that prime, about one run in a hundred on
        // cyclic-7): that prime is then set aside, or F4 runs afresh on it.
        EXPECT_EQ(stats.replayed + stats.replays_refused, stats.primes_used.size() - 1);
    }
}

// A coefficient with a small denominator is lifted as an integer over it (D·r = a/b with b
// below 2^64, D = 1 here), which needs about half the primes of a rational reconstruction
// (|n| and d both below √(M/2)): this basis has a³ − (N/3)·b with a 5 090-bit N, which took
// 331 primes and now 172. (Hostile sizes: lattices stop past 4 096 bits of modulus, so a
// 36 000-digit constant costs no lattice reductions: 12.4 → 1.0 s.)
TEST(Modular, ASmallDenominatorNeedsHalfThePrimesOfARational) {
    const IdealFile file = parse_ideal_file("vars: a,b\na^2*b-(2*10^38)^20\na*b^3-3\n");
    ModularOptions options;
    options.threads = 1;
    ModularStats stats;
    const GroebnerResult r = modular_groebner(file.generators, options, &stats);
    ASSERT_TRUE(stats.certified);
    EXPECT_EQ(normalized(r.basis, *file.ring),
              normalized(buchberger(file.generators).basis, *file.ring));
    std::size_t largest = 0;  // numerator bits, over denominators of at most 64 bits
    for (const Polynomial& g : r.basis) {
        for (std::size_t i = 0; i < g.num_terms(); ++i) {
            const Rational& c = g.coefficient(i);
            if (fmpz_bits(fmpq_denref(c.get())) <= 64) {
                largest = std::max<std::size_t>(largest, fmpz_bits(fmpq_numref(c.get())));
            }
        }
    }
    ASSERT_GT(largest, 5000u);
    // About B + 97 bits of primes for a B-bit numerator, where rational reconstruction needs 2B.
    EXPECT_LT(stats.primes_used.size() * 31, largest * 6 / 5);
}

// F4's linear algebra on two threads (the S-halves reduced by the reducers side by side, then
// in order by the new rows) makes the same rows as on one: the same basis, the same trace (a
// replay of the two-thread trace gives the one-thread basis modulo another prime) and the same
// count of rows reduced to zero — on the literature's systems modulo 65 521 and 2³¹ − 1, and
// on random dense quadric systems.
TEST(Modular, TwoThreadsGiveTheSameF4StepsAsOne) {
    std::vector<std::pair<std::string, std::vector<Polynomial>>> systems;
    for (const char* name : {"cyclic6", "katsura7", "eco7", "noon5"}) {
        const IdealFile ideal = parse_ideal_file(
            test::read_text(test::source_dir() + "/bench/data/" + name + ".ideal"));
        systems.push_back({name, ideal.generators});
    }
    {
        const RingPtr quadrics =
            PolyRing::make({"a", "b", "c", "d", "e", "f"}, MonomialOrder::grevlex(6));
        std::mt19937_64 random(65521);
        std::uniform_int_distribution<int> coefficient(-9, 9);
        for (int trial = 0; trial < 6; ++trial) {
            std::vector<Polynomial> generators;
            for (int g = 0; g < 6; ++g) {
                std::string text = "1";
                for (int i = 0; i < 6; ++i) {
                    for (int j = i; j < 6; ++j) {
                        text += "+(" + std::to_string(coefficient(random)) + ")*" +
                                std::string(1, static_cast<char>('a' + i)) + "*" +
                                std::string(1, static_cast<char>('a' + j));
                    }
                    text += "+(" + std::to_string(coefficient(random)) + ")*" +
                            std::string(1, static_cast<char>('a' + i));
                }
                generators.push_back(parse_polynomial(text, quadrics));
            }
            systems.push_back({"random quadrics " + std::to_string(trial), generators});
        }
    }
    for (const auto& [name, generators] : systems) {
        const MonomialLayout& layout = generators.front().ring()->layout();
        for (const std::uint32_t p : {65521u, 2147483647u}) {
            modular::F4Options one, two;
            one.threads = 1;
            two.threads = 2;
            modular::F4Stats stats_one, stats_two;
            modular::F4Trace trace_one, trace_two;
            const auto alone =
                modular::f4(modulo(generators, p), layout, {p}, one, &stats_one, &trace_one);
            const auto side_by_side =
                modular::f4(modulo(generators, p), layout, {p}, two, &stats_two, &trace_two);
            ASSERT_EQ(side_by_side.size(), alone.size()) << name << " mod " << p;
            for (std::size_t i = 0; i < alone.size(); ++i) {
                EXPECT_EQ(side_by_side[i].monomials, alone[i].monomials) << name << " mod " << p;
                EXPECT_EQ(side_by_side[i].coefficients, alone[i].coefficients)
                    << name << " mod " << p;
            }
            EXPECT_EQ(stats_two.zero_rows, stats_one.zero_rows) << name << " mod " << p;
            EXPECT_EQ(stats_two.pairs_reduced, stats_one.pairs_reduced) << name << " mod " << p;
            // The traces replay alike modulo another prime (or are refused alike, when p made a
            // coefficient vanish).
            const std::uint32_t other = 2147483629u;
            const auto replayed_one =
                modular::f4_replay(trace_one, modulo(generators, other), layout, {other});
            const auto replayed_two =
                modular::f4_replay(trace_two, modulo(generators, other), layout, {other});
            ASSERT_EQ(replayed_two.has_value(), replayed_one.has_value()) << name << " mod " << p;
            if (replayed_one) {
                ASSERT_EQ(replayed_two->size(), replayed_one->size()) << name;
                for (std::size_t i = 0; i < replayed_one->size(); ++i) {
                    EXPECT_EQ((*replayed_two)[i].coefficients, (*replayed_one)[i].coefficients)
                        << name;
                }
            }
        }
    }
}

// A deadline that passes while F4's rows are reduced on two threads stops the run with Timeout,
// thrown from a worker and carried to the caller (cyclic-7's larger steps take longer than the
// deadline left).
TEST(Modular, F4OnTwoThreadsStopsAtItsDeadline) {
    const IdealFile ideal =
        parse_ideal_file(test::read_text(test::source_dir() + "/bench/data/cyclic7.ideal"));
    const MonomialLayout& layout = ideal.ring->layout();
    modular::F4Options options;
    options.threads = 2;
    options.deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(30);
    EXPECT_THROW(modular::f4(modulo(ideal.generators, 65521u), layout, {65521u}, options), Timeout);
}

// Eleven primes below 2^31 from `start` down (not a multiple of 8: the last lanes repeat one).
std::vector<std::uint32_t> primes_below(std::uint32_t start, std::size_t count) {
    std::vector<std::uint32_t> primes;
    for (std::uint32_t p = modular::previous_prime(start); primes.size() < count;
         p = modular::previous_prime(p)) {
        primes.push_back(p);
    }
    return primes;
}

TEST(Modular, ReplayOnLanesEqualsTheReplayOfEachPrime) {
    // The last: a basis without a single F4 step (its only pair is coprime), whose replay is
    // the final matrix alone (it once wrote past empty scratch vectors).
    for (const std::string name : {"cyclic5", "katsura6", "eco6", "noon4", "cyclic6", "steps0"}) {
        const IdealFile ideal = parse_ideal_file(
            name == "steps0"
                ? "vars: x,y\norder: grevlex\nx^3-y^2+x\ny^2-1\n"
                : test::read_text(test::source_dir() + "/bench/data/" + name + ".ideal"));
        const MonomialLayout& layout = ideal.ring->layout();
        modular::F4Trace trace;
        modular::f4(modulo(ideal.generators, 2147483647u), layout, {2147483647u}, {}, nullptr,
                    &trace);
        const std::vector<std::uint32_t> primes = primes_below(2000000000u, 11);
        std::vector<std::vector<modular::ModularPolynomial>> inputs;
        for (const std::uint32_t p : primes) {
            inputs.push_back(modulo(ideal.generators, p));
        }
        const modular::LaneBases batch = modular::f4_replay_lanes(trace, inputs, primes, layout);
        ASSERT_EQ(batch.size(), primes.size());
        for (std::size_t i = 0; i < primes.size(); ++i) {
            const auto one = modular::f4_replay(trace, inputs[i], layout, {primes[i]});
            ASSERT_TRUE(one.has_value()) << name << " prime " << primes[i];
            const auto lane = batch.basis(i);
            ASSERT_TRUE(batch.has(i) && lane.has_value()) << name << " prime " << primes[i];
            ASSERT_EQ(lane->size(), one->size()) << name;
            for (std::size_t e = 0; e < one->size(); ++e) {
                EXPECT_EQ((*lane)[e].monomials, (*one)[e].monomials) << name;
                EXPECT_EQ((*lane)[e].coefficients, (*one)[e].coefficients) << name;
            }
        }
    }
}

TEST(Modular, ReplayRefusesAPrimeOnWhichTheComputationDiffers) {
    // S(x² − p·y, xy − z) = −p·y² + xz: its leading monomial is y² over Q and xz modulo p, so
    // a trace recorded modulo another prime does not fit p. The inputs' leading coefficients
    // are 1, so nothing sets p aside before F4.
    const std::uint32_t p = 2147483629u, other = 2147483647u;
    const IdealFile ideal =
        parse_ideal_file("vars: x,y,z\norder: grevlex\nx^2-" + std::to_string(p) + "*y\nx*y-z\n");
    const MonomialLayout& layout = ideal.ring->layout();
    modular::F4Trace trace;
    modular::f4(modulo(ideal.generators, other), layout, {other}, {}, nullptr, &trace);
    EXPECT_FALSE(modular::f4_replay(trace, modulo(ideal.generators, p), layout, {p}).has_value());
    // On lanes, that prime leaves the batch and the others go on.
    const std::vector<std::uint32_t> batch_primes = {2147483587u, p, 2147483579u};
    std::vector<std::vector<modular::ModularPolynomial>> inputs;
    for (const std::uint32_t q : batch_primes) {
        inputs.push_back(modulo(ideal.generators, q));
    }
    const modular::LaneBases batch = modular::f4_replay_lanes(trace, inputs, batch_primes, layout);
    EXPECT_TRUE(batch.has(0) && batch.basis(0).has_value());
    EXPECT_FALSE(batch.has(1) || batch.basis(1).has_value());
    EXPECT_TRUE(batch.has(2) && batch.basis(2).has_value());
    // The multi-modular driver then sets that prime aside, and the lift still gives the
    // rational basis.
    ModularOptions options;
    options.primes = {other, p};
    ModularStats stats;
    const GroebnerResult r = modular_groebner(ideal.generators, options, &stats);
    const std::string expected = normalized(buchberger(ideal.generators).basis, *ideal.ring);
    EXPECT_EQ(normalized(r.basis, *ideal.ring), expected);
    EXPECT_EQ(stats.replays_refused, 1u);
    EXPECT_EQ(stats.replays_refused_set_aside, 1u);
    EXPECT_TRUE(stats.certified);
    // Recorded on the unlucky prime, the trace fits no other: after one prime set aside, F4
    // runs afresh on the next refused one and is recorded, the primes after it replay that
    // recording, and the vote between the groups gives the basis. (Before, every later prime
    // ran F4 afresh: cyclic-8 once took 86 s instead of 13 so.)
    options.primes = {p, other};
    ModularStats unlucky_first;
    const GroebnerResult r3 = modular_groebner(ideal.generators, options, &unlucky_first);
    EXPECT_EQ(normalized(r3.basis, *ideal.ring), expected);
    EXPECT_GE(unlucky_first.replays_refused, 2u);
    EXPECT_EQ(unlucky_first.replays_refused_set_aside, 1u);
    EXPECT_EQ(unlucky_first.traces_recorded, 2u);
    EXPECT_GE(unlucky_first.replayed, 1u);
    EXPECT_TRUE(unlucky_first.certified);
    // Batches replayed side by side on two threads: the same basis.
    options.primes = {other, p};
    options.threads = 2;
    const GroebnerResult r4 = modular_groebner(ideal.generators, options);
    EXPECT_EQ(normalized(r4.basis, *ideal.ring), expected);
    options.threads = 1;
    // Without tracing, the same basis.
    options.trace = false;
    ModularStats untraced;
    const GroebnerResult r2 = modular_groebner(ideal.generators, options, &untraced);
    EXPECT_EQ(normalized(r2.basis, *ideal.ring), normalized(r.basis, *ideal.ring));
    EXPECT_EQ(untraced.replayed, 0u);
}

// Progress of the modular route: F4's steps on the first prime, then the primes, then the
// certification's S-pairs up to all of them; on two threads the calls never overlap.
TEST(Modular, ProgressReportsEveryStageOneCallAtATime) {
    const IdealFile ideal =
        parse_ideal_file(test::read_text(test::source_dir() + "/bench/data/cyclic6.ideal"));
    for (const int threads : {1, 2}) {
        using Stage = GroebnerProgress::Stage;
        std::vector<Stage> stages;
        std::size_t last_done = 0, total = 0, primes = 0;
        std::atomic<int> inside{0};
        bool overlapped = false;
        ModularOptions options;
        options.threads = threads;
        options.progress = [&](const GroebnerProgress& p) {
            overlapped = overlapped || inside.fetch_add(1) != 0;
            EXPECT_NE(p.stage, Stage::pairs);
            if (stages.empty() || stages.back() != p.stage) {
                stages.push_back(p.stage);
            }
            if (p.stage == Stage::primes) {
                EXPECT_GT(p.pairs_done, primes);
                primes = p.pairs_done;
            }
            if (p.stage == Stage::certification) {
                last_done = std::max(last_done, p.pairs_done);
                total = p.pairs_done + p.pairs_left;
            }
            inside.fetch_sub(1);
        };
        ModularStats stats;
        const GroebnerResult r = modular_groebner(ideal.generators, options, &stats);
        ASSERT_EQ(r.outcome, GroebnerOutcome::complete);
        EXPECT_FALSE(overlapped) << threads;
        ASSERT_GE(stages.size(), 3u) << threads;
        EXPECT_EQ(stages.front(), Stage::f4);
        EXPECT_EQ(stages.back(), Stage::certification);
        EXPECT_NE(std::find(stages.begin(), stages.end(), Stage::primes), stages.end());
        EXPECT_EQ(primes, stats.primes_used.size() - 1);  // the last prime confirms, then certifies
        EXPECT_GT(total, 0u);
        EXPECT_EQ(last_done, total) << threads;
    }
}

}  // namespace
}  // namespace locus::algebra
