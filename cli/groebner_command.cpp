// `locus groebner FILE`: the reduced Gröbner basis of an ideal file, normalized, on stdout.
#include <cstdio>
#include <iostream>

#include "algebra/error.h"
#include "algebra/groebner/buchberger.h"
#include "algebra/groebner/verify.h"
#include "algebra/print.h"
#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"

namespace locus::cli {
namespace {

struct GroebnerArgs {
    std::string file;
    std::optional<std::string> order;
    std::string format = "normalized";
    std::string selection = "auto";
    bool stats = false;
    bool check = false;
    double timeout_seconds = 0;
};

void print_stats(const algebra::GroebnerResult& r, const algebra::PolyRing& ring) {
    const auto& s = r.stats;
    std::fprintf(stderr,
                 "order: %s\nbasis size: %zu\npairs created: %zu\nremoved by product criterion: "
                 "%zu\nremoved by chain criterion: %zu\nS-polynomials reduced: %zu\nreductions "
                 "to zero: %zu\nreduction steps: %zu\nlargest intermediate basis: %zu\ntime: "
                 "%.6f s\n",
                 ring.order().to_string(ring.variable_names()).c_str(), r.basis.size(),
                 s.pairs_created, s.removed_by_product, s.removed_by_chain, s.reductions,
                 s.zero_reductions, s.reduction_steps, s.max_basis_size, s.seconds);
}

std::string seconds_text(double seconds) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g s", seconds);
    return buffer;
}

int run_groebner(const GroebnerArgs& args) {
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
    } else if (args.selection != "auto") {
        throw CommandFailure(exit_input, "--selection " + args.selection +
                                             ": expected auto, sugar, degree or normal");
    }
    options.deadline = deadline_after(args.timeout_seconds);
    options.progress = terminal_progress("groebner");
    algebra::GroebnerResult result = algebra::groebner(ideal.generators, options);
    finish_progress();
    if (result.outcome == algebra::GroebnerOutcome::stopped_timeout) {
        if (args.stats) {
            print_stats(result, *ideal.ring);
        }
        throw CommandFailure(exit_timeout, "timeout: stopped after " +
                                               seconds_text(args.timeout_seconds) + " with " +
                                               std::to_string(result.basis.size()) +
                                               " basis elements; the basis is not complete");
    }
    std::cout << algebra::format_polynomials(result.basis, *ideal.ring, format);
    std::cout.flush();
    if (args.stats) {
        print_stats(result, *ideal.ring);
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

void add_groebner_command(CLI::App& app, int& exit_code) {
    auto args = std::make_shared<GroebnerArgs>();
    CLI::App* cmd = app.add_subcommand(
        "groebner", "Reduced Gröbner basis of an ideal file, one polynomial a line");
    cmd->add_option("file", args->file, "ideal file (- for standard input)")->required();
    cmd->add_option("--order", args->order,
                    "override the file's order: lex, grlex, grevlex, weights(..), elim(..), "
                    "matrix(..)");
    cmd->add_option("--format", args->format, "normalized | singular | macaulay2 | latex");
    cmd->add_option("--selection", args->selection,
                    "pair selection: auto (default) | sugar | degree | normal");
    cmd->add_flag("--stats", args->stats, "print statistics to standard error");
    cmd->add_flag("--check", args->check,
                  "verify independently: generators and S-pairs reduce to zero, basis reduced");
    cmd->add_option("--timeout", args->timeout_seconds, "give up after SECONDS (exit code 3)");
    cmd->callback([args, &exit_code] { exit_code = run_groebner(*args); });
}

}  // namespace locus::cli
