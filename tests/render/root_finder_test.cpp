// Every root finder of render/root_finder.h on the same cases, built from known roots: simple,
// first among several, clustered, double (a tangent ray must be a hit, a near miss must not),
// at either end, Wilkinson-like, tiny and huge coefficients, degree 12, seeded random products
// compared to their known first root (within the conditioning of the rounded coefficients),
// and degenerate input (zero, leading zeros, non-finite, invalid interval). Methods and their
// tolerances: render/root_finders/.
#include "render/root_finder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "tests/support/test_data.h"

namespace locus::render {
namespace {

using test::seed_count;

// scale · Π (t − r) · Π (t² − 2·Re z·t + |z|²) over the real roots and the complex pairs.
RayPolynomial from_roots(const std::vector<double>& roots,
                         const std::vector<std::complex<double>>& pairs = {}, double scale = 1.0) {
    RayPolynomial f;
    f.degree = 0;
    f.c[0] = scale;
    const auto multiply = [&f](double c0, double c1, double c2, int extra) {
        std::array<double, kMaxDegree + 1> product{};
        for (int k = 0; k <= f.degree; ++k) {
            product[k] += c0 * f.c[k];
            product[k + 1] += c1 * f.c[k];
            if (extra == 2) {
                product[k + 2] += c2 * f.c[k];
            }
        }
        f.degree += extra;
        f.c = product;
    };
    for (double r : roots) {
        multiply(-r, 1.0, 0.0, 1);
    }
    for (const auto& z : pairs) {
        multiply(std::norm(z), -2.0 * z.real(), 1.0, 2);
    }
    return f;
}

template <class Finder>
class RootFinderTest : public ::testing::Test {
  protected:
    RootResult solve(const RayPolynomial& f, double lo, double hi) const {
        const RootResult result = Finder{}.first_root(f, lo, hi);
        EXPECT_TRUE(std::isfinite(result.t)) << "t = " << result.t;
        if (result.status == RootStatus::hit) {
            EXPECT_GE(result.t, lo);
            EXPECT_LE(result.t, hi);
        }
        return result;
    }

    // The first root in [lo, hi] is `expected`, within `tolerance`·max(1, hi − lo).
    void expect_hit(const RayPolynomial& f, double lo, double hi, double expected,
                    double tolerance = 1e-10) const {
        const RootResult result = solve(f, lo, hi);
        ASSERT_EQ(result.status, RootStatus::hit)
            << "on [" << lo << ", " << hi << "], reason: " << result.reason;
        EXPECT_NEAR(result.t, expected, tolerance * std::max(1.0, hi - lo))
            << "on [" << lo << ", " << hi << "]";
    }

    void expect_miss(const RayPolynomial& f, double lo, double hi) const {
        const RootResult result = solve(f, lo, hi);
        EXPECT_EQ(result.status, RootStatus::miss)
            << "on [" << lo << ", " << hi << "], t = " << result.t << ", reason: " << result.reason;
    }

    void expect_unknown(const RayPolynomial& f, double lo, double hi,
                        const std::string& reason) const {
        const RootResult result = solve(f, lo, hi);
        EXPECT_EQ(result.status, RootStatus::unknown);
        EXPECT_EQ(std::string(result.reason), reason);
    }
};

struct FinderName {
    template <class T>
    static std::string GetName(int) {
        return std::string(T::name);
    }
};

using Finders =
    ::testing::Types<SturmRootFinder, BernsteinRootFinder, LaguerreRootFinder, CompanionRootFinder>;
TYPED_TEST_SUITE(RootFinderTest, Finders, FinderName);

TYPED_TEST(RootFinderTest, SimpleRoots) {
    this->expect_hit(from_roots({0.4}), 0.0, 1.0, 0.4);
    this->expect_hit(from_roots({0.4}, {}, -3.0), 0.0, 1.0, 0.4);
    this->expect_hit(from_roots({0.7, -1.3}), 0.0, 1.0, 0.7);
    this->expect_hit(from_roots({0.7, -1.3}), -2.0, 0.0, -1.3);
    this->expect_hit(from_roots({37.25, -2.0, 80.0}), 0.0, 100.0, 37.25);
    this->expect_hit(from_roots({0.123456789}, {{0.5, 0.5}}), -1.0, 1.0, 0.123456789);
}

TYPED_TEST(RootFinderTest, FirstRootAmongSeveral) {
    const RayPolynomial f = from_roots({0.2, 0.5, 0.9});
    this->expect_hit(f, 0.0, 1.0, 0.2);
    this->expect_hit(f, 0.3, 1.0, 0.5);
    this->expect_hit(f, 0.6, 1.0, 0.9);
    this->expect_miss(f, 0.6, 0.8);
    this->expect_hit(from_roots({2.5, 1.5, 0.5, 3.5}, {{1.0, 0.3}}), 0.0, 4.0, 0.5);
}

TYPED_TEST(RootFinderTest, ClusteredRoots) {
    const RayPolynomial f = from_roots({0.5, 0.5 + 1e-4, -1.0});
    this->expect_hit(f, 0.0, 1.0, 0.5);
    this->expect_hit(f, 0.50005, 1.0, 0.5 + 1e-4);
    const RayPolynomial g = from_roots({0.3, 0.3 + 1e-3, 0.3 + 2e-3, 2.0});
    this->expect_hit(g, 0.0, 1.0, 0.3);
    this->expect_hit(g, 0.3005, 1.0, 0.301);
}

TYPED_TEST(RootFinderTest, DoubleRootIsAHit) {
    this->expect_hit(from_roots({0.3, 0.3, -2.0}), 0.0, 1.0, 0.3, 1e-6);
    this->expect_hit(from_roots({0.3, 0.3, 0.8}), 0.0, 1.0, 0.3, 1e-6);
    this->expect_hit(from_roots({0.5, 0.5}, {{0.0, 1.0}}), 0.0, 1.0, 0.5, 1e-6);
    this->expect_hit(from_roots({1.75, 1.75, -0.25}), 0.0, 4.0, 1.75, 1e-6);
    // A double root after a simple one does not hide the simple one.
    this->expect_hit(from_roots({0.6, 0.6, 0.2}), 0.0, 1.0, 0.2);
    // A double root with no sign change before a simple root.
    this->expect_hit(from_roots({0.2, 0.2, 0.6}), 0.0, 1.0, 0.2, 1e-6);
}

TYPED_TEST(RootFinderTest, NearTangentMissIsAMiss) {
    // A complex pair 1e-3 or 1e-5 off the axis: F stays far above its rounding, so no tangent.
    this->expect_miss(from_roots({-2.0}, {{0.5, 1e-3}}), 0.0, 1.0);
    this->expect_miss(from_roots({-2.0}, {{0.5, 1e-5}}), 0.0, 1.0);
    // ... and the real root after it is still found.
    this->expect_hit(from_roots({-2.0, 0.8}, {{0.5, 1e-5}}), 0.0, 1.0, 0.8);
    this->expect_hit(from_roots({-2.0, 0.8, 1.3, -0.7}, {{0.5, 1e-4}, {0.1, 0.3}}), 0.0, 1.0, 0.8);
}

TYPED_TEST(RootFinderTest, TangentAtZeroInsideTheInterval) {
    // F = t²·(t − 0.5)·(t + 3): the double root at exactly 0 comes first.
    this->expect_hit(from_roots({0.0, 0.0, 0.5, -3.0}), -0.25, 1.0, 0.0, 1e-6);
}

TYPED_TEST(RootFinderTest, RootAtEitherEnd) {
    const RayPolynomial f = from_roots({0.3, 2.0});
    this->expect_hit(f, 0.3, 1.0, 0.3);
    this->expect_hit(f, -1.0, 0.3, 0.3);
    this->expect_hit(f, 1.0, 2.0, 2.0);
    this->expect_hit(f, 0.3, 2.0, 0.3);
    this->expect_hit(from_roots({0.0, 5.0}), 0.0, 1.0, 0.0);
    this->expect_hit(from_roots({1.0, -1.0}), 0.0, 1.0, 1.0);
}

TYPED_TEST(RootFinderTest, NoRoots) {
    this->expect_miss(from_roots({}, {{0.0, 1.0}}), -10.0, 10.0);
    this->expect_miss(from_roots({2.0, 3.0}), 0.0, 1.0);
    this->expect_miss(from_roots({-0.5}, {{0.5, 0.1}, {0.2, 0.05}}), 0.0, 1.0);
    RayPolynomial constant;
    constant.degree = 0;
    constant.c[0] = 2.0;
    this->expect_miss(constant, 0.0, 1.0);
}

TYPED_TEST(RootFinderTest, WilkinsonLikeProduct) {
    const RayPolynomial f = from_roots({1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
    this->expect_hit(f, 0.5, 10.5, 1.0);
    this->expect_hit(f, 1.5, 10.5, 2.0);
    this->expect_hit(f, 7.5, 10.5, 8.0);
    this->expect_miss(f, 10.25, 10.75);
}

TYPED_TEST(RootFinderTest, TinyAndHugeCoefficients) {
    for (double scale : {1e-30, 1e30, -1e-30}) {
        SCOPED_TRACE("scale " + std::to_string(scale));
        const RayPolynomial f = from_roots({0.4, 0.6, -0.5}, {{0.1, 0.2}}, scale);
        this->expect_hit(f, 0.0, 1.0, 0.4);
        this->expect_hit(f, 0.5, 1.0, 0.6);
        this->expect_miss(f, 0.65, 1.0);
    }
}

TYPED_TEST(RootFinderTest, DegreeTwelveProduct) {
    const std::vector<double> roots = {-2.7, -1.9, -0.45, 0.15, 0.8, 1.35, 2.2, 2.95};
    const RayPolynomial f = from_roots(roots, {{0.5, 0.4}, {-1.0, 1.5}});
    ASSERT_EQ(f.degree, 12);
    this->expect_hit(f, -3.0, 3.0, -2.7);
    this->expect_hit(f, 0.0, 3.0, 0.15);
    this->expect_hit(f, 0.2, 1.0, 0.8);
    this->expect_hit(f, 1.4, 3.0, 2.2);
    this->expect_miss(f, 1.4, 2.1);
}

TYPED_TEST(RootFinderTest, RandomProductsAgainstKnownFirstRoot) {
    for (int seed = 0; seed < seed_count(2000); ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> position(-3.0, 3.0);
        const int real_count = std::uniform_int_distribution<int>(1, 8)(rng);
        const int pair_count = std::uniform_int_distribution<int>(0, 2)(rng);
        // Roots at least 0.05 apart, so each is conditioned well enough for 1e-10.
        std::vector<double> roots;
        while (static_cast<int>(roots.size()) < real_count) {
            const double r = position(rng);
            if (std::all_of(roots.begin(), roots.end(),
                            [r](double s) { return std::abs(r - s) >= 0.05; })) {
                roots.push_back(r);
            }
        }
        std::vector<std::complex<double>> pairs;
        for (int k = 0; k < pair_count; ++k) {
            pairs.emplace_back(position(rng),
                               std::uniform_real_distribution<double>(0.1, 2.0)(rng));
        }
        const RayPolynomial f = from_roots(roots, pairs, (seed % 2 ? 1.0 : -0.25));
        // An interval whose ends are not within 1e-6 of a root.
        double lo;
        double hi;
        do {
            lo = position(rng);
            hi = lo + std::uniform_real_distribution<double>(0.01, 6.0)(rng);
        } while (std::any_of(roots.begin(), roots.end(), [&](double r) {
            return std::abs(r - lo) < 1e-6 || std::abs(r - hi) < 1e-6;
        }));
        double expected = HUGE_VAL;
        for (double r : roots) {
            if (r >= lo && r <= hi) {
                expected = std::min(expected, r);
            }
        }
        if (expected == HUGE_VAL) {
            this->expect_miss(f, lo, hi);
            continue;
        }
        // Rounding the coefficients moves a simple root r by up to ~ε·Σ|c_k||r|^k / |F'(r)|;
        // closely spaced roots of degree 12 can make that exceed 1e-10.
        double magnitude = 0.0;
        double slope = 0.0;
        for (int k = f.degree; k >= 0; --k) {
            magnitude = magnitude * std::abs(expected) + std::abs(f.c[k]);
        }
        for (int k = f.degree; k >= 1; --k) {
            slope = slope * expected + k * f.c[k];
        }
        const double conditioning =
            4.0 * std::numeric_limits<double>::epsilon() * magnitude / std::abs(slope);
        this->expect_hit(f, lo, hi, expected, 1e-10 + conditioning / std::max(1.0, hi - lo));
    }
}

TYPED_TEST(RootFinderTest, RandomDoubleRootsAreHits) {
    int misses = 0;
    for (int seed = 0; seed < seed_count(1000); ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> position(-3.0, 3.0);
        const double twice = position(rng);
        std::vector<double> roots = {twice, twice};
        const int others = std::uniform_int_distribution<int>(0, 3)(rng);
        for (int k = 0; k < others; ++k) {
            const double r = position(rng);
            if (r > twice + 0.05) {
                roots.push_back(r);
            }
        }
        const double lo = twice - std::uniform_real_distribution<double>(0.01, 2.0)(rng);
        const double hi = twice + std::uniform_real_distribution<double>(0.01, 2.0)(rng);
        const RayPolynomial f = from_roots(roots, {{position(rng), 0.5}});
        // Rounding the coefficients changes F near the root by up to ~ε·Σ|c_k||r|^k, which
        // splits the double root by ~√(8ε·Σ|c_k||r|^k / |F''(r)|): no method can do better.
        double magnitude = 0.0;
        double second = 0.0;
        for (int k = f.degree; k >= 0; --k) {
            magnitude = magnitude * std::abs(twice) + std::abs(f.c[k]);
        }
        for (int k = f.degree; k >= 2; --k) {
            second = second * twice + k * (k - 1) * f.c[k];
        }
        const double split =
            std::sqrt(8.0 * std::numeric_limits<double>::epsilon() * magnitude / std::abs(second));
        // The same rounding may turn the double root into a complex pair, and the rounded F has
        // no root there: an answer past it (a miss, or the next root) is right only where F at
        // the double root is within that rounding (at LOCUS_TEST_MULTIPLIER=400 `sturm` passed
        // two such roots).
        const double allowed = 1e-6 + split / std::max(1.0, hi - lo);
        const RootResult result = this->solve(f, lo, hi);
        if (result.status == RootStatus::miss ||
            result.t - twice > allowed * std::max(1.0, hi - lo)) {
            EXPECT_LE(std::abs(f(twice)), 8.0 * std::numeric_limits<double>::epsilon() * magnitude)
                << "past the double root on [" << lo << ", " << hi
                << "] where F is not tangent to zero";
            ++misses;
            continue;
        }
        this->expect_hit(f, lo, hi, twice, allowed);
    }
    EXPECT_LE(misses, seed_count(1000) / 1000);
}

// Regression (stability atlas, cayley_line): a ray lying in the surface was `unknown` in every
// floating method while `exact` answered a hit at the start of the interval.
TYPED_TEST(RootFinderTest, IdenticallyZeroIsAHitAtTheStart) {
    RayPolynomial zero;
    this->expect_hit(zero, 0.25, 1.0, 0.25);
    zero.degree = 3;
    this->expect_hit(zero, 0.25, 1.0, 0.25);
}

TYPED_TEST(RootFinderTest, LeadingZeroCoefficientsReduceTheDegree) {
    RayPolynomial f = from_roots({0.5, -1.0});
    f.degree = 5;  // c[3..5] are zero
    this->expect_hit(f, 0.0, 1.0, 0.5);
    this->expect_miss(f, 0.6, 1.0);
    f.c[3] = 1e-300;  // negligible against the other terms on [0, 1]
    this->expect_hit(f, 0.0, 1.0, 0.5);
    RayPolynomial constant;
    constant.degree = 2;
    constant.c[0] = -1.0;
    this->expect_miss(constant, 0.0, 1.0);
}

TYPED_TEST(RootFinderTest, NonFiniteOrInvalidInputIsUnknown) {
    RayPolynomial f = from_roots({0.5, -1.0});
    f.c[1] = std::numeric_limits<double>::quiet_NaN();
    this->expect_unknown(f, 0.0, 1.0, "non-finite coefficient");
    f.c[1] = HUGE_VAL;
    this->expect_unknown(f, 0.0, 1.0, "non-finite coefficient");
    const RayPolynomial g = from_roots({0.5, -1.0});
    this->expect_unknown(g, 1.0, 0.0, "invalid interval");
    this->expect_unknown(g, 0.0, std::numeric_limits<double>::quiet_NaN(), "invalid interval");
}

// A hint (the neighbouring pixel's root) only changes how Sturm finds the first root: random
// products with hints at every root, next to them, between them and anywhere, against the
// known first root and against the answer without a hint. Hints near a later root while an
// earlier one exists, and near double roots, must not move the answer.
TEST(SturmHint, SameFirstRootWithAnyHint) {
    const SturmRootFinder sturm;
    int hinted_hits = 0;
    int shortcuts = 0;  // answers that skipped the chain (less work): the path is exercised
    int misses = 0;     // first roots missed (polynomials with a double root only)
    for (int seed = 0; seed < seed_count(600); ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> position(-2.0, 2.0);
        std::vector<double> roots;
        const int real_count = std::uniform_int_distribution<int>(1, 6)(rng);
        while (static_cast<int>(roots.size()) < real_count) {
            const double r = position(rng);
            if (std::all_of(roots.begin(), roots.end(),
                            [r](double q) { return std::abs(r - q) >= 0.05; })) {
                roots.push_back(r);
            }
        }
        if (seed % 3 == 0) {
            roots.push_back(roots.front());  // a double root (a tangent)
        }
        const RayPolynomial f = from_roots(roots, {{position(rng), 0.3}});
        const double lo = -2.5, hi = 2.5;
        // The known first root (the complex pair has imaginary part 0.3: not real).
        const double first = *std::min_element(roots.begin(), roots.end());
        // A double root is placed in doubles only to about √(u·Σ|terms|/|f''|), and a
        // floating-point Sturm sequence of a polynomial with a double root (its gcd with f' not
        // 1) can lose roots: `sturm` is not certified. Misses are counted, not failed, where f
        // has a double root (seeds past the default count showed them: 18 of 30 000, seed 4866
        // skipping a simple root at −0.44 for −0.08); with simple roots only there must be none.
        const bool tangent = seed % 3 == 0;
        const double allowed = tangent && roots.front() == first ? 1e-5 : 1e-7;
        const RootResult plain = sturm.first_root(f, lo, hi);
        const bool plain_right =
            plain.status == RootStatus::hit && std::abs(plain.t - first) <= allowed;
        if (!tangent) {
            EXPECT_TRUE(plain_right) << plain.t << " for " << first;
        }
        misses += plain_right ? 0 : 1;
        std::vector<double> hints = {lo + 1e-3, hi - 1e-3, 0.0};
        for (double r : roots) {
            for (double offset : {0.0, 1e-6, -1e-6, 0.01, -0.01, 0.07, -0.07}) {
                hints.push_back(r + offset);
            }
        }
        for (int k = 0; k < 8; ++k) {
            hints.push_back(std::uniform_real_distribution<double>(lo, hi)(rng));
        }
        for (double hint : hints) {
            SCOPED_TRACE("hint " + std::to_string(hint));
            const RootResult hinted = sturm.first_root(f, lo, hi, hint);
            // The hint does not move a right answer; a wrong one it leaves or puts right (a
            // hint at the lost root finds it).
            ASSERT_EQ(hinted.status, plain.status);
            if (plain_right) {
                EXPECT_NEAR(hinted.t, first, allowed);
            } else {
                EXPECT_TRUE(std::abs(hinted.t - plain.t) <= allowed ||
                            std::abs(hinted.t - first) <= allowed)
                    << hinted.t << " for " << first << ", " << plain.t << " without the hint";
            }
            ++hinted_hits;
            shortcuts += hinted.work < plain.work ? 1 : 0;
        }
    }
    EXPECT_LE(misses, seed_count(600) / 500);
    EXPECT_GT(hinted_hits, 1000);
    EXPECT_GT(shortcuts, hinted_hits / 20);
}

}  // namespace
}  // namespace locus::render
