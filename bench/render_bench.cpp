// `locus-bench render [--csv] [--size N] [--methods a,b] [--cases a,b] [--threads T]`
//
// For each suite surface: the primary rays through the pixel centres of an N×N image (default
// camera framing the clip sphere), first hits only, no shading. `exact` is traced once as the
// reference; every method is then timed (repeated until --min-seconds have passed, mean run,
// per-frame family expansion included) and compared with it ray by ray. A ray is wrong when
// hit/miss disagrees with `exact`, when the method could not decide, or when the hit distance
// differs by more than 1e-6 × the clip radius. When surf (Debian's surf-alggeo) is installed,
// it draws the same surface at the same size in the same run (its own camera and clipping,
// start-up excluded) for a speed reference, set beside `render s`: the whole picture as
// `locus render` makes it (its default method, shading without shadows, one sample, all
// cores). Both are the median of repeated runs, which shrugs off runs slowed by other work on a
// shared machine, and the two programs take turns (time_side_by_side) so that both see the same
// spells of load. `--whole-process` times the commands instead (bench/render_whole_process.h).

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

#include "algebra/error.h"
#include "bench/bench_options.h"
#include "bench/benches.h"
#include "bench/render_whole_process.h"
#include "bench/surf_run.h"
#include "bench/surface_suite.h"
#include "cli/command_support.h"
#include "cli/exit_codes.h"
#include "cli/patch_surfaces.h"
#include "render/primary_rays.h"
#include "render/renderer.h"
#include "render/scene.h"

namespace locus::bench {
namespace {

using cli::CommandFailure;
using cli::exit_input;
using cli::exit_ok;
using cli::on_path;
using cli::read_input;

struct RenderBenchArgs {
    SuiteOptions suite;
    std::vector<std::string> methods;      // empty: all but exact
    int size = 128;                        // size×size primary rays per surface
    int threads = 1;                       // the speed targets are single-core figures
    std::string surf = "surf-alggeo-nox";  // same-run reference renderer, or "off"
    bool whole_process = false;            // time `locus render` and surf as whole processes
    std::string locus;                     // the locus executable (empty: beside locus-bench)
};

// build/…/bench/locus-bench → build/…/cli/locus when that exists, else `locus` on the PATH.
std::string default_locus_executable() {
    std::error_code error;
    const auto self = std::filesystem::read_symlink("/proc/self/exe", error);
    if (!error) {
        const auto sibling = self.parent_path().parent_path() / "cli" / "locus";
        if (std::filesystem::exists(sibling, error)) {
            return sibling.string();
        }
    }
    return "locus";
}

// locus' picture and surf's, each the median (and the fastest) of repeated runs.
struct Comparison {
    RunTimes locus;
    RunTimes surf;  // negative when surf is absent or failed
};

// Times `frame` (one locus picture, returning its seconds) beside `surf` (null: locus alone).
// The two are interleaved in rounds — three locus frames, one surf drawing, one surf start-up —
// until at least five rounds and `min_seconds` of locus frames have passed (at most 20 rounds),
// so that both sides are timed across the same stretch of the machine's load: timed one after
// the other, a slow spell of this shared machine could fall on either side alone, and single
// surfaces then came out slower or faster than the other program by 15–30 % from run to run.
// Start-ups run as often as drawings: the fastest of a larger sample is lower, which would
// shrink the subtracted start-up and flatter locus' `best` ratio. A drawing no slower than a
// start-up means the figure is noise and is reported as missing.
template <class Frame>
Comparison time_side_by_side(Frame frame, const SurfRun* surf, double min_seconds) {
    std::vector<double> frames, draws, startups;
    double locus_total = 0.0;
    bool surf_ok = surf != nullptr;
    for (int round = 0; round < 20; ++round) {
        if (round >= 5 && locus_total >= min_seconds) {
            break;
        }
        for (int k = 0; k < 3; ++k) {
            frames.push_back(frame());
            locus_total += frames.back();
        }
        if (surf_ok) {
            const double draw = (*surf)(true);
            const double startup = (*surf)(false);
            surf_ok = draw >= 0.0 && startup >= 0.0;
            draws.push_back(draw);
            startups.push_back(startup);
        }
    }
    Comparison result{summary_of(std::move(frames)), {}};
    if (surf_ok) {
        auto difference = [](double total, double startup) {
            return total > startup ? total - startup : -1.0;
        };
        const RunTimes total = summary_of(std::move(draws));
        const RunTimes startup = summary_of(std::move(startups));
        result.surf = RunTimes{difference(total.median, startup.median),
                               difference(total.best, startup.best)};
    }
    return result;
}

// "0.83": locus' time over surf's, or "-" when surf's is missing.
std::string ratio_text(double locus, double surf) {
    char text[16] = "-";
    if (surf > 0) {
        std::snprintf(text, sizeof text, "%.2f", locus / surf);
    }
    return text;
}

// A method with one of its settings: the sphere-tracing methods are also run with their
// tolerance 100× looser and 100× tighter than the default.
struct Setting {
    render::TraceMethod method;
    std::string name;  // "default" or "tol=1e-05"
    double factor;     // scales the method's tolerances
    double tolerance;  // relative to the clip radius; 0 for the root finders
};

std::vector<Setting> settings_of(const std::vector<render::TraceMethod>& methods) {
    std::vector<Setting> settings;
    for (render::TraceMethod m : methods) {
        const bool gradient = m == render::TraceMethod::sphere_gradient;
        const bool lipschitz = m == render::TraceMethod::sphere_lipschitz;
        if (!gradient && !lipschitz) {
            settings.push_back({m, "default", 1.0, 0.0});
            continue;
        }
        const double base = gradient ? 1e-7 : 1e-9;  // surface_tracer.cpp's tolerances
        for (const double factor : {1.0, 100.0, 0.01}) {
            char name[32];
            std::snprintf(name, sizeof name, "tol=%.0e", base * factor);
            settings.push_back({m, factor == 1.0 ? "default" : name, factor, base * factor});
        }
    }
    return settings;
}

// A grey image of the hits: |n·l| for a fixed light, 0 for a miss; the benchmark's image
// difference is the RMS of two such images in 8-bit levels.
std::vector<double> shade_image(const algebra::CompiledPolynomial& f, const render::Camera& camera,
                                const render::PrimaryRays& rays, int size) {
    const render::Vec3 light = glm::normalize(render::Vec3{-0.4, 0.8, 0.6});
    std::vector<double> shade(rays.hits.size(), 0.0);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const std::size_t p = static_cast<std::size_t>(y) * size + x;
            if (rays.hits[p].status != render::RootStatus::hit) {
                continue;
            }
            const render::Ray ray = camera.ray(x + 0.5, y + 0.5);
            const algebra::ValueGradient vg =
                f.value_gradient(render::to_point(ray.at(rays.hits[p].t)));
            const render::Vec3 n = render::to_vec(vg.gradient);
            const double length = glm::length(n);
            shade[p] =
                length > 0.0 && std::isfinite(length) ? std::abs(glm::dot(n, light)) / length : 0.5;
        }
    }
    return shade;
}

// The teapot's 32 trimmed patches (implicit/teapot.bpt), the view of docs/rendering.md at
// size×size: whole frames as `locus render` makes them without shadows, timed by median. Exact
// arithmetic on every ray of 32 surfaces of degree 9–18 would take hours, so the certified
// method is the reference here; a pixel of another method is wrong when it hits where the
// reference misses or the other way round, or when its depth differs by more than 1e-6 × the
// teapot's size.
// surf cannot draw trimmed patches: there is no reference beside them.
void run_patch_bench(const RenderBenchArgs& args, const std::vector<render::TraceMethod>& methods) {
    const std::string path = args.suite.data_dir + "/implicit/teapot.bpt";
    render::Scene scene;
    scene.surfaces = cli::patch_surfaces(path, read_input(path), std::nullopt);
    scene.width = scene.height = args.size;
    scene.camera = render::CameraSpec{{0.0, -7.5, 5.0}, {0.0, 0.0, 1.3}, {0.0, 0.0, 1.0}, 35.0};
    scene.options.shadows = false;
    std::vector<algebra::CompiledPolynomial> compiled;
    int degree = 0;
    for (const render::Surface& surface : scene.surfaces) {
        compiled.push_back(algebra::compile_surface(surface.equation));
        degree = std::max(degree, compiled.back().degree());
    }
    render::ExecutionSettings execution;
    execution.threads = args.threads;
    // The median of frames repeated until --min-seconds have passed (three at least).
    auto frame = [&](render::TraceMethod method, render::RenderedImage& image) {
        scene.options.method = method;
        std::vector<double> seconds;
        double total = 0.0;
        while (seconds.size() < 3 || (total < args.suite.min_seconds && seconds.size() < 50)) {
            render::RenderStats stats;
            image = render::render(scene, compiled, execution, &stats);
            seconds.push_back(stats.seconds);
            total += stats.seconds;
        }
        std::sort(seconds.begin(), seconds.end());
        return seconds[seconds.size() / 2];
    };
    render::RenderedImage reference;
    const double reference_seconds = frame(render::TraceMethod::certified, reference);
    const double tolerance = 1e-6 * 3.5;  // the teapot spans about 6.4 × 4 × 3.2
    const double rays = static_cast<double>(reference.depth.size());
    for (const render::TraceMethod method : methods) {
        render::RenderedImage image;
        const double seconds =
            method == render::TraceMethod::certified ? reference_seconds : frame(method, image);
        const render::RenderedImage& traced =
            method == render::TraceMethod::certified ? reference : image;
        long wrong = 0;
        double max_error = 0.0;
        for (std::size_t p = 0; p < traced.depth.size(); ++p) {
            const bool hit = std::isfinite(traced.depth[p]);
            if (hit != std::isfinite(reference.depth[p])) {
                ++wrong;
            } else if (hit) {
                const double error = std::abs(traced.depth[p] - reference.depth[p]);
                max_error = std::max(max_error, error);
                wrong += error > tolerance;
            }
        }
        if (args.suite.csv) {
            std::cout << "teapot," << degree << "," << render::to_string(method) << ",patches,"
                      << tolerance << "," << traced.depth.size() << "," << seconds << ","
                      << rays / seconds << ",," << wrong << "," << wrong / rays << ",0,"
                      << max_error << ",,," << seconds << ",,,\n";
        } else {
            std::printf("%-18s %3d %-25s %10.0f %9s %8ld %8.3f %11.2e %11s %7s %9.4f %9s %6s %6s\n",
                        "teapot (32 patches)", degree,
                        std::string(render::to_string(method)).c_str(), rays / seconds, "-", wrong,
                        100.0 * wrong / rays, max_error, "-", "-", seconds, "-", "-", "-");
        }
        std::cout.flush();
    }
}

int run_render_bench(const RenderBenchArgs& args) {
    check_suite_options(args.suite);
    // "teapot" names the patch case, which is not in the surface suite.
    const std::string teapot_case = "teapot";
    const std::vector<SuiteSurface> suite =
        read_surface_cases(args.suite, "render", std::span(&teapot_case, 1));
    const bool teapot = args.suite.cases.empty() ||
                        std::find(args.suite.cases.begin(), args.suite.cases.end(), teapot_case) !=
                            args.suite.cases.end();
    std::vector<render::TraceMethod> methods;
    for (const std::string& name : args.methods) {
        methods.push_back(render::parse_trace_method(name));
    }
    if (methods.empty()) {
        for (render::TraceMethod m : render::all_trace_methods()) {
            if (m != render::TraceMethod::exact) {
                methods.push_back(m);
            }
        }
    }
    const bool with_surf = args.surf != "off" && on_path(args.surf);
    if (args.whole_process) {
        if (!with_surf && args.surf != "off") {
            std::fprintf(stderr, "surf not found: locus alone (install Debian's surf-alggeo)\n");
        }
        return run_whole_process_comparison(
            suite, {args.size, args.locus.empty() ? default_locus_executable() : args.locus,
                    with_surf ? args.surf : "",
                    args.methods.empty() ? std::string() : args.methods.front(),
                    args.suite.min_seconds, args.suite.csv});
    }
    if (args.suite.csv) {
        std::cout << "case,degree,method,setting,tolerance,rays,seconds,rays_per_second,"
                     "work_per_ray,wrong_rays,wrong_share,unknown_rays,max_depth_error,"
                     "mean_depth_error,image_rms,render_seconds,surf_seconds,"
                     "render_best_seconds,surf_best_seconds\n";
    } else {
        std::printf("%-18s %3s %-25s %10s %9s %8s %8s %11s %11s %7s %9s %9s %6s %6s\n", "case",
                    "deg", "method", "rays/s", "work/ray", "wrong", "wrong %", "max err",
                    "mean err", "img rms", "render s", "surf s", "ratio", "best");
    }
    for (const SuiteSurface& s : suite) {
        const algebra::CompiledPolynomial f = algebra::compile_surface(s.equation);
        render::Scene scene;
        scene.width = scene.height = args.size;
        scene.surfaces.push_back(
            {s.equation, "", render::ClipSphere{{0, 0, 0}, s.clip_radius}, {}, ""});
        const render::Camera camera(render::default_camera(scene), args.size, args.size);
        const render::ClipRegion region = scene.surfaces[0].clip;
        const render::PrimaryRays reference = render::trace_primary_rays(
            f, region, camera, args.size, args.size, render::TraceMethod::exact, 0);
        // The whole picture as `locus render` makes it (default method, Blinn–Phong, no
        // shadows, one sample, all cores): the figure to set beside surf's.
        scene.options.shadows = false;
        const std::vector<algebra::CompiledPolynomial> compiled = {f};
        auto frame = [&] {
            render::RenderStats stats;
            render::ExecutionSettings execution;
            execution.aovs = false;  // as `locus render` without --aov
            render::render(scene, compiled, execution, &stats);
            return stats.seconds;
        };
        std::optional<SurfRun> surf;
        if (with_surf) {
            surf.emplace(args.surf, s, args.size);
        }
        const Comparison timing =
            time_side_by_side(frame, surf ? &*surf : nullptr, args.suite.min_seconds);
        const double surf_seconds = timing.surf.median;
        const double render_seconds = timing.locus.median;
        const double render_best = timing.locus.best;
        const double tolerance = 1e-6 * s.clip_radius;
        const std::vector<double> reference_shade = shade_image(f, camera, reference, args.size);
        for (const Setting& setting : settings_of(methods)) {
            const render::TraceMethod method = setting.method;
            render::PrimaryRays traced;
            double total = 0.0;
            int runs = 0;
            do {
                traced = render::trace_primary_rays(f, region, camera, args.size, args.size, method,
                                                    args.threads, setting.factor);
                total += traced.seconds;
                ++runs;
            } while (total < args.suite.min_seconds && runs < 50);
            const double seconds = total / runs;
            long wrong = 0, unknown = 0, work = 0, compared = 0;
            double max_error = 0.0, sum_error = 0.0;
            for (std::size_t p = 0; p < traced.hits.size(); ++p) {
                const render::RootResult& mine = traced.hits[p];
                const render::RootResult& truth = reference.hits[p];
                work += mine.work;
                if (mine.status == render::RootStatus::unknown) {
                    ++unknown;
                    ++wrong;
                    continue;
                }
                if (mine.status != truth.status) {
                    ++wrong;
                    continue;
                }
                if (mine.status == render::RootStatus::hit) {
                    const double error = std::abs(mine.t - truth.t) * traced.ray_lengths[p];
                    max_error = std::max(max_error, error);
                    sum_error += error;
                    ++compared;
                    if (error > tolerance) {
                        ++wrong;
                    }
                }
            }
            const double rays = static_cast<double>(traced.hits.size());
            const double mean_error = compared > 0 ? sum_error / compared : 0.0;
            const std::vector<double> shade = shade_image(f, camera, traced, args.size);
            double square_sum = 0.0;
            for (std::size_t p = 0; p < shade.size(); ++p) {
                const double d = 255.0 * (shade[p] - reference_shade[p]);
                square_sum += d * d;
            }
            const double image_rms = std::sqrt(square_sum / static_cast<double>(shade.size()));
            if (args.suite.csv) {
                std::cout << s.name << "," << f.degree() << "," << render::to_string(method) << ","
                          << setting.name << "," << setting.tolerance << "," << traced.hits.size()
                          << "," << seconds << "," << rays / seconds << "," << work / rays << ","
                          << wrong << "," << wrong / rays << "," << unknown << "," << max_error
                          << "," << mean_error << "," << image_rms << "," << render_seconds << ","
                          << surf_seconds << "," << render_best << "," << timing.surf.best << "\n";
            } else {
                std::string label(render::to_string(method));
                if (setting.name != "default") {
                    label += " ";
                    label += setting.name;
                }
                // ratio: locus / surf by medians; best: by the fastest runs.
                std::printf(
                    "%-18s %3d %-25s %10.0f %9.2f %8ld %8.3f %11.2e %11.2e %7.2f %9.4f %9s %6s "
                    "%6s\n",
                    s.name.c_str(), f.degree(), label.c_str(), rays / seconds, work / rays, wrong,
                    100.0 * wrong / rays, max_error, mean_error, image_rms, render_seconds,
                    surf_seconds > 0 ? std::to_string(surf_seconds).substr(0, 6).c_str() : "-",
                    ratio_text(render_seconds, surf_seconds).c_str(),
                    ratio_text(render_best, timing.surf.best).c_str());
            }
            std::cout.flush();
        }
    }
    if (teapot) {
        run_patch_bench(args, methods);
    }
    if (!with_surf && args.surf != "off") {
        std::fprintf(stderr, "surf not found: no surf column (install Debian's surf-alggeo)\n");
    }
    return exit_ok;
}

}  // namespace

void add_render_bench(CLI::App& app, cli::CommandContext& context) {
    auto args = std::make_shared<RenderBenchArgs>();
    CLI::App* cmd = add_suite_command(
        app, context, "render",
        "Every trace method on the surface suite (bench/data/surfaces) against exact "
        "isolation, and surf's time",
        args, run_render_bench);
    add_size_option(cmd, args->size, "N×N primary rays per surface (128)");
    add_threads_option(cmd, args->threads);
    cmd->add_option("--methods", args->methods, "only these trace methods")->delimiter(',');
    cmd->add_option("--surf", args->surf, "surf executable for the same-run reference, or 'off'");
    cmd->add_flag("--whole-process", args->whole_process,
                  "time `locus render EQUATION -o F.png` and surf as whole processes, start-up "
                  "and writing included (use with --size 512)");
    cmd->add_option("--locus", args->locus,
                    "the locus executable for --whole-process (default: the build's, beside "
                    "locus-bench)");
}

}  // namespace locus::bench
