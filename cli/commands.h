// The subcommands of `locus`; each registers itself on the CLI11 app and, when run, writes its
// exit code to `context.exit_code` (or throws CommandFailure / a locus::Error that main() maps).
#pragma once

#include <CLI/CLI.hpp>

#include "cli/exit_codes.h"
#include "cli/progress_line.h"

namespace locus::cli {

// What main() shares with the subcommand that runs: the exit code it sets, and the progress
// line it draws on (which main() clears before printing an error).
struct CommandContext {
    int exit_code = exit_ok;
    ProgressLine progress;
};

void add_groebner_command(CLI::App& app, CommandContext& context);
void add_ideal_command(CLI::App& app, CommandContext& context);
void add_implicitize_command(CLI::App& app, CommandContext& context);
void add_bench_command(CLI::App& app, CommandContext& context);
void add_demo_command(CLI::App& app, CommandContext& context);
void add_render_command(CLI::App& app, CommandContext& context);
void add_trace_command(CLI::App& app, CommandContext& context);

}  // namespace locus::cli
