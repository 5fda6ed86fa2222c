// `locus trace EQUATION [--method M] [--t-max T]`: the first hit along rays read from standard
// input (DESIGN.md, "locus trace"), through the same SurfaceTracer as the renderer. Each input
// line is `ox oy oz dx dy dz`; each output line is the smallest t > 0 with f(o + t·d) = 0 with
// 17 significant digits, `miss`, or `unknown` when the method could not decide.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <sstream>

#include "algebra/error.h"
#include "cli/choices.h"
#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "cli/process_limits.h"
#include "cli/surface_input.h"
#include "render/ray_line.h"
#include "render/surface_tracer.h"

namespace locus::cli {
namespace {

struct TraceArgs {
    std::string equation;
    std::string method = "certified";
    double t_max = 100.0;
    ProcessLimitArgs limits;
};

int run_trace(const TraceArgs& args) {
    apply_process_limits(args.limits);
    const render::TraceMethod method = render::parse_trace_method(args.method);
    if (!(args.t_max > 0.0) || !std::isfinite(args.t_max)) {
        throw CommandFailure(exit_input, "--t-max: expected a positive number");
    }
    const algebra::CompiledPolynomial f = compile_equation("equation", args.equation, "tracing");
    const render::SurfaceTracer tracer(f, method, 1.0);
    std::string line;
    std::size_t line_number = 0;
    while (std::getline(std::cin, line)) {
        ++line_number;
        std::optional<render::Ray> parsed;
        try {
            parsed = render::parse_ray_line(line, line_number);
        } catch (const Error& e) {
            throw failure_about("<stdin>", e);
        }
        if (!parsed) {
            continue;
        }
        const render::Ray& ray = *parsed;
        // (0, t-max]: SurfaceTracer intervals are open at their start.
        const render::Interval interval{0.0, args.t_max};
        const render::RootResult hit = tracer.first_hit(ray, interval);
        if (hit.status == render::RootStatus::hit) {
            std::printf("%.17g\n", hit.t);
        } else if (hit.status == render::RootStatus::miss) {
            std::printf("miss\n");
        } else {
            std::printf("unknown\n");
        }
    }
    std::fflush(stdout);
    return exit_ok;
}

}  // namespace

void add_trace_command(CLI::App& app, CommandContext& context) {
    auto args = std::make_shared<TraceArgs>();
    CLI::App* cmd = app.add_subcommand(
        "trace",
        "First hit of rays (stdin: ox oy oz dx dy dz) with the surface f = 0.\n"
        "With the default method (certified) and with exact, for the exact equation and the\n"
        "exact ray: a hit t is within 1e-12*max(1,|t*|) of the smallest root t* in (0, t-max]\n"
        "(tangent and singular contacts included); 'miss' only when there is no root there.\n"
        "The other methods are floating-point estimates without that guarantee.");
    cmd->add_option("equation", args->equation, "f(x, y, z)")->required();
    add_choice(cmd, "--method", args->method, trace_method_choices(), "the root finder");
    cmd->add_option("--t-max", args->t_max, "search t in (0, T] (default 100)");
    add_process_limit_options(cmd, args->limits);
    cmd->callback([args, &context] { context.exit_code = run_trace(*args); });
}

}  // namespace locus::cli
