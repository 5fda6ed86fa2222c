// `locus implicitize FILE` or `locus implicitize -p s,t "x = s*t" "y = s" "z = t^2"`: the
// implicit equation of a parametrization, verified by substitution.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <optional>
#include <thread>

#include "algebra/error.h"
#include "algebra/flint_convert.h"
#include "algebra/print.h"
#include "cli/choices.h"
#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "cli/heap_pages.h"
#include "cli/process_limits.h"
#include "implicit/bezier_patch.h"
#include "implicit/dixon.h"
#include "implicit/implicitize.h"

namespace locus::cli {
namespace {

struct ImplicitizeArgs {
    std::vector<std::string> inputs;  // a file, or with --params the assignments
    std::string params;
    std::string format = "normalized";
    std::string method = "auto";
    int threads = 0;  // 0: all hardware threads
    ProcessLimitArgs limits;
};

// The maps to implicitize, each with a label for messages: one for a .param file, one per
// patch for a .bpt file.
std::vector<std::pair<std::string, implicit::Parametrization>> read_maps(
    const ImplicitizeArgs& args) {
    std::string text, source;
    if (!args.params.empty()) {
        text = "params: " + args.params + "\n";
        for (const auto& a : args.inputs) {
            text += a + "\n";
        }
        source = "<arguments>";
    } else {
        if (args.inputs.size() != 1) {
            throw CommandFailure(exit_input,
                                 "implicitize: give one parametrization file, or -p PARAMS and "
                                 "the assignments");
        }
        text = read_input(args.inputs[0]);
        source = args.inputs[0] == "-" ? "<stdin>" : args.inputs[0];
    }
    std::vector<std::pair<std::string, implicit::Parametrization>> maps;
    try {
        if (args.params.empty() &&
            (args.inputs[0].ends_with(".bpt") || implicit::looks_like_bpt(text))) {
            const auto patches = implicit::parse_bpt(text);
            for (std::size_t i = 0; i < patches.size(); ++i) {
                maps.emplace_back("patch " + std::to_string(i + 1) + " (line " +
                                      std::to_string(patches[i].first_line) + ")",
                                  implicit::to_parametrization(patches[i]));
            }
        } else {
            maps.emplace_back("", implicit::parse_parametrization(text));
        }
    } catch (const Error& e) {
        throw failure_about(source, e);
    }
    return maps;
}

const char* describe_method(const std::string& method) {
    return method == "resultant"     ? "resultant (iterated Sylvester, factor kept by substitution)"
           : method == "interpolate" ? "interpolate (kernel modulo primes, CRT, rational "
                                       "reconstruction)"
           : method == "dixon"       ? "dixon (Dixon determinant modulo primes, CRT, rational "
                                       "reconstruction, factor kept by substitution)"
           : method == "dixon-minor" ? "dixon (maximal minor of the singular Dixon matrix modulo "
                                       "primes, factor kept by substitution)"
                                     : "groebner (elimination)";
}

// Implicitizes one map and prints its equation (or generators) on stdout; the method and the
// verification go to stderr, prefixed with `label` when there are several maps.
void implicitize_one(const ImplicitizeArgs& args, const implicit::Parametrization& map,
                     const std::string& label, algebra::OutputFormat format,
                     const algebra::GroebnerOptions& options) {
    const std::string prefix = label.empty() ? "" : label + ": ";
    std::string fallback_reason;
    const implicit::ImplicitResult r = implicit::implicitize_by(
        map, *implicit::parse_implicit_method(args.method), options, &fallback_reason);
    if (!fallback_reason.empty()) {
        std::fprintf(stderr, "%sfaster routes gave up (%s)\n", prefix.c_str(),
                     fallback_reason.c_str());
    }
    std::fprintf(stderr, "%smethod: %s\n", prefix.c_str(), describe_method(r.method));
    for (const std::size_t v : map.half_angle) {
        const std::string& u = map.parameter_ring->variable_name(v);
        std::fprintf(stderr,
                     "trigonometric input: cos(%s) -> (1-%s^2)/(1+%s^2), sin(%s) -> 2*%s/(1+%s^2), "
                     "with %s standing for tan(%s/2)\n",
                     u.c_str(), u.c_str(), u.c_str(), u.c_str(), u.c_str(), u.c_str(), u.c_str(),
                     u.c_str());
    }
    const std::size_t k = map.parameter_ring->num_vars();
    // Verified before anything is printed: on the map as written (for angles, with
    // sin(u)^2 + cos(u)^2 = 1, not through the substitution the elimination used).
    const char* as_written = map.half_angle.empty()
                                 ? "the parametrization"
                                 : "the parametrization as written (sin^2 + cos^2 = 1)";
    if (const auto wrong = implicit::first_not_vanishing(r, map)) {
        throw CommandFailure(
            exit_check_failed,
            prefix + (r.equation ? "verification FAILED: the equation does not "
                                   "vanish on the parametrization"
                                 : "verification FAILED for " + algebra::to_string(*wrong)));
    }
    if (r.equation) {
        std::cout << algebra::format_polynomials(std::vector{*r.equation}, *r.ring, format);
        std::cout.flush();
        const algebra::Factorization fac = algebra::factor(*r.equation);
        const bool irreducible = fac.factors.size() == 1 && fac.factors[0].second == 1;
        std::fprintf(stderr, "%sverified: vanishes identically on %s\n", prefix.c_str(),
                     as_written);
        std::fprintf(stderr, "%sdegree %ld, %zu terms, %s\n", prefix.c_str(),
                     r.equation->total_degree(), r.equation->num_terms(),
                     irreducible ? "irreducible" : "reducible");
        return;
    }
    std::cout << algebra::format_polynomials(r.generators, *r.ring, format);
    std::cout.flush();
    std::fprintf(stderr, "%snot principal: %s\n%sverified: all %zu generators vanish on %s\n",
                 prefix.c_str(),
                 implicit::describe_image(r.image, k, map.coordinates.size()).c_str(),
                 prefix.c_str(), r.generators.size(), as_written);
}

int run_implicitize(const ImplicitizeArgs& args, ProgressLine& progress) {
    const Deadline deadline = apply_process_limits(args.limits);
    const algebra::OutputFormat format = algebra::parse_output_format(args.format);
    const auto maps = read_maps(args);
    if (args.threads < 0) {
        throw CommandFailure(exit_input, "--threads " + std::to_string(args.threads) +
                                             ": expected a positive count, or 0 for all cores");
    }
    algebra::GroebnerOptions options;
    options.deadline = deadline;
    options.progress = progress.groebner("implicitize");
    options.threads = args.threads > 0
                          ? args.threads
                          : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    // The main thread's heap only: most parametrizations take milliseconds, where a thread
    // started to advise oneTBB's (heap_pages.h) would cost more than it saves.
    use_large_pages_for_heap(1);
    for (const auto& [label, map] : maps) {
        implicitize_one(args, map, label, format, options);
        progress.clear();
    }
    return exit_ok;
}

}  // namespace

void add_implicitize_command(CLI::App& app, CommandContext& context) {
    auto args = std::make_shared<ImplicitizeArgs>();
    CLI::App* cmd = app.add_subcommand(
        "implicitize", "Implicit equation of a parametrization, verified by substitution");
    cmd->add_option("inputs", args->inputs,
                    "a .param or .bpt file (- for standard input), or with -p the assignments "
                    "\"x = ...\"")
        ->required();
    cmd->add_option("-p,--params", args->params, "parameters, comma-separated (inline form)");
    add_choice(cmd, "--method", args->method,
               {{"auto",
                 "the default: dense surface maps (a numerator or denominator of 9 terms or "
                 "more) dixon; other plane curves and surfaces groebner for 20 ms, then dixon "
                 "(surfaces), interpolate, resultant"},
                {"groebner", "elimination"},
                {"resultant", "iterated Sylvester resultants"},
                {"interpolate", "the kernel modulo primes"},
                {"dixon", "the Dixon determinant modulo primes (surfaces)"}},
               "the route");
    add_choice(cmd, "--format", args->format, output_format_choices(), "output");
    cmd->add_option("--threads", args->threads,
                    "threads for the dixon route's primes and the proofs (0: all cores, the "
                    "default)");
    add_process_limit_options(cmd, args->limits);
    cmd->callback(
        [args, &context] { context.exit_code = run_implicitize(*args, context.progress); });
}

}  // namespace locus::cli
