// What the binding files of `locus._locus` share: the registration functions module.cpp calls,
// exact conversions between Python numbers and Rational, and the rule for long work (run off
// the interpreter's thread with the GIL released, interruptible by Ctrl-C).
#pragma once

#include <pybind11/pybind11.h>

#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>

#include "algebra/deadline.h"
#include "algebra/flint_threads.h"
#include "algebra/poly_ring.h"
#include "algebra/rational.h"

namespace locus::python {

namespace py = pybind11;

void bind_errors(py::module_& m);
void bind_algebra(py::module_& m);
void bind_implicit(py::module_& m);
void bind_render(py::module_& m);

// A bad argument of a binding call, raised as locus.InputError by the translator (errors.cpp).
struct ArgumentError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Raise the locus exception of that name (errors.cpp) from C++. throw_input_error throws
// ArgumentError and may be called anywhere; the others set the Python error and need the GIL:
// only on the interpreter's thread, never inside run_interruptible's work.
[[noreturn]] void throw_timeout(const std::string& message);
[[noreturn]] void throw_resource_error(const std::string& message);
[[noreturn]] void throw_verification_error(const std::string& message);
[[noreturn]] void throw_input_error(const std::string& message);

// A ring as Python holds it (pybind11 cannot hold a shared_ptr to const).
struct Ring {
    algebra::RingPtr ptr;
};

// Python int, fractions.Fraction (any numbers.Rational) or float, exactly (a float is the
// binary fraction it stores). Throws py::type_error for anything else.
algebra::Rational to_rational(const py::handle& value);
bool is_number(const py::handle& value);
// A fractions.Fraction of the same value.
py::object to_fraction(const algebra::Rational& value);

// The deadline of a call: `timeout` seconds from now, or a distant one when there is none, so
// that the work still polls. It is a cancellable deadline (algebra/deadline.h) registered for
// this thread's current call, which run_interruptible cancels on Ctrl-C: only this call stops,
// not the other threads' calls.
std::chrono::steady_clock::time_point deadline_after(std::optional<double> timeout);

// The current call's cancellation flag (null before deadline_after), and the end of the call
// (its deadline's registration is forgotten).
std::atomic<bool>* current_call_flag();
void end_current_call();

// Runs `work` on a thread of its own with the GIL released while this thread checks for
// signals every 20 ms. On Ctrl-C it cancels the call's deadline (deadline_after), waits for the
// work to return, and raises KeyboardInterrupt; otherwise returns the work's result or rethrows
// its exception. `work` must not touch Python objects.
template <class Work>
std::invoke_result_t<Work&> run_interruptible(Work&& work) {
    using Result = std::invoke_result_t<Work&>;
    std::optional<Result> result;
    std::exception_ptr failure;
    bool interrupted = false;
    {
        py::gil_scoped_release release;
        std::mutex mutex;
        std::condition_variable finished;
        bool done = false;
        std::thread worker([&] {
            // FLINT's caches are per thread and only the thread can release them: without
            // this a call that met big integers leaked about 70–220 kB (heaptrack, a loop of
            // groebner calls). What the work returns stays valid (FLINT frees its pages when
            // their last integer is cleared, by whichever thread).
            algebra::release_flint_caches_at_thread_exit();
            try {
                result.emplace(work());
            } catch (...) {
                failure = std::current_exception();
            }
            const std::lock_guard<std::mutex> lock(mutex);
            done = true;
            finished.notify_one();
        });
        std::unique_lock<std::mutex> lock(mutex);
        while (!done) {
            finished.wait_for(lock, std::chrono::milliseconds(20));
            if (done || interrupted) {
                continue;
            }
            lock.unlock();
            {
                py::gil_scoped_acquire acquire;
                // Runs the Python-level handlers; for SIGINT that sets KeyboardInterrupt.
                interrupted = PyErr_CheckSignals() != 0;
            }
            if (interrupted) {
                if (std::atomic<bool>* flag = current_call_flag()) {
                    flag->store(true);
                }
            }
            lock.lock();
        }
        lock.unlock();
        worker.join();
    }
    end_current_call();
    if (interrupted) {
        throw py::error_already_set();
    }
    if (failure) {
        std::rethrow_exception(failure);
    }
    return std::move(*result);
}

}  // namespace locus::python
