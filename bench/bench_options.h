// Options every suite of `locus-bench` takes, and the suite files' case lists.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench/surface_suite.h"
#include "cli/process_limits.h"
#include "cli/run_app.h"

namespace locus::bench {

struct SuiteOptions {
    std::string data_dir = LOCUS_BENCH_DATA;  // bench/data of the source tree it was built from
    std::vector<std::string> cases;           // empty: the whole suite
    bool csv = false;
    double min_seconds = 0.2;  // repeat each measurement until this much time has passed
    cli::ProcessLimitArgs limits;
};

// Adds --data, --cases, --csv, --min-seconds, --timeout and --max-memory to a suite's
// subcommand.
void add_suite_options(CLI::App* command, SuiteOptions& options);

// A suite's subcommand: `args` (whose `suite` member gets the shared options) is filled by the
// parser, then `run(*args)` sets the exit code. The caller adds the suite's own options.
template <class Args>
CLI::App* add_suite_command(CLI::App& app, cli::CommandContext& context, const std::string& name,
                            const std::string& description, const std::shared_ptr<Args>& args,
                            int (*run)(const Args&)) {
    CLI::App* command = app.add_subcommand(name, description);
    add_suite_options(command, args->suite);
    command->callback([args, run, &context] { context.exit_code = run(*args); });
    return command;
}

// Applies the process limits and checks the options shared by every suite (CommandFailure,
// exit 2, for a value out of range).
void check_suite_options(const SuiteOptions& options);

// --size and --threads of the render and SDF suites, with their ranges.
void add_size_option(CLI::App* command, int& size, const std::string& description);
void add_threads_option(CLI::App* command, int& threads);

// The names of a suite's cases: `chosen` when it is not empty, else the lines of
// `dir`/SUITE.txt that are neither empty nor comments ('#').
std::vector<std::string> suite_case_names(const std::string& dir,
                                          const std::vector<std::string>& chosen);

// The surface suite (`surfaces/SUITE.txt` under --data), narrowed to --cases in their order
// when there are any; a name in `not_surfaces` (the render suite's "teapot") is left to the
// caller. A file that does not parse, or a case it lacks, is a CommandFailure (exit 2) naming
// the file or `command`.
std::vector<SuiteSurface> read_surface_cases(const SuiteOptions& options,
                                             const std::string& command,
                                             std::span<const std::string> not_surfaces = {});

}  // namespace locus::bench
