// `locus bench groebner [--csv]`: times the Gröbner suite (bench/data/SUITE.txt) and, when
// Singular is on the PATH, Singular's `std` on the same ideals in the same run, with the ratio.
// Each side is repeated until 0.2 s have passed (at most 20 runs) and the mean run is reported,
// so that millisecond cases are not lost in timer noise. Singular's time is measured inside
// Singular with `rtimer` (microsecond ticks), so its start-up is not counted.
#include <sys/wait.h>  // for WEXITSTATUS

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

#include "algebra/error.h"
#include "algebra/groebner/buchberger.h"
#include "algebra/print.h"
#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "implicit/implicitize.h"

#ifndef LOCUS_SOURCE_DIR
#define LOCUS_SOURCE_DIR "."
#endif

namespace locus::cli {
namespace {

struct BenchArgs {
    std::string suite;
    bool csv = false;
    std::string data_dir = std::string(LOCUS_SOURCE_DIR) + "/bench/data";
    std::vector<std::string> cases;
    std::string singular = "Singular";
    double min_seconds = 0.2;
    double limit_seconds = 60;
};

struct Timing {
    double seconds = 0;
    int runs = 0;
};

bool on_path(const std::string& program) {
    if (program.find('/') != std::string::npos) {
        return std::filesystem::exists(program);
    }
    const char* path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "");
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        if (!dir.empty() && std::filesystem::exists(std::filesystem::path(dir) / program)) {
            return true;
        }
    }
    return false;
}

// Mean seconds of Singular's std (reduced basis) on the ideal, or a negative value on failure.
Timing time_singular(const std::string& singular, const algebra::IdealFile& ideal,
                     double min_seconds) {
    std::string script = "system(\"--ticks-per-sec\", 1000000);\n" +
                         algebra::singular_ring(*ideal.ring) +
                         "\noption(redSB); option(redTail);\nideal I =";
    for (std::size_t i = 0; i < ideal.generators.size(); ++i) {
        script += (i ? ",\n  " : "\n  ") + algebra::to_string(ideal.generators[i]);
    }
    const long min_us = std::lround(min_seconds * 1e6);
    script +=
        ";\nideal G; int reps = 0; int t0 = rtimer; int el = 0;\n"
        "while (1) { G = std(I); reps++; el = rtimer - t0;\n"
        "  if (el >= " +
        std::to_string(min_us) +
        " || reps >= 20) { break; } }\n"
        "print(\"LOCUSBENCH \" + string(el) + \" \" + string(reps));\nquit;\n";
    const auto path = std::filesystem::temp_directory_path() /
                      ("locus-bench-" + std::to_string(::getpid()) + ".sing");
    {
        std::ofstream out(path);
        out << script;
    }
    const std::string command = singular + " -q --no-rc " + path.string() + " </dev/null 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    Timing t{-1, 0};
    if (pipe) {
        char line[4096];
        while (std::fgets(line, sizeof line, pipe)) {
            long us = 0;
            int reps = 0;
            if (std::sscanf(line, "LOCUSBENCH %ld %d", &us, &reps) == 2 && reps > 0) {
                t = {static_cast<double>(us) / 1e6 / reps, reps};
            }
        }
        pclose(pipe);
    }
    std::filesystem::remove(path);
    return t;
}

// Seconds of Singular's `eliminate` on the elimination ideal of `map`, or -1 when Singular
// failed or took longer than `limit_seconds` (killed by timeout(1)).
double time_singular_eliminate(const std::string& singular, const implicit::Parametrization& map,
                               double limit_seconds) {
    const implicit::EliminationIdeal ideal = implicit::elimination_ideal(map);
    std::string script = "system(\"--ticks-per-sec\", 1000000);\n" +
                         algebra::singular_ring(*ideal.ring) + "\nideal I =";
    for (std::size_t i = 0; i < ideal.generators.size(); ++i) {
        script += (i ? ",\n  " : "\n  ") + algebra::to_string(ideal.generators[i]);
    }
    std::string product;
    for (const std::size_t v : ideal.eliminated) {
        if (!product.empty()) {
            product += '*';
        }
        product += ideal.ring->variable_name(v);
    }
    script += ";\nint t0 = rtimer;\nideal E = eliminate(I, " + product +
              ");\nprint(\"LOCUSBENCH \" + string(rtimer - t0) + \" 1\");\nquit;\n";
    const auto path = std::filesystem::temp_directory_path() /
                      ("locus-bench-" + std::to_string(::getpid()) + ".sing");
    {
        std::ofstream out(path);
        out << script;
    }
    const std::string command = "timeout " + std::to_string(std::lround(limit_seconds)) + " " +
                                singular + " -q --no-rc " + path.string() + " </dev/null 2>&1";
    double seconds = -1;
    if (FILE* pipe = popen(command.c_str(), "r")) {
        char line[4096];
        while (std::fgets(line, sizeof line, pipe)) {
            long us = 0;
            int reps = 0;
            if (std::sscanf(line, "LOCUSBENCH %ld %d", &us, &reps) == 2) {
                seconds = static_cast<double>(us) / 1e6;
            }
        }
        pclose(pipe);
    }
    std::filesystem::remove(path);
    return seconds;
}

std::string seconds_or_limit(double seconds, double limit) {
    if (seconds < 0) {
        return ">" + std::to_string(std::lround(limit));
    }
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6f", seconds);
    return buffer;
}

std::vector<std::string> suite_cases(const BenchArgs& args, const std::string& dir) {
    if (!args.cases.empty()) {
        return args.cases;
    }
    std::ifstream suite(dir + "/SUITE.txt");
    if (!suite) {
        throw CommandFailure(exit_input, dir + "/SUITE.txt: cannot open (use --data)");
    }
    std::vector<std::string> cases;
    std::string name;
    while (std::getline(suite, name)) {
        if (!name.empty() && name[0] != '#') {
            cases.push_back(name);
        }
    }
    return cases;
}

// `locus bench implicit`: every case of bench/data/implicit/SUITE.txt by each method, and by
// Singular's eliminate on the same elimination ideal when Singular is installed. Groebner runs
// under a deadline of --limit seconds, Singular under timeout(1) with the same limit. `auto` is
// Gröbner when it finishes within 0.2 s and the resultant route after that, as in
// `locus implicitize`.
int run_implicit_bench(const BenchArgs& args) {
    const std::string dir = args.data_dir + "/implicit";
    const std::vector<std::string> cases = suite_cases(args, dir);
    const bool with_singular = args.singular != "off" && on_path(args.singular);
    if (args.csv) {
        std::cout << "case,degree,terms,auto_method,auto_seconds,groebner_seconds,"
                     "resultant_seconds,singular_eliminate_seconds\n";
    } else {
        std::printf("%-18s %6s %6s %-10s %10s %10s %10s %10s\n", "case", "degree", "terms", "auto",
                    "auto s", "groebner s", "result. s", "Singular s");
    }
    auto seconds_since = [](std::chrono::steady_clock::time_point t) {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    };
    for (const auto& name : cases) {
        const implicit::Parametrization map =
            implicit::parse_parametrization(read_input(dir + "/" + name + ".param"));
        double resultant_seconds = -1;
        std::optional<implicit::ImplicitResult> result;
        try {
            const auto t = std::chrono::steady_clock::now();
            result = implicit::implicitize_by_resultant(map);
            resultant_seconds = seconds_since(t);
        } catch (const Error&) {
            // not applicable or gave up: auto falls back to Gröbner
        }
        double groebner_seconds = -1;
        try {
            algebra::GroebnerOptions options;
            options.deadline = deadline_after(args.limit_seconds);
            const auto t = std::chrono::steady_clock::now();
            implicit::ImplicitResult by_groebner = implicit::implicitize(map, options);
            groebner_seconds = seconds_since(t);
            if (!result) {
                result = std::move(by_groebner);
            }
        } catch (const Timeout&) {
            // reported as ">limit"
        }
        // As in `locus implicitize`: Gröbner when it finishes within 0.2 s, else resultants
        // (0.2 s wasted on the way), else Gröbner.
        const bool groebner_quick = groebner_seconds >= 0 && groebner_seconds <= 0.2;
        const bool auto_is_resultant = !groebner_quick && resultant_seconds >= 0;
        const double auto_seconds = groebner_quick      ? groebner_seconds
                                    : auto_is_resultant ? 0.2 + resultant_seconds
                                                        : groebner_seconds;
        const double singular_seconds =
            with_singular ? time_singular_eliminate(args.singular, map, args.limit_seconds) : -2;
        const long degree = result && result->equation ? result->equation->total_degree() : -1;
        const std::size_t terms = result && result->equation ? result->equation->num_terms() : 0;
        const std::string singular_text =
            singular_seconds == -2 ? "-" : seconds_or_limit(singular_seconds, args.limit_seconds);
        if (args.csv) {
            std::cout << name << "," << degree << "," << terms << ","
                      << (auto_is_resultant ? "resultant" : "groebner") << "," << auto_seconds
                      << "," << groebner_seconds << "," << resultant_seconds << ","
                      << singular_seconds << "\n";
        } else {
            std::printf(
                "%-18s %6ld %6zu %-10s %10s %10s %10s %10s\n", name.c_str(), degree, terms,
                auto_is_resultant ? "resultant" : "groebner",
                seconds_or_limit(auto_seconds, args.limit_seconds).c_str(),
                seconds_or_limit(groebner_seconds, args.limit_seconds).c_str(),
                resultant_seconds < 0 ? "-" : seconds_or_limit(resultant_seconds, 0).c_str(),
                singular_text.c_str());
        }
        std::cout.flush();
    }
    return exit_ok;
}

int run_bench(const BenchArgs& args) {
    if (args.suite == "implicit") {
        return run_implicit_bench(args);
    }
    if (args.suite != "groebner") {
        throw CommandFailure(exit_input, "bench: unknown suite '" + args.suite +
                                             "' (available: groebner, implicit)");
    }
    std::vector<std::string> cases = args.cases;
    if (cases.empty()) {
        std::ifstream suite(args.data_dir + "/SUITE.txt");
        if (!suite) {
            throw CommandFailure(exit_input,
                                 args.data_dir + "/SUITE.txt: cannot open (use --data)");
        }
        std::string name;
        while (std::getline(suite, name)) {
            if (!name.empty() && name[0] != '#') {
                cases.push_back(name);
            }
        }
    }
    const bool with_singular = args.singular != "off" && on_path(args.singular);
    if (args.csv) {
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
        const algebra::IdealFile ideal = read_ideal(args.data_dir + "/" + name + ".ideal");
        Timing mine;
        algebra::GroebnerResult result;
        const auto start = std::chrono::steady_clock::now();
        do {
            result = algebra::groebner(ideal.generators);
            ++mine.runs;
            mine.seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        } while (mine.seconds < args.min_seconds && mine.runs < 20);
        mine.seconds /= mine.runs;
        const std::string order = ideal.ring->order().to_string(ideal.ring->variable_names());
        Timing theirs{-1, 0};
        if (with_singular) {
            theirs = time_singular(args.singular, ideal, args.min_seconds);
        }
        const double ratio = theirs.seconds > 0 ? mine.seconds / theirs.seconds : NAN;
        if (std::isfinite(ratio)) {
            log_ratio_sum += std::log(ratio);
            ++ratio_count;
            worst_ratio = std::max(worst_ratio, ratio);
        }
        if (args.csv) {
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
        std::fprintf(args.csv ? stderr : stdout,
                     "geometric-mean ratio locus/Singular: %.3f over %d cases; worst %.3f\n",
                     std::exp(log_ratio_sum / ratio_count), ratio_count, worst_ratio);
    } else if (!with_singular) {
        std::fprintf(stderr, "Singular not found: no ratios (install Debian's singular)\n");
    }
    return exit_ok;
}

}  // namespace

void add_bench_command(CLI::App& app, int& exit_code) {
    auto args = std::make_shared<BenchArgs>();
    CLI::App* cmd = app.add_subcommand("bench", "Benchmark suites (groebner, implicit)");
    cmd->add_option("suite", args->suite, "the suite: groebner | implicit")->required();
    cmd->add_flag("--csv", args->csv, "write CSV rows instead of a table");
    cmd->add_option("--data", args->data_dir, "folder with SUITE.txt and the .ideal files");
    cmd->add_option("--cases", args->cases, "run only these cases")->delimiter(',');
    cmd->add_option("--singular", args->singular,
                    "Singular executable for the same-run reference, or 'off'");
    cmd->add_option("--min-seconds", args->min_seconds,
                    "repeat each case until this much time has passed (at most 20 runs)");
    cmd->add_option("--limit", args->limit_seconds,
                    "implicit suite: give Gröbner and Singular at most this many seconds");
    cmd->callback([args, &exit_code] { exit_code = run_bench(*args); });
}

}  // namespace locus::cli
