// The limits of one locus process, from the command line of every subcommand:
//   --timeout SECONDS   a deadline for the whole command. The algorithms stop at it on their own
//                       (they poll the deadline); a watchdog thread ends the process with exit
//                       code 3 at 1.03·SECONDS + 0.05 s whatever phase it is in (reading, parsing,
//                       FLINT's resultants, writing), so no phase can run past it.
//   --max-memory BYTES  an address-space limit (setrlimit); running out of memory, under it or
//                       not, is a message and exit code 5, never an abort: C++, GMP and FLINT
//                       allocation failures all end in the same handler.
// Output files are written under a temporary name beside their final one and renamed when
// complete (render/image_output.cpp); the watchdog removes an unfinished one.
#pragma once

#include <chrono>
#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace locus::cli {

struct ProcessLimitArgs {
    std::string timeout;     // as typed; empty: none
    std::string max_memory;  // as typed; empty: none
};

// Adds --timeout and --max-memory to a subcommand.
void add_process_limit_options(CLI::App* command, ProcessLimitArgs& args);

using Deadline = std::optional<std::chrono::steady_clock::time_point>;

// Validates the options (CommandFailure with exit code 2 for a malformed value), sets the
// memory limit, arms the watchdog, and returns the deadline (none without --timeout).
// "--timeout inf" (or any value above a year) means no limit; NaN, zero and negative values
// are input errors.
Deadline apply_process_limits(const ProcessLimitArgs& args);

// Called by main() once the outcome is decided (the result written, or the error about to be
// printed): the watchdog then no longer ends the process. If it has already fired, this waits
// for it, and the process ends with its message and exit code 3.
void stop_watchdog();

// The --timeout value as messages quote it ("0.5 s"), or "" when there is none.
std::string timeout_text(const ProcessLimitArgs& args);

// Installed once by main(): allocation failures anywhere print one line and exit with 5.
void install_out_of_memory_handlers();

// A file being written under a temporary name (partial), which the watchdog removes if the
// process is ended before it is complete, naming final_name in its message.
void register_partial_file(const std::string& partial, const std::string& final_name);
void unregister_partial_file(const std::string& partial);

}  // namespace locus::cli
