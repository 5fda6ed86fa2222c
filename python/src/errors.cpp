// locus's typed errors (algebra/error.h) as Python exceptions, all under locus.Error:
//   ParseError(Error, ValueError)   with .line and .column (1-based)
//   InputError(Error, ValueError)   well-formed but unacceptable input
//   Timeout(Error, TimeoutError)    the timeout= of the call passed
//   ResourceError(Error, MemoryError)  a documented size limit would be exceeded
//   VerificationError(Error, ArithmeticError)  an independent check found a result wrong
// and the CLI's CommandFailure (from the surface helpers the renderer shares with `locus`)
// by its exit code.
#include <string>

#include "algebra/error.h"
#include "cli/command_support.h"
#include "cli/exit_codes.h"
#include "python/src/bindings.h"

namespace locus::python {
namespace {

PyObject* new_exception(py::module_& m, const char* name, PyObject* bases, const char* doc) {
    const std::string qualified = std::string("locus.") + name;
    PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases, nullptr);
    if (type == nullptr) {
        throw py::error_already_set();
    }
    m.add_object(name, py::handle(type));
    return type;
}

PyObject* with_base(PyObject* error, PyObject* builtin) {
    return py::make_tuple(py::handle(error), py::handle(builtin)).release().ptr();
}

PyObject* error_type = nullptr;
PyObject* parse_error_type = nullptr;
PyObject* input_error_type = nullptr;
PyObject* timeout_type = nullptr;
PyObject* resource_error_type = nullptr;
PyObject* verification_error_type = nullptr;

void raise(PyObject* type, const char* message) {
    PyErr_SetString(type, message);
}

}  // namespace

void bind_errors(py::module_& m) {
    error_type = new_exception(m, "Error", PyExc_RuntimeError, "Base of every locus error.");
    parse_error_type = new_exception(m, "ParseError", with_base(error_type, PyExc_ValueError),
                                     "Malformed text; .line and .column point at it (1-based).");
    input_error_type = new_exception(m, "InputError", with_base(error_type, PyExc_ValueError),
                                     "Well-formed but unacceptable input.");
    timeout_type = new_exception(m, "Timeout", with_base(error_type, PyExc_TimeoutError),
                                 "The call's timeout passed before it finished.");
    resource_error_type =
        new_exception(m, "ResourceError", with_base(error_type, PyExc_MemoryError),
                      "A documented size limit would be exceeded.");
    verification_error_type =
        new_exception(m, "VerificationError", with_base(error_type, PyExc_ArithmeticError),
                      "An independent check found a result wrong.");
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) {
                std::rethrow_exception(p);
            }
        } catch (const ParseError& e) {
            py::object error = py::reinterpret_borrow<py::object>(parse_error_type)(e.what());
            error.attr("line") = e.line();
            error.attr("column") = e.column();
            error.attr("expected") = e.expected();
            error.attr("found") = e.found();
            PyErr_SetObject(parse_error_type, error.ptr());
        } catch (const ArgumentError& e) {
            raise(input_error_type, e.what());
        } catch (const InputError& e) {
            raise(input_error_type, e.what());
        } catch (const MixedRings& e) {
            raise(input_error_type, e.what());
        } catch (const ExponentOverflow& e) {
            raise(resource_error_type, e.what());
        } catch (const ResourceLimit& e) {
            raise(resource_error_type, e.what());
        } catch (const Timeout& e) {
            raise(timeout_type, e.what());
        } catch (const Error& e) {
            raise(error_type, e.what());
        } catch (const cli::CommandFailure& e) {
            const int code = e.code();
            raise(code == cli::exit_input          ? input_error_type
                  : code == cli::exit_timeout      ? timeout_type
                  : code == cli::exit_check_failed ? verification_error_type
                  : code == cli::exit_resource     ? resource_error_type
                                                   : error_type,
                  e.what());
        }
    });
}

[[noreturn]] void throw_python(PyObject* type, const std::string& message) {
    PyErr_SetString(type, message.c_str());
    throw py::error_already_set();
}

[[noreturn]] void throw_timeout(const std::string& message) {
    throw_python(timeout_type, message);
}
[[noreturn]] void throw_resource_error(const std::string& message) {
    throw_python(resource_error_type, message);
}
[[noreturn]] void throw_verification_error(const std::string& message) {
    throw_python(verification_error_type, message);
}
[[noreturn]] void throw_input_error(const std::string& message) {
    // A C++ exception, translated when it reaches Python: safe on a worker thread without the
    // GIL (PyErr_SetString there crashed locus.render with a bad size).
    throw ArgumentError(message);
}

}  // namespace locus::python
