#include "cli/run_app.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <new>
#include <string>

#include "algebra/error.h"
#include "cli/command_support.h"
#include "cli/process_limits.h"

namespace locus::cli {

const char* const kExitCodesHelp =
    "Exit codes: 0 success; 1 the \"no\" of a yes/no question (ideal member, contains, ...);\n"
    "2 bad input or usage; 3 --timeout passed; 4 a verification or --check failed;\n"
    "5 a resource limit (--max-memory, a size limit, a failed write); 70 an internal error\n"
    "(a bug: please report it).";

namespace {

// Everything written to standard output must have reached it: a full disk or a closed pipe is
// an error, not a silent success.
int finish_output(int code, const char* program) {
    std::cout.flush();
    if (std::fflush(stdout) != 0 || std::ferror(stdout) || !std::cout) {
        const int error = errno;
        std::fprintf(stderr, "%s: cannot write standard output: %s\n", program,
                     error != 0 ? std::strerror(error) : "write error");
        return code == exit_ok || code == exit_no ? exit_resource : code;
    }
    return code;
}

}  // namespace

int run_app(CLI::App& app, CommandContext& context, int argc, char** argv, const char* program) {
    const auto fail = [&](int code, const char* message) {
        stop_watchdog();
        context.progress.clear();
        std::fprintf(stderr, "%s: %s\n", program, message);
        return finish_output(code, program);
    };
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return finish_output(code == 0 ? exit_ok : exit_input, program);
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
    const int code = finish_output(context.exit_code, program);
    stop_watchdog();
    return code;
}

}  // namespace locus::cli
