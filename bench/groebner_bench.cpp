// `locus-bench groebner`: times the Gröbner suite (bench/data/SUITE.txt) and, when Singular is on
// the PATH, Singular's `std` on the same ideals in the same run, with the ratio. Each side is
// repeated until --min-seconds have passed (at most kMaxRuns runs) and the mean run is
// reported, so that millisecond cases are not lost in timer noise.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "algebra/groebner.h"
#include "bench/bench_options.h"
#include "bench/benches.h"
#include "bench/singular.h"
#include "cli/choices.h"
#include "cli/command_support.h"

namespace locus::bench {
namespace {

struct GroebnerBenchArgs {
    SuiteOptions suite;
    std::string algorithm = "auto";  // as `locus groebner --algorithm`
    std::string singular = "Singular";
};

int run_groebner_bench(const GroebnerBenchArgs& args) {
    check_suite_options(args.suite);
    const std::vector<std::string> cases = suite_case_names(args.suite.data_dir, args.suite.cases);
    const bool with_singular = args.singular != "off" && cli::on_path(args.singular);
    if (args.suite.csv) {
        std::cout << "case,order,vars,seconds,runs,pairs,zero_reductions,basis_size"
                  << (with_singular ? ",singular_seconds,ratio" : "") << "\n";
    } else {
        std::printf("%-22s %-14s %12s %12s %8s %7s %6s %6s\n", "case", "order", "locus s",
                    "singular s", "ratio", "pairs", "zero", "basis");
    }
    double log_ratio_sum = 0;
    int ratio_count = 0;
    double worst_ratio = 0;
    for (const auto& name : cases) {
        const algebra::IdealFile ideal =
            cli::read_ideal(args.suite.data_dir + "/" + name + ".ideal");
        Timing mine;
        algebra::GroebnerRequest request;
        request.algorithm = *algebra::parse_algorithm(args.algorithm);  // a CLI11 choice
        request.characteristic = ideal.characteristic;                  // over GF(p): F4 modulo p
        algebra::GroebnerAnswer result;
        const auto start = std::chrono::steady_clock::now();
        do {
            result = algebra::groebner(ideal.generators, request);
            ++mine.runs;
            mine.seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        } while (mine.seconds < args.suite.min_seconds && mine.runs < kMaxRuns);
        mine.seconds /= mine.runs;
        const std::string order = ideal.ring->order().to_string(ideal.ring->variable_names());
        Timing theirs{-1, 0};
        if (with_singular) {
            theirs = time_singular_std(args.singular, ideal, args.suite.min_seconds);
        }
        const double ratio = theirs.seconds > 0 ? mine.seconds / theirs.seconds : NAN;
        if (std::isfinite(ratio)) {
            log_ratio_sum += std::log(ratio);
            ++ratio_count;
            worst_ratio = std::max(worst_ratio, ratio);
        }
        if (args.suite.csv) {
            std::cout << name << ",\"" << order << "\"," << ideal.ring->num_vars() << ","
                      << mine.seconds << "," << mine.runs << "," << result.stats.pairs_created
                      << "," << result.stats.zero_reductions << "," << result.basis.size();
            if (with_singular) {
                std::cout << "," << theirs.seconds << "," << ratio;
            }
            std::cout << "\n";
        } else {
            std::printf(
                "%-22s %-14s %12.6f %12s %8s %7zu %6zu %6zu\n", name.c_str(), order.c_str(),
                mine.seconds, theirs.seconds > 0 ? std::to_string(theirs.seconds).c_str() : "-",
                std::isfinite(ratio) ? std::to_string(ratio).substr(0, 7).c_str() : "-",
                result.stats.pairs_created, result.stats.zero_reductions, result.basis.size());
        }
        std::cout.flush();
    }
    if (ratio_count > 0) {
        std::fprintf(args.suite.csv ? stderr : stdout,
                     "geometric-mean ratio locus/Singular: %.3f over %d cases; worst %.3f\n",
                     std::exp(log_ratio_sum / ratio_count), ratio_count, worst_ratio);
    } else if (!with_singular && args.singular != "off") {
        std::fprintf(stderr, "Singular not found: no ratios (install Debian's singular)\n");
    }
    return cli::exit_ok;
}

}  // namespace

void add_groebner_bench(CLI::App& app, cli::CommandContext& context) {
    auto args = std::make_shared<GroebnerBenchArgs>();
    CLI::App* cmd = add_suite_command(
        app, context, "groebner",
        "Gröbner bases of the suite (bench/data/SUITE.txt) against Singular's std", args,
        run_groebner_bench);
    cli::add_choice(cmd, "--algorithm", args->algorithm,
                    {{"auto", "the default"},
                     {"buchberger", ""},
                     {"signature", ""},
                     {"modular", "certified; over GF(p), F4 modulo p"}},
                    "the algorithm, as `locus groebner --algorithm`");
    cmd->add_option("--singular", args->singular,
                    "Singular executable for the same-run reference, or 'off'");
}

}  // namespace locus::bench
