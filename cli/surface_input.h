// Turning what a user names as a surface (an equation, a .param file, a scene) into compiled
// polynomials, shared by `locus render`, `locus trace` and `locus-bench render`.
#pragma once

#include "cli/process_limits.h"

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "algebra/compiled.h"
#include "render/scene.h"
#include "render/trace_method.h"

namespace locus::cli {

// The implicit equation of the parametrization in `param_path` (implicitize --method auto),
// verified by substitution; reports the route and the equation on standard error. Throws
// CommandFailure: exit 2 for bad input or an image that is not a surface, 4 when verification
// fails; Timeout when the implicitization passes `deadline`.
std::string implicit_equation_of(const std::string& param_path, Deadline deadline = std::nullopt);

// Compiles one equation; errors become CommandFailure (exit 2) prefixed with `name`, and a
// replacement by the square-free part is reported on standard error ("NAME: ... `use` its
// square-free part ...", `use` being "rendering" or "tracing").
algebra::CompiledPolynomial compile_equation(const std::string& name, const std::string& equation,
                                             const char* use);

// Resolves `param` surfaces to equations, then compiles every surface; errors name the surface
// (`surface[2].equation: line 1, column 5: ...`). Reports on standard error when an equation
// was replaced by its square-free part.
std::vector<algebra::CompiledPolynomial> compile_surfaces(render::Scene& scene,
                                                          Deadline deadline = std::nullopt);

// Equations whose clip region lies far from the origin (its centre more than four radii out)
// are rewritten in a frame centred on it, as patches are, and compiled again: expanded at the
// origin, (x-1e8)^2+y^2+z^2-1 cancels in doubles (sturm saw 854 hits where there are 368), and
// the certified method falls back to exact arithmetic on every ray. Call after
// compile_surfaces, before the clip regions are fitted (a surface to be fitted is skipped).
void frame_far_equations(render::Scene& scene, std::vector<algebra::CompiledPolynomial>& compiled);

// The compiler for algebraic leaves of scene trees: implicitizes `param` files as above and
// compiles with the same reports; errors name the leaf ("object[2].equation: ...").
render::SurfaceCompiler scene_surface_compiler(Deadline deadline = std::nullopt);

// What `locus render`, `locus view` and Python's locus.render take as a surface.
enum class SourceKind {
    equation,    // an equation in x, y, z
    scene_file,  // a TOML scene (.toml)
    param_file,  // a parametrization or Bézier patches (.param, .bpt)
};
// By the name's extension: .toml a scene, .param and .bpt a parametrization; else an equation.
SourceKind source_kind(const std::string& source);

// The scene of one source, before compilation: an equation as one surface; a scene file parsed
// (its algebraic leaves compiled with scene_surface_compiler, `method` replacing its [render]
// method before they are built); a parametrization as its implicit surface trimmed to its
// domain, and patches as one trimmed surface each (patch_surfaces.h). Errors as those
// functions throw them (CommandFailure, Error, Timeout).
render::Scene scene_from_source(const std::string& source, SourceKind kind,
                                std::optional<render::TraceMethod> method = std::nullopt,
                                Deadline deadline = std::nullopt);

}  // namespace locus::cli
