// The `locus` executable: subcommands over the libraries (commands.h); run_app() turns their
// outcome into messages and exit codes. No algorithm lives here.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <string_view>

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
    // Building every subcommand's options takes CLI11 about a millisecond, a fiftieth of a whole
    // `locus render` of a sphere: when the first argument names a subcommand, only that one is
    // built (a subcommand is always the first argument: locus has no options of its own but
    // --help and --version). Otherwise all are, for the help, the version and the error that
    // lists them.
    struct Command {
        std::string_view name;
        void (*add)(CLI::App&, CommandContext&);
    };
    static constexpr Command kCommands[] = {{"groebner", add_groebner_command},
                                            {"ideal", add_ideal_command},
                                            {"implicitize", add_implicitize_command},
                                            {"demo", add_demo_command},
                                            {"render", add_render_command},
                                            {"trace", add_trace_command},
                                            {"view", add_view_command}};
    const std::string_view first = argc > 1 ? argv[1] : "";
    const bool named = std::any_of(std::begin(kCommands), std::end(kCommands),
                                   [&](const Command& c) { return c.name == first; });
    for (const Command& command : kCommands) {
        if (!named || command.name == first) {
            command.add(app, context);
        }
    }
    const int code = run_app(app, context, argc, argv, "locus");
#if defined(__SANITIZE_ADDRESS__)
    return code;  // LeakSanitizer checks at exit
#else
    // Every file is written and closed and standard output flushed (run_app reports a failed
    // flush). What is left is freeing memory the process is about to give back whole, ending
    // oneTBB's workers and FLINT's caches: 0.6–0.9 ms of a 45 ms `locus render`.
    std::fflush(nullptr);
    std::_Exit(code);
#endif
}
