// `locus demo [-o FILE]`: the main job on a built-in default. The torus given by its
// trigonometric parametrization is made rational by the half-angle substitution, implicitized
// by Gröbner elimination, verified by exact substitution, compiled and ray-traced (Sturm
// isolation, shadows, 2×2 samples) to a PNG.
#include <cstdio>
#include <iostream>

#include "algebra/flint_convert.h"
#include "algebra/print.h"
#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "implicit/implicitize.h"
#include "render/image_output.h"
#include "render/renderer.h"

namespace locus::cli {
namespace {

constexpr const char* demo_parametrization = R"(# the torus with radii 2 and 1
params: u,v
x = (2+cos(v))*cos(u)
y = (2+cos(v))*sin(u)
z = sin(v)
)";

int run_demo(const std::string& output) {
    std::cout << "Parametrization:\n" << demo_parametrization;
    const implicit::Parametrization map = implicit::parse_parametrization(demo_parametrization);
    const implicit::ImplicitResult r = implicit::implicitize(map);
    if (!r.equation || !implicit::vanishes_on(*r.equation, map)) {
        std::fprintf(stderr, "demo: implicitization FAILED\n");
        return exit_check_failed;
    }
    const algebra::Factorization factors = algebra::factor(*r.equation);
    std::printf("\nImplicit equation (Gröbner elimination, %.1f ms):\n", r.stats.seconds * 1e3);
    std::cout << algebra::to_string(*r.equation) << "\n"
              << "verified: vanishes identically on the parametrization; degree "
              << r.equation->total_degree() << ", " << r.equation->num_terms() << " terms, "
              << (factors.factors.size() == 1 && factors.factors[0].second == 1 ? "irreducible"
                                                                                : "reducible")
              << "\n";

    render::Scene scene;
    scene.width = 640;
    scene.height = 480;
    render::Surface surface;
    surface.equation = algebra::to_string(*r.equation);
    surface.clip = render::ClipSphere{{0.0, 0.0, 0.0}, 3.2};
    scene.surfaces.push_back(surface);
    scene.camera = render::CameraSpec{{5.0, 6.5, 9.0}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 35.0};
    scene.options.samples = 2;
    const std::vector<algebra::CompiledPolynomial> compiled = {
        algebra::compile_surface(*r.equation)};
    render::RenderStats stats;
    const render::RenderedImage image = render::render(scene, compiled, {}, &stats);
    render::write_image(image, output);
    std::printf(
        "\nRendered %dx%d (2x2 samples, shadows, method sturm) in %.3f s: "
        "%s\n",
        scene.width, scene.height, stats.seconds, output.c_str());
    return exit_ok;
}

}  // namespace

void add_demo_command(CLI::App& app, int& exit_code) {
    auto output = std::make_shared<std::string>("locus-demo.png");
    CLI::App* cmd = app.add_subcommand(
        "demo", "Implicitize a torus from its trigonometric parametrization and render it");
    cmd->add_option("-o,--output", *output, "image file (default locus-demo.png)");
    cmd->callback([output, &exit_code] { exit_code = run_demo(*output); });
}

}  // namespace locus::cli
