// The CLI's preparation of a scene's surfaces (cli/surface_input.h): an equation far from the
// origin is written in a frame about its clip region, and keeps its sides there.
#include "cli/surface_input.h"

#include <gtest/gtest.h>

#include "algebra/compiled.h"
#include "render/scene.h"

namespace locus::cli {
namespace {

// f = 1 − (x − 20)² − y² − z² is positive inside the ball: written in a frame about its clip
// sphere (x = 20 + 2x'), the equation is made integral by its content, not primitive, whose
// positive leading coefficient would swap the sides (the two-sided colours, an SDF leaf's
// inside). The compiled frame equation must be positive at the ball's centre and negative
// outside it, as f is at the same world points.
TEST(FrameFarEquations, KeepTheEquationsSides) {
    render::Scene scene;
    scene.surfaces.push_back({"1-(x-20)^2-y^2-z^2", "", render::ClipSphere{{20.0, 0.0, 0.0}, 1.5},
                              render::Material{}, ""});
    scene.surfaces[0].fit_clip = false;  // the clip sphere is given
    std::vector<algebra::CompiledPolynomial> compiled = {
        algebra::compile_surface(scene.surfaces[0].equation)};
    ASSERT_GT(compiled[0].value({20.0, 0.0, 0.0}), 0.0);
    frame_far_equations(scene, compiled);
    const render::SurfaceFrame& frame = scene.surfaces[0].frame;
    ASSERT_FALSE(frame.is_identity());
    const auto local = [&](double x, double y, double z) {
        return algebra::Point3{(x - frame.origin.x) / frame.scale,
                               (y - frame.origin.y) / frame.scale,
                               (z - frame.origin.z) / frame.scale};
    };
    EXPECT_GT(compiled[0].value(local(20.0, 0.0, 0.0)), 0.0) << scene.surfaces[0].equation;
    EXPECT_GT(compiled[0].value(local(20.5, 0.3, -0.2)), 0.0) << scene.surfaces[0].equation;
    EXPECT_LT(compiled[0].value(local(21.4, 0.0, 0.0)), 0.0) << scene.surfaces[0].equation;
    EXPECT_LT(compiled[0].value(local(19.0, 0.9, 0.5)), 0.0) << scene.surfaces[0].equation;
}

}  // namespace
}  // namespace locus::cli
