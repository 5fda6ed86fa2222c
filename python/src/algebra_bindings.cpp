// Rings, polynomials, Gröbner bases, division and the ideal operations as `locus._locus`
// exposes them; python/locus/__init__.py builds the documented API on top (strings with vars=,
// the Basis list, the `ideal` namespace).
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "algebra/division.h"
#include "algebra/error.h"
#include "algebra/groebner.h"
#include "algebra/groebner/verify.h"
#include "algebra/ideal_ops.h"
#include "algebra/monomial.h"
#include "algebra/monomial_order.h"
#include "algebra/parse.h"
#include "algebra/print.h"
#include "algebra/system_input.h"
#include "python/src/bindings.h"

namespace locus::python {
namespace {

using algebra::Polynomial;
using algebra::Rational;
using algebra::RingPtr;
using Polynomials = std::vector<Polynomial>;

std::vector<std::string> variable_list(const py::object& variables) {
    if (py::isinstance<py::str>(variables)) {
        const std::string text = variables.cast<std::string>();
        return algebra::parse_name_list(text, 1, 1);
    }
    return variables.cast<std::vector<std::string>>();
}

Ring make_ring(const py::object& variables, const std::string& order) {
    std::vector<std::string> names = variable_list(variables);
    if (names.empty()) {
        throw_input_error("Ring: expected at least one variable");
    }
    algebra::MonomialOrder parsed = algebra::parse_monomial_order(order, names);
    return Ring{algebra::PolyRing::make(std::move(names), std::move(parsed))};
}

std::size_t variable_index(const Ring& ring, const py::handle& variable) {
    if (py::isinstance<py::int_>(variable)) {
        const long i = variable.cast<long>();
        if (i < 0 || static_cast<std::size_t>(i) >= ring.ptr->num_vars()) {
            throw py::index_error("variable index " + std::to_string(i) + " out of range");
        }
        return static_cast<std::size_t>(i);
    }
    std::string name;
    if (py::isinstance<Polynomial>(variable)) {
        name = algebra::to_string(variable.cast<const Polynomial&>());
    } else {
        name = variable.cast<std::string>();
    }
    const auto index = ring.ptr->variable_index(name);
    if (!index) {
        throw_input_error("'" + name + "' is not a variable of the ring");
    }
    return *index;
}

// A polynomial, or a number made a constant of `ring`.
Polynomial as_polynomial(const py::handle& value, const RingPtr& ring) {
    if (py::isinstance<Polynomial>(value)) {
        return value.cast<Polynomial>();
    }
    if (py::isinstance<py::str>(value)) {
        return algebra::parse_polynomial(value.cast<std::string>(), ring);
    }
    return Polynomial::constant(ring, to_rational(value));
}

RingPtr common_ring(const Polynomials& polys) {
    if (polys.empty()) {
        throw_input_error("expected at least one polynomial");
    }
    for (const Polynomial& p : polys) {
        if (!algebra::same_ring(p.ring(), polys.front().ring())) {
            throw MixedRings();
        }
    }
    return polys.front().ring();
}

std::string ring_repr(const Ring& ring) {
    std::string names;
    for (const std::string& n : ring.ptr->variable_names()) {
        names += (names.empty() ? "" : ",") + n;
    }
    return "Ring('" + names + "', order='" +
           ring.ptr->order().to_string(ring.ptr->variable_names()) + "')";
}

py::object evaluate(const Polynomial& f, const py::args& args) {
    if (args.size() != f.ring()->num_vars()) {
        throw py::type_error("expected " + std::to_string(f.ring()->num_vars()) +
                             " values, one per variable");
    }
    std::vector<Rational> point;
    bool any_float = false;
    for (const py::handle value : args) {
        any_float = any_float || py::isinstance<py::float_>(value);
        point.push_back(to_rational(value));
    }
    py::object exact = to_fraction(f.evaluate(point));
    // Exact at the floats' binary values, rounded once at the end.
    return any_float ? py::float_(exact) : exact;
}

Polynomial substitute(const Polynomial& f, const py::dict& values) {
    const Ring ring{f.ring()};
    Polynomials images;
    for (std::size_t v = 0; v < ring.ptr->num_vars(); ++v) {
        images.push_back(Polynomial::variable(ring.ptr, v));
    }
    for (const auto& [key, value] : values) {
        images[variable_index(ring, key)] = as_polynomial(value, ring.ptr);
    }
    return f.substitute(images);
}

py::list terms_of(const Polynomial& f) {
    py::list out;
    for (std::size_t i = 0; i < f.num_terms(); ++i) {
        const std::vector<std::uint32_t> e = f.exponents(i);
        out.append(py::make_tuple(to_fraction(f.coefficient(i)), py::tuple(py::cast(e))));
    }
    return out;
}

// Moves f into `target` by variable names (its order may differ; variables f does not use
// need not exist there).
Polynomial in_ring(const Polynomial& f, const Ring& target) {
    const auto& names = f.ring()->variable_names();
    std::vector<std::size_t> map(names.size(), 0);
    for (std::size_t v = 0; v < names.size(); ++v) {
        const auto index = target.ptr->variable_index(names[v]);
        if (index) {
            map[v] = *index;
        } else if (f.contains_variable(v)) {
            throw_input_error("'" + names[v] + "' is not a variable of the target ring");
        }
    }
    return f.in_ring(target.ptr, map);
}

algebra::GroebnerOptions ideal_options(std::optional<double> timeout) {
    algebra::GroebnerOptions options;
    options.deadline = deadline_after(timeout);
    return options;
}

py::dict stats_of(const algebra::GroebnerAnswer& a) {
    py::dict s;
    s["algorithm"] = algebra::algorithm_name(a.algorithm);
    s["characteristic"] = a.characteristic;
    s["certified"] = a.certified;
    s["seconds"] = a.stats.seconds;
    s["pairs_created"] = a.stats.pairs_created;
    s["reductions"] = a.stats.reductions;
    s["zero_reductions"] = a.stats.zero_reductions;
    s["basis_size"] = a.basis.size();
    if (a.modular) {
        s["primes"] = a.modular->primes_used.size();
        s["lift_seconds"] = a.modular->lift_seconds;
        s["certify_seconds"] = a.modular->certify_seconds;
        s["f4_seconds"] = a.modular->modular_seconds;
        if (a.modular->equality) {
            // "proven": the basis generates exactly the input's ideal (not only contains it).
            s["ideal_equality"] = algebra::ideal_equality_status_name(a.modular->equality->status);
            s["ideal_equality_argument"] = a.modular->equality->argument;
        }
    }
    if (a.f4) {
        s["f4_steps"] = a.f4->steps;
        s["largest_matrix"] = py::make_tuple(a.f4->largest_rows, a.f4->largest_columns);
    }
    return s;
}

py::tuple groebner_basis(const Polynomials& polys, const std::string& algorithm, bool certify,
                         std::optional<double> timeout, std::uint32_t characteristic, int threads,
                         bool check) {
    const RingPtr ring = common_ring(polys);
    algebra::GroebnerRequest request;
    const auto parsed = algebra::parse_algorithm(algorithm);
    if (!parsed) {
        throw_input_error("algorithm '" + algorithm +
                          "': expected auto, buchberger, signature or modular");
    }
    request.algorithm = *parsed;
    request.characteristic = characteristic;
    request.certify = certify;
    request.threads = std::max(1, threads);
    request.deadline = deadline_after(timeout);
    struct Checked {
        algebra::GroebnerAnswer answer;
        std::string check_failure;  // empty: not asked, or passed
    };
    const Checked checked = run_interruptible([&] {
        Checked c{algebra::groebner(polys, request), {}};
        const algebra::GroebnerAnswer& a = c.answer;
        if (check && a.outcome == algebra::GroebnerOutcome::complete) {
            const algebra::BasisCheck verdict =
                characteristic != 0 ? algebra::check_groebner_basis_modulo(
                                          a.basis, polys, characteristic, request.deadline)
                                    : algebra::check_groebner_basis(a.basis, polys);
            if (!verdict.ok) {
                c.check_failure = verdict.failure;
            } else if (!algebra::is_reduced(a.basis)) {
                c.check_failure = "the basis is not reduced";
            }
        }
        return c;
    });
    const algebra::GroebnerAnswer& answer = checked.answer;
    if (!checked.check_failure.empty()) {
        throw_verification_error("groebner: check FAILED: " + checked.check_failure);
    }
    switch (answer.outcome) {
    case algebra::GroebnerOutcome::complete:
        break;
    case algebra::GroebnerOutcome::stopped_timeout:
        throw_timeout("groebner: " + answer.reason + " (timeout " +
                      (timeout ? std::to_string(*timeout) + " s" : std::string("none")) +
                      "); the basis is not complete");
    case algebra::GroebnerOutcome::stopped_size:
    case algebra::GroebnerOutcome::unable:
        throw_resource_error(answer.reason);
    }
    return py::make_tuple(answer.basis, stats_of(answer));
}

void bind_ring(py::module_& m) {
    py::class_<Ring>(m, "Ring",
                     "A polynomial ring Q[variables] with a monomial order: lex, grlex, grevlex, "
                     "weights(...), elim(...), matrix(...), as in ideal files.")
        .def(py::init(&make_ring), py::arg("variables"), py::arg("order") = "grevlex")
        .def_property_readonly("variables", [](const Ring& r) { return r.ptr->variable_names(); })
        .def_property_readonly(
            "order",
            [](const Ring& r) { return r.ptr->order().to_string(r.ptr->variable_names()); })
        .def(
            "__call__",
            [](const Ring& r, const py::object& value) { return as_polynomial(value, r.ptr); },
            "Parses a polynomial (`x^2 - y`, `x**2 - y`) or makes a number a constant.")
        .def("gens",
             [](const Ring& r) {
                 Polynomials out;
                 for (std::size_t v = 0; v < r.ptr->num_vars(); ++v) {
                     out.push_back(Polynomial::variable(r.ptr, v));
                 }
                 return out;
             })
        .def("with_order",
             [](const Ring& r, const std::string& order) {
                 return Ring{r.ptr->with_order(
                     algebra::parse_monomial_order(order, r.ptr->variable_names()))};
             })
        .def("__eq__", [](const Ring& a, const Ring& b) { return *a.ptr == *b.ptr; })
        .def("__hash__", [](const Ring& r) { return py::hash(py::str(ring_repr(r))); })
        .def("__repr__", &ring_repr);
}

void bind_polynomial(py::module_& m) {
    using P = const Polynomial&;
    py::class_<Polynomial>(m, "Polynomial", "A polynomial with exact rational coefficients.")
        .def_property_readonly("ring", [](P f) { return Ring{f.ring()}; })
        .def("__str__", [](P f) { return algebra::to_string(f); })
        .def("__repr__",
             [](P f) {
                 return "Polynomial('" + algebra::to_string(f) + "', " + ring_repr(Ring{f.ring()}) +
                        ")";
             })
        .def("__add__", [](P f, const py::object& g) { return f + as_polynomial(g, f.ring()); })
        .def("__radd__", [](P f, const py::object& g) { return as_polynomial(g, f.ring()) + f; })
        .def("__sub__", [](P f, const py::object& g) { return f - as_polynomial(g, f.ring()); })
        .def("__rsub__", [](P f, const py::object& g) { return as_polynomial(g, f.ring()) - f; })
        .def("__mul__", [](P f, const py::object& g) { return f * as_polynomial(g, f.ring()); })
        .def("__rmul__", [](P f, const py::object& g) { return as_polynomial(g, f.ring()) * f; })
        .def("__truediv__",
             [](P f, const py::object& c) {
                 const Rational divisor = to_rational(c);
                 if (divisor.is_zero()) {
                     throw py::value_error("division by zero");
                 }
                 return f * (Rational(1) / divisor);
             })
        .def("__neg__", [](P f) { return -f; })
        .def(
            "__pow__",
            [](P f, const py::int_& exponent) {
                // Checked before any narrowing: 2**32 must not wrap to 0.
                const py::int_ limit(algebra::MonomialLayout::max_field_value);
                if (exponent < py::int_(0)) {
                    throw py::value_error("a polynomial power needs a non-negative exponent");
                }
                if (exponent > limit) {
                    throw py::value_error("an exponent of at most " +
                                          std::to_string(algebra::MonomialLayout::max_field_value));
                }
                const auto k = exponent.cast<unsigned long>();
                return run_interruptible([&] { return f.pow(static_cast<unsigned>(k)); });
            })
        .def("__eq__",
             [](P f, const py::object& g) {
                 if (!py::isinstance<Polynomial>(g) && !is_number(g)) {
                     return false;
                 }
                 if (py::isinstance<Polynomial>(g) &&
                     !algebra::same_ring(g.cast<P>().ring(), f.ring())) {
                     return false;
                 }
                 return f == as_polynomial(g, f.ring());
             })
        // A constant hashes as the number it equals (R(1) == 1, so their hashes agree).
        .def("__hash__",
             [](P f) {
                 if (f.is_constant()) {
                     return py::hash(f.is_zero() ? py::object(py::int_(0))
                                                 : to_fraction(f.leading_coefficient()));
                 }
                 return py::hash(py::str(algebra::to_string(f)));
             })
        .def("__bool__", [](P f) { return !f.is_zero(); })
        .def("__call__", &evaluate, "The exact value at a point (a float if any value is one).")
        .def(
            "diff",
            [](P f, const py::object& v) {
                return f.derivative(variable_index(Ring{f.ring()}, v));
            },
            py::arg("variable"))
        .def("subs", &substitute, py::arg("values"),
             "Substitutes {variable: polynomial or number}, at once.")
        .def("terms", &terms_of, "[(coefficient as Fraction, exponents)], leading term first.")
        .def(
            "degree",
            [](P f, const py::object& v) {
                return v.is_none() ? f.total_degree() : f.degree(variable_index(Ring{f.ring()}, v));
            },
            py::arg("variable") = py::none())
        .def("leading_coefficient", [](P f) { return to_fraction(f.leading_coefficient()); })
        .def("is_zero", &Polynomial::is_zero)
        .def("in_ring", &in_ring, py::arg("ring"))
        .def(
            "format",
            [](P f, const std::string& format) {
                std::string text = algebra::format_polynomials(
                    std::vector{f}, *f.ring(), algebra::parse_output_format(format));
                while (!text.empty() && text.back() == '\n') {
                    text.pop_back();
                }
                return text;
            },
            py::arg("format"));
}

void bind_groebner(py::module_& m) {
    m.def("_groebner", &groebner_basis, py::arg("polys"), py::arg("algorithm"), py::arg("certify"),
          py::arg("timeout"), py::arg("characteristic"), py::arg("threads"), py::arg("check"));
    m.def("_format", [](const Polynomials& polys, const Ring& ring, const std::string& format,
                        std::uint32_t characteristic) {
        return algebra::format_polynomials(polys, *ring.ptr, algebra::parse_output_format(format),
                                           "G", characteristic);
    });
    m.def("_verify", [](const Polynomials& basis, const Polynomials& generators,
                        std::uint32_t characteristic) {
        const algebra::BasisCheck c = characteristic != 0
                                          ? algebra::check_groebner_basis_modulo(
                                                basis, generators, characteristic, std::nullopt)
                                          : algebra::check_groebner_basis(basis, generators);
        return py::make_tuple(c.ok, c.ok && !algebra::is_reduced(basis)
                                        ? std::string("the basis is not reduced")
                                        : c.failure);
    });
    m.def("_read_ideal", [](const std::string& text, bool msolve) {
        // As `locus groebner FILE` reads: msolve's format by the .ms extension, else by content
        // (an ideal file, a Singular or Macaulay2 session, msolve's two header lines).
        const algebra::IdealFile file = algebra::parse_ideal_text(
            text, msolve ? algebra::IdealFormat::msolve : algebra::detect_ideal_format(text));
        return py::make_tuple(Ring{file.ring}, file.generators, file.characteristic);
    });
    m.def("_divide", [](const Polynomial& f, const Polynomials& divisors) {
        algebra::DivisionResult r = algebra::divide(f, divisors);
        return py::make_tuple(r.quotients, r.remainder);
    });
    m.def("_normal_form", [](const Polynomial& f, const Polynomials& basis) {
        return algebra::normal_form(f, basis);
    });
}

// The ideal operations: each takes generators (and a timeout) and returns a reduced basis or
// an answer; the work runs interruptibly.
void bind_ideal_operations(py::module_& m) {
    using Binary =
        Polynomials (*)(algebra::Generators, algebra::Generators, const algebra::GroebnerOptions&);
    const auto binary = [&m](const char* name, Binary operation) {
        m.def(name, [operation](const Polynomials& i, const Polynomials& j,
                                std::optional<double> timeout) {
            const auto options = ideal_options(timeout);
            return run_interruptible([&] { return operation(i, j, options); });
        });
    };
    binary("_ideal_sum", &algebra::ideal_sum);
    binary("_ideal_product", &algebra::ideal_product);
    binary("_ideal_intersection", &algebra::ideal_intersection);
    binary("_ideal_quotient", &algebra::ideal_quotient);
    binary("_saturation", &algebra::saturation);
    m.def("_eliminate",
          [](const Polynomials& gens, const py::list& variables, std::optional<double> timeout) {
              const Ring ring{common_ring(gens)};
              std::vector<std::size_t> indices;
              for (const py::handle v : variables) {
                  indices.push_back(variable_index(ring, v));
              }
              const auto options = ideal_options(timeout);
              return run_interruptible([&] { return algebra::eliminate(gens, indices, options); });
          });
    m.def("_contains", [](const Polynomials& i, const Polynomials& j, std::optional<double> t) {
        const auto options = ideal_options(t);
        return run_interruptible([&] { return algebra::ideal_contains(i, j, options); });
    });
    m.def("_equal", [](const Polynomials& i, const Polynomials& j, std::optional<double> t) {
        const auto options = ideal_options(t);
        return run_interruptible([&] { return algebra::ideal_equal(i, j, options); });
    });
    m.def("_member", [](const Polynomial& f, const Polynomials& gens, std::optional<double> t) {
        const auto options = ideal_options(t);
        algebra::MembershipCertificate c =
            run_interruptible([&] { return algebra::ideal_membership(f, gens, options); });
        return py::make_tuple(c.is_member, c.cofactors, c.remainder);
    });
    m.def("_radical_member", [](const Polynomial& f, const Polynomials& gens,
                                std::optional<double> t) {
        const auto options = ideal_options(t);
        return run_interruptible([&] { return algebra::radical_membership(f, gens, options); });
    });
    m.def("_dimension", [](const Ring& ring, const Polynomials& gens, std::optional<double> t) {
        const auto options = ideal_options(t);
        const algebra::HilbertData h =
            run_interruptible([&] { return algebra::ideal_hilbert_data(ring.ptr, gens, options); });
        py::dict out;
        if (h.unit) {
            out["kind"] = "unit";
            out["dimension"] = -1;
            out["solutions"] = 0;
            return out;
        }
        out["kind"] = h.dimension == 0 ? "zero-dimensional" : "positive-dimensional";
        out["dimension"] = h.dimension;
        out["degree"] = py::int_(py::str(h.degree.to_string()));
        out["solutions"] = h.dimension == 0 ? py::object(out["degree"]) : py::none();
        py::list series, polynomial, independent;
        for (const algebra::Integer& q : h.reduced_numerator) {
            series.append(py::int_(py::str(q.to_string())));
        }
        for (const Rational& c : h.hilbert_polynomial) {
            polynomial.append(to_fraction(c));
        }
        for (const std::size_t v : h.independent_set) {
            independent.append(ring.ptr->variable_name(v));
        }
        out["hilbert_series"] = series;
        out["hilbert_polynomial"] = polynomial;
        out["regularity"] = h.regularity;
        out["independent_set"] = independent;
        return out;
    });
}

}  // namespace

void bind_algebra(py::module_& m) {
    bind_ring(m);
    bind_polynomial(m);
    bind_groebner(m);
    bind_ideal_operations(m);
}

}  // namespace locus::python
