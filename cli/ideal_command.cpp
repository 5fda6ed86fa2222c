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
#include "cli/process_limits.h"

namespace locus::cli {
namespace {

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
    return out;
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
    const auto& gens = ideal.generators;
    if (gens.empty()) {
        throw CommandFailure(exit_input, args.first + ": the ideal has no generators");
    }
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
        const auto report = algebra::zero_dimension_test(gens, options);
        progress.clear();
        switch (report.kind) {
        case algebra::Dimension::unit_ideal:
            std::cout << "unit ideal (no solutions)\n";
            break;
        case algebra::Dimension::zero_dimensional:
            std::cout << "zero-dimensional: " << *report.quotient_dimension
                      << " solutions counted with multiplicity\n";
            break;
        case algebra::Dimension::positive:
            std::cout << "positive-dimensional (infinitely many solutions)\n";
            break;
        }
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
        "  dimension FILE            zero-dimension test and number of solutions");
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
