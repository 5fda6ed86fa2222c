// The subcommands of `locus`; each registers itself on the CLI11 app and, when run, writes its
// exit code to `context.exit_code` (or throws CommandFailure / a locus::Error that run_app() maps).
#pragma once

#include <CLI/CLI.hpp>

#include "cli/run_app.h"

namespace locus::cli {

void add_groebner_command(CLI::App& app, CommandContext& context);
void add_ideal_command(CLI::App& app, CommandContext& context);
void add_implicitize_command(CLI::App& app, CommandContext& context);
void add_demo_command(CLI::App& app, CommandContext& context);
void add_render_command(CLI::App& app, CommandContext& context);
void add_trace_command(CLI::App& app, CommandContext& context);
void add_view_command(CLI::App& app, CommandContext& context);

}  // namespace locus::cli
