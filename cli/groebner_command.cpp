// `locus groebner FILE`: the reduced Gröbner basis of an ideal file, normalized, on stdout.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <thread>

#include "algebra/error.h"
#include "algebra/groebner.h"
#include "algebra/groebner/verify.h"
#include "algebra/print.h"
#include "cli/choices.h"
#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "cli/heap_pages.h"
#include "cli/process_limits.h"

namespace locus::cli {
namespace {

struct GroebnerArgs {
    std::string file;
    std::optional<std::string> order;
    std::string format = "normalized";
    std::string selection = "auto";
    std::string algorithm = "auto";
    std::optional<std::uint32_t> prime;  // for --algorithm f4 (default 2³¹ − 1)
    bool no_certify = false;
    bool stats = false;
    bool check = false;
    ProcessLimitArgs limits;
    int threads = 0;  // signature batches, the modular route, GF(p); 0 = all hardware threads
};

void print_modular_stats(const algebra::ModularStats& s) {
    std::fprintf(stderr,
                 "primes used: %zu (unlucky, set aside: %zu; F4 replayed from a recorded "
                 "trace: %zu, recordings: %zu, replays refused: %zu, of which set aside: %zu)\n"
                 "F4 on the first prime: %zu steps, %zu pairs reduced, %zu rows reduced to zero, "
                 "largest matrix %zu x %zu (%.2f %% non-zero), symbolic preprocessing %.6f s, "
                 "linear algebra %.6f s\n"
                 "time: F4 %.6f s over all primes (replays %.6f s each), lifting %.6f s (lattices "
                 "%.6f s), certification %.6f s\n%s\n",
                 s.primes_used.size(), s.unlucky_primes, s.replayed, s.traces_recorded,
                 s.replays_refused, s.replays_refused_set_aside, s.f4.steps, s.f4.pairs_reduced,
                 s.f4.zero_rows, s.f4.largest_rows, s.f4.largest_columns,
                 100.0 * s.f4.largest_density, s.f4.symbolic_seconds, s.f4.linear_algebra_seconds,
                 s.modular_seconds, s.replayed > 0 ? s.replay_seconds / s.replayed : 0.0,
                 s.lift_seconds, s.lattice_seconds, s.certify_seconds,
                 s.certified ? "certified over Q: the input reduces to zero and every S-pair "
                               "left by the criteria reduces to zero"
                             : "NOT certified (--no-certify): the basis is probabilistic");
    if (!s.probe.empty()) {
        std::fprintf(stderr, "auto's probe: %s (%.6f s)\n", s.probe.c_str(), s.probe_seconds);
    }
    if (s.certified) {
        const algebra::CertificationWork& work = s.certification;
        std::fprintf(stderr, "certification: %zu reduction steps", work.reduction_steps);
        if (work.lanes > 0) {
            std::fprintf(stderr,
                         " on residues modulo %zu primes (%s kernels; %zu reductions begun again "
                         "on more, %zu rebuilds in full; %zu reducer terms on %.1f lanes on "
                         "average, each read for %.1f reductions, %zu columns)",
                         work.lanes, algebra::certification_kernels(), work.lane_restarts,
                         work.rebuilds, work.reducer_terms,
                         work.reducer_terms > 0 ? static_cast<double>(work.lane_terms) /
                                                      static_cast<double>(work.reducer_terms)
                                                : 0.0,
                         work.row_terms > 0 ? static_cast<double>(work.reducer_terms) /
                                                  static_cast<double>(work.row_terms)
                                            : 0.0,
                         work.columns);
        }
        std::fprintf(stderr, "%s\n",
                     work.exact_fallback
                         ? (work.lanes > 0 ? ", then on GMP integers" : " on GMP integers")
                         : "");
    }
    if (s.equality) {
        const algebra::IdealEquality& e = *s.equality;
        std::fprintf(stderr, "ideal equality: %s: %s (%.6f s)%s\n",
                     algebra::ideal_equality_status_name(e.status), e.argument.c_str(), e.seconds,
                     e.status == algebra::IdealEquality::Status::proven
                         ? ""
                         : "; that the basis generates no more than the input rests on a lucky "
                           "prime (Arnold's theorem)");
    }
}

void print_stats(const algebra::GroebnerAnswer& answer, const algebra::PolyRing& ring) {
    const auto& s = answer.stats;
    std::fprintf(stderr, "order: %s\nbasis size: %zu\npairs created: %zu\n",
                 ring.order().to_string(ring.variable_names()).c_str(), answer.basis.size(),
                 s.pairs_created);
    if (s.algorithm == algebra::GroebnerAlgorithm::signature) {
        std::fprintf(stderr, "removed as syzygies: %zu\nremoved by rewriting: %zu\n",
                     s.removed_by_syzygy, s.removed_by_rewriting);
        if (s.batched_signatures > 0) {
            std::fprintf(stderr, "signatures attempted side by side: %zu\n", s.batched_signatures);
        }
    } else {
        std::fprintf(stderr, "removed by product criterion: %zu\nremoved by chain criterion: %zu\n",
                     s.removed_by_product, s.removed_by_chain);
    }
    std::fprintf(stderr,
                 "S-polynomials reduced: %zu\nreductions to zero: %zu\nreduction steps: "
                 "%zu\nlargest intermediate basis: %zu\ntime: %.6f s\n",
                 s.reductions, s.zero_reductions, s.reduction_steps, s.max_basis_size, s.seconds);
}

void print_modulo_stats(const algebra::GroebnerAnswer& answer) {
    const algebra::modular::F4Stats& f4 = *answer.f4;
    std::fprintf(stderr,
                 "basis over GF(%u), computed there (no lifting): %zu elements, %zu F4 steps, "
                 "largest matrix %zu x %zu, symbolic %.6f s, linear algebra %.6f s\n",
                 answer.characteristic, answer.basis.size(), f4.steps, f4.largest_rows,
                 f4.largest_columns, f4.symbolic_seconds, f4.linear_algebra_seconds);
}

void print_answer_stats(const algebra::GroebnerAnswer& answer, const algebra::PolyRing& ring) {
    if (answer.f4) {
        print_modulo_stats(answer);
        return;
    }
    const auto algorithm = answer.stats.algorithm;
    std::fprintf(stderr, "algorithm: %s\n",
                 algorithm == algebra::GroebnerAlgorithm::modular ? "modular (multi-modular F4)"
                 : algorithm == algebra::GroebnerAlgorithm::signature
                     ? "signature (SB, Schreyer order)"
                     : "buchberger");
    print_stats(answer, ring);
    if (answer.modular) {
        print_modular_stats(*answer.modular);
    }
}

// --check: independent verification, over Q or modulo the answer's characteristic (there it
// shows a Gröbner basis of an ideal containing the input; F4 modulo p keeps no cofactors).
void check_answer(const GroebnerArgs& args, const algebra::GroebnerAnswer& answer,
                  const algebra::IdealFile& ideal, const Deadline& deadline) {
    const std::uint32_t p = answer.characteristic;
    algebra::BasisCheck check;
    try {
        check = p != 0 ? algebra::check_groebner_basis_modulo(answer.basis, ideal.generators, p,
                                                              deadline)
                       : algebra::check_groebner_basis(answer.basis, ideal.generators);
    } catch (const Timeout&) {
        throw CommandFailure(exit_timeout,
                             "timeout: the check stopped after " + timeout_text(args.limits));
    }
    if (!check.ok) {
        throw CommandFailure(exit_check_failed, "check: FAILED: " + check.failure);
    }
    if (!algebra::is_reduced(answer.basis)) {
        throw CommandFailure(exit_check_failed, "check: FAILED: the basis is not reduced");
    }
    if (p != 0) {
        std::fprintf(stderr,
                     "check: ok modulo %u (%zu generators and %zu S-pairs reduce to zero; the "
                     "basis is reduced; it is not checked to lie in the input's ideal)\n",
                     p, check.generators_checked, check.pairs_checked);
    } else {
        std::fprintf(stderr,
                     "check: ok (%zu generators and %zu S-pairs reduce to zero; the basis is "
                     "reduced)\n",
                     check.generators_checked, check.pairs_checked);
    }
}

// The flags as a request of the library's entry point (algebra/groebner.h). An input with a
// characteristic, and --algorithm f4 (modulo --prime, by default 2^31 - 1), compute over GF(p)
// directly; nothing is lifted there, so nothing needs certifying.
algebra::GroebnerRequest request_of(const GroebnerArgs& args, const algebra::IdealFile& ideal,
                                    const Deadline& deadline) {
    algebra::GroebnerRequest request;
    request.algorithm = *algebra::parse_algorithm(args.algorithm);  // a CLI11 choice
    const std::uint32_t file_p = ideal.characteristic;
    if (file_p != 0 && args.algorithm != "auto" && args.algorithm != "f4") {
        throw CommandFailure(exit_input, "--algorithm " + args.algorithm +
                                             " computes over Q, and the input has characteristic " +
                                             std::to_string(file_p) + ": use auto or f4");
    }
    if (file_p != 0 && args.prime && *args.prime != file_p) {
        throw CommandFailure(exit_input, "--prime " + std::to_string(*args.prime) +
                                             ": the input has characteristic " +
                                             std::to_string(file_p));
    }
    if (args.prime && file_p == 0 && args.algorithm != "f4") {
        throw CommandFailure(exit_input, "--prime " + std::to_string(*args.prime) +
                                             ": applies to --algorithm f4 (or write the "
                                             "characteristic into the input)");
    }
    if (file_p != 0) {
        request.characteristic = file_p;
    } else if (args.algorithm == "f4") {
        request.characteristic = args.prime.value_or(2147483647u);
    }
    if (args.selection == "normal") {
        request.selection = algebra::SelectionStrategy::normal;
    } else if (args.selection == "sugar") {
        request.selection = algebra::SelectionStrategy::sugar;
    } else if (args.selection == "degree") {
        request.selection = algebra::SelectionStrategy::degree;
    }
    request.deadline = deadline;
    if (args.threads < 0) {
        throw CommandFailure(exit_input, "--threads " + std::to_string(args.threads) +
                                             ": expected a positive count, or 0 for all cores");
    }
    request.certify = !args.no_certify;
    request.threads = args.threads > 0
                          ? args.threads
                          : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    return request;
}

int run_groebner(const GroebnerArgs& args, ProgressLine& progress) {
    const Deadline deadline = apply_process_limits(args.limits);
    const algebra::OutputFormat format = [&] {
        try {
            return algebra::parse_output_format(args.format);
        } catch (const Error& e) {
            throw CommandFailure(exit_input, e.what());
        }
    }();
    algebra::IdealFile ideal = read_ideal(args.file, args.order);
    algebra::GroebnerRequest request = request_of(args, ideal, deadline);
    // The oneTBB threads' heaps too (heap_pages.h) only for the computations that are long:
    // `auto`'s large shape (katsura-9, 0.27 s, is below it; katsura-10, cyclic-7, eco-10 above).
    const bool long_computation = algebra::automatic_shape(ideal.generators) > algebra::kLargeShape;
    use_large_pages_for_heap(long_computation ? request.threads : 1);
    if (request.characteristic == 0) {
        request.progress = progress.groebner("groebner");
    }
    algebra::GroebnerAnswer answer;
    try {
        answer = algebra::groebner(ideal.generators, request);
    } catch (const InputError& e) {
        progress.clear();
        throw CommandFailure(exit_input, e.what());
    }
    progress.clear();
    if (answer.outcome == algebra::GroebnerOutcome::unable) {
        throw CommandFailure(exit_resource, answer.reason);
    }
    if (answer.outcome == algebra::GroebnerOutcome::stopped_timeout) {
        if (args.stats && !answer.f4) {
            print_stats(answer, *ideal.ring);
        }
        if (answer.f4) {
            throw CommandFailure(exit_timeout,
                                 "timeout: F4 stopped after " + timeout_text(args.limits));
        }
        if (answer.algorithm == algebra::Algorithm::modular) {
            throw CommandFailure(exit_timeout, "timeout: the modular algorithm stopped after " +
                                                   timeout_text(args.limits));
        }
        throw CommandFailure(exit_timeout, "timeout: stopped after " + timeout_text(args.limits) +
                                               " with " + std::to_string(answer.basis.size()) +
                                               " basis elements; the basis is not complete");
    }
    std::cout << algebra::format_polynomials(answer.basis, *ideal.ring, format, "G",
                                             answer.characteristic);
    std::cout.flush();
    if (args.stats) {
        print_answer_stats(answer, *ideal.ring);
    }
    if (args.check) {
        check_answer(args, answer, ideal, deadline);
    }
    return exit_ok;
}

}  // namespace

void add_groebner_command(CLI::App& app, CommandContext& context) {
    auto args = std::make_shared<GroebnerArgs>();
    CLI::App* cmd = app.add_subcommand(
        "groebner", "Reduced Gröbner basis of an ideal file, one polynomial a line");
    cmd->add_option("file", args->file,
                    "ideal file, or msolve's format (.ms); - for standard input")
        ->required();
    cmd->add_option("--order", args->order,
                    "override the file's order: lex, grlex, grevlex, weights(..), elim(..), "
                    "matrix(..)");
    add_choice(cmd, "--format", args->format, output_format_choices(), "output");
    add_choice(cmd, "--selection", args->selection,
               {{"auto", "the default"}, {"sugar", ""}, {"degree", ""}, {"normal", ""}},
               "Buchberger's pair selection");
    add_choice(cmd, "--algorithm", args->algorithm,
               {{"auto",
                 "the default: modular for large systems (by Bezout's bound), else "
                 "signature within a budget of work, then modular"},
                {"buchberger", ""},
                {"signature", "signature-based, over Q"},
                {"f4", "the basis modulo --prime (the input's characteristic when it has one)"},
                {"modular", "multi-modular F4 over Q, certified"}},
               "the algorithm");
    cmd->add_option("--prime", args->prime,
                    "the prime below 2^31 of --algorithm f4 (2147483647); an input with a "
                    "characteristic computes modulo that one");
    cmd->add_flag("--no-certify", args->no_certify,
                  "modular: skip the exact certification (the result is then probabilistic)");
    cmd->add_flag("--stats", args->stats, "print statistics to standard error");
    cmd->add_flag("--check", args->check,
                  "verify independently: generators and S-pairs reduce to zero, basis reduced");
    add_process_limit_options(cmd, args->limits);
    cmd->add_option("--threads", args->threads,
                    "threads for the signature algorithm (a degree's signatures side by side) "
                    "and the modular route — F4's linear algebra, the replays on other primes, "
                    "the certification — and over GF(p) (0: all cores, the default; the "
                    "benchmarks use 1)");
    cmd->callback([args, &context] { context.exit_code = run_groebner(*args, context.progress); });
}

}  // namespace locus::cli
