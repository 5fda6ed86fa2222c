// Internal to render/: a thread's scratch object, kept from one use to the next so that its
// memory is allocated, and its pages faulted in, once per thread rather than once per use (a
// frame's rows, a PNG's bands, a row's hits).
#pragma once

#include <optional>

namespace locus::render::detail {

// ThreadScratch<T> scratch; T& t = scratch.get(); — this thread's T for the scratch's lifetime.
// A use begun on the same thread while that T is in use (parallel work waited on inside the
// first use, during which the thread may take another task) gets a T of its own instead.
template <class T>
class ThreadScratch {
  public:
    ThreadScratch() : holds_shared_(!busy()) {
        if (holds_shared_) {
            busy() = true;
        } else {
            own_.emplace();
        }
    }
    ~ThreadScratch() {
        if (holds_shared_) {
            busy() = false;
        }
    }
    ThreadScratch(const ThreadScratch&) = delete;
    ThreadScratch& operator=(const ThreadScratch&) = delete;

    T& get() { return holds_shared_ ? shared() : *own_; }

  private:
    static T& shared() {
        thread_local T value;
        return value;
    }
    static bool& busy() {
        thread_local bool in_use = false;
        return in_use;
    }

    bool holds_shared_;
    std::optional<T> own_;
};

}  // namespace locus::render::detail
