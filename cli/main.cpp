// The `locus` executable: subcommands over the libraries. The only place that turns errors into
// messages and exit codes (exit_codes.h); no algorithm lives here.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

#include <CLI/CLI.hpp>

#include "algebra/error.h"
#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "cli/process_limits.h"

namespace {

constexpr const char* kExitCodes =
    "Exit codes: 0 success; 1 the \"no\" of a yes/no question (ideal member, contains, ...);\n"
    "2 bad input or usage; 3 --timeout passed; 4 a verification or --check failed;\n"
    "5 a resource limit (--max-memory, a size limit, a failed write); 70 an internal error\n"
    "(a bug: please report it).";

// Everything written to standard output must have reached it: a full disk or a closed pipe is
// an error, not a silent success.
int finish_output(int code) {
    std::cout.flush();
    if (std::fflush(stdout) != 0 || std::ferror(stdout) || !std::cout) {
        const int error = errno;
        std::fprintf(stderr, "locus: cannot write standard output: %s\n",
                     error != 0 ? std::strerror(error) : "write error");
        return code == locus::cli::exit_ok || code == locus::cli::exit_no
                   ? locus::cli::exit_resource
                   : code;
    }
    return code;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace locus::cli;
    install_out_of_memory_handlers();
    CLI::App app("locus: exact implicit equations and Gröbner bases over Q", "locus");
    app.footer(kExitCodes);
    app.require_subcommand(1);
    CommandContext context;
    add_groebner_command(app, context);
    add_ideal_command(app, context);
    add_implicitize_command(app, context);
    add_bench_command(app, context);
    add_demo_command(app, context);
    add_render_command(app, context);
    add_trace_command(app, context);
    const auto fail = [&context](int code, const char* message) {
        stop_watchdog();
        context.progress.clear();
        std::fprintf(stderr, "locus: %s\n", message);
        return finish_output(code);
    };
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return finish_output(code == 0 ? exit_ok : exit_input);
    } catch (const CommandFailure& e) {
        return fail(e.code(), e.what());
    } catch (const locus::Timeout& e) {
        return fail(exit_timeout, e.what());
    } catch (const locus::ResourceLimit& e) {
        return fail(exit_resource, e.what());
    } catch (const locus::Error& e) {
        // Parse errors, unacceptable input, and a method that cannot handle this input.
        return fail(exit_input, e.what());
    } catch (const std::bad_alloc&) {
        return fail(exit_resource, "out of memory");
    } catch (const std::exception& e) {
        const std::string message =
            std::string("internal error (a bug; please report it): ") + e.what();
        return fail(exit_internal, message.c_str());
    }
    const int code = finish_output(context.exit_code);
    stop_watchdog();
    return code;
}
