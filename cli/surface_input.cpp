#include "cli/surface_input.h"

#include <cmath>
#include <cstdio>

#include "algebra/error.h"
#include "algebra/parse.h"
#include "algebra/print.h"
#include "cli/command_support.h"
#include "cli/exit_codes.h"
#include "cli/patch_surfaces.h"
#include "implicit/implicitize.h"
#include "render/scene_file.h"

namespace locus::cli {

std::string implicit_equation_of(const std::string& param_path, Deadline deadline) {
    const std::string text = read_input(param_path);
    implicit::Parametrization map;
    try {
        map = implicit::parse_parametrization(text);
    } catch (const Error& e) {
        throw failure_about(param_path, e);
    }
    if (map.coordinates.size() != 3 || map.parameter_ring->num_vars() != 2) {
        throw CommandFailure(exit_input, param_path +
                                             ": rendering needs a surface: two parameters and "
                                             "coordinates x, y, z");
    }
    algebra::GroebnerOptions options;
    options.deadline = deadline;
    const implicit::ImplicitResult result = implicit::implicitize_auto(map, options);
    if (!result.equation) {
        throw CommandFailure(exit_input, param_path + ": " +
                                             implicit::describe_image(result.image, 2, 3) +
                                             "; there is no single equation to render");
    }
    if (!implicit::vanishes_on_map_as_written(*result.equation, map)) {
        throw CommandFailure(exit_check_failed,
                             param_path +
                                 ": verification FAILED: the implicit equation does "
                                 "not vanish on the parametrization");
    }
    const std::string equation = algebra::to_string(*result.equation);
    std::fprintf(stderr, "%s: implicit equation (%s, verified): %s\n", param_path.c_str(),
                 result.method.c_str(), equation.c_str());
    return equation;
}

algebra::CompiledPolynomial compile_equation(const std::string& name, const std::string& equation,
                                             const char* use) {
    algebra::CompiledPolynomial compiled = [&] {
        try {
            return algebra::compile_surface(equation);
        } catch (const InputError& e) {
            // compile_surface names its subject "equation", which `name` already says.
            throw failure_about(name, e.subject() == "equation" ? InputError(name, e.reason()) : e);
        } catch (const Error& e) {
            throw failure_about(name, e);
        }
    }();
    if (compiled.made_square_free()) {
        std::fprintf(stderr, "%s: the equation has repeated factors; %s its square-free part %s\n",
                     name.c_str(), use, compiled.equation().c_str());
    }
    return compiled;
}

std::vector<algebra::CompiledPolynomial> compile_surfaces(render::Scene& scene, Deadline deadline) {
    std::vector<algebra::CompiledPolynomial> compiled;
    for (std::size_t i = 0; i < scene.surfaces.size(); ++i) {
        render::Surface& surface = scene.surfaces[i];
        const std::string name = !surface.source.empty()
                                     ? surface.source
                                     : "surface[" + std::to_string(i + 1) + "].equation";
        if (!surface.param_file.empty()) {
            surface.equation = implicit_equation_of(surface.param_file, deadline);
        }
        compiled.push_back(compile_equation(name, surface.equation, "rendering"));
    }
    return compiled;
}

void frame_far_equations(render::Scene& scene, std::vector<algebra::CompiledPolynomial>& compiled) {
    const algebra::RingPtr xyz =
        algebra::PolyRing::make({"x", "y", "z"}, algebra::MonomialOrder::grevlex(3));
    for (std::size_t i = 0; i < scene.surfaces.size(); ++i) {
        render::Surface& surface = scene.surfaces[i];
        if (surface.fit_clip || !surface.frame.is_identity()) {
            continue;
        }
        const render::ClipSphere bound = render::bounding_sphere(surface.clip);
        if (!(render::largest_component(bound.center) > 4.0 * bound.radius) ||
            !std::isfinite(bound.radius)) {
            continue;
        }
        const render::ClipBox box{bound.center - render::Vec3(bound.radius),
                                  bound.center + render::Vec3(bound.radius)};
        // The compiled (square-free) equation, exactly, written in the frame.
        auto [frame, local] = framed(algebra::parse_polynomial(compiled[i].equation(), xyz), box);
        surface.equation = algebra::to_string(local);
        surface.frame = frame;
        compiled[i] = algebra::compile_surface(local);
    }
}

render::SurfaceCompiler scene_surface_compiler(Deadline deadline) {
    return [deadline](const render::AlgebraicSource& source) {
        if (source.param_file.empty()) {
            return compile_equation(source.key + ".equation", source.equation, "rendering");
        }
        std::string equation;
        try {
            equation = implicit_equation_of(source.param_file, deadline);
        } catch (const CommandFailure& e) {
            throw CommandFailure(e.code(), source.key + ".param: " + e.what());
        }
        return compile_equation(source.key + ".param", equation, "rendering");
    };
}

SourceKind source_kind(const std::string& source) {
    if (source.ends_with(".toml")) {
        return SourceKind::scene_file;
    }
    if (source.ends_with(".param") || source.ends_with(".bpt")) {
        return SourceKind::param_file;
    }
    return SourceKind::equation;
}

render::Scene scene_from_source(const std::string& source, SourceKind kind,
                                std::optional<render::TraceMethod> method, Deadline deadline) {
    render::Scene scene;
    switch (kind) {
    case SourceKind::scene_file:
        scene = render::parse_scene(read_input(source), scene_surface_compiler(deadline), method,
                                    deadline);
        break;
    case SourceKind::param_file: {
        const std::string text = read_input(source);
        if (holds_patches(source, text)) {
            // Patches: one trimmed surface each, clipped to its control points' box.
            scene.surfaces = patch_surfaces(source, text, deadline);
        } else {
            render::Surface surface;
            surface.param_file = source;
            trim_to_domain(source, text, surface);
            scene.surfaces.push_back(surface);
        }
        break;
    }
    case SourceKind::equation: {
        render::Surface surface;
        surface.equation = source;
        surface.source = "equation";
        scene.surfaces.push_back(surface);
        break;
    }
    }
    if (method && kind != SourceKind::scene_file) {
        scene.options.method = *method;
    }
    return scene;
}

}  // namespace locus::cli
