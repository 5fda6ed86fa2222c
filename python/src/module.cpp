// `locus._locus`, the extension module under the `locus` Python package (python/locus/): the
// registration of every binding file, and the conversions they share.
#include <pybind11/pybind11.h>

#include <memory>
#include <optional>
#include <string>

#include "python/src/bindings.h"

namespace locus::python {

bool is_number(const py::handle& value) {
    if (py::isinstance<py::bool_>(value)) {
        return false;
    }
    if (py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value)) {
        return true;
    }
    static const py::object rational_type = py::module_::import("numbers").attr("Rational");
    return py::isinstance(value, rational_type);
}

algebra::Rational to_rational(const py::handle& value) {
    if (!is_number(value)) {
        throw py::type_error("expected a number (int, fractions.Fraction or float), got " +
                             std::string(py::str(py::type::of(value)).cast<std::string>()));
    }
    std::string text;
    if (py::isinstance<py::int_>(value)) {
        text = py::str(value).cast<std::string>();
    } else if (py::isinstance<py::float_>(value)) {
        const double x = value.cast<double>();
        if (!std::isfinite(x)) {
            throw py::value_error("expected a finite number");
        }
        // The exact binary fraction the float stores.
        const py::tuple ratio = value.attr("as_integer_ratio")();
        text = py::str(ratio[0]).cast<std::string>() + "/" + py::str(ratio[1]).cast<std::string>();
    } else {
        text = py::str(value.attr("numerator")).cast<std::string>() + "/" +
               py::str(value.attr("denominator")).cast<std::string>();
    }
    // Rational's literal reader takes an unsigned numerator.
    const bool negative = !text.empty() && text[0] == '-';
    algebra::Rational out;
    if (!algebra::Rational::from_literal(negative ? text.substr(1) : text, out)) {
        throw py::value_error("not a rational number: " + text);
    }
    return negative ? -out : out;
}

py::object to_fraction(const algebra::Rational& value) {
    static const py::object fraction = py::module_::import("fractions").attr("Fraction");
    const std::string text = value.to_string();
    const auto slash = text.find('/');
    const py::object numerator = py::int_(py::str(text.substr(0, slash)));
    const py::object denominator =
        slash == std::string::npos ? py::int_(1) : py::int_(py::str(text.substr(slash + 1)));
    return fraction(numerator, denominator);
}

namespace {

// The call in progress on this (Python) thread: its flag and registered deadline.
struct CurrentCall {
    std::unique_ptr<std::atomic<bool>> flag;
    std::optional<std::chrono::steady_clock::time_point> registered;
};
thread_local CurrentCall current_call;

}  // namespace

std::atomic<bool>* current_call_flag() {
    return current_call.flag.get();
}

void end_current_call() {
    if (current_call.registered) {
        forget_cancellable_deadline(*current_call.registered);
        current_call.registered.reset();
    }
}

std::chrono::steady_clock::time_point deadline_after(std::optional<double> timeout) {
    const auto now = std::chrono::steady_clock::now();
    // Ten years stands for no limit: far enough, and far from the clock's range.
    const double seconds = timeout ? *timeout : 10.0 * 365 * 86400;
    if (!(seconds >= 0.0) || !std::isfinite(seconds)) {
        throw_input_error("timeout: expected a non-negative number of seconds, or None");
    }
    end_current_call();  // a call that set a deadline and never ran
    current_call.flag = std::make_unique<std::atomic<bool>>(false);
    current_call.registered = cancellable_deadline(
        now + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                  std::chrono::duration<double>(std::min(seconds, 10.0 * 365 * 86400))),
        current_call.flag.get());
    return *current_call.registered;
}

}  // namespace locus::python

PYBIND11_MODULE(_locus, m) {
    m.doc() =
        "locus: exact Gröbner bases, implicitization and certified ray tracing "
        "(the extension under the `locus` package; import locus)";
    locus::python::bind_errors(m);
    locus::python::bind_algebra(m);
    locus::python::bind_implicit(m);
    locus::python::bind_render(m);
}
