// `locus groebner FILE`: the reduced Gröbner basis of an ideal file, normalized, on stdout.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <thread>

#include "algebra/error.h"
#include "algebra/groebner/buchberger.h"
#include "algebra/groebner/signature_groebner.h"
#include "algebra/groebner/verify.h"
#include "algebra/modular/modular_groebner.h"
#include "algebra/print.h"
#include "cli/choices.h"
#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
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
    int threads = 0;  // for the certification; 0 = all hardware threads
};

void print_modular_stats(const algebra::ModularStats& s) {
    std::fprintf(stderr,
                 "primes used: %zu (unlucky, set aside: %zu; F4 replayed from the first "
                 "prime's trace: %zu, replays refused: %zu)\n"
                 "F4 on the first prime: %zu steps, %zu pairs reduced, %zu rows reduced to zero, "
                 "largest matrix %zu x %zu (%.2f %% non-zero), symbolic preprocessing %.6f s, "
                 "linear algebra %.6f s\n"
                 "time: F4 %.6f s over all primes (replays %.6f s each), lifting %.6f s, "
                 "certification %.6f s\n%s\n",
                 s.primes_used.size(), s.unlucky_primes, s.replayed, s.replays_refused, s.f4.steps,
                 s.f4.pairs_reduced, s.f4.zero_rows, s.f4.largest_rows, s.f4.largest_columns,
                 100.0 * s.f4.largest_density, s.f4.symbolic_seconds, s.f4.linear_algebra_seconds,
                 s.modular_seconds, s.replayed > 0 ? s.replay_seconds / s.replayed : 0.0,
                 s.lift_seconds, s.certify_seconds,
                 s.certified ? "certified over Q: the input reduces to zero and every S-pair "
                               "left by the criteria reduces to zero"
                             : "NOT certified (--no-certify): the basis is probabilistic");
    if (s.certified) {
        std::fprintf(stderr, "certification: %zu reduction steps", s.certify_steps);
        if (s.certify_lanes > 0) {
            std::fprintf(stderr,
                         " on residues modulo %zu primes (%s kernels; %zu reductions begun again "
                         "on more, %zu rebuilds in full)",
                         s.certify_lanes, algebra::certification_kernels(), s.certify_restarts,
                         s.certify_rebuilds);
        }
        std::fprintf(stderr, "%s\n",
                     s.certify_exact
                         ? (s.certify_lanes > 0 ? ", then on GMP integers" : " on GMP integers")
                         : "");
    }
}

void print_stats(const algebra::GroebnerResult& r, const algebra::PolyRing& ring) {
    const auto& s = r.stats;
    std::fprintf(stderr, "order: %s\nbasis size: %zu\npairs created: %zu\n",
                 ring.order().to_string(ring.variable_names()).c_str(), r.basis.size(),
                 s.pairs_created);
    if (s.algorithm == algebra::GroebnerAlgorithm::signature) {
        std::fprintf(stderr, "removed as syzygies: %zu\nremoved by rewriting: %zu\n",
                     s.removed_by_syzygy, s.removed_by_rewriting);
    } else {
        std::fprintf(stderr, "removed by product criterion: %zu\nremoved by chain criterion: %zu\n",
                     s.removed_by_product, s.removed_by_chain);
    }
    std::fprintf(stderr,
                 "S-polynomials reduced: %zu\nreductions to zero: %zu\nreduction steps: "
                 "%zu\nlargest intermediate basis: %zu\ntime: %.6f s\n",
                 s.reductions, s.zero_reductions, s.reduction_steps, s.max_basis_size, s.seconds);
}

// The reduced basis over GF(p), computed there directly by the modular F4 (nothing is lifted,
// so nothing needs certifying): for an ideal file of characteristic p, or for --algorithm f4
// with --prime p on any file (the basis of its reduction modulo p). Coefficients in [0, p).
int run_groebner_modulo(const GroebnerArgs& args, const algebra::IdealFile& ideal,
                        algebra::OutputFormat format, const Deadline& deadline) {
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
    const std::uint32_t p = file_p != 0 ? file_p : args.prime.value_or(2147483647u);
    algebra::modular::F4Options f4_options;
    f4_options.deadline = deadline;
    algebra::modular::F4Stats f4_stats;
    std::vector<algebra::Polynomial> basis;
    try {
        basis = algebra::groebner_modulo(ideal.generators, p, f4_options, &f4_stats);
    } catch (const Timeout&) {
        throw CommandFailure(exit_timeout,
                             "timeout: F4 stopped after " + timeout_text(args.limits));
    } catch (const InputError& e) {
        throw CommandFailure(exit_input, e.what());
    }
    std::cout << algebra::format_polynomials(basis, *ideal.ring, format, "G", p);
    std::cout.flush();
    if (args.stats) {
        std::fprintf(stderr,
                     "basis over GF(%u), computed there (no lifting): %zu elements, %zu F4 steps, "
                     "largest matrix %zu x %zu, symbolic %.6f s, linear algebra %.6f s\n",
                     p, basis.size(), f4_stats.steps, f4_stats.largest_rows,
                     f4_stats.largest_columns, f4_stats.symbolic_seconds,
                     f4_stats.linear_algebra_seconds);
    }
    if (args.check) {
        algebra::BasisCheck check;
        try {
            check = algebra::check_groebner_basis_modulo(basis, ideal.generators, p,
                                                         f4_options.deadline);
        } catch (const Timeout&) {
            throw CommandFailure(exit_timeout,
                                 "timeout: the check stopped after " + timeout_text(args.limits));
        }
        if (!check.ok) {
            throw CommandFailure(exit_check_failed, "check: FAILED: " + check.failure);
        }
        if (!algebra::is_reduced(basis)) {
            throw CommandFailure(exit_check_failed, "check: FAILED: the basis is not reduced");
        }
        std::fprintf(stderr,
                     "check: ok modulo %u (%zu generators and %zu S-pairs reduce to zero; the "
                     "basis is reduced; it is not checked to lie in the input's ideal)\n",
                     p, check.generators_checked, check.pairs_checked);
    }
    return exit_ok;
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
    algebra::GroebnerOptions options;
    if (args.selection == "normal") {
        options.selection = algebra::SelectionStrategy::normal;
    } else if (args.selection == "sugar") {
        options.selection = algebra::SelectionStrategy::sugar;
    } else if (args.selection == "degree") {
        options.selection = algebra::SelectionStrategy::degree;
    }
    options.deadline = deadline;
    if (args.threads < 0) {
        throw CommandFailure(exit_input, "--threads " + std::to_string(args.threads) +
                                             ": expected a positive count, or 0 for all cores");
    }
    options.certify = !args.no_certify;
    options.threads = args.threads > 0
                          ? args.threads
                          : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    if (ideal.characteristic != 0 || args.algorithm == "f4") {
        return run_groebner_modulo(args, ideal, format, deadline);
    }
    algebra::GroebnerResult result;
    algebra::ModularStats modular_stats;
    bool modular = args.algorithm == "modular";
    try {
        if (modular) {
            algebra::ModularOptions modular_options;
            modular_options.deadline = options.deadline;
            modular_options.certify = !args.no_certify;
            modular_options.threads = options.threads;
            result = algebra::modular_groebner(ideal.generators, modular_options, &modular_stats);
        } else if (args.algorithm == "auto") {
            options.progress = progress.groebner("groebner");
            result =
                algebra::groebner_automatic(ideal.generators, options, &modular_stats, &modular);
            progress.clear();
        } else {
            options.progress = progress.groebner("groebner");
            result = args.algorithm == "signature"
                         ? algebra::signature_groebner(ideal.generators, options)
                         : algebra::groebner(ideal.generators, options);
            progress.clear();
        }
    } catch (const Timeout&) {
        progress.clear();
        throw CommandFailure(exit_timeout, "timeout: the modular algorithm stopped after " +
                                               timeout_text(args.limits));
    }
    if (result.outcome == algebra::GroebnerOutcome::stopped_timeout) {
        if (args.stats) {
            print_stats(result, *ideal.ring);
        }
        throw CommandFailure(exit_timeout, "timeout: stopped after " + timeout_text(args.limits) +
                                               " with " + std::to_string(result.basis.size()) +
                                               " basis elements; the basis is not complete");
    }
    std::cout << algebra::format_polynomials(result.basis, *ideal.ring, format);
    std::cout.flush();
    if (args.stats) {
        const auto algorithm = result.stats.algorithm;
        std::fprintf(stderr, "algorithm: %s\n",
                     algorithm == algebra::GroebnerAlgorithm::modular ? "modular (multi-modular F4)"
                     : algorithm == algebra::GroebnerAlgorithm::signature
                         ? "signature (SB, Schreyer order)"
                         : "buchberger");
        print_stats(result, *ideal.ring);
        if (modular) {
            print_modular_stats(modular_stats);
        }
    }
    if (args.check) {
        const algebra::BasisCheck check =
            algebra::check_groebner_basis(result.basis, ideal.generators);
        if (!check.ok) {
            throw CommandFailure(exit_check_failed, "check: FAILED: " + check.failure);
        }
        if (!algebra::is_reduced(result.basis)) {
            throw CommandFailure(exit_check_failed, "check: FAILED: the basis is not reduced");
        }
        std::fprintf(stderr,
                     "check: ok (%zu generators and %zu S-pairs reduce to zero; the basis is "
                     "reduced)\n",
                     check.generators_checked, check.pairs_checked);
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
                 "the default: signature for up to 100 ms under degree orders, 1 ms "
                 "under others, then modular"},
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
                    "threads for the certification of the modular route (0: all cores, the "
                    "default; the benchmarks use 1)");
    cmd->callback([args, &context] { context.exit_code = run_groebner(*args, context.progress); });
}

}  // namespace locus::cli
