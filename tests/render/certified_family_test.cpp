// The certified method on primary rays, as the renderer runs it: each pixel's ball from the
// frame's CertifiedRayFamily, searched with and without a neighbour's hint
// (CertifiedTracer::first_hit_from, isolate_first_root_near). The hint only steers the search,
// so every answer — whatever the hint: the true root, a later root, a random point, a window far
// too narrow or too wide — must keep the contract, checked against the exact oracle
// (tests/support/exact_ray_oracle.h), which shares no code with the tracer. Surfaces and
// cameras nobody tuned the search for: thin walls (Chmutov's octic), nodes, double surfaces,
// random eyes.
#include <gtest/gtest.h>

#include <flint/fmpq.h>

#include <cmath>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "algebra/compiled.h"
#include "bench/surface_suite.h"
#include "render/bernstein_ball.h"
#include "render/certified_isolation.h"
#include "render/certified_ray_family.h"
#include "render/certified_tracer.h"
#include "tests/support/chmutov.h"
#include "tests/support/exact_ray_oracle.h"
#include "tests/support/test_data.h"

namespace locus::render {
namespace {

bench::SuiteSurface suite_surface(const std::string& name) {
    const std::string text = test::read_text(test::source_dir() + "/bench/data/surfaces/SUITE.txt");
    for (const bench::SuiteSurface& s : bench::parse_surface_suite(text)) {
        if (s.name == name) {
            return s;
        }
    }
    throw std::runtime_error("no suite surface " + name);
}

// The ray's chord of the clip sphere about the origin, inside the family's range of t
// (nothing when the ray misses the sphere).
std::optional<Interval> clip_chord(const Ray& ray, double radius, double t0, double width) {
    const double a = glm::dot(ray.direction, ray.direction);
    const double b = glm::dot(ray.origin, ray.direction);
    const double c = glm::dot(ray.origin, ray.origin) - radius * radius;
    const double discriminant = b * b - a * c;
    if (!(discriminant > 0.0)) {
        return std::nullopt;
    }
    const double root = std::sqrt(discriminant);
    return Interval{std::max(t0, (-b - root) / a), std::min(t0 + width, (-b + root) / a)};
}

// A camera looking at the origin from an eye at 2.5–4 clip radii in a random direction.
Camera random_camera(std::mt19937_64& random, double radius, int width, int height) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0), fraction(0.0, 1.0);
    Vec3 eye{unit(random), unit(random), unit(random)};
    eye *= (2.5 + 1.5 * fraction(random)) * radius / glm::length(eye);
    return Camera({eye, {0.0, 0.0, 0.0}, {0.3, 1.0, 0.1}, 35.0}, width, height);
}

class GuidedSearch : public ::testing::TestWithParam<const char*> {};

TEST_P(GuidedSearch, EveryHintGivesACertifiedAnswer) {
    const bench::SuiteSurface surface = suite_surface(GetParam());
    const algebra::CompiledPolynomial f = algebra::compile_surface(surface.equation);
    const test::ExactRayOracle oracle(surface.equation);
    const CertifiedTracer tracer(f);
    const double radius = surface.clip_radius;
    std::mt19937_64 random(std::hash<std::string>{}(surface.name));
    std::uniform_real_distribution<double> unit(-1.0, 1.0), fraction(0.0, 1.0);
    constexpr int kSize = 24;
    int checked = 0, hits = 0, guided_hits = 0;
    for (int view = 0; view < 2; ++view) {
        const Camera camera = random_camera(random, radius, kSize, kSize);
        const CertifiedRayFamily family(f, camera, {0.0, 0.0, 0.0}, radius,
                                        {0.0, 0.0, kSize, kSize});
        ASSERT_TRUE(family.certified());
        const double t0 = family.t_start(), width = family.t_width();
        auto row = std::make_unique<CertifiedRayFamily::Row>();
        for (int j = 0; j < kSize; ++j) {
            const double y = j + 0.5;
            family.expand_row(y, *row);
            NeighbourHint neighbour,
                alone_neighbour;  // carried along the row, as the renderer does
            for (int i = 0; i < kSize; ++i) {
                const double x = i + 0.5;
                const Ray ray = camera.ray(x, y);
                const std::optional<Interval> chord = clip_chord(ray, radius, t0, width);
                if (!chord) {
                    neighbour = alone_neighbour = NeighbourHint{};
                    continue;
                }
                const Interval interval = *chord;
                if (!(interval.hi > interval.lo)) {
                    continue;
                }
                BernsteinBall ball;
                family.ball_at(*row, x, ball);
                const test::ExactRayOracle::Restriction exact =
                    oracle.restrict(to_point(ray.origin), to_point(ray.direction));
                const auto check = [&](const RootResult& r, const char* how) {
                    ++checked;
                    ASSERT_NE(r.status, RootStatus::unknown) << how;
                    EXPECT_TRUE(test::ExactRayOracle::is_right(exact, interval.lo, interval.hi,
                                                               r.status == RootStatus::hit, r.t,
                                                               kRenderTolerance))
                        << surface.name << ", pixel " << i << ' ' << j << " of view " << view
                        << ", " << how << ": answered "
                        << (r.status == RootStatus::hit ? std::to_string(r.t) : "miss");
                };
                const RootResult plain =
                    tracer.first_hit_from(ball, t0, width, ray, interval, kRenderTolerance);
                check(plain, "no hint");
                hits += plain.status == RootStatus::hit ? 1 : 0;
                // The row's own hint, as in a frame.
                const bool had_hint = std::isfinite(neighbour.t);
                const RootResult in_row = tracer.first_hit_from(ball, t0, width, ray, interval,
                                                                kRenderTolerance, &neighbour);
                check(in_row, "the neighbour's hint");
                guided_hits += had_hint && in_row.status == RootStatus::hit ? 1 : 0;
                // Hints that are wrong on purpose: a random point with a random reach, the root
                // itself with a reach far too small, a point just past the root (so that the
                // window holds a later root, or none).
                const double span = interval.hi - interval.lo;
                NeighbourHint random_hint{interval.lo + fraction(random) * span,
                                          std::pow(10.0, -6.0 * fraction(random)) * span};
                check(tracer.first_hit_from(ball, t0, width, ray, interval, kRenderTolerance,
                                            &random_hint),
                      "a random hint");
                // Windows hard against either end of the interval.
                NeighbourHint near_start{interval.lo + 2e-6 * span, 1e-6 * span};
                check(tracer.first_hit_from(ball, t0, width, ray, interval, kRenderTolerance,
                                            &near_start),
                      "a window at the interval's start");
                NeighbourHint near_end{interval.hi - 2e-6 * span, 1e-6 * span};
                check(tracer.first_hit_from(ball, t0, width, ray, interval, kRenderTolerance,
                                            &near_end),
                      "a window at the interval's end");
                if (plain.status == RootStatus::hit) {
                    NeighbourHint tight{plain.t, 1e-12 * span};
                    check(tracer.first_hit_from(ball, t0, width, ray, interval, kRenderTolerance,
                                                &tight),
                          "the root with a tiny reach");
                    NeighbourHint past{plain.t + 0.2 * (interval.hi - plain.t), 0.1 * span};
                    check(tracer.first_hit_from(ball, t0, width, ray, interval, kRenderTolerance,
                                                &past),
                          "a point past the root");
                }
                // The ray traced alone takes the same hints (a frame whose family does not
                // decide carries the row's hint there).
                check(tracer.first_hit(ray, interval, kRenderTolerance, &alone_neighbour),
                      "alone, the neighbour's hint");
                NeighbourHint alone_random{interval.lo + fraction(random) * span,
                                           std::pow(10.0, -6.0 * fraction(random)) * span};
                check(tracer.first_hit(ray, interval, kRenderTolerance, &alone_random),
                      "alone, a random hint");
                NeighbourHint alone_start{interval.lo + 2e-6 * span, 1e-6 * span};
                check(tracer.first_hit(ray, interval, kRenderTolerance, &alone_start),
                      "alone, a window at the interval's start");
                if (plain.status == RootStatus::hit) {
                    NeighbourHint alone_past{plain.t + 0.2 * (interval.hi - plain.t), 0.1 * span};
                    check(tracer.first_hit(ray, interval, kRenderTolerance, &alone_past),
                          "alone, a point past the root");
                }
            }
        }
    }
    // The frames are not empty, and the row's hint was used.
    EXPECT_GT(hits, 50) << surface.name;
    EXPECT_GT(guided_hits, 25) << surface.name;
    EXPECT_GT(checked, 1000) << surface.name;
}

// Every pixel's ball holds the exact restriction of the exact surface along the camera's own
// ray (doubles read exactly): the balls' radii, one per tile of the frame and coefficient, are
// checked against the Bernstein coefficients computed over Q by the oracle. A frame of several
// tiles in each direction, pixels of every tile (centres and points between them), surfaces
// with decimal coefficients (the rounding of f itself) and random eyes.
TEST(CertifiedFamily, EveryPixelsBallHoldsTheExactRestriction) {
    for (const char* name : {"endrass_octic", "chmutov_octic", "kummer_quartic", "barth_decic"}) {
        const bench::SuiteSurface surface = suite_surface(name);
        const algebra::CompiledPolynomial f = algebra::compile_surface(surface.equation);
        // The polynomial the balls are of: the equation's square-free part, a multiple of it by
        // a rational (its coefficients made coprime integers), which the oracle reads with
        // FLINT's parser.
        const test::ExactRayOracle oracle(f.equation());
        const double radius = surface.clip_radius;
        std::mt19937_64 random(std::hash<std::string>{}(surface.name) + 7);
        std::uniform_real_distribution<double> fraction(0.0, 1.0);
        constexpr int kWidth = 200, kHeight = 150;
        int checked = 0;
        for (int view = 0; view < 2; ++view) {
            const Camera camera = random_camera(random, radius, kWidth, kHeight);
            const CertifiedRayFamily family(f, camera, {0.0, 0.0, 0.0}, radius,
                                            {0.0, 0.0, kWidth, kHeight});
            ASSERT_TRUE(family.certified()) << name;
            auto row = std::make_unique<CertifiedRayFamily::Row>();
            BernsteinBall ball;
            for (int j = 0; j < kHeight; j += 11) {
                const double y = j + (view == 0 ? 0.5 : fraction(random));
                family.expand_row(y, *row);
                for (int i = 0; i < kWidth; i += 9) {
                    const double x = i + (view == 0 ? 0.5 : fraction(random));
                    family.ball_at(*row, x, ball);
                    const Ray ray = camera.ray(x, y);
                    const int missed = oracle.ball_misses(
                        to_point(ray.origin), to_point(ray.direction), family.t_start(),
                        family.t_width(), ball.b.data(), ball.r.data(), ball.degree);
                    ++checked;
                    ASSERT_EQ(missed, -1) << name << ": pixel (" << x << ", " << y << ") of view "
                                          << view << ", coefficient " << missed;
                }
            }
        }
        EXPECT_GT(checked, 500) << name;
    }
}

// A root exactly at the end of a ray's interval is a hit (intervals are (lo, hi]) whatever the
// family's range start rounds to: σ(hi) computed from t0 = fl(D − R) may fall below the root's
// exact σ by u·|t0|/width, which first_hit_from widens its search by. Each trial's surface is
// the plane z = c through the point of its ray at t* = hi, c written exactly as a rational;
// eyes far from the clip sphere (t0 ≫ width), where that error is largest. (In these trials
// the balls' radii blur G's sign over more than that sliver, so the search reports the piece
// undecided rather than free of roots even without the widening: the test holds the answer,
// not the widening itself.)
TEST(CertifiedFamily, ARootAtTheIntervalsEndIsAHit) {
    std::mt19937_64 random(2911);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), fraction(0.0, 1.0);
    constexpr int kSize = 16;
    const int trials = test::seed_count(200);
    for (int trial = 0; trial < trials; ++trial) {
        Vec3 eye{unit(random), unit(random), unit(random)};
        eye *= (20.0 + 60.0 * fraction(random)) / glm::length(eye);
        const double radius = 0.7 + fraction(random);
        const Camera camera({eye, {0.0, 0.0, 0.0}, {0.3, 1.0, 0.1}, 2.0}, kSize, kSize);
        const double x = kSize * fraction(random), y = kSize * fraction(random);
        const Ray ray = camera.ray(x, y);
        // The plane through the ray's point at t*, well inside the family's range of t.
        const double t_star =
            glm::dot(-eye, camera.forward()) + radius * (0.6 * fraction(random) - 0.3);
        fmpq_t c, term, direction_z;
        fmpq_init(c);
        fmpq_init(term);
        fmpq_init(direction_z);
        test::ExactRayOracle::exact(c, ray.origin.z);
        test::ExactRayOracle::exact(term, t_star);
        test::ExactRayOracle::exact(direction_z, ray.direction.z);
        fmpq_mul(term, term, direction_z);
        fmpq_add(c, c, term);
        char* text = fmpq_get_str(nullptr, 10, c);
        const std::string equation = "z-(" + std::string(text) + ")";
        flint_free(text);
        fmpq_clear(c);
        fmpq_clear(term);
        fmpq_clear(direction_z);
        const algebra::CompiledPolynomial f = algebra::compile_surface(equation);
        const CertifiedRayFamily family(f, camera, {0.0, 0.0, 0.0}, radius,
                                        {0.0, 0.0, kSize, kSize});
        ASSERT_TRUE(family.certified());
        auto row = std::make_unique<CertifiedRayFamily::Row>();
        family.expand_row(y, *row);
        BernsteinBall ball;
        family.ball_at(*row, x, ball);
        const CertifiedTracer tracer(f);
        const RootResult r =
            tracer.first_hit_from(ball, family.t_start(), family.t_width(), ray,
                                  {t_star - 0.2 * radius, t_star}, kRenderTolerance);
        ASSERT_EQ(r.status, RootStatus::hit)
            << "trial " << trial << ": the root at the interval's end " << t_star << " ("
            << equation << ")";
        EXPECT_LE(std::abs(r.t - t_star), kRenderTolerance * std::max(1.0, std::abs(t_star)));
    }
}

INSTANTIATE_TEST_SUITE_P(Suite, GuidedSearch,
                         ::testing::Values("chmutov_octic", "endrass_octic", "torus",
                                           "kummer_quartic", "squared_sphere", "steiner_roman"));

// A family too blurred to decide (as at degree 30) rests: after kFamilyFailuresBeforeRest
// undecided rays of a row, the next kFamilyRest rays are traced alone without a search of the
// ball, and then the ball is searched again. Every answer, searched or alone, keeps the contract.
TEST(BlurredFamily, RestsAndEveryAnswerKeepsTheContract) {
    const bench::SuiteSurface surface = suite_surface("chmutov_octic");
    const algebra::CompiledPolynomial f = algebra::compile_surface(surface.equation);
    const test::ExactRayOracle oracle(surface.equation);
    const CertifiedTracer tracer(f);
    const double radius = surface.clip_radius;
    constexpr int kSize = 96;
    const Camera camera(
        {{0.3 * radius, 0.4 * radius, 3.0 * radius}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 35.0}, kSize,
        kSize);
    const CertifiedRayFamily family(f, camera, {0.0, 0.0, 0.0}, radius, {0.0, 0.0, kSize, kSize});
    ASSERT_TRUE(family.certified());
    const double t0 = family.t_start(), width = family.t_width();
    auto row = std::make_unique<CertifiedRayFamily::Row>();
    int searched = 0, rested = 0, rests_begun = 0;
    for (const int j : {kSize / 2, kSize / 3}) {
        const double y = j + 0.5;
        family.expand_row(y, *row);
        NeighbourHint neighbour;
        for (int i = 0; i < kSize; ++i) {
            const double x = i + 0.5;
            const Ray ray = camera.ray(x, y);
            const std::optional<Interval> chord = clip_chord(ray, radius, t0, width);
            if (!chord || !(chord->hi > chord->lo)) {
                continue;
            }
            const Interval interval = *chord;
            if (!(interval.hi > interval.lo)) {
                continue;
            }
            BernsteinBall ball;
            family.ball_at(*row, x, ball);
            double largest = 0.0;
            for (int k = 0; k <= ball.degree; ++k) {
                largest = std::max(largest, std::abs(ball.b[k]));
            }
            for (int k = 0; k <= ball.degree; ++k) {
                ball.r[k] += 1e3 * largest;  // still an enclosure, but one that decides nothing
            }
            const NeighbourHint before = neighbour;
            const RootResult r =
                tracer.first_hit_from(ball, t0, width, ray, interval, kRenderTolerance, &neighbour);
            if (before.family_rest > 0) {
                ++rested;
                EXPECT_EQ(neighbour.family_rest, before.family_rest - 1);
                EXPECT_EQ(neighbour.family_failures, before.family_failures);
            } else {
                ++searched;
                if (before.family_failures + 1 == kFamilyFailuresBeforeRest) {
                    ++rests_begun;
                    EXPECT_EQ(neighbour.family_rest, kFamilyRest);
                    EXPECT_EQ(neighbour.family_failures, 0);
                } else {
                    EXPECT_EQ(neighbour.family_failures, before.family_failures + 1);
                }
            }
            ASSERT_NE(r.status, RootStatus::unknown);
            const test::ExactRayOracle::Restriction exact =
                oracle.restrict(to_point(ray.origin), to_point(ray.direction));
            EXPECT_TRUE(test::ExactRayOracle::is_right(exact, interval.lo, interval.hi,
                                                       r.status == RootStatus::hit, r.t,
                                                       kRenderTolerance))
                << "pixel " << i << ' ' << j;
        }
    }
    // Both rows are long enough for a rest and a second try of the family after it.
    EXPECT_GE(rests_begun, 3);
    EXPECT_GT(rested, 2 * kFamilyRest);
    EXPECT_GT(searched, 2 * kFamilyFailuresBeforeRest);
    // A search that decides — here that the ray misses — ends the run of failures.
    BernsteinBall positive;
    positive.degree = 2;
    for (int k = 0; k <= 2; ++k) {
        positive.b[k] = 1.0;
        positive.r[k] = 0.0;
    }
    NeighbourHint failing;
    failing.family_failures = kFamilyFailuresBeforeRest - 1;
    // (An interval inside the ball's range: one reaching its ends, within their roundings, is
    // traced alone.)
    const RootResult decided = tracer.first_hit_from(positive, 0.0, 1.0, camera.ray(0.5, 0.5),
                                                     {0.25, 0.75}, kRenderTolerance, &failing);
    EXPECT_EQ(decided.status, RootStatus::miss);
    EXPECT_EQ(failing.family_failures, 0);
    EXPECT_EQ(failing.family_rest, 0);
}

// Whether a frame's rays search the family at all is asked once, of a sample of its rays: at
// degree 30 over a whole frame the balls decide almost none (a tenth of the frame's time went
// into such searches); on the suite's surfaces they decide most, and the family is kept.
TEST(FamilyTest, SampleDecidesWhetherTheFamilyIsSearched) {
    constexpr int kSize = 64;
    const auto family_of = [&](const std::string& equation, double radius) {
        const algebra::CompiledPolynomial f = algebra::compile_surface(equation);
        const Camera camera(
            {{0.3 * radius, 0.4 * radius, 3.0 * radius}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 35.0},
            kSize, kSize);
        return std::make_unique<CertifiedRayFamily>(f, camera, Vec3{0.0, 0.0, 0.0}, radius,
                                                    ImageRect{0.0, 0.0, kSize, kSize});
    };
    const auto worth_building = [&](const std::string& equation, double radius) {
        const algebra::CompiledPolynomial f = algebra::compile_surface(equation);
        const Camera camera(
            {{0.3 * radius, 0.4 * radius, 3.0 * radius}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 35.0},
            kSize, kSize);
        return CertifiedRayFamily::worth_building(f, camera, Vec3{0.0, 0.0, 0.0}, radius,
                                                  ImageRect{0.0, 0.0, kSize, kSize}, 4,
                                                  kFamilyDepth, 0.25);
    };
    const auto t30 = family_of(test::chmutov_equation(30), 1.2);
    ASSERT_TRUE(t30->certified());
    EXPECT_FALSE(t30->decides_often(8, kFamilyDepth, 0.25));
    EXPECT_TRUE(t30->decides_often(8, kFamilyDepth, 0.0));  // nothing asked: true at once
    // And the family is not even built: 16 rays' balls predict it.
    EXPECT_FALSE(worth_building(test::chmutov_equation(30), 1.2));
    for (const char* name : {"torus", "chmutov_octic", "sarti_dodecic"}) {
        const bench::SuiteSurface surface = suite_surface(name);
        const auto family = family_of(surface.equation, surface.clip_radius);
        EXPECT_TRUE(family->decides_often(8, kFamilyDepth, 0.25)) << name;
        EXPECT_TRUE(worth_building(surface.equation, surface.clip_radius)) << name;
    }
}

}  // namespace
}  // namespace locus::render
