#include "bench/script_run.h"

#include <unistd.h>  // for getpid

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace locus::bench {

void run_script(const ScriptRun& run, const std::string& script,
                const std::function<void(const char* line)>& line) {
    std::filesystem::path path = std::filesystem::temp_directory_path();
    path /= "locus-bench-" + std::to_string(::getpid()) + run.extension;
    {
        std::ofstream out(path);
        out << script;
    }
    std::string command;
    if (run.limit_seconds > 0) {
        command = "timeout ";
        command += std::to_string(std::max(1L, std::lround(std::ceil(run.limit_seconds))));
        command += ' ';
    }
    command += '\'';
    command += run.program;
    command += "' ";
    if (!run.arguments.empty()) {
        command += run.arguments;
        command += ' ';
    }
    command += run.on_stdin ? "< '" : "'";
    command += path.string();
    command += run.on_stdin ? "' 2>&1" : "' </dev/null 2>&1";
    if (FILE* pipe = popen(command.c_str(), "r")) {
        char buffer[4096];
        while (std::fgets(buffer, sizeof buffer, pipe)) {
            line(buffer);
        }
        pclose(pipe);
    }
    std::filesystem::remove(path);
}

}  // namespace locus::bench
