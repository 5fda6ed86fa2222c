// `locus demo [-o FILE]`: the main job on a built-in default. Steiner's Roman surface, given by
// its rational parametrization, is implicitized (implicitize --method auto), verified by exact
// substitution, and its equation stands on a pedestal in an SDF scene (render/sdf/) beside
// primitives on a checkered floor: the surface keeps its exact root finder (Sturm) while the
// primitives are sphere-traced, with soft shadows and 2×2 samples, to a PNG.
// docs/scenes/steiner_in_scene.toml is the same scene reading the .param file.
#include <chrono>
#include <cstdio>
#include <iostream>

#include "algebra/flint_convert.h"
#include "algebra/print.h"
#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "cli/process_limits.h"
#include "implicit/implicitize.h"
#include "render/image_output.h"
#include "render/scene_file.h"
#include "render/sdf/sdf_renderer.h"

namespace locus::cli {
namespace {

constexpr const char* demo_parametrization = R"(# Steiner's Roman surface
params: s,t
x = 2*t*(s^2+t^2-1)/(1+s^2+t^2)^2
y = 2*s*(s^2+t^2-1)/(1+s^2+t^2)^2
z = 4*s*t/(1+s^2+t^2)^2
)";

// The scene of docs/scenes/steiner_in_scene.toml, with the equation in place of the .param file.
constexpr const char* demo_scene_before_equation = R"(
[image]
width = 800
height = 500
background = [0.6, 0.68, 0.8]
[camera]
eye = [0.4, 2.9, 6.6]
target = [0.0, 1.05, 0.0]
fov = 38
[[light]]
direction = [-0.55, 1.0, 0.65]
intensity = 0.9
radius = 0.03
[[light]]
direction = [0.9, 0.45, 0.35]
color = [0.75, 0.82, 1.0]
intensity = 0.4
radius = 0.1
[render]
samples = 2
[materials.floor]
color = [0.86, 0.86, 0.86]
checker = [0.3, 0.3, 0.33]
checker_size = 0.5
[materials.surface]
color = [0.95, 0.62, 0.2]
inside = [0.3, 0.45, 0.85]
specular = 0.45
[materials.stone]
color = [0.78, 0.76, 0.72]
specular = 0.15
[materials.red]
color = [0.85, 0.2, 0.15]
specular = 0.5
[materials.green]
color = [0.25, 0.65, 0.35]
[[object]]
type = "plane"
material = "floor"
[[object]]
type = "cylinder"
radius = 0.95
half_height = 0.4
round = 0.05
material = "stone"
translate = [0.0, 0.45, 0.0]
[[object]]
type = "sphere"
radius = 0.55
material = "red"
translate = [-2.2, 0.55, 0.9]
[[object]]
type = "capsule"
a = [1.5, 0.25, 1.4]
b = [2.9, 0.25, 0.2]
radius = 0.25
material = "green"
[[object]]
type = "cone"
bottom_radius = 0.5
top_radius = 0.0
half_height = 0.7
material = "stone"
translate = [2.3, 0.7, -1.8]
[[object]]
type = "algebraic"
clip = "box"
clip_min = [-0.51, -0.51, -0.51]
clip_max = [0.51, 0.51, 0.51]
material = "surface"
rotate_axis = [-1, 0, 1]
rotate_degrees = 54.7356
euler = [0, 60, 0]
scale = 2.0
translate = [0.0, 1.478, 0.0]
equation = ")";

int run_demo(const std::string& output) {
    std::cout << "Parametrization:\n" << demo_parametrization;
    const implicit::Parametrization map = implicit::parse_parametrization(demo_parametrization);
    const auto start = std::chrono::steady_clock::now();
    const implicit::ImplicitResult r = implicit::implicitize_auto(map);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!r.equation || !implicit::vanishes_on_map_as_written(*r.equation, map)) {
        std::fprintf(stderr, "demo: implicitization FAILED\n");
        return exit_check_failed;
    }
    const algebra::Factorization factors = algebra::factor(*r.equation);
    const std::string equation = algebra::to_string(*r.equation);
    std::printf("\nImplicit equation (%s, %.1f ms):\n", r.method.c_str(), seconds * 1e3);
    std::cout << equation << "\n"
              << "verified: vanishes identically on the parametrization; degree "
              << r.equation->total_degree() << ", " << r.equation->num_terms() << " terms, "
              << (factors.factors.size() == 1 && factors.factors[0].second == 1 ? "irreducible"
                                                                                : "reducible")
              << "\n";

    std::string scene_text = demo_scene_before_equation;
    scene_text += equation;
    scene_text += "\"\n";
    const render::Scene scene =
        render::parse_scene(scene_text, [](const render::AlgebraicSource& source) {
            return algebra::compile_surface(source.equation);
        });
    render::RenderStats stats;
    render::ExecutionSettings execution;
    execution.aovs = false;  // the demo writes the picture only
    const render::RenderedImage image = render::render_sdf_scene(scene, {}, execution, &stats);
    register_partial_file(render::partial_path(output), output);
    render::write_image(image, output);
    unregister_partial_file(render::partial_path(output));
    std::printf(
        "\nRendered %dx%d in an SDF scene (the surface by certified isolation, five primitives "
        "sphere-traced; soft shadows, 2x2 samples) in %.3f s: %s\n",
        scene.width, scene.height, stats.seconds, output.c_str());
    return exit_ok;
}

}  // namespace

void add_demo_command(CLI::App& app, CommandContext& context) {
    auto output = std::make_shared<std::string>("locus-demo.png");
    auto limits = std::make_shared<ProcessLimitArgs>();
    CLI::App* cmd = app.add_subcommand(
        "demo", "Implicitize Steiner's Roman surface and render it standing in an SDF scene");
    cmd->add_option("-o,--output", *output, "image file (default locus-demo.png)");
    add_process_limit_options(cmd, *limits);
    cmd->callback([output, limits, &context] {
        apply_process_limits(*limits);
        try {
            render::check_image_path(*output);
        } catch (const Error& e) {
            throw failure_about("", e);
        }
        context.exit_code = run_demo(*output);
    });
}

}  // namespace locus::cli
