// When long work must stop: at its deadline, or at once when whoever gave that deadline
// cancels it (the Python bindings do on Ctrl-C, from the thread that waits for the work). Every
// loop that polls a deadline polls it through deadline_passed, so a cancellation reaches
// Buchberger, F4, the certification, implicitization and the renderer alike, on whichever
// threads they run.
//
// A cancellable deadline is an instant made unique to its caller and registered with a flag:
// every copy of it, in every thread, then reads that flag. Other computations, with other
// deadlines, are not affected. Work without a deadline cannot be cancelled: a caller that wants
// to be without a time limit gives a distant one.
#pragma once

#include <atomic>
#include <chrono>
#include <map>
#include <mutex>
#include <optional>

namespace locus {

namespace detail {
struct CancellableDeadlines {
    std::mutex mutex;
    std::map<std::chrono::steady_clock::time_point, const std::atomic<bool>*> flags;
    std::atomic<std::size_t> count{0};  // read without the lock: most polls find none
};
inline CancellableDeadlines cancellable_deadlines;
}  // namespace detail

// Registers `cancelled` for the returned instant: `deadline`, or the first nanosecond after it
// that no other registration holds. Work given that instant stops at its next poll once
// `cancelled` is true. Unregister with forget_cancellable_deadline when the work has returned.
inline std::chrono::steady_clock::time_point cancellable_deadline(
    std::chrono::steady_clock::time_point deadline, const std::atomic<bool>* cancelled) {
    detail::CancellableDeadlines& d = detail::cancellable_deadlines;
    const std::lock_guard<std::mutex> lock(d.mutex);
    while (d.flags.count(deadline) != 0) {
        deadline += std::chrono::nanoseconds(1);
    }
    d.flags.emplace(deadline, cancelled);
    d.count.store(d.flags.size(), std::memory_order_relaxed);
    return deadline;
}

inline void forget_cancellable_deadline(std::chrono::steady_clock::time_point deadline) {
    detail::CancellableDeadlines& d = detail::cancellable_deadlines;
    const std::lock_guard<std::mutex> lock(d.mutex);
    d.flags.erase(deadline);
    d.count.store(d.flags.size(), std::memory_order_relaxed);
}

inline bool deadline_passed(std::chrono::steady_clock::time_point deadline) {
    detail::CancellableDeadlines& d = detail::cancellable_deadlines;
    if (d.count.load(std::memory_order_relaxed) != 0) {
        const std::lock_guard<std::mutex> lock(d.mutex);
        const auto it = d.flags.find(deadline);
        if (it != d.flags.end() && it->second->load(std::memory_order_relaxed)) {
            return true;
        }
    }
    return std::chrono::steady_clock::now() >= deadline;
}

inline bool deadline_passed(const std::optional<std::chrono::steady_clock::time_point>& deadline) {
    return deadline && deadline_passed(*deadline);
}

}  // namespace locus
