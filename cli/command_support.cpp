#include "cli/command_support.h"

#include <fcntl.h>       // for O_CLOEXEC
#include <signal.h>      // for kill
#include <sys/select.h>  // for select
#include <sys/wait.h>    // for waitpid
#include <unistd.h>      // for fork, pipe

#include <cerrno>
#include <chrono>
#include <cstring>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "algebra/error.h"
#include "algebra/system_input.h"
#include "cli/exit_codes.h"

namespace locus::cli {

CommandFailure failure_about(const std::string& where, const Error& error) {
    const int code = dynamic_cast<const Timeout*>(&error) != nullptr         ? exit_timeout
                     : dynamic_cast<const ResourceLimit*>(&error) != nullptr ? exit_resource
                                                                             : exit_input;
    const std::string message = error.what();
    const bool named = where.empty() || message.rfind(where + ": ", 0) == 0;
    return CommandFailure(code, named ? message : where + ": " + message);
}

std::string read_input(const std::string& path) {
    const std::string name = path == "-" ? "<stdin>" : path;
    if (path != "-") {
        std::error_code error;
        if (std::filesystem::is_directory(path, error)) {
            throw CommandFailure(exit_input, path + ": is a directory, not a file");
        }
    }
    FILE* file = path == "-" ? stdin : std::fopen(path.c_str(), "rb");
    if (file == nullptr) {
        throw CommandFailure(exit_input, path + ": cannot open file: " + std::strerror(errno));
    }
    struct Closer {
        FILE* file;
        ~Closer() {
            if (file != stdin) {
                std::fclose(file);
            }
        }
    } closer{file};
    // Read in chunks, checking as it comes that this is UTF-8 text: garbage (/dev/zero,
    // /dev/urandom, a binary file) is refused at its first bad byte, not after reading it all.
    std::string text;
    std::size_t line = 1, column = 1;
    int continuation = 0;  // UTF-8 continuation bytes still expected
    char buffer[1 << 16];
    for (;;) {
        const std::size_t n = std::fread(buffer, 1, sizeof buffer, file);
        for (std::size_t i = 0; i < n; ++i) {
            const auto byte = static_cast<unsigned char>(buffer[i]);
            bool bad = false;
            if (continuation > 0) {
                bad = (byte & 0xC0) != 0x80;
                --continuation;
            } else if (byte >= 0x80) {
                continuation = byte >= 0xF0 && byte < 0xF8   ? 3
                               : byte >= 0xE0 && byte < 0xF0 ? 2
                               : byte >= 0xC2 && byte < 0xE0 ? 1
                                                             : -1;
                bad = continuation < 0;
            } else {
                bad = (byte < 0x20 && byte != '\t' && byte != '\n' && byte != '\r' &&
                       byte != '\f' && byte != '\v') ||
                      byte == 0x7F;
            }
            if (bad) {
                char code[16];
                std::snprintf(code, sizeof code, "0x%02X", byte);
                throw CommandFailure(exit_input, name + ": line " + std::to_string(line) +
                                                     ", column " + std::to_string(column) +
                                                     ": expected UTF-8 text, found the byte " +
                                                     code);
            }
            if (byte == '\n') {
                ++line;
                column = 1;
            } else if ((byte & 0xC0) != 0x80) {
                ++column;
            }
        }
        if (text.size() + n > kMaxInputBytes) {
            throw CommandFailure(exit_resource, name + ": input larger than the limit of " +
                                                    std::to_string(kMaxInputBytes >> 20) + " MiB");
        }
        text.append(buffer, n);
        if (n < sizeof buffer) {
            break;
        }
    }
    if (std::ferror(file)) {
        throw CommandFailure(exit_input, name + ": cannot read: " + std::strerror(errno));
    }
    // A UTF-8 byte order mark is not part of the text.
    if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) {
        text.erase(0, 3);
    }
    return text;
}

algebra::IdealFile read_ideal(const std::string& path,
                              const std::optional<std::string>& order_override) {
    const std::string text = read_input(path);
    const std::string name = path == "-" ? "<stdin>" : path;
    algebra::IdealFile file;
    try {
        // msolve's format by its extension (or on standard input by its shape); a pasted
        // Singular or Macaulay2 session by its ring declaration; else an ideal file.
        algebra::IdealFormat format = path.ends_with(".ms") ? algebra::IdealFormat::msolve
                                                            : algebra::detect_ideal_format(text);
        if (format == algebra::IdealFormat::msolve && path != "-" && !path.ends_with(".ms")) {
            format = algebra::IdealFormat::ideal_file;
        }
        file = algebra::parse_ideal_text(text, format);
    } catch (const Error& e) {  // ParseError, InputError, ExponentOverflow, ResourceLimit
        throw failure_about(name, e);
    }
    if (order_override) {
        try {
            const auto order =
                algebra::parse_monomial_order(*order_override, file.ring->variable_names(), 1, 1);
            const auto ring = file.ring->with_order(order);
            for (auto& g : file.generators) {
                g = g.in_ring(ring);
            }
            file.ring = ring;
        } catch (const Error& e) {
            throw CommandFailure(exit_input, std::string("--order: ") + e.what());
        }
    }
    return file;
}

std::string seconds_text(double seconds) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g s", seconds);
    return buffer;
}

std::optional<std::chrono::steady_clock::time_point> deadline_after(double seconds) {
    if (seconds <= 0) {
        return std::nullopt;
    }
    return std::chrono::steady_clock::now() +
           std::chrono::duration_cast<std::chrono::steady_clock::duration>(
               std::chrono::duration<double>(seconds));
}

bool on_path(const std::string& program) {
    if (program.find('/') != std::string::npos) {
        return std::filesystem::exists(program);
    }
    const char* path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "");
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        if (!dir.empty() && std::filesystem::exists(std::filesystem::path(dir) / program)) {
            return true;
        }
    }
    return false;
}

ChildOutcome run_in_child(double limit_seconds, const std::function<std::string()>& work) {
    ChildOutcome outcome;
    int channel[2];
    if (pipe2(channel, O_CLOEXEC) != 0) {
        return outcome;
    }
    const auto start = std::chrono::steady_clock::now();
    const pid_t child = fork();
    if (child == 0) {
        close(channel[0]);
        int code = 1;
        try {
            const std::string text = work();
            std::size_t written = 0;
            while (written < text.size()) {
                const ssize_t n = write(channel[1], text.data() + written, text.size() - written);
                if (n <= 0) {
                    break;
                }
                written += static_cast<std::size_t>(n);
            }
            code = written == text.size() ? 0 : 1;
        } catch (...) {
            code = 1;
        }
        close(channel[1]);
        _exit(code);
    }
    close(channel[1]);
    if (child < 0) {
        close(channel[0]);
        return outcome;
    }
    // Read while waiting: a child blocked on a full pipe would otherwise never finish.
    std::string text;
    char buffer[4096];
    int status = 0;
    bool end_of_text = false, exited = false;
    while (!(end_of_text && exited)) {
        const double elapsed =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        // A limit of 0 or less means none, as for deadline_after. A child already reaped is
        // never killed (its pid may belong to another process by now).
        if (limit_seconds > 0.0 && elapsed > limit_seconds && !exited) {
            kill(child, SIGKILL);
            waitpid(child, &status, 0);
            close(channel[0]);
            outcome.timed_out = true;
            return outcome;
        }
        if (!end_of_text) {
            fd_set readable;
            FD_ZERO(&readable);
            FD_SET(channel[0], &readable);
            timeval wait{0, 1000};
            if (select(channel[0] + 1, &readable, nullptr, nullptr, &wait) > 0) {
                const ssize_t n = read(channel[0], buffer, sizeof buffer);
                if (n > 0) {
                    text.append(buffer, static_cast<std::size_t>(n));
                } else if (n == 0 || (errno != EINTR && errno != EAGAIN)) {
                    end_of_text = true;  // the child closed its end (or the pipe failed)
                }
            }
        } else {
            usleep(1000);
        }
        if (!exited && waitpid(child, &status, WNOHANG) == child) {
            exited = true;
        }
    }
    close(channel[0]);
    outcome.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
        outcome.text = std::move(text);
    }
    return outcome;
}

}  // namespace locus::cli
