// `locus-bench`: the benchmark suites of locus, each against a reference measured in the same
// run (Singular, surf, exact root isolation). Developer tooling: it reads the suites from the
// source tree (bench/data) and drives other programs, which the user binary `locus` never does.
#include <CLI/CLI.hpp>

#include "bench/benches.h"
#include "cli/process_limits.h"
#include "cli/run_app.h"

int main(int argc, char** argv) {
    using namespace locus;
    cli::install_out_of_memory_handlers();
    CLI::App app("locus-bench: the benchmark suites of locus (groebner, implicit, render, sdf)",
                 "locus-bench");
    app.footer(cli::kExitCodesHelp);
    app.require_subcommand(1);
    cli::CommandContext context;
    bench::add_groebner_bench(app, context);
    bench::add_implicit_bench(app, context);
    bench::add_render_bench(app, context);
    bench::add_png_bench(app, context);
    bench::add_sdf_bench(app, context);
    bench::add_view_bench(app, context);
    bench::add_lanes_bench(app, context);
    return cli::run_app(app, context, argc, argv, "locus-bench");
}
