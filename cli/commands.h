// The subcommands of `locus`; each registers itself on the CLI11 app and, when run, writes its
// exit code to `exit_code` (or throws CommandFailure / a locus::Error that main() maps).
#pragma once

#include <CLI/CLI.hpp>

namespace locus::cli {

void add_groebner_command(CLI::App& app, int& exit_code);
void add_ideal_command(CLI::App& app, int& exit_code);
void add_implicitize_command(CLI::App& app, int& exit_code);
void add_bench_command(CLI::App& app, int& exit_code);
void add_demo_command(CLI::App& app, int& exit_code);
void add_render_command(CLI::App& app, int& exit_code);
void add_trace_command(CLI::App& app, int& exit_code);

}  // namespace locus::cli
