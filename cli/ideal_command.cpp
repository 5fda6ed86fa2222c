// `locus ideal OPERATION ...`: ideal operations on ideal files (algebra/ideal_ops.h).
// Operations producing an ideal print its reduced basis like `locus groebner`; yes/no questions
// print `yes` or `no` and exit 0 or 1.
#include <iostream>

#include "algebra/error.h"
#include "algebra/ideal_ops.h"
#include "algebra/parse.h"
#include "algebra/print.h"
#include "cli/choices.h"
#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "cli/heap_pages.h"
#include "cli/process_limits.h"

namespace locus::cli {
namespace {

// c_0 + c_1·v + … as text, ascending ("1+2*t-t^3", as series are written) or descending
// ("3*s+1", as polynomials are); `Number` prints with to_string().
template <class Number>
std::string univariate(const std::vector<Number>& coefficients, const char* v,
                       bool descending = false) {
    std::string out;
    for (std::size_t k = 0; k < coefficients.size(); ++k) {
        const std::size_t e = descending ? coefficients.size() - 1 - k : k;
        std::string c = coefficients[e].to_string();
        if (c == "0") {
            continue;
        }
        const bool negative = c[0] == '-';
        if (negative) {
            c.erase(0, 1);
        }
        out += negative ? "-" : out.empty() ? "" : "+";
        if (e == 0) {
            out += c;
            continue;
        }
        out += c == "1" ? "" : c + "*";
        out += v;
        if (e > 1) {
            out += "^" + std::to_string(e);
        }
    }
    return out.empty() ? "0" : out;
}

// `locus ideal dimension`: the zero-dimension answer first (as before), then the Krull
// dimension, the degree, the Hilbert series and polynomial and an independent set.
void print_dimension(const algebra::HilbertData& h, const algebra::PolyRing& ring) {
    if (h.unit) {
        std::cout << "unit ideal (no solutions)\nKrull dimension: -1\n";
        return;
    }
    if (h.dimension == 0) {
        std::cout << "zero-dimensional: " << h.degree.to_string()
                  << " solutions counted with multiplicity\n";
    } else {
        std::cout << "positive-dimensional (infinitely many solutions)\n";
    }
    std::cout << "Krull dimension: " << h.dimension << "\ndegree: " << h.degree.to_string() << "\n";
    const std::string numerator = univariate(h.reduced_numerator, "t");
    std::cout << "Hilbert series: ";
    if (h.dimension == 0) {
        std::cout << numerator << "\n";
    } else {
        std::cout << (h.reduced_numerator.size() > 1 ? "(" + numerator + ")" : numerator)
                  << "/(1-t)" << (h.dimension > 1 ? "^" + std::to_string(h.dimension) : "") << "\n";
    }
    std::cout << "Hilbert polynomial: " << univariate(h.hilbert_polynomial, "s", true);
    if (h.regularity > 0) {
        std::cout << " (for s >= " << h.regularity << ")";
    }
    std::cout << "\nindependent set: {";
    for (std::size_t i = 0; i < h.independent_set.size(); ++i) {
        std::cout << (i ? ", " : "") << ring.variable_name(h.independent_set[i]);
    }
    std::cout << "}\n";
}

struct IdealArgs {
    std::string operation;
    std::string first;
    std::string second;  // a second ideal file, a polynomial, or a variable list
    std::optional<std::string> order;
    std::string format = "normalized";
    ProcessLimitArgs limits;
};

// The ideal operations compute over Q: an ideal of prime characteristic is refused.
void require_rationals(const algebra::IdealFile& ideal, const std::string& path) {
    if (ideal.characteristic != 0) {
        throw CommandFailure(exit_input, path + ": characteristic " +
                                             std::to_string(ideal.characteristic) +
                                             ": the ideal operations compute over Q (locus "
                                             "groebner computes over GF(p))");
    }
}

// The zero ideal (a file of no non-zero generator) as the one generator 0: the library then
// knows its ring, and every operation has its answer (I : 0 = ⟨1⟩, I ∩ 0 = 0, f ∈ 0 iff f = 0).
std::vector<algebra::Polynomial> with_zero_generator(std::vector<algebra::Polynomial> generators,
                                                     const algebra::RingPtr& ring) {
    if (generators.empty()) {
        generators.emplace_back(ring);
    }
    return generators;
}

// The generators of `path`, moved into `ring` (same variable names, any declared order).
std::vector<algebra::Polynomial> generators_in(const std::string& path,
                                               const algebra::RingPtr& ring) {
    const algebra::IdealFile other = read_ideal(path);
    require_rationals(other, path);
    std::vector<std::size_t> map;
    for (const auto& name : other.ring->variable_names()) {
        const auto v = ring->variable_index(name);
        if (!v) {
            throw CommandFailure(exit_input, path + ": variable '" + name +
                                                 "' is not a variable of the first ideal");
        }
        map.push_back(*v);
    }
    std::vector<algebra::Polynomial> out;
    for (const auto& g : other.generators) {
        out.push_back(g.in_ring(ring, map));
    }
    return with_zero_generator(std::move(out), ring);
}

algebra::Polynomial polynomial_argument(const std::string& text, const algebra::RingPtr& ring) {
    try {
        return algebra::parse_polynomial(text, ring);
    } catch (const ParseError& e) {
        throw CommandFailure(exit_input, std::string("polynomial argument: ") + e.what());
    }
}

int answer(bool yes, ProgressLine& progress) {
    progress.clear();
    std::cout << (yes ? "yes" : "no") << "\n";
    return yes ? exit_ok : exit_no;
}

int run_operation(const IdealArgs& args, const algebra::GroebnerOptions& options,
                  ProgressLine& progress) {
    const algebra::OutputFormat format = algebra::parse_output_format(args.format);
    const bool second_is_file = args.operation != "member" && args.operation != "radical-member" &&
                                args.operation != "eliminate" && args.operation != "dimension";
    if (args.first == "-" && second_is_file && args.second == "-") {
        throw CommandFailure(exit_input, "ideal " + args.operation +
                                             ": standard input can be read only once; give a "
                                             "file for one of the two ideals");
    }
    const algebra::IdealFile ideal = read_ideal(args.first, args.order);
    require_rationals(ideal, args.first);
    const algebra::RingPtr& ring = ideal.ring;
    const std::vector<algebra::Polynomial> gens = args.operation == "dimension"
                                                      ? ideal.generators
                                                      : with_zero_generator(ideal.generators, ring);
    auto print_basis = [&](const std::vector<algebra::Polynomial>& basis) {
        progress.clear();
        std::cout << algebra::format_polynomials(basis, *ring, format);
        return exit_ok;
    };
    const std::string& op = args.operation;
    const bool needs_second = op != "dimension";
    if (needs_second && args.second.empty()) {
        throw CommandFailure(exit_input, "ideal " + op + ": missing second argument");
    }
    if (!needs_second && !args.second.empty()) {
        throw CommandFailure(exit_input, "ideal " + op +
                                             ": takes one ideal file, found a second "
                                             "argument '" +
                                             args.second + "'");
    }
    if (op == "member") {
        const auto cert =
            algebra::ideal_membership(polynomial_argument(args.second, ring), gens, options);
        progress.clear();
        if (!cert.is_member) {
            std::cout << "no\nremainder: " << algebra::format_polynomial(cert.remainder, format)
                      << "\n";
            return exit_no;
        }
        std::cout << "yes\n";
        for (std::size_t i = 0; i < cert.cofactors.size(); ++i) {
            std::cout << "cofactor " << i + 1 << ": "
                      << algebra::format_polynomial(cert.cofactors[i], format) << "\n";
        }
        return exit_ok;
    }
    if (op == "radical-member") {
        return answer(
            algebra::radical_membership(polynomial_argument(args.second, ring), gens, options),
            progress);
    }
    if (op == "eliminate") {
        std::vector<std::size_t> vars;
        const std::vector<std::string> names = [&] {
            try {
                return algebra::parse_name_list(args.second, 1, 1);
            } catch (const Error& e) {
                throw failure_about("eliminate: the variables '" + args.second + "'", e);
            }
        }();
        for (const auto& name : names) {
            const auto v = ring->variable_index(name);
            if (!v) {
                throw CommandFailure(exit_input, "eliminate: '" + name + "' is not a variable");
            }
            vars.push_back(*v);
        }
        return print_basis(algebra::eliminate(gens, vars, options));
    }
    if (op == "dimension") {
        const algebra::HilbertData h = algebra::ideal_hilbert_data(ring, gens, options);
        progress.clear();
        print_dimension(h, *ring);
        return exit_ok;
    }
    const auto second = generators_in(args.second, ring);
    if (op == "sum") {
        return print_basis(algebra::ideal_sum(gens, second, options));
    }
    if (op == "product") {
        return print_basis(algebra::ideal_product(gens, second, options));
    }
    if (op == "intersect") {
        return print_basis(algebra::ideal_intersection(gens, second, options));
    }
    if (op == "quotient") {
        return print_basis(algebra::ideal_quotient(gens, second, options));
    }
    if (op == "saturate") {
        return print_basis(algebra::saturation(gens, second, options));
    }
    if (op == "contains") {
        return answer(algebra::ideal_contains(gens, second, options), progress);
    }
    if (op == "equal") {
        return answer(algebra::ideal_equal(gens, second, options), progress);
    }
    throw CommandFailure(exit_input, "ideal: unknown operation '" + op + "'");
}

int run_ideal(const IdealArgs& args, ProgressLine& progress) {
    algebra::GroebnerOptions options;
    options.deadline = apply_process_limits(args.limits);
    use_large_pages_for_heap(1);  // the ideal operations run on one thread
    options.progress = progress.groebner("ideal " + args.operation);
    try {
        return run_operation(args, options, progress);
    } catch (const Timeout& e) {
        throw CommandFailure(
            exit_timeout, std::string(e.what()) + " (--timeout " + timeout_text(args.limits) + ")");
    }
}

}  // namespace

void add_ideal_command(CLI::App& app, CommandContext& context) {
    auto args = std::make_shared<IdealArgs>();
    CLI::App* cmd = app.add_subcommand("ideal", "Ideal operations on ideal files");
    cmd->footer(
        "Operations:\n"
        "  member FILE POLY          is POLY in the ideal? prints cofactors (exit 1 if not)\n"
        "  radical-member FILE POLY  is POLY in the radical? (exit 1 if not)\n"
        "  eliminate FILE VARS       elimination ideal, VARS comma-separated\n"
        "  sum|product|intersect|quotient|saturate FILE1 FILE2\n"
        "                            the ideal I op J, as a reduced basis in FILE1's ring\n"
        "  contains FILE1 FILE2      is the second ideal contained in the first? (exit 1 if not)\n"
        "  equal FILE1 FILE2         are the ideals equal? (exit 1 if not)\n"
        "  dimension FILE            Krull dimension, degree, Hilbert series and polynomial");
    cmd->add_option("operation", args->operation, "the operation (see below)")
        ->required()
        ->check(
            CLI::IsMember({"member", "radical-member", "eliminate", "sum", "product", "intersect",
                           "quotient", "saturate", "contains", "equal", "dimension"}));
    cmd->add_option("file", args->first, "ideal file (- for standard input)")->required();
    cmd->add_option("argument", args->second, "second ideal file, polynomial or variables");
    cmd->add_option("--order", args->order, "override the first file's order");
    add_choice(cmd, "--format", args->format, output_format_choices(), "output");
    add_process_limit_options(cmd, args->limits);
    cmd->callback([args, &context] { context.exit_code = run_ideal(*args, context.progress); });
}

}  // namespace locus::cli
