// Runs another system (Singular, Giac) on a script for the same-run references of the bench:
// the script goes to a temporary file, the program runs on it under timeout(1) when a limit is
// given, and each line of its output (standard output and error together) is handed back.
#pragma once

#include <functional>
#include <string>

namespace locus::bench {

struct ScriptRun {
    std::string program;       // the executable (quoted for the shell here)
    std::string arguments;     // before the script's path, e.g. "-q --no-rc"; empty for none
    bool on_stdin = false;     // the script on standard input rather than as the last argument
    std::string extension;     // of the temporary file, e.g. ".sing"
    double limit_seconds = 0;  // > 0: killed after this many seconds (at least one)
};

// Runs `script` as `run` says and calls `line` with every line of the output.
void run_script(const ScriptRun& run, const std::string& script,
                const std::function<void(const char* line)>& line);

}  // namespace locus::bench
