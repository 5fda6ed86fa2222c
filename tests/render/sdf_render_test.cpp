// Tracing SDF scenes: every primary ray of a small scene against a fine-step
// reference march (no holes, depths agree), the speed-ups change the work but not the picture,
// and an algebraic surface in a plain union keeps its exact first root.
#include <gtest/gtest.h>

#include <cmath>

#include "render/camera.h"
#include "render/scene_file.h"
#include "render/sdf/algebraic_leaf.h"
#include "render/sdf/scene_tracer.h"
#include "render/sdf/sdf_renderer.h"
#include "render/surface_tracer.h"
#include "sdf_test_nodes.h"

namespace locus::render::sdf {
namespace {

using testing::plain_material;

SurfaceCompiler plain_compiler() {
    return [](const AlgebraicSource& source) { return algebra::compile_surface(source.equation); };
}

// Everything that makes sphere tracing hard in one small scene: a blend, a twist, soft
// objects, noise, an algebraic surface inside a blend (an estimate) and one in the plain
// union (traced exactly), and a floor.
constexpr const char* kScene = R"(
[[object]]
type = "plane"
offset = -1.2
[[object]]
type = "smooth_union"
k = 0.4
translate = [-1.6, 0, 0]
  [[object.children]]
  type = "sphere"
  radius = 0.6
  [[object.children]]
  type = "algebraic"
  equation = "x^2+y^2/4+z^2-0.25"
  clip_radius = 1.2
  translate = [0.5, 0, 0]
[[object]]
type = "group"
twist = 1.5
translate = [0, 0, 0]
  [[object.children]]
  type = "box"
  half_size = [0.3, 0.9, 0.5]
[[object]]
type = "soft_objects"
threshold = 0.4
balls = [{center = [0, 0, 0], radius = 0.8}, {center = [0.5, 0.3, 0], radius = 0.6}]
translate = [1.5, 0.2, 0]
displace = {amplitude = 0.04, frequency = 3, octaves = 2}
[[object]]
type = "algebraic"
equation = "x^2*y^2+y^2*z^2+z^2*x^2-x*y*z"
clip_radius = 0.7
translate = [0, 0, 1.6]
)";

struct Frame {
    Scene scene;
    std::vector<NodePtr> items;
    Camera camera;
    double far;
};

Frame make_frame(const char* text, int width, int height) {
    Scene scene = parse_scene(text, plain_compiler());
    scene.width = width;
    scene.height = height;
    scene.camera = CameraSpec{{0.5, 2.0, 6.0}, {0, 0, 0.3}, {0, 1, 0}, 45.0};
    std::vector<NodePtr> items = scene_items(scene, {});
    const Camera camera(*scene.camera, width, height);
    return {scene, items, camera, 30.0};
}

// The reference: march in steps of 1e-3 and report the first sign change of any item's value.
double reference_hit(const std::vector<NodePtr>& items, const Ray& ray, double far) {
    const double step = 1e-3;
    std::vector<double> previous;
    for (const NodePtr& item : items) {
        previous.push_back(item->value(ray.origin));
    }
    for (double t = step; t < far; t += step) {
        for (std::size_t i = 0; i < items.size(); ++i) {
            // Skip the far part of boxes quickly: a bounded item cannot change sign outside.
            const Vec3 p = ray.at(t);
            if (items[i]->bounds().distance(p) > 0.0) {
                previous[i] = 1.0;
                continue;
            }
            const double v = items[i]->value(p);
            if ((v < 0.0) != (previous[i] < 0.0)) {
                return t;
            }
            previous[i] = v;
        }
    }
    return INFINITY;
}

TEST(SdfRender, NoHolesAgainstAFineStepReference) {
    Frame frame = make_frame(kScene, 48, 32);
    const SceneTracer tracer(frame.items, 2.5);
    const double footprint =
        glm::length(frame.camera.per_row()) / glm::length(frame.camera.direction(24, 16));
    int hits = 0, disagreements = 0, holes = 0;
    std::vector<char> reference_hits(48 * 32);
    std::vector<char> traced_hits(48 * 32);
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 48; ++x) {
            const Ray ray{frame.camera.eye(),
                          glm::normalize(frame.camera.direction(x + 0.5, y + 0.5))};
            TraceCounters counters;
            const SceneHit hit = tracer.first_hit(ray, {0.0, frame.far}, footprint, counters);
            const double reference = reference_hit(frame.items, ray, frame.far);
            reference_hits[y * 48 + x] = std::isfinite(reference);
            traced_hits[y * 48 + x] = hit.found();
            hits += hit.found();
            // Disagreements: hit against miss, or a different first surface (a corner
            // clipped by less than the half-pixel tolerance, which the tracer may step over).
            if (hit.found() != std::isfinite(reference) ||
                (hit.found() && std::abs(hit.t - reference) > 2e-3 + footprint * hit.t)) {
                ++disagreements;
            }
        }
    }
    // A hole: the reference hits this pixel and all four neighbours, the tracer does not.
    for (int y = 1; y < 31; ++y) {
        for (int x = 1; x < 47; ++x) {
            const int p = y * 48 + x;
            if (reference_hits[p] && reference_hits[p - 1] && reference_hits[p + 1] &&
                reference_hits[p - 48] && reference_hits[p + 48] && !traced_hits[p]) {
                ++holes;
            }
        }
    }
    EXPECT_EQ(holes, 0);
    EXPECT_LE(disagreements, 8);  // silhouette pixels only: 0.5 % of 1536
    EXPECT_GT(hits, 700);
}

TEST(SdfRender, SpeedUpsChangeTheWorkNotThePicture) {
    // A hundred primitives in a plain union, as in `locus-bench sdf`.
    const MaterialPtr m = plain_material();
    std::vector<NodePtr> objects{make_plane({0, 1, 0}, -0.5, m)};
    for (int i = 0; i < 10; ++i) {
        for (int j = 0; j < 10; ++j) {
            const Vec3 at{i - 4.5, 0.0, j - 4.5};
            NodePtr shape = (i + j) % 3 == 0   ? make_sphere(0.35, m)
                            : (i + j) % 3 == 1 ? make_box({0.3, 0.3, 0.3}, 0.05, m)
                                               : make_torus(0.3, 0.1, m);
            objects.push_back(make_placement(shape, glm::dmat3(1.0), 1.0, at));
        }
    }
    const Camera camera({{0, 6, 9}, {0, 0, 0}, {0, 1, 0}, 40.0}, 64, 48);
    const double footprint = glm::length(camera.per_row()) / glm::length(camera.direction(32, 24));
    const SceneTracer fast(objects, 7.0);
    const SceneTracer plain(objects, 7.0, kNoSpeedUps);
    long fast_work = 0, plain_work = 0;
    int differing = 0;
    for (int y = 0; y < 48; ++y) {
        for (int x = 0; x < 64; ++x) {
            const Ray ray{camera.eye(), glm::normalize(camera.direction(x + 0.5, y + 0.5))};
            TraceCounters a, b;
            const SceneHit h1 = fast.first_hit(ray, {0, 100}, footprint, a);
            const SceneHit h2 = plain.first_hit(ray, {0, 100}, footprint, b);
            fast_work += a.evaluations;
            plain_work += b.evaluations;
            if (h1.found() != h2.found() ||
                (h1.found() && std::abs(h1.t - h2.t) > 2.0 * footprint * h1.t)) {
                ++differing;
            }
        }
    }
    EXPECT_LE(differing, 15);  // 0.5 %: silhouettes decided within the hit tolerance
    EXPECT_LT(2 * fast_work, plain_work) << fast_work << " vs " << plain_work;
}

TEST(SdfRender, RoundingABoundDoesNotLeaveItsBoundingBox) {
    // Regression (review): round = 0.3 on a twisted box grew the shape past its box grown by
    // 0.3, where the bounding volumes cut it off: 29 % of the pixels differed.
    const Scene scene = parse_scene(R"(
[[object]]
type = "group"
round = 0.3
  [[object.children]]
  type = "box"
  half_size = [0.6, 0.4, 0.6]
  twist = 3.0
)");
    const std::vector<NodePtr> items = scene_items(scene, {});
    const Camera camera({{0.0, 0.3, 5.0}, {0, 0, 0}, {0, 1, 0}, 40.0}, 48, 32);
    const double footprint = glm::length(camera.per_row()) / glm::length(camera.direction(24, 16));
    const SceneTracer with(items, 1.0);
    const SceneTracer without(items, 1.0, {.bounding_volumes = false});
    int differing = 0;
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 48; ++x) {
            const Ray ray{camera.eye(), glm::normalize(camera.direction(x + 0.5, y + 0.5))};
            TraceCounters a, b;
            differing += with.first_hit(ray, {0, 20}, footprint, a).found() !=
                         without.first_hit(ray, {0, 20}, footprint, b).found();
        }
    }
    EXPECT_LE(differing, 8);
}

TEST(SdfRender, SoftShadowUnderAnOverheadLightIsNotBlack) {
    // Regression: with the light straight above, the field grows by about the step itself
    // along the shadow ray, the improved-penumbra estimate degenerated (y ≥ h gave d = 0) and
    // the whole floor went dark.
    const MaterialPtr m = plain_material();
    const std::vector<NodePtr> objects{
        make_plane({0, 1, 0}, 0.0, m),
        make_placement(make_sphere(0.5, m), glm::dmat3(1.0), 1.0, {0, 1.5, 0})};
    const SceneTracer tracer(objects, 2.0);
    TraceCounters counters;
    const double open = tracer.transmittance({{3, 1e-3, 0}, {0, 1, 0}}, 100.0, 20.0, counters);
    EXPECT_GT(open, 0.99);
    const double under = tracer.transmittance({{0, 1e-3, 0}, {0, 1, 0}}, 100.0, 20.0, counters);
    EXPECT_EQ(under, 0.0);
}

TEST(SdfRender, AlgebraicSurfaceInAPlainUnionKeepsItsExactRoot) {
    const Scene scene = parse_scene(R"(
[[object]]
type = "union"
  [[object.children]]
  type = "sphere"
  radius = 0.3
  translate = [3, 0, 0]
  [[object.children]]
  type = "algebraic"
  equation = "x^4+y^4+z^4-1"
  clip_radius = 1.5
  translate = [0, 0.25, 0]
)",
                                    plain_compiler());
    const std::vector<NodePtr> items = scene_items(scene, {});
    const SceneTracer tracer(items, 2.0);
    const algebra::CompiledPolynomial f = algebra::compile_surface("x^4+y^4+z^4-1");
    for (const Vec3 direction : {Vec3{0, -0.05, -1}, Vec3{0.1, 0.02, -1}, Vec3{-0.2, 0.1, -1}}) {
        const Ray ray{{0, 0.25, 5}, glm::normalize(direction)};
        TraceCounters counters;
        const SceneHit hit = tracer.first_hit(ray, {0, 20}, 1e-3, counters);
        ASSERT_TRUE(hit.found());
        // The certified root of the untranslated quartic along the same ray, shifted.
        const algebra::ExactRoot exact = algebra::exact_first_root(
            f, to_point(ray.origin - Vec3(0, 0.25, 0)), to_point(ray.direction), 0.0, 20.0);
        ASSERT_EQ(exact.status, algebra::ExactRoot::Status::hit);
        EXPECT_NEAR(hit.t, exact.t, 1e-9);
        EXPECT_EQ(counters.evaluations, 0);  // no sphere tracing was needed
    }
    // A placement on the union is distributed over its members (regression: it made the
    // union one sphere-traced item, the algebraic leaf an estimate).
    const Scene moved = parse_scene(R"(
[[object]]
type = "union"
translate = [0, 0.5, 0]
  [[object.children]]
  type = "sphere"
  radius = 0.3
  translate = [3, 0, 0]
  [[object.children]]
  type = "algebraic"
  equation = "x^4+y^4+z^4-1"
  clip_radius = 1.5
)",
                                    plain_compiler());
    const SceneTracer moved_tracer(scene_items(moved, {}), 2.0);
    {
        const Ray ray{{0, 0.5, 5}, {0, 0, -1}};
        TraceCounters counters;
        const SceneHit hit = moved_tracer.first_hit(ray, {0, 20}, 1e-3, counters);
        ASSERT_TRUE(hit.found());
        EXPECT_NEAR(hit.t, 4.0, 1e-12);
        EXPECT_EQ(counters.evaluations, 0);
    }
}

}  // namespace
}  // namespace locus::render::sdf
