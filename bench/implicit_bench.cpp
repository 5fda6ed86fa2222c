// `locus-bench implicit`: every case of bench/data/implicit/SUITE.txt by each route of
// `locus implicitize`, and by Singular's eliminate on the same elimination ideal when Singular is
// installed. Gröbner runs under a deadline of --limit seconds, Singular under timeout(1) with the
// same limit; `auto` is timed as `locus implicitize` runs it. A case with a `.bpt` file instead
// of a `.param` (the teapot) is a set of patches: `auto` and `dixon` are timed over all of them
// (degree and terms are the largest), the other routes are left out — per patch they take the
// minutes the bicubic row shows.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "algebra/error.h"
#include "bench/bench_options.h"
#include "bench/benches.h"
#include "bench/singular.h"
#include "cli/command_support.h"
#include "cli/heap_pages.h"
#include "implicit/bezier_patch.h"
#include "implicit/dixon.h"
#include "implicit/implicitize.h"

namespace locus::bench {
namespace {

struct ImplicitBenchArgs {
    SuiteOptions suite;
    double limit_seconds = 60;  // each route and Singular get at most this long per case
    std::string singular = "Singular";
};

std::string seconds_or_limit(double seconds, double limit) {
    if (seconds < 0) {
        return ">" + std::to_string(std::lround(limit));
    }
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6f", seconds);
    return buffer;
}

int run_implicit_bench(const ImplicitBenchArgs& args) {
    check_suite_options(args.suite);
    cli::use_large_pages_for_heap(1);  // as `locus implicitize` does
    const std::string dir = args.suite.data_dir + "/implicit";
    const std::vector<std::string> cases = suite_case_names(dir, args.suite.cases);
    const bool with_singular = args.singular != "off" && cli::on_path(args.singular);
    if (args.suite.csv) {
        std::cout << "case,degree,terms,auto_method,auto_seconds,dixon_seconds,interpolate_seconds,"
                     "groebner_seconds,resultant_seconds,singular_eliminate_seconds\n";
    } else {
        std::printf("%-28s %6s %6s %-12s %10s %10s %10s %10s %10s %10s\n", "case", "degree",
                    "terms", "auto", "auto s", "dixon s", "interp. s", "groebner s", "result. s",
                    "Singular s");
    }
    auto seconds_since = [](std::chrono::steady_clock::time_point t) {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    };
    // Each route is timed on its own; `auto` is timed as `locus implicitize` runs it
    // (implicit::implicitize_auto, under the same --limit).
    auto timed = [&](auto&& route) {
        try {
            const auto t = std::chrono::steady_clock::now();
            route();
            return seconds_since(t);
        } catch (const Error&) {
            return -1.0;  // not applicable, gave up, or ran out of time
        }
    };
    for (const auto& name : cases) {
        std::vector<implicit::Parametrization> maps;
        const bool patches = std::filesystem::exists(dir + "/" + name + ".bpt");
        if (patches) {
            for (const auto& patch :
                 implicit::parse_bpt(cli::read_input(dir + "/" + name + ".bpt"))) {
                maps.push_back(implicit::to_parametrization(patch));
            }
        } else {
            maps.push_back(
                implicit::parse_parametrization(cli::read_input(dir + "/" + name + ".param")));
        }
        const implicit::Parametrization& map = maps.front();
        algebra::GroebnerOptions options;
        std::optional<implicit::ImplicitResult> result;
        long degree = -1;
        std::size_t terms = 0;
        std::string method = "-";
        options.deadline = cli::deadline_after(args.limit_seconds);
        const double auto_seconds = timed([&] {
            for (const auto& m : maps) {
                result = implicit::implicitize_auto(m, options);
                if (result->equation) {
                    degree = std::max(degree, result->equation->total_degree());
                    terms = std::max(terms, result->equation->num_terms());
                }
                method = maps.size() > 1 ? "mixed" : result->method;
            }
        });
        options.deadline = cli::deadline_after(args.limit_seconds);
        const double dixon_seconds = timed([&] {
            for (const auto& m : maps) {
                implicit::implicitize_by_dixon(m, options.deadline);
            }
        });
        if (patches) {
            if (args.suite.csv) {
                std::cout << name << "," << degree << "," << terms << "," << method << ","
                          << auto_seconds << "," << dixon_seconds << ",-1,-1,-1,-2\n";
            } else {
                std::printf("%-28s %6ld %6zu %-12s %10s %10s %10s %10s %10s %10s\n",
                            (name + " (" + std::to_string(maps.size()) + " patches)").c_str(),
                            degree, terms, method.c_str(),
                            seconds_or_limit(auto_seconds, args.limit_seconds).c_str(),
                            seconds_or_limit(dixon_seconds, args.limit_seconds).c_str(), "-", "-",
                            "-", "-");
            }
            std::cout.flush();
            continue;
        }
        const double interpolate_seconds = [&] {
            options.deadline = cli::deadline_after(args.limit_seconds);
            return timed([&] { implicit::implicitize_by_interpolation(map, options.deadline); });
        }();
        // FLINT's resultants cannot be interrupted (the bicubic patch runs for many minutes):
        // time them in a child process that is killed at the limit.
        const double resultant_seconds = [&] {
            // In a child process: FLINT's resultants have no deadline of their own.
            const cli::ChildOutcome outcome = cli::run_in_child(args.limit_seconds, [&] {
                implicit::implicitize_by_resultant(map);
                return std::string();
            });
            return outcome.text ? outcome.seconds : -1.0;
        }();
        options.deadline = cli::deadline_after(args.limit_seconds);
        const double groebner_seconds = timed([&] { implicit::implicitize(map, options); });
        const double singular_seconds =
            with_singular ? time_singular_eliminate(args.singular, map, args.limit_seconds) : -2;
        const std::string singular_text =
            singular_seconds == -2 ? "-" : seconds_or_limit(singular_seconds, args.limit_seconds);
        auto shown = [&](double seconds) {
            return seconds < 0 ? std::string("-") : seconds_or_limit(seconds, 0);
        };
        if (args.suite.csv) {
            std::cout << name << "," << degree << "," << terms << "," << method << ","
                      << auto_seconds << "," << dixon_seconds << "," << interpolate_seconds << ","
                      << groebner_seconds << "," << resultant_seconds << "," << singular_seconds
                      << "\n";
        } else {
            std::printf("%-28s %6ld %6zu %-12s %10s %10s %10s %10s %10s %10s\n", name.c_str(),
                        degree, terms, method.c_str(), shown(auto_seconds).c_str(),
                        shown(dixon_seconds).c_str(), shown(interpolate_seconds).c_str(),
                        groebner_seconds < 0
                            ? (">" + std::to_string(std::lround(args.limit_seconds))).c_str()
                            : shown(groebner_seconds).c_str(),
                        resultant_seconds < 0
                            ? (">" + std::to_string(std::lround(args.limit_seconds))).c_str()
                            : shown(resultant_seconds).c_str(),
                        singular_text.c_str());
        }
        std::cout.flush();
    }
    return cli::exit_ok;
}

}  // namespace

void add_implicit_bench(CLI::App& app, cli::CommandContext& context) {
    auto args = std::make_shared<ImplicitBenchArgs>();
    CLI::App* cmd = add_suite_command(
        app, context, "implicit",
        "Implicitization of the suite (bench/data/implicit) by every route, against "
        "Singular's eliminate",
        args, run_implicit_bench);
    cmd->add_option("--limit", args->limit_seconds,
                    "give each route and Singular at most this many seconds per case (60)");
    cmd->add_option("--singular", args->singular,
                    "Singular executable for the same-run reference, or 'off'");
}

}  // namespace locus::bench
