// `locus-bench view`: drives the server of `locus view` as the page does, over HTTP on the
// loopback: a turn around each suite surface in 36 steps, one frame in flight at a time, at a
// quarter of the resolution (128², what dragging asks for) and at full resolution (512², what
// the page shows when the pointer rests), with the page's defaults (certified, no shadows).
// Reports frames per second for each and the input-to-picture latency of the quarter frames
// (request sent to PNG received): the targets are ≥ 15 frames/s at full and ≥ 60 at a
// quarter for degree ≤ 8, ≥ 5 at full for degree 12, latency ≤ 100 ms.
#include <httplib.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <thread>

#include "bench/bench_options.h"
#include "bench/benches.h"
#include "bench/surface_suite.h"
#include "cli/command_support.h"
#include "cli/exit_codes.h"
#include "view/view_server.h"

namespace locus::bench {
namespace {

struct ViewBenchArgs {
    SuiteOptions suite;
    int steps = 36;
    int threads = 0;
    std::string method = "default";
};

struct Run {
    double frames_per_second = 0;
    double median_latency_ms = 0, worst_latency_ms = 0;
    long failed = 0;
};

// One turn around the surface at `side`², the camera on a circle of radius 3.2·clip at a
// fixed height, as dragging moves it.
Run turn(httplib::Client& client, const SuiteSurface& surface, int side, int steps,
         const std::string& method) {
    Run run;
    std::vector<double> latencies;
    const double r = 3.2 * surface.clip_radius;
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < steps; ++k) {
        const double a = 2.0 * M_PI * k / steps;
        char camera[160];
        std::snprintf(camera, sizeof camera, "%.6f,%.6f,%.6f,0,0,0,0,1,0,35", r * std::sin(a),
                      0.45 * r, r * std::cos(a));
        const httplib::Params params = {{"equation", surface.equation},
                                        {"width", std::to_string(side)},
                                        {"height", std::to_string(side)},
                                        {"camera", camera},
                                        {"client", "bench"},
                                        {"shadows", "0"},
                                        {"method", method}};
        const auto sent = std::chrono::steady_clock::now();
        const auto response = client.Post("/api/render", params);
        latencies.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - sent)
                .count());
        if (!response || response->status != 200) {
            ++run.failed;
        }
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    run.frames_per_second = steps / seconds;
    std::sort(latencies.begin(), latencies.end());
    run.median_latency_ms = latencies[latencies.size() / 2];
    run.worst_latency_ms = latencies.back();
    return run;
}

int run_view_bench(const ViewBenchArgs& args) {
    check_suite_options(args.suite);
    if (args.steps < 2 || args.steps > 10000) {
        throw cli::CommandFailure(cli::exit_input, "--steps: expected 2 to 10000");
    }
    std::vector<SuiteSurface> suite =
        parse_surface_suite(cli::read_input(args.suite.data_dir + "/surfaces/SUITE.txt"));
    if (!args.suite.cases.empty()) {
        std::erase_if(suite, [&](const SuiteSurface& s) {
            return std::find(args.suite.cases.begin(), args.suite.cases.end(), s.name) ==
                   args.suite.cases.end();
        });
    }
    view::ViewOptions options;
    options.port = 0;
    options.render_threads = args.threads;
    view::ViewServer server(std::move(options));
    const int port = server.bind();
    std::thread serving([&] { server.run(); });
    httplib::Client client("127.0.0.1", port);
    client.set_read_timeout(120, 0);
    client.set_keep_alive(true);
    client.set_tcp_nodelay(true);  // as a browser does: no Nagle delay between header and body
    if (args.suite.csv) {
        std::cout << "surface,degree,full_fps,quarter_fps,quarter_latency_ms,"
                     "quarter_worst_latency_ms,failed\n";
    } else {
        std::printf("%-16s %6s %12s %12s %14s %14s\n", "surface", "degree", "512² fps", "128² fps",
                    "128² latency", "worst");
    }
    for (const SuiteSurface& surface : suite) {
        const int degree = algebra::compile_surface(surface.equation).degree();
        turn(client, surface, 128, 2, args.method);  // warm: compiled and framed once
        const Run quarter = turn(client, surface, 128, args.steps, args.method);
        const Run full = turn(client, surface, 512, args.steps, args.method);
        if (args.suite.csv) {
            std::cout << surface.name << "," << degree << "," << full.frames_per_second << ","
                      << quarter.frames_per_second << "," << quarter.median_latency_ms << ","
                      << quarter.worst_latency_ms << "," << quarter.failed + full.failed << "\n";
        } else {
            std::printf("%-16s %6d %12.1f %12.1f %11.1f ms %11.1f ms%s\n", surface.name.c_str(),
                        degree, full.frames_per_second, quarter.frames_per_second,
                        quarter.median_latency_ms, quarter.worst_latency_ms,
                        quarter.failed + full.failed > 0 ? "  (failed frames)" : "");
        }
        std::fflush(stdout);
    }
    server.stop();
    serving.join();
    return cli::exit_ok;
}

}  // namespace

void add_view_bench(CLI::App& app, cli::CommandContext& context) {
    auto args = std::make_shared<ViewBenchArgs>();
    CLI::App* cmd = add_suite_command(
        app, context, "view",
        "the server of `locus view` driven like the page: frames/s and latency per surface", args,
        run_view_bench);
    cmd->add_option("--steps", args->steps, "frames per turn (36)");
    cmd->add_option("--threads", args->threads, "render threads (0: every core)");
    cmd->add_option("--method", args->method,
                    "the page's method: default (certified) or any of locus render --method");
}

}  // namespace locus::bench
