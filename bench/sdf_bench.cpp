// `locus-bench sdf`: Hart's speed-ups on SDF scenes (bench/data/sdf/SUITE.txt). Every scene's
// primary rays are traced (no shading) with the speed-ups off, each one alone, and all on;
// the rows give rays per second, primitive evaluations per ray and the share of pixels whose
// first hit differs from the plain march.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "algebra/error.h"
#include "bench/bench_options.h"
#include "bench/benches.h"
#include "cli/command_support.h"
#include "cli/exit_codes.h"
#include "cli/surface_input.h"
#include "render/camera.h"
#include "render/scene_file.h"
#include "render/sdf/scene_tracer.h"
#include "render/sdf/sdf_renderer.h"

namespace locus::bench {
namespace {

using cli::CommandFailure;
using cli::exit_input;
using cli::exit_ok;

struct SdfBenchArgs {
    SuiteOptions suite;
    int size = 256;  // image width; the height follows the scene's aspect
};

struct Setting {
    const char* name;
    render::sdf::SpeedUps speed_ups;
};

constexpr Setting kSettings[] = {
    {"none", render::sdf::kNoSpeedUps},
    {"bounding_volumes",
     {.bounding_volumes = true, .triangle_inequality = false, .convexity = false}},
    {"triangle_inequality",
     {.bounding_volumes = false, .triangle_inequality = true, .convexity = false}},
    {"convexity", {.bounding_volumes = false, .triangle_inequality = false, .convexity = true}},
    {"all", {}},
};

struct Frame {
    std::vector<render::sdf::SceneHit> hits;
    long evaluations = 0;
    long root_work = 0;
    double seconds = 0.0;
    int runs = 0;
};

Frame trace_frame(const std::vector<render::sdf::NodePtr>& items, double scale,
                  const render::Camera& camera, int width, int height,
                  render::sdf::SpeedUps speed_ups, double min_seconds) {
    const render::sdf::SceneTracer tracer(items, scale, speed_ups);
    const double footprint =
        glm::length(camera.per_row()) / glm::length(camera.direction(0.5 * width, 0.5 * height));
    Frame frame;
    frame.hits.resize(static_cast<std::size_t>(width) * height);
    const auto start = std::chrono::steady_clock::now();
    do {
        frame.evaluations = frame.root_work = 0;
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                const render::Ray ray{camera.eye(),
                                      glm::normalize(camera.direction(x + 0.5, y + 0.5))};
                render::sdf::TraceCounters counters;
                frame.hits[static_cast<std::size_t>(y) * width + x] =
                    tracer.first_hit(ray, {0.0, 1e3 * scale}, footprint, counters);
                frame.evaluations += counters.evaluations;
                frame.root_work += counters.root_work;
            }
        }
        ++frame.runs;
        frame.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    } while (frame.seconds < min_seconds && frame.runs < 20);
    frame.seconds /= frame.runs;
    return frame;
}

double share_differing(const Frame& a, const Frame& reference, double tolerance) {
    long differing = 0;
    for (std::size_t i = 0; i < a.hits.size(); ++i) {
        const auto& h = a.hits[i];
        const auto& r = reference.hits[i];
        if (h.found() != r.found() || (h.found() && std::abs(h.t - r.t) > tolerance * r.t)) {
            ++differing;
        }
    }
    return static_cast<double>(differing) / static_cast<double>(a.hits.size());
}

int run_sdf_bench(const SdfBenchArgs& args) {
    check_suite_options(args.suite);
    const std::string dir = args.suite.data_dir + "/sdf";
    const std::vector<std::string> cases = suite_case_names(dir, args.suite.cases);
    if (args.suite.csv) {
        std::printf(
            "scene,items,primitives,setting,width,height,seconds,rays_per_second,"
            "evaluations_per_ray,root_work_per_ray,hits,differing_share\n");
    } else {
        std::printf("%-16s %-20s %10s %12s %10s %10s\n", "scene", "speed-ups", "M rays/s",
                    "evals/ray", "vs none", "differ");
    }
    for (const std::string& name : cases) {
        const std::string path = dir + "/" + name + ".toml";
        render::Scene scene;
        try {
            scene = render::parse_scene(cli::read_input(path), cli::scene_surface_compiler());
        } catch (const Error& e) {
            throw CommandFailure(exit_input, path + ": " + e.what());
        }
        std::vector<algebra::CompiledPolynomial> compiled = cli::compile_surfaces(scene);
        const std::vector<render::sdf::NodePtr> items = render::scene_items(scene, compiled);
        const int width = args.size;
        const int height = std::max(1, width * scene.height / scene.width);
        const render::Camera camera(scene.camera.value_or(render::default_camera(scene)), width,
                                    height);
        int primitives = 0;
        for (const render::sdf::NodePtr& item : items) {
            primitives += item->primitive_count();
        }
        // The renderer's scale, so that the benchmark traces with its tolerances.
        const double scale = render::sdf::scene_scale(render::sdf::finite_bounds(items));
        const render::sdf::SceneTracer flat(items, scale);
        std::vector<Frame> frames;
        for (const Setting& setting : kSettings) {
            frames.push_back(trace_frame(items, scale, camera, width, height, setting.speed_ups,
                                         args.suite.min_seconds));
        }
        const double rays = static_cast<double>(width) * height;
        const double plain_evaluations = frames.front().evaluations / rays;
        for (std::size_t s = 0; s < frames.size(); ++s) {
            const Frame& f = frames[s];
            long hits = 0;
            for (const auto& h : f.hits) {
                hits += h.found();
            }
            const double evaluations = f.evaluations / rays;
            const double differing = share_differing(f, frames.front(), 1e-3);
            if (args.suite.csv) {
                std::printf("%s,%d,%d,%s,%d,%d,%.6f,%.1f,%.3f,%.3f,%ld,%.6f\n", name.c_str(),
                            flat.item_count(), primitives, kSettings[s].name, width, height,
                            f.seconds, rays / f.seconds, evaluations, f.root_work / rays, hits,
                            differing);
            } else {
                std::printf("%-16s %-20s %10.3f %12.2f %9.1f× %9.2f%%\n", name.c_str(),
                            kSettings[s].name, rays / f.seconds * 1e-6, evaluations,
                            plain_evaluations / evaluations, 100.0 * differing);
            }
        }
    }
    return exit_ok;
}

}  // namespace

void add_sdf_bench(CLI::App& app, cli::CommandContext& context) {
    auto args = std::make_shared<SdfBenchArgs>();
    CLI::App* cmd = add_suite_command(
        app, context, "sdf",
        "Hart's speed-ups on the SDF scene suite (bench/data/sdf), each alone and all on", args,
        run_sdf_bench);
    add_size_option(cmd, args->size, "image width (256); the height follows the scene's aspect");
}

}  // namespace locus::bench
