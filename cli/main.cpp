// The `locus` executable: subcommands over the libraries. The only place that turns errors into
// messages and exit codes (exit_codes.h); no algorithm lives here.
#include <cstdio>

#include <CLI/CLI.hpp>

#include "algebra/error.h"
#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"

int main(int argc, char** argv) {
    using namespace locus::cli;
    CLI::App app("locus: exact implicit equations and Gröbner bases over Q", "locus");
    app.require_subcommand(1);
    int exit_code = exit_ok;
    add_groebner_command(app, exit_code);
    add_ideal_command(app, exit_code);
    add_implicitize_command(app, exit_code);
    add_bench_command(app, exit_code);
    add_demo_command(app, exit_code);
    add_render_command(app, exit_code);
    add_trace_command(app, exit_code);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? exit_ok : exit_input;
    } catch (const CommandFailure& e) {
        finish_progress();
        std::fprintf(stderr, "locus: %s\n", e.what());
        return e.code();
    } catch (const locus::ParseError& e) {
        std::fprintf(stderr, "locus: %s\n", e.what());
        return exit_input;
    } catch (const locus::InputError& e) {
        std::fprintf(stderr, "locus: %s\n", e.what());
        return exit_input;
    } catch (const locus::ExponentOverflow& e) {
        std::fprintf(stderr, "locus: %s\n", e.what());
        return exit_input;
    } catch (const locus::Timeout& e) {
        std::fprintf(stderr, "locus: %s\n", e.what());
        return exit_timeout;
    } catch (const locus::Error& e) {
        std::fprintf(stderr, "locus: error: %s\n", e.what());
        return 1;
    }
    return exit_code;
}
