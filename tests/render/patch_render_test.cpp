// Trimmed rendering of Bézier patches, checked against a renderer that shares no code with it:
// a fine tessellation of the parametrization (its vertices by de Casteljau on control points the
// test reads itself, or by the parametrization's own formulas), intersected ray by ray
// (Möller–Trumbore), with the same camera; designed patches and random ones. The silhouettes must
// agree to within 0.5 % of the pixels and the depths to within the tessellation's own error. Also:
// the trim test accepts points of the patch and refuses points of the implicit surface beyond the
// patch's edges.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <sstream>

#include "algebra/compiled.h"
#include "algebra/print.h"
#include "cli/patch_surfaces.h"
#include "implicit/implicitize.h"
#include "render/camera.h"
#include "render/patch_trim.h"
#include "render/renderer.h"
#include "render/surface_tracer.h"
#include "tests/support/test_data.h"

namespace locus::render {
namespace {

TEST(PatchTrim, PointsBeyondTheEdgesOfTheDomainAreRefused) {
    // The bilinear patch x = s, y = t, z = s·t on [0, 1]², whose surface is z = x·y.
    const auto surfaces =
        cli::patch_surfaces("bilinear.bpt", "1\n1 1\n0 0 0\n0 1 0\n1 0 0\n1 1 1\n", std::nullopt);
    ASSERT_EQ(surfaces.size(), 1u);
    // z = x·y, written in the frame centred on the box of control points: x = 1/2 + x', ….
    EXPECT_EQ(surfaces[0].frame.origin, Vec3(0.5));
    EXPECT_EQ(surfaces[0].frame.scale, 1.0);
    EXPECT_EQ(surfaces[0].equation, "4*x*y+2*x+2*y-4*z-1");
    const PatchTrim& trim = *surfaces[0].trim;
    EXPECT_TRUE(trim.contains({0.5, 0.25, 0.125}, 1e-9));
    EXPECT_TRUE(trim.contains({1.0, 1.0, 1.0}, 1e-9));    // a corner
    EXPECT_FALSE(trim.contains({1.5, 0.5, 0.75}, 1e-9));  // on z = x·y, beyond s = 1
    EXPECT_FALSE(trim.contains({-0.2, -0.3, 0.06}, 1e-9));
    EXPECT_FALSE(trim.contains({0.5, 0.5, 0.3}, 1e-9));  // off the surface
    const auto st = trim.preimage({0.3, 0.7, 0.21});
    EXPECT_NEAR(st[0], 0.3, 1e-12);
    EXPECT_NEAR(st[1], 0.7, 1e-12);
    // A triangle: the plane x + y + z = 1 only where x, y, z ≥ 0.
    const auto plane = cli::patch_surfaces(
        "plane.param", "bezier: triangle 1\n1 0 0\n0 1 0\n0 0 1\n", std::nullopt);
    EXPECT_TRUE(plane[0].trim->contains({0.2, 0.3, 0.5}, 1e-9));
    EXPECT_FALSE(plane[0].trim->contains({0.7, 0.7, -0.4}, 1e-9));
}

TEST(PatchTrim, ExponentsOfAnyHeightAreEvaluated) {
    // Regression: the trim's evaluator kept a fixed table of 34 powers and read past its end for
    // a `.param` of higher degree.
    Surface surface;
    surface.equation = "x-y^40";
    cli::trim_to_domain("high.param",
                        "params: u,v\ndomain: u in [0, 1], v in [0, 1]\nx = u^40\ny = u\n"
                        "z = u*v^37\n",
                        surface);
    ASSERT_TRUE(surface.trim);
    const Vec3 p = surface.trim->at(0.9, 0.95);
    EXPECT_NEAR(p.x, std::pow(0.9, 40), 1e-15);
    EXPECT_NEAR(p.z, 0.9 * std::pow(0.95, 37), 1e-15);
    EXPECT_TRUE(surface.trim->contains(p, 1e-9));
    EXPECT_FALSE(surface.trim->contains({std::pow(1.1, 40), 1.1, 0.5}, 1e-9));
}

// The oracle's own patch evaluation: control points read from the test's text (not by locus's
// parser) and evaluated by de Casteljau's algorithm in homogeneous coordinates — sharing
// neither the Bernstein-to-monomial conversion nor the evaluator with the trim under test.
struct ControlNet {
    int m = 0, n = 0;
    std::vector<std::array<double, 4>> points;  // w·x, w·y, w·z, w
};

ControlNet read_control_net(const std::string& text) {
    std::istringstream in(text);
    ControlNet net;
    std::string word, line;
    in >> word >> net.m >> net.n;  // "bezier: m n"
    std::getline(in, line);
    while (std::getline(in, line)) {
        std::istringstream fields(line);
        std::array<double, 4> p{0.0, 0.0, 0.0, 1.0};
        if (!(fields >> p[0] >> p[1] >> p[2])) {
            continue;
        }
        fields >> p[3];
        net.points.push_back({p[3] * p[0], p[3] * p[1], p[3] * p[2], p[3]});
    }
    EXPECT_EQ(net.points.size(), static_cast<std::size_t>((net.m + 1) * (net.n + 1)));
    return net;
}

std::array<double, 4> de_casteljau(std::vector<std::array<double, 4>> points, double u) {
    for (std::size_t r = 1; r < points.size(); ++r) {
        for (std::size_t j = 0; j + r < points.size(); ++j) {
            for (int c = 0; c < 4; ++c) {
                points[j][c] = (1.0 - u) * points[j][c] + u * points[j + 1][c];
            }
        }
    }
    return points[0];
}

Vec3 point_of(const ControlNet& net, double s, double t) {
    std::vector<std::array<double, 4>> column;
    for (int i = 0; i <= net.m; ++i) {
        const auto row = net.points.begin() + i * (net.n + 1);
        column.push_back(de_casteljau({row, row + net.n + 1}, t));
    }
    const auto h = de_casteljau(column, s);
    return Vec3(h[0], h[1], h[2]) / h[3];
}

// Hit mask and depth of a tessellated patch for every pixel.
struct TessellatedView {
    std::vector<double> depth;  // +inf on a miss
    double error = 0.0;         // largest distance of the patch from its triangles (sampled)
};

// `at` maps the unit square onto the patch.
TessellatedView tessellate_and_trace(const std::function<Vec3(double, double)>& at,
                                     const Camera& camera, int width, int height, int cells) {
    std::vector<Vec3> grid;
    for (int i = 0; i <= cells; ++i) {
        for (int j = 0; j <= cells; ++j) {
            grid.push_back(at(static_cast<double>(i) / cells, static_cast<double>(j) / cells));
        }
    }
    auto vertex = [&](int i, int j) { return grid[static_cast<std::size_t>(i * (cells + 1) + j)]; };
    std::vector<std::array<Vec3, 3>> triangles;
    TessellatedView view;
    for (int i = 0; i < cells; ++i) {
        for (int j = 0; j < cells; ++j) {
            const Vec3 a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1),
                       d = vertex(i, j + 1);
            triangles.push_back({a, b, c});
            triangles.push_back({a, c, d});
            // The patch at the cell's centre against the triangles' shared edge midpoint.
            const Vec3 mid = at((i + 0.5) / cells, (j + 0.5) / cells);
            view.error = std::max(view.error, glm::length(mid - 0.5 * (a + c)));
        }
    }
    view.depth.assign(static_cast<std::size_t>(width) * height, INFINITY);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const Ray ray = camera.ray(x + 0.5, y + 0.5);
            double best = INFINITY;
            for (const auto& [p0, p1, p2] : triangles) {
                // Möller–Trumbore.
                const Vec3 e1 = p1 - p0, e2 = p2 - p0;
                const Vec3 h = glm::cross(ray.direction, e2);
                const double det = glm::dot(e1, h);
                if (std::abs(det) < 1e-300) {
                    continue;
                }
                const Vec3 s = ray.origin - p0;
                const double u = glm::dot(s, h) / det;
                const Vec3 q = glm::cross(s, e1);
                const double v = glm::dot(ray.direction, q) / det;
                const double t = glm::dot(e2, q) / det;
                if (u >= 0 && v >= 0 && u + v <= 1 && t > 0 && t < best) {
                    best = t;
                }
            }
            view.depth[static_cast<std::size_t>(y) * width + x] = best * glm::length(ray.direction);
        }
    }
    return view;
}

void expect_surfaces_match_tessellation(
    const std::string& name, std::vector<Surface> surfaces,
    const std::vector<std::function<Vec3(double, double)>>& patches, const CameraSpec& spec) {
    SCOPED_TRACE(name);
    Scene scene;
    scene.surfaces = std::move(surfaces);
    scene.width = scene.height = 64;
    scene.camera = spec;
    scene.options.shadows = false;
    std::vector<algebra::CompiledPolynomial> compiled;
    for (const auto& surface : scene.surfaces) {
        compiled.push_back(algebra::compile_surface(surface.equation));
    }
    ExecutionSettings execution;
    execution.threads = 2;
    RenderStats stats;
    const RenderedImage image = render(scene, compiled, execution, &stats);
    EXPECT_EQ(stats.unknown, 0);
    const Camera camera(spec, scene.width, scene.height);
    const std::size_t pixels = image.depth.size();
    std::vector<double> reference(pixels, INFINITY);
    double error = 0.0;
    for (const auto& at : patches) {
        const TessellatedView view =
            tessellate_and_trace(at, camera, scene.width, scene.height, 48);
        error = std::max(error, view.error);
        for (std::size_t i = 0; i < pixels; ++i) {
            reference[i] = std::min(reference[i], view.depth[i]);
        }
    }
    std::size_t silhouette_differs = 0, both = 0, depth_differs = 0, hits = 0;
    for (std::size_t i = 0; i < pixels; ++i) {
        const bool a = std::isfinite(image.depth[i]), b = std::isfinite(reference[i]);
        hits += b;
        if (a != b) {
            ++silhouette_differs;
        } else if (a) {
            ++both;
            // Up to the tessellation error along a ray at up to 75° from the surface normal.
            depth_differs += std::abs(image.depth[i] - reference[i]) > 4.0 * error + 1e-9;
        }
    }
    EXPECT_GT(hits, pixels / 20);  // the patch is in the picture
    EXPECT_LE(silhouette_differs, pixels / 200) << "of " << pixels << " pixels";
    EXPECT_LE(depth_differs, both / 100) << "of " << both << " pixels hit by both; error " << error;
}

void expect_trimmed_render_matches_tessellation(const std::string& name, const std::string& text,
                                                const CameraSpec& spec) {
    const ControlNet net = read_control_net(text);
    expect_surfaces_match_tessellation(name, cli::patch_surfaces(name, text, std::nullopt),
                                       {[net](double s, double t) { return point_of(net, s, t); }},
                                       spec);
}

TEST(PatchRender, TrimmedPatchesMatchTheirTessellation) {
    // A biquadratic patch whose implicit quartic-by-quartic surface has sheets beyond its edges,
    // a rational one, and one with a collapsed edge (its Dixon matrix is singular).
    const CameraSpec camera{{4.0, 3.0, 6.0}, {0.5, 0.5, 1.0}, {0.0, 0.0, 1.0}, 40.0};
    expect_trimmed_render_matches_tessellation(
        "biquadratic.param",
        "bezier: 2 2\n0 0 0\n1 0 1\n2 0 0\n0 1 1\n1 1 3\n2 1 1\n0 2 0\n1 2 1\n2 2 0\n",
        {{5.0, -3.0, 4.0}, {1.0, 1.0, 0.8}, {0.0, 0.0, 1.0}, 40.0});
    expect_trimmed_render_matches_tessellation(
        "rational.param",
        "bezier: 2 2\n1 0 0\n1 1 0 2\n0 1 1\n2 0 1 3\n1 2 1 1\n-1 1 2\n0 0 2\n1 -1 3 2\n2 1 1\n",
        camera);
    expect_trimmed_render_matches_tessellation(
        "collapsed.param",
        "bezier: 2 2\n0 0 3\n0 0 3\n0 0 3\n2 0 1\n1 2 1\n-1 1 2\n0 1 0\n1 -1 3\n2 2 1\n", camera);
}

// A random biquadratic patch: integer control points in [-2, 2]³, weights in {1/2, 1, 3/2, 2}
// when `rational`; `collapse` pulls the first row of points to within 1e-3 of one point (an
// almost-degenerate edge).
std::string random_patch(std::mt19937& rng, bool rational, bool collapse) {
    std::uniform_int_distribution<int> coordinate(-2, 2), weight(1, 4);
    std::ostringstream text;
    text << "bezier: 2 2\n";
    std::array<int, 3> first{};
    for (int k = 0; k < 9; ++k) {
        std::array<int, 3> p{coordinate(rng), coordinate(rng), coordinate(rng)};
        if (k == 0) {
            first = p;
        }
        if (collapse && k < 3) {
            text << first[0] + 0.001 * k << ' ' << first[1] << ' ' << first[2] - 0.001 * k;
        } else {
            text << p[0] << ' ' << p[1] << ' ' << p[2];
        }
        if (rational) {
            text << ' ' << 0.5 * weight(rng);
        }
        text << "\n";
    }
    return text.str();
}

TEST(PatchRender, RandomPatchesMatchTheirTessellation) {
    // Patches nobody designed: polynomial, rational and almost-collapsed ones, seen from a
    // camera placed by their control points' box.
    std::mt19937 rng(20261126);
    for (int k = 0; k < 6; ++k) {
        const std::string text = random_patch(rng, k % 2 == 1, k >= 4);
        const ControlNet net = read_control_net(text);
        Vec3 lo(INFINITY), hi(-INFINITY);
        for (const auto& p : net.points) {
            lo = glm::min(lo, Vec3(p[0], p[1], p[2]) / p[3]);
            hi = glm::max(hi, Vec3(p[0], p[1], p[2]) / p[3]);
        }
        const Vec3 centre = 0.5 * (lo + hi);
        const double size = std::max(1.0, glm::length(hi - lo));
        const Vec3 eye = centre + 1.2 * size * glm::normalize(Vec3(1.3, -0.9, 0.8));
        expect_trimmed_render_matches_tessellation(
            "random patch " + std::to_string(k) + ":\n" + text, text,
            {eye, centre, {0.0, 0.0, 1.0}, 40.0});
    }
}

TEST(PatchRender, AParametrizationTrimmedToItsDomainMatchesItsTessellation) {
    // Enneper's surface for |u|, |v| ≤ 2: its degree-9 equation describes the whole surface.
    const std::string text =
        "params: u,v\ndomain: u in [-2, 2], v in [-2, 2]\nx = u - u^3/3 + u*v^2\n"
        "y = v - v^3/3 + v*u^2\nz = u^2 - v^2\n";
    const implicit::Parametrization map = implicit::parse_parametrization(text);
    const implicit::ImplicitResult r = implicit::implicitize_auto(map);
    ASSERT_TRUE(r.equation);
    Surface surface;
    surface.equation = algebra::to_string(*r.equation);
    cli::trim_to_domain("enneper.param", text, surface);
    ASSERT_TRUE(surface.trim);
    EXPECT_EQ(surface.trim->box().s0, -2.0);
    EXPECT_EQ(surface.trim->box().t1, 2.0);
    // The tessellation evaluates Enneper's formulas itself, over the domain.
    const auto enneper = [](double a, double b) {
        const double u = 4.0 * a - 2.0, v = 4.0 * b - 2.0;
        return Vec3(u - u * u * u / 3 + u * v * v, v - v * v * v / 3 + v * u * u, u * u - v * v);
    };
    expect_surfaces_match_tessellation(
        "enneper", {surface}, {enneper},
        {{16.0, -22.0, 14.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 30.0});
}

TEST(PatchRender, CertifiedTracingFindsTheSpoutWhereFloatingPointSturmDoesNot) {
    // The teapot's patch 19 (the spout's tip): degree 18, coefficients of up to 300 bits. Rays
    // along the normal through points of the patch, from both sides, must meet the surface at
    // the point or at another sheet in front of it — never miss it, never pass it. Floating-
    // point Sturm sequences missed 48 of these 50 rays: the reason patches render with the
    // certified method.
    std::istringstream file(
        test::read_text(test::source_dir() + "/bench/data/implicit/teapot.bpt"));
    std::string line, text = "1\n";
    for (int number = 1; std::getline(file, line); ++number) {
        if (number >= 308 && number <= 324) {  // patch 19: its degree line and 16 points
            text += line + "\n";
        }
    }
    const auto surfaces = cli::patch_surfaces("spout.bpt", text, std::nullopt);
    ASSERT_EQ(surfaces.size(), 1u);
    const PatchTrim& trim = *surfaces[0].trim;
    const algebra::CompiledPolynomial f = algebra::compile_surface(surfaces[0].equation);
    ASSERT_EQ(f.degree(), 18);
    const SurfaceTracer certified(f, TraceMethod::certified, 5.0, kRenderTolerance,
                                  surfaces[0].frame);
    int at_point = 0;
    for (const double s : {0.1, 0.5, 0.8, 0.9, 0.95}) {
        for (const double t : {0.1, 0.3, 0.5, 0.7, 0.9}) {
            const Vec3 p = trim.at(s, t);
            const double h = 1e-5;
            const Vec3 normal = glm::normalize(glm::cross(trim.at(s + h, t) - trim.at(s - h, t),
                                                          trim.at(s, t + h) - trim.at(s, t - h)));
            for (const double side : {1.0, -1.0}) {
                const Ray ray{p + 0.05 * side * normal, -side * normal};
                const RootResult hit = certified.first_hit(ray, {0.0, 0.1});
                ASSERT_EQ(hit.status, RootStatus::hit) << "s " << s << ", t " << t;
                EXPECT_LE(hit.t, 0.05 + 1e-9) << "s " << s << ", t " << t;
                at_point += std::abs(hit.t - 0.05) < 1e-6;
            }
        }
    }
    EXPECT_GE(at_point, 35);
}

}  // namespace
}  // namespace locus::render
