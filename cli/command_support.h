// Helpers shared by the subcommands: reading inputs, progress on a terminal, deadlines.
#pragma once

#include <chrono>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

#include "algebra/error.h"
#include "algebra/parse.h"

namespace locus::cli {

// A failure already explained to the user; main() prints `what()` and exits with `code`.
class CommandFailure : public std::runtime_error {
  public:
    CommandFailure(int code, const std::string& message)
        : std::runtime_error(message), code_(code) {}
    int code() const { return code_; }

  private:
    int code_;
};

// The CommandFailure for a library error about `where` (a file name, an option): exit 3 for a
// Timeout, 5 for a ResourceLimit, 2 otherwise, with "where: " in front unless the message
// already names it (no "scene.toml: scene.toml: …").
CommandFailure failure_about(const std::string& where, const Error& error);

// Inputs larger than this are refused (exit code 5) as they are read.
inline constexpr std::size_t kMaxInputBytes = std::size_t{256} << 20;

// The whole of a file, or of standard input for "-", which must be UTF-8 text (a byte order
// mark is dropped). Throws CommandFailure: exit 2 for a missing file, a directory or a byte
// that is not text (with its line and column), exit 5 past kMaxInputBytes.
std::string read_input(const std::string& path);

// Reads an ideal file; parse errors are prefixed with the file name. `order_override` (the
// text of --order) replaces the file's order.
algebra::IdealFile read_ideal(const std::string& path,
                              const std::optional<std::string>& order_override = std::nullopt);

// "0.5 s": a --timeout value as messages quote it.
std::string seconds_text(double seconds);

// A deadline `seconds` from now, or none for seconds <= 0.
std::optional<std::chrono::steady_clock::time_point> deadline_after(double seconds);

// Runs `work` in a forked child for library calls that have no deadline of their own (FLINT's
// resultants): its text comes back through a pipe. Nothing when the child fails or runs past
// `limit_seconds` (it is then killed; `timed_out` says which), else the text and, in
// `seconds`, the time it took.
struct ChildOutcome {
    std::optional<std::string> text;
    bool timed_out = false;
    double seconds = 0.0;
};
ChildOutcome run_in_child(double limit_seconds, const std::function<std::string()>& work);

// Is `program` an existing path, or an executable name found in a directory of PATH?
bool on_path(const std::string& program);

}  // namespace locus::cli
