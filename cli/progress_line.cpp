#include "cli/progress_line.h"

#include <unistd.h>  // for isatty

#include <chrono>
#include <memory>

namespace locus::cli {

ProgressLine::ProgressLine(std::FILE* out) : out_(out), terminal_(isatty(fileno(out)) != 0) {}

std::function<void(const algebra::GroebnerProgress&)> ProgressLine::groebner(
    const std::string& label) {
    if (!terminal_) {
        return {};
    }
    auto last = std::make_shared<std::chrono::steady_clock::time_point>();
    return [this, label, last](const algebra::GroebnerProgress& p) {
        const auto now = std::chrono::steady_clock::now();
        if (now - *last < std::chrono::milliseconds(100)) {
            return;
        }
        *last = now;
        using Stage = algebra::GroebnerProgress::Stage;
        switch (p.stage) {
        case Stage::pairs:
            std::fprintf(out_, "\r%s: %zu pairs done, %zu left, basis %zu, sugar %u   ",
                         label.c_str(), p.pairs_done, p.pairs_left, p.basis_size, p.current_sugar);
            break;
        case Stage::f4:
            std::fprintf(out_, "\r\033[K%s: modular, F4 step %zu modulo a prime, basis %zu",
                         label.c_str(), p.pairs_done, p.basis_size);
            break;
        case Stage::primes:
            std::fprintf(out_, "\r\033[K%s: modular, %zu primes, basis %zu modulo the last",
                         label.c_str(), p.pairs_done, p.basis_size);
            break;
        case Stage::certification:
            std::fprintf(out_,
                         "\r\033[K%s: certification, %zu of %zu S-pairs reduced to zero, basis %zu",
                         label.c_str(), p.pairs_done, p.pairs_done + p.pairs_left, p.basis_size);
            break;
        }
        std::fflush(out_);
        shown_ = true;
    };
}

std::function<void(double)> ProgressLine::fraction(const std::string& label) {
    if (!terminal_) {
        return {};
    }
    return [this, label](double fraction) {
        const int width = 40;
        const int filled = static_cast<int>(fraction * width);
        std::fprintf(out_, "\r%s [%s%s] %3d%%", label.c_str(), std::string(filled, '#').c_str(),
                     std::string(width - filled, ' ').c_str(), static_cast<int>(100.0 * fraction));
        std::fflush(out_);
        shown_ = true;
    };
}

void ProgressLine::clear() {
    if (shown_.exchange(false)) {
        std::fprintf(out_, "\r\033[K");
        std::fflush(out_);
    }
}

}  // namespace locus::cli
