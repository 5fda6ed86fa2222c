// Differential checks on small ideal files:
//  - parse → print → parse is a fixpoint (to_ideal_file of the reparsed ideal is the same text,
//    orders included);
//  - for tiny ideals (≤ 3 variables, ≤ 4 generators of degree ≤ 4), the reduced Gröbner bases
//    of Buchberger's algorithm, the signature algorithm (on one and two threads, with the same
//    decisions) and the certified multi-modular F4 agree (each is unique, so any difference is
//    a bug in one of them), and the proof of ideal equality (modular/ideal_equality.h) never
//    refutes Buchberger's basis; for a tiny ideal with a `characteristic:` line, the basis F4
//    computes modulo p passes the independent check modulo p (groebner/verify.h), which shares
//    no code with F4.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <flint/fmpz.h>

#include "algebra/error.h"
#include "algebra/groebner/buchberger.h"
#include "algebra/groebner/signature_groebner.h"
#include "algebra/groebner/verify.h"
#include "algebra/modular/modular_groebner.h"
#include "algebra/parse.h"
#include "algebra/print.h"
#include "tests/fuzz/fuzz_input.h"

namespace {

using locus::algebra::GroebnerOutcome;
using locus::algebra::Polynomial;

std::string text_of(const std::vector<Polynomial>& basis) {
    std::string text;
    for (const Polynomial& g : basis) {
        text += locus::algebra::to_string(g);
        text += '\n';
    }
    return text;
}

bool tiny(const locus::algebra::IdealFile& file) {
    if (file.ring->num_vars() > 3 || file.generators.empty() || file.generators.size() > 4) {
        return false;
    }
    for (const Polynomial& g : file.generators) {
        if (g.total_degree() > 4 || g.num_terms() > 8) {
            return false;
        }
    }
    return true;
}

// Coefficients of more than 2¹⁶ bits (about 20 000 digits), which a few bytes such as
// `2e123^30000` build: printing 3.7 million digits and reading them back took 4.5 s in release
// and over 10 s under the sanitizers, the whole of this target's time limit, and the
// algorithms' work on them is big-number arithmetic that this target does not compare. That
// such inputs stop at --timeout is the job of the deadline tests (cli.hostile_input,
// Groebner.APartialBasisOfHugeCoefficientsIsReturnedAtTheDeadline).
bool has_giant_coefficient(const locus::algebra::IdealFile& file) {
    for (const Polynomial& g : file.generators) {
        for (std::size_t i = 0; i < g.num_terms(); ++i) {
            if (fmpz_bits(g.coefficient(i).numerator()) > 65536 ||
                fmpz_bits(g.coefficient(i).denominator()) > 65536) {
                return true;
            }
        }
    }
    return false;
}

void compare_algorithms(const locus::algebra::IdealFile& file, std::string_view input) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    locus::algebra::GroebnerOptions options;
    options.deadline = deadline;
    const auto by_buchberger = locus::algebra::buchberger(file.generators, options);
    const auto signature = locus::algebra::signature_groebner(file.generators, options);
    if (by_buchberger.outcome != GroebnerOutcome::complete ||
        signature.outcome != GroebnerOutcome::complete) {
        return;
    }
    const std::string expected = text_of(by_buchberger.basis);
    if (text_of(signature.basis) != expected) {
        locus::fuzz::property_failed("Buchberger and the signature algorithm disagree", input);
    }
    // On two threads (batches of a degree attempted side by side) every decision is the
    // sequential one: the same basis and the same counts of each criterion's skips.
    locus::algebra::GroebnerOptions two_threads = options;
    two_threads.threads = 2;
    const auto parallel = locus::algebra::signature_groebner(
        file.generators, two_threads, locus::algebra::SignatureOrder::schreyer, 0);
    if (parallel.outcome == GroebnerOutcome::complete &&
        (text_of(parallel.basis) != expected ||
         parallel.stats.removed_by_syzygy != signature.stats.removed_by_syzygy ||
         parallel.stats.removed_by_rewriting != signature.stats.removed_by_rewriting ||
         parallel.stats.reductions != signature.stats.reductions ||
         parallel.stats.zero_reductions != signature.stats.zero_reductions ||
         parallel.stats.max_basis_size != signature.stats.max_basis_size)) {
        locus::fuzz::property_failed("the signature algorithm decides otherwise on two threads",
                                     input);
    }
    locus::algebra::ModularOptions modular_options;
    modular_options.deadline = deadline;
    modular_options.max_primes = 200;
    const auto modular = locus::algebra::modular_groebner(file.generators, modular_options);
    // A stopped run (deadline, more primes than max_primes) is an outcome, not an answer.
    if (modular.outcome == GroebnerOutcome::complete && text_of(modular.basis) != expected) {
        locus::fuzz::property_failed("Buchberger and modular F4 disagree", input);
    }
    // Buchberger's basis generates the input's ideal by construction: the proof of ideal
    // equality may leave it unproven, never refute it (a false refutation would send the
    // modular route on to more primes until max_primes, an outcome the check above lets pass).
    try {
        const auto equality =
            locus::algebra::prove_ideal_equality(by_buchberger.basis, file.generators, deadline);
        if (equality.status == locus::algebra::IdealEquality::Status::refuted) {
            std::fprintf(stderr, "%s\n", equality.argument.c_str());
            locus::fuzz::property_failed("the exact basis is refuted as larger than the input",
                                         input);
        }
    } catch (const locus::Timeout&) {
    }
}

void check_prime_field(const locus::algebra::IdealFile& file, std::string_view input) {
    locus::algebra::modular::F4Options options;
    options.deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    try {
        const auto basis =
            locus::algebra::groebner_modulo(file.generators, file.characteristic, options);
        const auto check = locus::algebra::check_groebner_basis_modulo(
            basis, file.generators, file.characteristic, options.deadline);
        if (!check.ok || !locus::algebra::is_reduced(basis)) {
            std::fprintf(stderr, "%s\n", check.failure.c_str());
            locus::fuzz::property_failed("F4 modulo the characteristic fails the check", input);
        }
    } catch (const locus::Timeout&) {
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto text = locus::fuzz::input_text(data, size);
    if (!text || text->size() > 512) {
        return 0;
    }
    locus::algebra::IdealFile file;
    try {
        file = locus::algebra::parse_ideal_file(*text);
    } catch (const locus::Error&) {
        return 0;
    }
    if (has_giant_coefficient(file)) {
        return 0;
    }
    const std::string printed =
        locus::algebra::to_ideal_file(file.generators, *file.ring, file.characteristic);
    locus::algebra::IdealFile again;
    try {
        again = locus::algebra::parse_ideal_file(printed);
    } catch (const locus::Error& e) {
        locus::fuzz::property_failed("the printed ideal file does not parse", printed);
    }
    if (locus::algebra::to_ideal_file(again.generators, *again.ring, again.characteristic) !=
        printed) {
        locus::fuzz::property_failed("parse → print → parse is not a fixpoint", printed);
    }
    if (tiny(file)) {
        try {
            if (file.characteristic != 0) {
                check_prime_field(file, *text);
            } else {
                compare_algorithms(file, *text);
            }
        } catch (const locus::ExponentOverflow&) {
        }
    }
    return 0;
}
