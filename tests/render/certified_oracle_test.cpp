// The accuracy contract of `locus trace` (docs/rendering.md, "Accuracy"), checked ray by ray
// against an exact oracle that shares no code with the tracer (tests/support/exact_ray_oracle.h)
// on rays nobody tuned the tracer for: random rays through every surface of the render suite
// and the stability atlas, long intervals (t-max 1e3 and 1e6), far origins (|o| ≈ 1e4 clip
// radii), near-tangent rays to spheres and tori displaced by 1e-3 … 1e-12, rays through
// singular points and rays that start on the surface. The default method (`certified`) must
// answer every ray right; the other methods (`exact` included: it is slow) are measured with
// LOCUS_ORACLE_METHODS=all, not held to it here.
//
// LOCUS_ORACLE_CSV=FILE writes, for every method, the rays and wrong answers per surface and
// kind of ray (docs/stability.md, "Random and constructed rays"); LOCUS_ORACLE_METHODS=all
// measures every method (the default measures certified and exact only).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <map>
#include <mutex>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "algebra/compiled.h"
#include "bench/surface_suite.h"
#include "render/surface_tracer.h"
#include "render/trace_method.h"
#include "tests/support/chmutov.h"
#include "tests/support/exact_ray_oracle.h"
#include "tests/support/test_data.h"

namespace locus::render {
namespace {

using Point = std::array<double, 3>;

struct OracleRay {
    Point origin, direction;
    double t_max;
    std::string kind;
};

struct Case {
    bench::SuiteSurface surface;
    std::string suite;
};

// For readable test names and failure messages.
void PrintTo(const Case& c, std::ostream* out) {
    *out << c.surface.name;
}

std::vector<Case> all_cases() {
    std::vector<Case> cases;
    for (const char* suite : {"surfaces", "atlas/surfaces"}) {
        const std::string text =
            test::read_text(test::source_dir() + "/bench/data/" + suite + "/SUITE.txt");
        for (const bench::SuiteSurface& s : bench::parse_surface_suite(text)) {
            cases.push_back({s, suite});
        }
    }
    return cases;
}

Point unit(std::mt19937_64& rng) {
    std::normal_distribution<double> normal;
    Point p{normal(rng), normal(rng), normal(rng)};
    const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    return {p[0] / n, p[1] / n, p[2] / n};
}

Point scaled(const Point& p, double s) {
    return {p[0] * s, p[1] * s, p[2] * s};
}

Point minus(const Point& a, const Point& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

// A random point of the ball of radius r.
Point in_ball(std::mt19937_64& rng, double r) {
    std::uniform_real_distribution<double> radius(0.0, 1.0);
    return scaled(unit(rng), r * std::cbrt(radius(rng)));
}

// A unit vector orthogonal to n.
Point tangent_to(const Point& n, std::mt19937_64& rng) {
    const Point r = unit(rng);
    const double along = r[0] * n[0] + r[1] * n[1] + r[2] * n[2];
    Point t = minus(r, scaled(n, along));
    const double length = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
    return scaled(t, 1.0 / length);
}

// Spheres centred at 0 among the cases, with their radii; tori x²+y²+z²+R²−r² … with R = 1,
// r = 0.4.
double sphere_radius(const std::string& name) {
    static const std::map<std::string, double> radii = {{"sphere", 1.0},
                                                        {"squared_sphere", 1.0},
                                                        {"cubed_sphere", 1.0},
                                                        {"twin_spheres_1e-4", 1.0},
                                                        {"twin_spheres_1e-6", 1.0},
                                                        {"twin_spheres_1e-8", 1.0},
                                                        {"tiny_coefficients", 1.0},
                                                        {"huge_coefficients", 1.0},
                                                        {"tiny_sphere", 1e-3},
                                                        {"huge_sphere", 1000.0},
                                                        {"repeated_plane", 1.0},
                                                        {"nested_spheres_20", 0.5}};
    const auto it = radii.find(name);
    return it == radii.end() ? 0.0 : it->second;
}
bool is_torus(const std::string& name) {
    return name == "torus" || name == "twin_tori";
}

// Singular points that are doubles, exactly.
std::vector<Point> singular_points(const std::string& name) {
    if (name == "cayley_cubic" || name == "cayley_nodes") {
        return {{0.5, 0.5, -0.5}, {0.5, -0.5, 0.5}, {-0.5, 0.5, 0.5}, {-0.5, -0.5, -0.5}};
    }
    if (name == "whitney_umbrella" || name == "whitney_handle") {
        return {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.5}, {0.0, 0.0, -0.75}};
    }
    if (name == "steiner_roman" || name == "steiner_double_lines") {
        return {{0.0, 0.0, 0.0}, {0.25, 0.0, 0.0}, {0.0, -0.25, 0.0}, {0.0, 0.0, 0.375}};
    }
    if (name == "cusp_cylinder") {
        return {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.5}};
    }
    if (name == "zitrus") {
        return {{0.0, 0.5, 0.0}, {0.0, -0.5, 0.0}};
    }
    if (name == "a3_double_cone") {
        return {{0.0, 0.0, 0.0}};
    }
    return {};
}

// Points exactly on the surface (doubles), for rays that start there.
std::vector<Point> surface_points(const std::string& name) {
    if (sphere_radius(name) == 1.0 && name != "repeated_plane") {
        return {{1.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, {0.0, 1.0, 0.0}};
    }
    if (name == "cayley_cubic" || name == "cayley_nodes") {
        return {{0.5, 0.0, 0.0}, {0.0, -0.5, 0.0}};
    }
    if (name == "whitney_umbrella" || name == "whitney_handle") {
        return {{1.0, 1.0, 1.0}, {0.5, 0.25, 4.0}, {0.0, 0.0, -1.0}};
    }
    if (name == "steiner_roman" || name == "steiner_double_lines") {
        return {{1.0, 0.0, 0.0}, {0.5, 0.0, 0.0}};
    }
    if (name == "a3_double_cone") {
        return {{1.0, 0.0, 1.0}, {0.0, 0.25, 0.5}};
    }
    return {};
}

// The exact oracle's Sturm sequences cost O(n⁴)-ish in the degree n, so the surfaces of degree
// 14 and more get a fifth of the random rays (the suite stays above 10 000 rays in all).
std::vector<OracleRay> rays_for(const Case& c, int degree, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::vector<OracleRay> rays;
    const double R = c.surface.clip_radius;
    const int random_rays = degree >= 14 ? 48 : 240;
    std::uniform_real_distribution<double> distance(2.0, 4.0);
    // Random rays through the clip ball, searched well past it.
    for (int i = 0; i < random_rays; ++i) {
        const Point origin = scaled(unit(rng), R * distance(rng));
        const Point target = in_ball(rng, R);
        rays.push_back({origin, minus(target, origin), 3.0, "random"});
    }
    // Unit directions and long intervals.
    for (int i = 0; i < random_rays / 6; ++i) {
        const Point origin = scaled(unit(rng), R * distance(rng));
        Point d = minus(in_ball(rng, R), origin);
        const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        rays.push_back({origin, scaled(d, 1.0 / n), i % 2 == 0 ? 1e3 : 1e6, "long"});
    }
    // Far origins.
    for (int i = 0; i < random_rays / 12; ++i) {
        const Point origin = scaled(unit(rng), 1e4 * R);
        Point d = minus(in_ball(rng, R), origin);
        const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        rays.push_back({origin, scaled(d, 1.0 / n), 2e4 * R, "far"});
    }
    const std::array<double, 9> offsets = {1e-3,  -1e-3, 1e-6,   -1e-6, 1e-9,
                                           -1e-9, 1e-12, -1e-12, 0.0};
    // Near-tangent rays to spheres: tangent at ρ·n, moved out (δ > 0) or in along n.
    if (const double rho = sphere_radius(c.surface.name); rho > 0.0) {
        for (int i = 0; i < 12; ++i) {
            const Point n = unit(rng);
            const Point t = tangent_to(n, rng);
            for (const double delta : offsets) {
                const Point origin = minus(scaled(n, rho * (1.0 + delta)), scaled(t, 3.0 * rho));
                rays.push_back({origin, scaled(t, rho), 6.0, "tangent"});
            }
        }
    }
    // Near-tangent rays to tori: at the outer and inner equators and the top circle.
    if (is_torus(c.surface.name)) {
        std::uniform_real_distribution<double> angle(0.0, 6.283185307179586);
        for (int i = 0; i < 6; ++i) {
            const double phi = angle(rng);
            const Point radial{std::cos(phi), std::sin(phi), 0.0};
            const Point around{-std::sin(phi), std::cos(phi), 0.0};
            for (const double delta : offsets) {
                // Outer equator, tangent vertically and along it.
                const Point outer = scaled(radial, 1.4 + delta);
                rays.push_back({minus(outer, Point{0, 0, 3.0}), {0.0, 0.0, 1.0}, 6.0, "tangent"});
                rays.push_back({minus(outer, scaled(around, 3.0)), around, 6.0, "tangent"});
                // Top circle, tangent horizontally.
                const Point top{radial[0], radial[1], 0.4 + delta};
                rays.push_back({minus(top, scaled(around, 3.0)), around, 6.0, "tangent"});
                // Inner equator from inside the hole, tangent vertically.
                const Point inner = scaled(radial, 0.6 - delta);
                rays.push_back({minus(inner, Point{0, 0, 3.0}), {0.0, 0.0, 1.0}, 6.0, "tangent"});
            }
        }
    }
    // Through singular points: o = P − 4·d with d of eighths, so the ray meets P at t = 4 exactly.
    std::uniform_int_distribution<int> eighths(-8, 8);
    for (const Point& p : singular_points(c.surface.name)) {
        for (int i = 0; i < 24; ++i) {
            Point d{0.0, 0.0, 0.0};
            while (d == Point{0.0, 0.0, 0.0}) {
                d = {eighths(rng) / 8.0, eighths(rng) / 8.0, eighths(rng) / 8.0};
            }
            rays.push_back({minus(p, scaled(d, 4.0)), d, 8.0, "singular"});
        }
    }
    // Starting on the surface.
    for (const Point& p : surface_points(c.surface.name)) {
        for (int i = 0; i < 12; ++i) {
            rays.push_back({p, unit(rng), 4.0, "on-surface"});
        }
    }
    return rays;
}

struct Tally {
    int rays = 0, wrong = 0, unknown = 0;
};

// The CSV of LOCUS_ORACLE_CSV, shared by the parametrized tests.
std::mutex csv_mutex;

class OracleRays : public ::testing::TestWithParam<Case> {};

TEST_P(OracleRays, CertifiedAnswersEveryRayRight) {
    const Case& c = GetParam();
    const algebra::CompiledPolynomial f = algebra::compile_surface(c.surface.equation);
    const test::ExactRayOracle oracle(c.surface.equation);
    const std::vector<OracleRay> rays =
        rays_for(c, f.degree(), std::hash<std::string>{}(c.surface.name) & 0xffffffu);

    const char* all = std::getenv("LOCUS_ORACLE_METHODS");
    std::vector<TraceMethod> methods = {TraceMethod::certified};
    if (all != nullptr && std::string(all) == "all") {
        methods.assign(all_trace_methods().begin(), all_trace_methods().end());
    }
    std::map<std::pair<TraceMethod, std::string>, Tally> tallies;
    std::map<TraceMethod, std::unique_ptr<SurfaceTracer>> tracers;
    for (const TraceMethod m : methods) {
        tracers[m] = std::make_unique<SurfaceTracer>(f, m, c.surface.clip_radius);
    }
    for (const OracleRay& ray : rays) {
        const test::ExactRayOracle::Restriction exact_restriction =
            oracle.restrict(ray.origin, ray.direction);
        for (const TraceMethod m : methods) {
            const RootResult r = tracers[m]->first_hit({to_vec(ray.origin), to_vec(ray.direction)},
                                                       {0.0, ray.t_max});
            Tally& tally = tallies[{m, ray.kind}];
            ++tally.rays;
            const bool right =
                r.status != RootStatus::unknown &&
                test::ExactRayOracle::is_right(exact_restriction, ray.t_max,
                                               r.status == RootStatus::hit, r.t, kTraceTolerance);
            tally.unknown += r.status == RootStatus::unknown ? 1 : 0;
            tally.wrong += right ? 0 : 1;
            if (!right && (m == TraceMethod::certified || m == TraceMethod::exact)) {
                const test::ExactRayOracle::Answer truth =
                    oracle.first_root(ray.origin, ray.direction, ray.t_max);
                std::ostringstream message;
                message << to_string(m) << " on " << c.surface.name << " (" << ray.kind << "): ray "
                        << ray.origin[0] << ' ' << ray.origin[1] << ' ' << ray.origin[2] << ' '
                        << ray.direction[0] << ' ' << ray.direction[1] << ' ' << ray.direction[2]
                        << " t-max " << ray.t_max << ": answered ";
                if (r.status == RootStatus::hit) {
                    message << r.t;
                } else {
                    message << (r.status == RootStatus::miss ? "miss" : "unknown");
                }
                message << ", the oracle ";
                if (truth.hit) {
                    message << '[' << truth.lower << ", " << truth.upper << ']';
                } else {
                    message << "miss";
                }
                ADD_FAILURE() << message.str();
            }
        }
        // The shadows' query: whether there is a root in (0, t_max], the t anywhere in it.
        const RootResult occluded = tracers[TraceMethod::certified]->occluded(
            {to_vec(ray.origin), to_vec(ray.direction)}, {0.0, ray.t_max});
        ASSERT_NE(occluded.status, RootStatus::unknown);
        const bool occluded_hit = occluded.status == RootStatus::hit;
        EXPECT_TRUE(test::ExactRayOracle::is_right(exact_restriction, ray.t_max, occluded_hit,
                                                   occluded_hit ? ray.t_max : 0.0, INFINITY))
            << c.surface.name << " (" << ray.kind << "): occluded answered "
            << (occluded_hit ? "hit" : "miss");
        if (occluded_hit) {
            EXPECT_GE(occluded.t, 0.0) << c.surface.name;
            EXPECT_LE(occluded.t, ray.t_max) << c.surface.name;
        }
    }
    if (const char* path = std::getenv("LOCUS_ORACLE_CSV")) {
        const std::lock_guard<std::mutex> lock(csv_mutex);
        const bool fresh = !std::ifstream(path).good() || std::ifstream(path).peek() == EOF;
        std::ofstream out(path, std::ios::app);
        if (fresh) {
            out << "surface,kind,method,rays,wrong,unknown\n";
        }
        for (const auto& [key, tally] : tallies) {
            out << c.surface.name << ',' << key.second << ',' << to_string(key.first) << ','
                << tally.rays << ',' << tally.wrong << ',' << tally.unknown << '\n';
        }
    }
}

std::string case_name(const ::testing::TestParamInfo<Case>& info) {
    std::string name = info.param.surface.name;
    for (char& ch : name) {
        if (!std::isalnum(static_cast<unsigned char>(ch))) {
            ch = '_';
        }
    }
    return name;
}

INSTANTIATE_TEST_SUITE_P(Suites, OracleRays, ::testing::ValuesIn(all_cases()), case_name);

// The contract is checked on at least 10 000 rays in all, as the suite promises.
TEST(OracleRaySet, HoldsAtLeastTenThousandRays) {
    std::size_t total = 0;
    for (const Case& c : all_cases()) {
        const algebra::CompiledPolynomial f = algebra::compile_surface(c.surface.equation);
        total += rays_for(c, f.degree(), 0).size();
    }
    EXPECT_GE(total, 10000u);
}

// Rays that start exactly on the surface and leave it at a grazing angle, inward by ε from
// 10^-1 to 10^-12: F(0) = 0, which no ball decides, so exact arithmetic settles the first
// undecided piece alone and the search goes on past it when the next root lies beyond — or
// finds it there when the root is within the piece (ε small). Every answer against the oracle.
TEST(OracleRays, GrazingRaysFromTheSurfaceFindTheNextRoot) {
    struct Start {
        const char* equation;
        Point point, tangent, inward;
    };
    const std::array<Start, 3> starts{{
        {"x^2+y^2+z^2-1", {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {-1.0, 0.0, 0.0}},
        {"(x^2+y^2+z^2+3)^2-16*(x^2+y^2)", {3.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, {-1.0, 0.0, 0.0}},
        {"x^4-5*x^2*y^2+y^4+z^2-1", {1.0, 0.0, 0.0}, {0.0, 0.6, 0.8}, {-1.0, 0.0, 0.0}},
    }};
    for (const Start& start : starts) {
        const algebra::CompiledPolynomial f = algebra::compile_surface(start.equation);
        const test::ExactRayOracle oracle(start.equation);
        const SurfaceTracer tracer(f, TraceMethod::certified, 4.0);
        for (int k = 1; k <= 12; ++k) {
            const double epsilon = std::pow(10.0, -k);
            for (const double sign : {1.0, -1.0}) {
                const Point d{start.tangent[0] + sign * epsilon * start.inward[0],
                              start.tangent[1] + epsilon * start.inward[1],
                              start.tangent[2] + epsilon * start.inward[2]};
                const RootResult r = tracer.first_hit({to_vec(start.point), to_vec(d)}, {0.0, 6.0});
                ASSERT_NE(r.status, RootStatus::unknown) << start.equation << ", ε " << epsilon;
                EXPECT_TRUE(test::ExactRayOracle::is_right(oracle.restrict(start.point, d), 6.0,
                                                           r.status == RootStatus::hit, r.t,
                                                           kTraceTolerance))
                    << start.equation << ", ε " << epsilon << " sign " << sign << ": answered "
                    << (r.status == RootStatus::hit ? std::to_string(r.t) : "miss");
            }
        }
    }
}

// Degree 30 (Chmutov's T₃₀(x) + T₃₀(y) + T₃₀(z), clip radius 1.2), where doubles cannot
// decide most pieces near the roots and the double-double tier and exact arithmetic take over:
// rays of a small frame through the clip sphere, some entering it where the surface crosses
// the sphere (F tiny at the start), each against the exact oracle.
// Chmutov's surfaces of degree 30, 46 and 64 (the most the compiled form takes), on rays from
// afar and rays entering the clip sphere where the surface crosses it.
class HighDegreeRays : public ::testing::TestWithParam<int> {};

TEST_P(HighDegreeRays, AreRightThroughEveryTier) {
    const std::string equation = test::chmutov_equation(GetParam());
    const algebra::CompiledPolynomial f = algebra::compile_surface(equation);
    const test::ExactRayOracle oracle(equation);
    const double radius = 1.2;
    const SurfaceTracer tracer(f, TraceMethod::certified, radius);
    std::mt19937_64 rng(static_cast<std::uint64_t>(GetParam()));
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    // f = T_n(x) + T_n(y) + T_n(z) by T_n(cos θ) = cos(nθ) and T_n(±cosh u) = (±1)^n·cosh(nu):
    // accurate where the power basis in doubles is not (at degree 64 its roundings reach 10³).
    const int n = GetParam();
    const auto chebyshev = [n](double c) {
        if (std::abs(c) <= 1.0) {
            return std::cos(n * std::acos(c));
        }
        const double magnitude = std::cosh(n * std::acosh(std::abs(c)));
        return c < 0.0 && n % 2 == 1 ? -magnitude : magnitude;
    };
    const auto f_at = [&](const Point& p) {
        return chebyshev(p[0]) + chebyshev(p[1]) + chebyshev(p[2]);
    };
    const auto on_sphere = [&](Point p) {
        return scaled(p, radius / std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
    };
    // The oracle's square-free part takes a second a ray at degree 46 and six at 64: fewer
    // rays there.
    const int rays = n <= 30 ? 16 : 4;
    int hits = 0;
    for (int i = 0; i < rays; ++i) {
        Point origin, d;
        if (i % 2 == 0) {
            // From 3.5 radii away toward a random point of the ball.
            origin = scaled(on_sphere({unit(rng), unit(rng), unit(rng)}), 3.5);
            d = minus(scaled({unit(rng), unit(rng), unit(rng)}, 0.6 * radius), origin);
        } else {
            // Entering the sphere where the surface crosses it: bisection in doubles on an
            // arc between points of the sphere where f has opposite signs.
            Point positive, negative;
            do {
                positive = on_sphere({unit(rng), unit(rng), unit(rng)});
            } while (!(f_at(positive) > 0.0));
            do {
                negative = on_sphere({unit(rng), unit(rng), unit(rng)});
            } while (!(f_at(negative) < 0.0));
            for (int step = 0; step < 60; ++step) {
                const Point middle =
                    on_sphere(scaled(minus(positive, scaled(negative, -1.0)), 0.5));
                (f_at(middle) > 0.0 ? positive : negative) = middle;
            }
            const Point entry = positive;
            // Inward, at a random angle to the sphere's normal, from 2 radii outside.
            Point inward = minus({unit(rng), unit(rng), unit(rng)}, scaled(entry, 1.6 / radius));
            d = inward;
            origin = minus(entry, scaled(d, 2.0));
        }
        const double a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        const double b = origin[0] * d[0] + origin[1] * d[1] + origin[2] * d[2];
        const double c =
            origin[0] * origin[0] + origin[1] * origin[1] + origin[2] * origin[2] - radius * radius;
        const double root = std::sqrt(b * b - a * c);
        const double lo = (-b - root) / a, hi = (-b + root) / a;
        const RootResult r = tracer.first_hit({to_vec(origin), to_vec(d)}, {lo, hi});
        ASSERT_NE(r.status, RootStatus::unknown) << "ray " << i;
        const test::ExactRayOracle::Restriction exact = oracle.restrict(origin, d);
        EXPECT_TRUE(test::ExactRayOracle::is_right(exact, lo, hi, r.status == RootStatus::hit, r.t,
                                                   kTraceTolerance))
            << "ray " << i << ": answered "
            << (r.status == RootStatus::hit ? std::to_string(r.t) : "miss");
        hits += r.status == RootStatus::hit ? 1 : 0;
        // Guided by a neighbour's answer (as along an image row whose family does not decide):
        // a hint near the root, and one past it, whose window holds a later root.
        const CertifiedTracer alone(f);
        for (const double at : {0.999, 1.05}) {
            if (r.status != RootStatus::hit) {
                break;
            }
            NeighbourHint hint{lo + at * (r.t - lo), 1e-3 * (hi - lo)};
            const RootResult guided =
                alone.first_hit({to_vec(origin), to_vec(d)}, {lo, hi}, kTraceTolerance, &hint);
            EXPECT_TRUE(test::ExactRayOracle::is_right(
                exact, lo, hi, guided.status == RootStatus::hit, guided.t, kTraceTolerance))
                << "ray " << i << " guided to " << at << " of its root: answered "
                << (guided.status == RootStatus::hit ? std::to_string(guided.t) : "miss");
            EXPECT_EQ(hint.t, guided.t) << "the hint is the answer, for the next ray";
        }
    }
    EXPECT_GT(hits, rays / 2);
}

INSTANTIATE_TEST_SUITE_P(Chmutov, HighDegreeRays, ::testing::Values(30, 46, 64));

// The oracle itself, on closed forms: it must be right for the tests above to mean anything.
TEST(ExactRayOracle, AgreesWithClosedForms) {
    const test::ExactRayOracle sphere("x^2+y^2+z^2-1");
    const auto hit = sphere.first_root({0.0, 0.0, 5.0}, {0.0, 0.0, -1.0}, 100.0);
    ASSERT_TRUE(hit.hit);
    EXPECT_LE(hit.lower, 4.0);
    EXPECT_GE(hit.upper, 4.0);
    EXPECT_LT(hit.upper - hit.lower, 1e-13);
    // Starting on the surface: the next root, not 0.
    const auto next = sphere.first_root({1.0, 0.0, 0.0}, {-1.0, 0.0, 0.0}, 100.0);
    ASSERT_TRUE(next.hit);
    EXPECT_LE(next.lower, 2.0);
    EXPECT_GE(next.upper, 2.0);
    EXPECT_FALSE(sphere.first_root({3.0, 3.0, 3.0}, {1.0, 0.0, 0.0}, 100.0).hit);
    // A tangent ray (double root at t = 3) is a hit; 1e-12 outside it is a miss.
    const auto tangent = sphere.first_root({1.0, -3.0, 0.0}, {0.0, 1.0, 0.0}, 10.0);
    ASSERT_TRUE(tangent.hit);
    EXPECT_NEAR(tangent.lower, 3.0, 1e-12);
    EXPECT_FALSE(sphere.first_root({1.0 + 1e-12, -3.0, 0.0}, {0.0, 1.0, 0.0}, 10.0).hit);
    // Decimals are read exactly: the sphere of radius 0.1 (not the double nearest 0.01).
    const test::ExactRayOracle small("x^2+y^2+z^2-0.01");
    const auto small_hit = small.first_root({0.0, 0.0, 1.0}, {0.0, 0.0, -1.0}, 10.0);
    ASSERT_TRUE(small_hit.hit);
    EXPECT_NEAR(small_hit.lower, 0.9, 1e-14);
    EXPECT_EQ(test::ExactRayOracle::fractions_for_decimals("2.5e-3*x+1e2-x2"),
              "(25/10000)*x+(100)-x2");
}

}  // namespace
}  // namespace locus::render
