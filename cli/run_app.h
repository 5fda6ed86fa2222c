// The part of a locus executable's main() that is the same for `locus` and `locus-bench`:
// parsing the command line, running the chosen subcommand, and turning its outcome into a
// message and an exit code (exit_codes.h). Both executables map errors in this one place.
#pragma once

#include <CLI/CLI.hpp>

#include "cli/exit_codes.h"
#include "cli/progress_line.h"

namespace locus::cli {

// What main() shares with the subcommand that runs: the exit code it sets, and the progress
// line it draws on (cleared before an error is printed).
struct CommandContext {
    int exit_code = exit_ok;
    ProgressLine progress;
};

// The footer of `--help`: the exit codes.
extern const char* const kExitCodesHelp;

// Parses argv, runs the subcommand whose callback the app holds, and returns the process's
// exit code: the subcommand's, or the code of the error it threw, printed as
// "program: message" on standard error. A failed write to standard output is exit 5.
int run_app(CLI::App& app, CommandContext& context, int argc, char** argv, const char* program);

}  // namespace locus::cli
