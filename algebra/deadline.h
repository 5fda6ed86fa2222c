// When long work must stop: at its deadline, or at once when the process asked every computation
// to stop (the Python bindings do on Ctrl-C, from the thread that waits for the work). Every
// loop that polls a deadline polls it through deadline_passed, so one flag reaches Buchberger,
// F4, the certification, implicitization and the renderer alike.
//
// The interrupt is process-wide, like SIGINT itself, and is only seen by work that has a
// deadline: a caller that wants to be interruptible without a time limit gives a distant one.
#pragma once

#include <atomic>
#include <chrono>
#include <optional>

namespace locus {

namespace detail {
inline std::atomic<bool> interrupt_requested{false};
}  // namespace detail

// Ask every computation with a deadline to stop at its next poll, as if its deadline had
// passed; cleared by clear_interrupt once the interrupted work has returned.
inline void request_interrupt() {
    detail::interrupt_requested.store(true, std::memory_order_relaxed);
}
inline void clear_interrupt() {
    detail::interrupt_requested.store(false, std::memory_order_relaxed);
}
inline bool interrupt_requested() {
    return detail::interrupt_requested.load(std::memory_order_relaxed);
}

inline bool deadline_passed(std::chrono::steady_clock::time_point deadline) {
    return interrupt_requested() || std::chrono::steady_clock::now() >= deadline;
}

inline bool deadline_passed(const std::optional<std::chrono::steady_clock::time_point>& deadline) {
    return deadline && deadline_passed(*deadline);
}

}  // namespace locus
