#include "bench/bench_options.h"

#include <algorithm>
#include <fstream>

#include "algebra/error.h"
#include "cli/choices.h"
#include "cli/command_support.h"
#include "cli/exit_codes.h"

namespace locus::bench {

void add_suite_options(CLI::App* command, SuiteOptions& options) {
    command->add_option("--data", options.data_dir,
                        "folder of the suites (bench/data of the source tree by default)");
    command->add_option("--cases", options.cases, "run only these cases")->delimiter(',');
    command->add_flag("--csv", options.csv, "write CSV rows instead of a table");
    command->add_option("--min-seconds", options.min_seconds,
                        "repeat each measurement until this much time has passed (0 to 3600)");
    cli::add_process_limit_options(command, options.limits);
}

void check_suite_options(const SuiteOptions& options) {
    cli::apply_process_limits(options.limits);
    if (!(options.min_seconds >= 0.0) || !(options.min_seconds <= 3600.0)) {
        throw cli::CommandFailure(cli::exit_input,
                                  "--min-seconds: expected seconds from 0 to 3600");
    }
}

void add_size_option(CLI::App* command, int& size, const std::string& description) {
    command->add_option("--size", size, description)
        ->check(cli::integer_range(1, 4096, "N from 1 to 4096 (N×N rays)"));
}

void add_threads_option(CLI::App* command, int& threads) {
    command->add_option("--threads", threads, "worker threads (1); 0 for every core")
        ->check(cli::integer_range(0, 1024, "a count from 1 to 1024, or 0 for every core"));
}

std::vector<std::string> suite_case_names(const std::string& dir,
                                          const std::vector<std::string>& chosen) {
    if (!chosen.empty()) {
        return chosen;
    }
    std::ifstream suite(dir + "/SUITE.txt");
    if (!suite) {
        throw cli::CommandFailure(cli::exit_input, dir + "/SUITE.txt: cannot open (use --data)");
    }
    std::vector<std::string> cases;
    for (std::string name; std::getline(suite, name);) {
        if (!name.empty() && name[0] != '#') {
            cases.push_back(name);
        }
    }
    return cases;
}

std::vector<SuiteSurface> read_surface_cases(const SuiteOptions& options,
                                             const std::string& command,
                                             std::span<const std::string> not_surfaces) {
    const std::string path = options.data_dir + "/surfaces/SUITE.txt";
    std::vector<SuiteSurface> suite;
    try {
        suite = parse_surface_suite(cli::read_input(path));
    } catch (const Error& e) {
        throw cli::CommandFailure(cli::exit_input, path + ": " + e.what());
    }
    if (options.cases.empty()) {
        return suite;
    }
    std::vector<SuiteSurface> chosen;
    for (const std::string& name : options.cases) {
        if (std::find(not_surfaces.begin(), not_surfaces.end(), name) != not_surfaces.end()) {
            continue;
        }
        const auto it = std::find_if(suite.begin(), suite.end(),
                                     [&](const SuiteSurface& s) { return s.name == name; });
        if (it == suite.end()) {
            throw cli::CommandFailure(cli::exit_input,
                                      command + ": no surface '" + name + "' in the suite");
        }
        chosen.push_back(*it);
    }
    return chosen;
}

}  // namespace locus::bench
