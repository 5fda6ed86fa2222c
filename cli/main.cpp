// The `locus` executable: subcommands over the libraries (commands.h); run_app() turns their
// outcome into messages and exit codes. No algorithm lives here.
#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "cli/process_limits.h"
#include "cli/run_app.h"
#include "cli/version.h"

int main(int argc, char** argv) {
    using namespace locus::cli;
    install_out_of_memory_handlers();
    CLI::App app("locus: exact implicit equations and Gröbner bases over Q", "locus");
    app.footer(kExitCodesHelp);
    app.set_version_flag("--version", version_text());
    app.require_subcommand(1);
    CommandContext context;
    add_groebner_command(app, context);
    add_ideal_command(app, context);
    add_implicitize_command(app, context);
    add_demo_command(app, context);
    add_render_command(app, context);
    add_trace_command(app, context);
    add_view_command(app, context);
    return run_app(app, context, argc, argv, "locus");
}
