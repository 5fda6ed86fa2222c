// The suites of `locus-bench`; each registers its subcommand, with its own options, on the app.
#pragma once

#include <CLI/CLI.hpp>

#include "cli/run_app.h"

namespace locus::bench {

// Gröbner bases of bench/data/SUITE.txt against Singular's std (bench/groebner_bench.cpp).
void add_groebner_bench(CLI::App& app, cli::CommandContext& context);
// Implicitization of bench/data/implicit/SUITE.txt by every route, against Singular's
// eliminate (bench/implicit_bench.cpp).
void add_implicit_bench(CLI::App& app, cli::CommandContext& context);
// Every trace method on the surface suite against exact isolation, and surf's time
// (bench/render_bench.cpp).
void add_render_bench(CLI::App& app, cli::CommandContext& context);
// The PNG writer on the surface suite's frames against zlib in the same run
// (bench/png_bench.cpp).
void add_png_bench(CLI::App& app, cli::CommandContext& context);
// The server of `locus view` driven like the page: frames/s and latency (bench/view_bench.cpp).
void add_view_bench(CLI::App& app, cli::CommandContext& context);
// The certification's row kernel, eight reductions together against one a call
// (bench/lanes_bench.cpp).
void add_lanes_bench(CLI::App& app, cli::CommandContext& context);
// Hart's speed-ups on the SDF scene suite (bench/sdf_bench.cpp).
void add_sdf_bench(CLI::App& app, cli::CommandContext& context);

}  // namespace locus::bench
