// `locus-bench groebner`: times the Gröbner suite (bench/data/SUITE.txt) and, when Singular and
// Giac are on the PATH, Singular's `std` and Giac's `gbasis` on the same ideals in the same run,
// with the ratios. Each side is repeated until --min-seconds have passed (at most kMaxRuns
// runs) and the mean run is reported, so that millisecond cases are not lost in timer noise.
#include <algorithm>
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
#include "bench/giac.h"
#include "bench/singular.h"
#include "cli/choices.h"
#include "cli/command_support.h"
#include "cli/heap_pages.h"

namespace locus::bench {
namespace {

struct GroebnerBenchArgs {
    SuiteOptions suite;
    std::string algorithm = "auto";  // as `locus groebner --algorithm`
    std::string singular = "Singular";
    std::string giac = "giac";
    int threads = 1;          // locus's and Giac's
    double giac_limit = 600;  // seconds before a Giac run is killed
};

// The geometric mean and the worst of a column of ratios.
struct RatioSummary {
    double log_sum = 0, worst = 0;
    int count = 0;
    void add(double ratio) {
        if (std::isfinite(ratio)) {
            log_sum += std::log(ratio);
            ++count;
            worst = std::max(worst, ratio);
        }
    }
};

int run_groebner_bench(const GroebnerBenchArgs& args) {
    check_suite_options(args.suite);
    // As `locus groebner` does for long computations (every case of more than one thread in
    // docs/performance.md is one); for the suite's small cases it also advises the worker
    // threads' heaps, which `locus groebner` leaves, a difference of the process's start only.
    cli::use_large_pages_for_heap(args.threads);
    const std::vector<std::string> cases = suite_case_names(args.suite.data_dir, args.suite.cases);
    const bool with_singular = args.singular != "off" && cli::on_path(args.singular);
    const bool with_giac = args.giac != "off" && cli::on_path(args.giac);
    if (args.suite.csv) {
        std::cout << "case,order,vars,seconds,runs,pairs,zero_reductions,basis_size"
                  << (with_singular ? ",singular_seconds,ratio" : "")
                  << (with_giac ? ",giac_seconds,giac_ratio" : "") << "\n";
    } else {
        std::printf("%-22s %-14s %12s %12s %8s %12s %8s %7s %6s %6s\n", "case", "order", "locus s",
                    "singular s", "ratio", "giac s", "ratio", "pairs", "zero", "basis");
    }
    RatioSummary singular_ratios, giac_ratios;
    auto cell = [](double value, std::size_t width) {
        return value > 0 && std::isfinite(value) ? std::to_string(value).substr(0, width)
                                                 : std::string("-");
    };
    for (const auto& name : cases) {
        const algebra::IdealFile ideal =
            cli::read_ideal(args.suite.data_dir + "/" + name + ".ideal");
        Timing mine;
        algebra::GroebnerRequest request;
        request.algorithm = *algebra::parse_algorithm(args.algorithm);  // a CLI11 choice
        request.characteristic = ideal.characteristic;                  // over GF(p): F4 modulo p
        request.threads = args.threads;
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
        Timing theirs{-1, 0}, giac{-1, 0};
        if (with_singular) {
            theirs = time_singular_std(args.singular, ideal, args.suite.min_seconds);
        }
        if (with_giac) {
            giac = time_giac_gbasis(args.giac, ideal, args.threads, args.giac_limit);
        }
        const double ratio = theirs.seconds > 0 ? mine.seconds / theirs.seconds : NAN;
        const double giac_ratio = giac.seconds > 0 ? mine.seconds / giac.seconds : NAN;
        singular_ratios.add(ratio);
        giac_ratios.add(giac_ratio);
        if (args.suite.csv) {
            std::cout << name << ",\"" << order << "\"," << ideal.ring->num_vars() << ","
                      << mine.seconds << "," << mine.runs << "," << result.stats.pairs_created
                      << "," << result.stats.zero_reductions << "," << result.basis.size();
            if (with_singular) {
                std::cout << "," << theirs.seconds << "," << ratio;
            }
            if (with_giac) {
                std::cout << "," << giac.seconds << "," << giac_ratio;
            }
            std::cout << "\n";
        } else {
            std::printf("%-22s %-14s %12.6f %12s %8s %12s %8s %7zu %6zu %6zu\n", name.c_str(),
                        order.c_str(), mine.seconds, cell(theirs.seconds, 10).c_str(),
                        cell(ratio, 7).c_str(), cell(giac.seconds, 10).c_str(),
                        cell(giac_ratio, 7).c_str(), result.stats.pairs_created,
                        result.stats.zero_reductions, result.basis.size());
        }
        std::cout.flush();
    }
    FILE* summary = args.suite.csv ? stderr : stdout;
    if (singular_ratios.count > 0) {
        std::fprintf(summary,
                     "geometric-mean ratio locus/Singular: %.3f over %d cases; worst %.3f\n",
                     std::exp(singular_ratios.log_sum / singular_ratios.count),
                     singular_ratios.count, singular_ratios.worst);
    } else if (!with_singular && args.singular != "off") {
        std::fprintf(stderr, "Singular not found: no ratios (install Debian's singular)\n");
    }
    if (giac_ratios.count > 0) {
        std::fprintf(summary, "geometric-mean ratio locus/Giac: %.3f over %d cases; worst %.3f\n",
                     std::exp(giac_ratios.log_sum / giac_ratios.count), giac_ratios.count,
                     giac_ratios.worst);
    } else if (!with_giac && args.giac != "off") {
        std::fprintf(stderr, "giac not found: no Giac ratios (install Debian's xcas)\n");
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
    cmd->add_option("--giac", args->giac,
                    "Giac executable (Debian's xcas) for the second same-run reference, or 'off'");
    cmd->add_option("--threads", args->threads, "threads for locus and Giac (Singular has one)")
        ->check(CLI::Range(1, 256));
    cmd->add_option("--giac-limit", args->giac_limit,
                    "seconds before a Giac run is stopped (its column then shows '-')")
        ->check(CLI::PositiveNumber);
}

}  // namespace locus::bench
