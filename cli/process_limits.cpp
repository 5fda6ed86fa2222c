#include "cli/process_limits.h"

#include <flint/flint.h>
#include <gmp.h>
#include <sys/resource.h>  // for setrlimit
#include <unistd.h>        // for write, isatty

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <new>
#include <thread>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/command_support.h"
#include "cli/exit_codes.h"

namespace locus::cli {

namespace {

// What the out-of-memory message names: the --max-memory value, or the machine.
char memory_limit_text[64] = "the memory available";

[[noreturn]] void out_of_memory() {
    // No allocation from here on: a fixed buffer and write(2).
    char message[160];
    const int length =
        std::snprintf(message, sizeof message, "locus: out of memory (%s); exit code %d\n",
                      memory_limit_text, exit_resource);
    if (length > 0) {
        [[maybe_unused]] const auto ignored = write(2, message, static_cast<std::size_t>(length));
    }
    std::_Exit(exit_resource);
}

void* checked_malloc(std::size_t size) {
    void* p = std::malloc(size);
    if (p == nullptr && size != 0) {
        out_of_memory();
    }
    return p;
}
void* checked_calloc(std::size_t count, std::size_t size) {
    void* p = std::calloc(count, size);
    if (p == nullptr && count != 0 && size != 0) {
        out_of_memory();
    }
    return p;
}
void* checked_realloc(void* old, std::size_t size) {
    void* p = std::realloc(old, size);
    if (p == nullptr && size != 0) {
        out_of_memory();
    }
    return p;
}
void* gmp_realloc(void* old, std::size_t, std::size_t size) {
    return checked_realloc(old, size);
}
void gmp_free(void* p, std::size_t) {
    std::free(p);
}

// Files being written (under a temporary name) and the name each will have when complete: the
// watchdog removes them when it ends the process.
std::mutex partial_mutex;

// Held by the watchdog from the moment it fires until the process ends, and by
// stop_watchdog(): whichever takes it first decides the outcome, so a command that stopped at
// its deadline by itself prints its message alone, and a finished command is not ended
// afterwards.
std::mutex watchdog_mutex;
bool watchdog_stopped = false;
std::vector<std::pair<std::string, std::string>> partial_files;

// More than a year is no limit (and keeps the arithmetic on time points finite).
constexpr double kNoLimitSeconds = 365.25 * 24 * 3600;

std::optional<double> parse_timeout(const std::string& text) {
    if (text.empty()) {
        return std::nullopt;
    }
    const auto fail = [&]() -> std::optional<double> {
        throw CommandFailure(exit_input,
                             "--timeout: expected a positive number of seconds or "
                             "'inf' (no limit), found '" +
                                 text + "'");
    };
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    // !(value > 0) also refuses NaN.
    if (end == text.c_str() || *end != '\0' || !(value > 0.0)) {
        return fail();
    }
    if (!(value < kNoLimitSeconds)) {
        return std::nullopt;  // inf, 1e10: no limit
    }
    return value;
}

std::optional<unsigned long long> parse_bytes(const std::string& text) {
    if (text.empty()) {
        return std::nullopt;
    }
    const auto fail = [&]() -> std::optional<unsigned long long> {
        throw CommandFailure(exit_input,
                             "--max-memory: expected a number of bytes, optionally with K, M or G "
                             "(powers of 1024), such as 512M; found '" +
                                 text + "'");
    };
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    double scale = 1.0;
    if (end != text.c_str() && *end != '\0' && end[1] == '\0') {
        switch (*end) {
        case 'k':
        case 'K':
            scale = 1024.0;
            break;
        case 'm':
        case 'M':
            scale = 1024.0 * 1024.0;
            break;
        case 'g':
        case 'G':
            scale = 1024.0 * 1024.0 * 1024.0;
            break;
        default:
            return fail();
        }
        ++end;
    }
    if (end == text.c_str() || *end != '\0' || !std::isfinite(value) || !(value >= 1.0)) {
        return fail();
    }
    const double bytes = value * scale;
    if (!(bytes < 1.8e19)) {
        return std::nullopt;
    }
    return static_cast<unsigned long long>(bytes);
}

}  // namespace

void add_process_limit_options(CLI::App* command, ProcessLimitArgs& args) {
    command->add_option("--timeout", args.timeout,
                        "give up after SECONDS (exit code 3); 'inf': no limit");
    command->add_option("--max-memory", args.max_memory,
                        "limit memory to BYTES (K, M, G suffixes); running out is exit code 5");
}

Deadline apply_process_limits(const ProcessLimitArgs& args) {
    const std::optional<double> seconds = parse_timeout(args.timeout);
    if (const std::optional<unsigned long long> bytes = parse_bytes(args.max_memory)) {
        rlimit limit{};
        limit.rlim_cur = static_cast<rlim_t>(*bytes);
        limit.rlim_max = static_cast<rlim_t>(*bytes);
        if (setrlimit(RLIMIT_AS, &limit) != 0) {
            throw CommandFailure(exit_input, std::string("--max-memory: cannot set the limit: ") +
                                                 std::strerror(errno));
        }
        std::snprintf(memory_limit_text, sizeof memory_limit_text, "--max-memory %s",
                      args.max_memory.c_str());
    }
    if (!seconds) {
        return std::nullopt;
    }
    const auto start = std::chrono::steady_clock::now();
    const auto as_duration = [](double s) {
        return std::chrono::duration_cast<std::chrono::steady_clock::duration>(
            std::chrono::duration<double>(s));
    };
    const auto deadline = start + as_duration(*seconds);
    // The algorithms stop at the deadline themselves; the watchdog is for the phases that
    // cannot (a FLINT call, a write), a little later so that theirs is the message seen.
    const auto kill_at = start + as_duration(1.03 * *seconds + 0.05);
    const std::string text = seconds_text(*seconds);
    std::thread([kill_at, text] {
        std::this_thread::sleep_until(kill_at);
        const std::unique_lock<std::mutex> deciding(watchdog_mutex);
        if (watchdog_stopped) {
            return;
        }
        std::string not_written;
        {
            const std::unique_lock<std::mutex> lock(partial_mutex, std::try_to_lock);
            if (lock.owns_lock()) {
                for (const auto& [partial, final_name] : partial_files) {
                    std::remove(partial.c_str());
                    not_written += "; nothing written to '" + final_name + "'";
                }
            }
        }
        std::fflush(stdout);
        if (isatty(2)) {
            std::fputs("\r\033[K", stderr);
        }
        std::fprintf(stderr, "locus: timeout: stopped after %s (--timeout)%s\n", text.c_str(),
                     not_written.c_str());
        std::fflush(stderr);
        std::_Exit(exit_timeout);
    }).detach();
    return deadline;
}

std::string timeout_text(const ProcessLimitArgs& args) {
    const std::optional<double> seconds = parse_timeout(args.timeout);
    return seconds ? seconds_text(*seconds) : std::string();
}

void install_out_of_memory_handlers() {
    std::set_new_handler([] { out_of_memory(); });
    mp_set_memory_functions(&checked_malloc, &gmp_realloc, &gmp_free);
    __flint_set_memory_functions(&checked_malloc, &checked_calloc, &checked_realloc, &std::free);
}

void stop_watchdog() {
    const std::lock_guard<std::mutex> lock(watchdog_mutex);
    watchdog_stopped = true;
}

void register_partial_file(const std::string& partial, const std::string& final_name) {
    const std::lock_guard<std::mutex> lock(partial_mutex);
    partial_files.emplace_back(partial, final_name);
}

void unregister_partial_file(const std::string& partial) {
    const std::lock_guard<std::mutex> lock(partial_mutex);
    std::erase_if(partial_files, [&](const auto& file) { return file.first == partial; });
}

}  // namespace locus::cli
