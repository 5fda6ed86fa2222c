// `locus render EQUATION|SCENE.toml|--param FILE -o out.png [flags]`: ray-trace algebraic
// surfaces. Flags override the scene file and the defaults (render/scene.h); their names are
// the interface benchmarks and comparisons with other renderers rely on.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <thread>

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include "algebra/error.h"
#include "cli/choices.h"
#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "cli/patch_surfaces.h"
#include "cli/process_limits.h"
#include "cli/surface_input.h"
#include "render/framing.h"
#include "render/image_output.h"
#include "render/renderer.h"
#include "render/scene_file.h"
#include "render/sdf/sdf_renderer.h"
#include "render/turntable.h"

namespace locus::cli {
namespace {

struct RenderArgs {
    std::string input;  // an equation, or a scene file ending in .toml
    std::string param;
    std::string output = "render.png";
    std::string size, eye, target, up, background, shadows, ao;
    std::optional<double> fov, clip_radius;
    std::string method;
    std::optional<int> samples;
    std::optional<int> threads;
    std::optional<int> turntable;
    bool fit = false;
    ProcessLimitArgs limits;
    std::vector<std::string> aovs;
};

[[noreturn]] void bad_flag(const std::string& flag, const std::string& value,
                           const std::string& expected) {
    throw CommandFailure(exit_input, flag + " '" + value + "': expected " + expected);
}

render::Vec3 parse_triple(const std::string& flag, const std::string& text) {
    std::istringstream in(text);
    render::Vec3 v;
    char comma1 = 0, comma2 = 0;
    in >> v.x >> comma1 >> v.y >> comma2 >> v.z;
    if (!in || comma1 != ',' || comma2 != ',' || !(in >> std::ws).eof() || !std::isfinite(v.x) ||
        !std::isfinite(v.y) || !std::isfinite(v.z)) {
        bad_flag(flag, text, "three numbers X,Y,Z");
    }
    return v;
}

bool parse_on_off(const std::string& flag, const std::string& text) {
    if (text == "on") {
        return true;
    }
    if (text != "off") {
        bad_flag(flag, text, "on or off");
    }
    return false;
}

void apply_flags(const RenderArgs& args, render::Scene& scene) {
    if (!args.size.empty()) {
        std::istringstream in(args.size);
        int width = 0, height = 0;
        char times = 0;
        in >> width >> times >> height;
        if (!in || times != 'x' || !(in >> std::ws).eof() || width < 1 || height < 1 ||
            width > 16384 || height > 16384) {
            bad_flag("--size", args.size, "WIDTHxHEIGHT, each from 1 to 16384");
        }
        scene.width = width;
        scene.height = height;
    }
    if (args.clip_radius) {
        if (!(*args.clip_radius > 0.0) || !std::isfinite(*args.clip_radius)) {
            bad_flag("--clip-radius", std::to_string(*args.clip_radius), "a positive radius");
        }
        if (args.fit) {
            throw CommandFailure(exit_input,
                                 "--fit and --clip-radius: give one (--fit sets the clip spheres)");
        }
        for (render::Surface& surface : scene.surfaces) {
            surface.clip = render::ClipSphere{{0.0, 0.0, 0.0}, *args.clip_radius};
            surface.fit_clip = false;
        }
    }
    if (!args.method.empty()) {
        scene.options.method = render::parse_trace_method(args.method);
    }
    if (args.samples) {
        if (*args.samples < 1 || *args.samples > 16) {
            bad_flag("--samples", std::to_string(*args.samples), "N from 1 to 16 (N×N per pixel)");
        }
        scene.options.samples = *args.samples;
    }
    if (!args.shadows.empty()) {
        scene.options.shadows = parse_on_off("--shadows", args.shadows);
    }
    if (!args.ao.empty()) {
        scene.options.ambient_occlusion = parse_on_off("--ao", args.ao);
    }
    if (!args.background.empty()) {
        scene.background = parse_triple("--background", args.background);
        for (int i = 0; i < 3; ++i) {
            if (scene.background[i] < 0.0 || scene.background[i] > 1.0) {
                bad_flag("--background", args.background,
                         "a linear colour R,G,B with each value from 0 to 1");
            }
        }
    }
    if (args.threads) {
        if (*args.threads < 0 || *args.threads > 1024) {
            bad_flag("--threads", std::to_string(*args.threads),
                     "a count from 1 to 1024, or 0 for every core");
        }
        scene.options.threads = *args.threads;
    }
}

render::Scene build_scene(const RenderArgs& args, Deadline deadline) {
    if (args.input.empty() == args.param.empty()) {
        throw CommandFailure(exit_input,
                             "render: give an equation, a scene file (.toml), patches (.bpt) or "
                             "--param FILE");
    }
    const std::string& source = args.param.empty() ? args.input : args.param;
    const SourceKind kind = args.param.empty() ? source_kind(args.input) : SourceKind::param_file;
    std::optional<render::TraceMethod> method;
    if (!args.method.empty()) {
        method = render::parse_trace_method(args.method);
    }
    render::Scene scene;
    if (kind == SourceKind::scene_file) {
        try {
            scene = scene_from_source(source, kind, method, deadline);
            for (const std::string& note : scene.notes) {
                std::fprintf(stderr, "locus: %s: %s\n", source.c_str(), note.c_str());
            }
        } catch (const Timeout&) {
            throw;  // an implicitization ran past --timeout: not a fault of the file
        } catch (const Error& e) {
            throw failure_about(source, e);
        } catch (const CommandFailure& e) {
            // An algebraic leaf that failed to implicitize or compile.
            const std::string message = e.what();
            throw CommandFailure(
                e.code(), message.rfind(source + ": ", 0) == 0 ? message : source + ": " + message);
        }
    } else {
        scene = scene_from_source(source, kind, method, deadline);
    }
    apply_flags(args, scene);
    return scene;
}

// The camera flags, on top of the scene's camera or the one framed on the (fitted) clip regions.
void apply_camera_flags(const RenderArgs& args, render::Scene& scene) {
    if (args.eye.empty() && args.target.empty() && args.up.empty() && !args.fov) {
        return;
    }
    render::CameraSpec camera = scene.camera.value_or(render::default_camera(scene));
    if (!args.eye.empty()) {
        camera.eye = parse_triple("--eye", args.eye);
    }
    if (!args.target.empty()) {
        camera.target = parse_triple("--target", args.target);
    }
    if (!args.up.empty()) {
        camera.up = parse_triple("--up", args.up);
    }
    if (args.fov) {
        camera.fov_degrees = *args.fov;
    }
    scene.camera = camera;
}

using Extents = std::vector<std::optional<render::SurfaceExtent>>;

// Fits the clip spheres of the surfaces given without one (all of them under --fit) to their
// extents; --fit also drops the scene file's camera, so that the camera frames them too.
Extents fit_scene(const RenderArgs& args, render::Scene& scene,
                  std::span<const algebra::CompiledPolynomial> compiled, Deadline deadline) {
    Extents extents = render::fit_clip_regions(scene, compiled, args.fit, deadline);
    if (!args.fit) {
        return extents;
    }
    if (scene.camera_path) {
        throw CommandFailure(exit_input, args.input +
                                             ": --fit and the scene's camera path "
                                             "([[camera.key]]): give one");
    }
    scene.camera.reset();
    for (std::size_t i = 0; i < extents.size(); ++i) {
        if (extents[i]->kind != render::SurfaceExtent::Kind::bounded) {
            std::fprintf(stderr,
                         "locus: warning: --fit: surface %zu %s; it keeps the default clip "
                         "sphere (radius 2 about the origin)\n",
                         i + 1,
                         extents[i]->kind == render::SurfaceExtent::Kind::unbounded
                             ? "is not bounded (its top-degree form is not definite)"
                             : "has no real point on the lines searched");
        }
    }
    if (!scene.objects.empty()) {
        std::fprintf(stderr,
                     "locus: note: --fit frames the camera on the scene tree; its "
                     "algebraic leaves are fitted only where they have no clip keys\n");
    }
    return extents;
}

// Says on stderr why a picture shows only the background, surface by surface.
// `camera` is the first frame's; `undecided` the rays no method could decide.
void warn_nothing_hit(const render::Scene& scene,
                      std::span<const algebra::CompiledPolynomial> compiled, const Extents& extents,
                      const render::CameraSpec& camera, long undecided, bool animation,
                      Deadline deadline) {
    if (undecided > 0) {
        std::fprintf(stderr,
                     "locus: warning: no ray hit a surface, and %ld rays were undecided (drawn as "
                     "background): the method could not settle them (see --method)\n",
                     undecided);
        return;
    }
    if (!scene.objects.empty() || scene.surfaces.empty()) {
        std::fprintf(stderr,
                     "locus: warning: no ray hit the scene: the picture shows the "
                     "background only (see --fit, --eye, --target)\n");
        return;
    }
    std::fprintf(stderr, "locus: warning: no ray hit %s, so the %s the background only%s:\n",
                 scene.surfaces.size() == 1 ? "the surface" : "any surface",
                 animation ? "frames show" : "picture shows",
                 animation ? " (where the camera is concerned, as seen from the first frame)" : "");
    for (std::size_t i = 0; i < scene.surfaces.size(); ++i) {
        std::string reason;
        try {
            const render::EmptyPictureReason why =
                render::why_not_hit(scene.surfaces[i], compiled[i], camera, scene.width,
                                    scene.height, extents[i], deadline);
            reason = why.text;
            using Remedy = render::EmptyPictureReason::Remedy;
            switch (why.remedy) {
            case Remedy::clip_region:
                reason += " (give one: --clip-radius, or clip keys in a scene file)";
                break;
            case Remedy::fit:
                reason += " (--fit frames it)";
                break;
            case Remedy::larger_clip_region:
                reason += " (a larger --clip-radius, or clip keys in a scene file, takes it in)";
                break;
            case Remedy::finer_sampling:
                reason += " (try --samples or a closer --eye)";
                break;
            case Remedy::none:
                break;
            }
        } catch (const Timeout&) {
            reason = "(not examined: --timeout passed)";
        }
        if (scene.surfaces.size() == 1) {
            std::fprintf(stderr, "locus:   %s\n", reason.c_str());
        } else {
            std::fprintf(stderr, "locus:   surface %zu: %s\n", i + 1, reason.c_str());
        }
    }
}

void print_frame_stats(const render::Scene& scene, const render::RenderStats& stats) {
    std::fprintf(stderr,
                 "rendered %dx%d, %d×%d samples, method %s: %.3f s, %.2f M primary rays/s, "
                 "%ld hits, %ld undecided rays\n",
                 scene.width, scene.height, scene.options.samples, scene.options.samples,
                 std::string(render::to_string(scene.options.method)).c_str(), stats.seconds,
                 stats.primary_rays / stats.seconds * 1e-6, stats.hits, stats.unknown);
    if (!scene.objects.empty()) {
        std::fprintf(stderr, "scene tree: %.1f primitive evaluations per primary ray\n",
                     static_cast<double>(stats.primary_work) / stats.primary_rays);
    }
}

int run_render(const RenderArgs& args, ProgressLine& progress) {
    // The limit covers implicitizing `param` surfaces as well as rendering.
    const Deadline deadline = apply_process_limits(args.limits);
    if (args.turntable && (*args.turntable < 1 || *args.turntable > 100000)) {
        bad_flag("--turntable", std::to_string(*args.turntable), "a frame count from 1 to 100000");
    }
    int frames = args.turntable.value_or(0);  // 0: one still picture
    render::ExecutionSettings execution;
    execution.deadline = deadline;
    // oneTBB starts on first use: it loads its allocator library, maps its pools and starts its
    // worker threads, about a millisecond and a hundred page faults. Started here on another
    // thread, that overlaps reading and compiling the scene on this one (joined on return), as
    // does loading the image writer's library (ISA-L for PNG).
    const std::jthread start_tbb([output = args.output] {
        tbb::parallel_for(0, 2, [](int) {});
        render::prepare_image_writer(output);
    });
    render::Scene scene;
    std::vector<render::Aov> aovs;
    try {
        render::check_image_path(args.output);
    } catch (const Error& e) {
        throw failure_about("", e);
    }
    // Registered from the start, so that a timeout in any phase says that nothing was written.
    std::string partial =
        render::partial_path(frames > 0 ? render::frame_path(args.output, 1, frames) : args.output);
    register_partial_file(partial, args.output);
    std::vector<algebra::CompiledPolynomial> compiled;
    Extents extents;
    // --threads (or the scene file's threads) bounds every parallel phase of the command: the
    // extent estimate and the image encoding as well as the frames' rows, which alone took it
    // from ExecutionSettings::threads.
    std::optional<tbb::global_control> thread_limit;
    try {
        scene = build_scene(args, deadline);
        if (scene.options.threads > 0) {
            thread_limit.emplace(tbb::global_control::max_allowed_parallelism,
                                 static_cast<std::size_t>(scene.options.threads));
        }
        for (const std::string& name : args.aovs) {
            aovs.push_back(render::parse_aov(name));
        }
        execution.aovs = !aovs.empty();
        try {
            compiled = compile_surfaces(scene, deadline);
        } catch (const CommandFailure& e) {
            // A scene file's surface: say which file.
            const std::string message = e.what();
            if (args.input.ends_with(".toml") && message.rfind(args.input, 0) != 0) {
                throw CommandFailure(e.code(), args.input + ": " + message);
            }
            throw;
        }
        frame_far_equations(scene, compiled);
        extents = fit_scene(args, scene, compiled, deadline);
        apply_camera_flags(args, scene);
        if (scene.camera_path) {
            if (args.turntable) {
                throw CommandFailure(exit_input, args.input +
                                                     ": the scene's camera path and --turntable: "
                                                     "give one");
            }
            if (!args.eye.empty() || !args.target.empty() || !args.up.empty() || args.fov) {
                throw CommandFailure(exit_input, args.input +
                                                     ": the camera flags do not apply to the "
                                                     "scene's camera path ([[camera.key]])");
            }
            frames = scene.camera_path->frames;
            unregister_partial_file(partial);
            partial = render::partial_path(render::frame_path(args.output, 1, frames));
            register_partial_file(partial, args.output);
        }
    } catch (const Timeout& e) {
        throw CommandFailure(exit_timeout, std::string(e.what()) + " (--timeout " +
                                               timeout_text(args.limits) +
                                               "); nothing written to '" + args.output + "'");
    }
    execution.threads = scene.options.threads;
    const render::CameraSpec base_camera = scene.camera.value_or(render::default_camera(scene));
    const auto frame_camera = [&](int frame) {
        return scene.camera_path ? render::camera_on_path(*scene.camera_path, frame)
                                 : render::turntable_camera(base_camera, frame, frames);
    };
    // Every frame's camera before the first is rendered: between its keys a camera path can
    // pass through a degenerate camera (an up direction blended to zero, the eye on the
    // target), which must be refused up front, not after some frames are written.
    for (int frame = 0; frame < frames; ++frame) {
        try {
            const render::Camera check(frame_camera(frame), scene.width, scene.height);
        } catch (const Error& e) {
            throw CommandFailure(
                exit_input, args.input + ": " + (scene.camera_path ? "camera path" : "turntable") +
                                ", frame " + std::to_string(frame + 1) + ": " + e.what());
        }
    }
    const auto started = std::chrono::steady_clock::now();
    render::RenderStats total;
    // One frame, or each frame of the turntable or the camera path in turn: the surfaces are
    // compiled once above.
    for (int frame = 0; frame < std::max(frames, 1); ++frame) {
        const std::string path =
            frames > 0 ? render::frame_path(args.output, frame + 1, frames) : args.output;
        if (frames > 0) {
            scene.camera = frame_camera(frame);
            if (frame > 0) {
                partial = render::partial_path(path);
                register_partial_file(partial, path);
            }
        }
        execution.progress = progress.fraction(frames > 0 ? "frame " + std::to_string(frame + 1) +
                                                                "/" + std::to_string(frames)
                                                          : std::string("render"));
        render::RenderStats stats;
        render::RenderedImage image;
        try {
            image = scene.objects.empty()
                        ? render::render(scene, compiled, execution, &stats)
                        : render::render_sdf_scene(scene, compiled, execution, &stats);
        } catch (const Timeout& e) {
            throw CommandFailure(
                exit_timeout,
                std::string(e.what()) + " (--timeout " + timeout_text(args.limits) + "); " +
                    (frame == 0 ? "nothing written to '" + args.output + "'"
                                : std::to_string(frame) + " of " + std::to_string(frames) +
                                      " frames written, up to '" +
                                      render::frame_path(args.output, frame, frames) + "'"));
        }
        progress.clear();
        const std::vector<std::string> written = render::write_image(image, path, aovs);
        unregister_partial_file(partial);
        if (frames == 0) {
            if (stats.hits == 0) {
                warn_nothing_hit(scene, compiled, extents, base_camera, stats.unknown, false,
                                 deadline);
            }
            print_frame_stats(scene, stats);
            for (const std::string& written_path : written) {
                std::fprintf(stderr, "wrote %s\n", written_path.c_str());
            }
        }
        total.seconds += stats.seconds;
        total.primary_rays += stats.primary_rays;
        total.hits += stats.hits;
        total.unknown += stats.unknown;
        total.primary_work += stats.primary_work;
    }
    if (frames > 0) {
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        if (total.hits == 0) {
            warn_nothing_hit(scene, compiled, extents, base_camera, total.unknown, true, deadline);
        }
        print_frame_stats(scene, total);
        std::fprintf(stderr, "%s: %d frames in %.3f s (%.2f frames/s, writing included)\n",
                     scene.camera_path ? "camera path" : "turntable", frames, seconds,
                     frames / seconds);
        std::fprintf(stderr, "wrote %s ... %s\n",
                     render::frame_path(args.output, 1, frames).c_str(),
                     render::frame_path(args.output, frames, frames).c_str());
    }
    return exit_ok;
}

}  // namespace

void add_render_command(CLI::App& app, CommandContext& context) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* cmd = app.add_subcommand("render", "Ray-trace algebraic surfaces f(x,y,z) = 0");
    cmd->add_option("input", args->input,
                    "an equation such as \"x^2+y^2+z^2-1\", a scene file ending in .toml, or "
                    "Bezier patches in a .bpt file (rendered trimmed to their domains)");
    cmd->add_option("--param", args->param,
                    "render the implicit equation of this parametrization file");
    cmd->add_option("-o,--output", args->output,
                    "image file (PNG by default; .exr writes linear half floats)");
    cmd->add_option("--size", args->size, "WIDTHxHEIGHT (default 512x512)");
    cmd->add_option("--eye", args->eye, "camera position X,Y,Z");
    cmd->add_option("--target", args->target, "point looked at X,Y,Z");
    cmd->add_option("--up", args->up, "up direction X,Y,Z");
    cmd->add_option("--fov", args->fov, "vertical field of view in degrees (default 35)");
    cmd->add_option("--clip-radius", args->clip_radius,
                    "clip every surface to a sphere of this radius about the origin (default: "
                    "fitted to a bounded surface, else 2)");
    cmd->add_flag("--fit", args->fit,
                  "clip spheres and camera from the surfaces' extents, replacing the scene "
                  "file's clip regions and camera (camera flags still apply)");
    add_choice(cmd, "--method", args->method, trace_method_choices(), "the root finder");
    cmd->add_option("--samples", args->samples, "N: N×N samples per pixel (default 1)");
    add_choice(cmd, "--shadows", args->shadows, on_off_choices(), "shadows (default on)");
    add_choice(cmd, "--ao", args->ao, on_off_choices(), "ambient occlusion (default off)");
    cmd->add_option("--background", args->background, "background colour R,G,B (linear, 0..1)");
    cmd->add_option("--threads", args->threads, "worker threads (default: all cores)");
    cmd->add_option("--turntable", args->turntable,
                    "N: render N frames around the up axis through the target, written as "
                    "NAME_0001.png, ...");
    add_process_limit_options(cmd, args->limits);
    add_choice(cmd, "--aov", args->aovs, {{"depth", ""}, {"normal", ""}, {"work", ""}},
               "also write these as <stem>.<aov>.exr, comma-separated")
        ->delimiter(',');
    cmd->callback([args, &context] { context.exit_code = run_render(*args, context.progress); });
}

}  // namespace locus::cli
