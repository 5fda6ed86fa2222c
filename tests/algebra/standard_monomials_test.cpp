// Counting standard monomials by the pivot recursion against walking the box of pure powers
// (the method it replaced), on random zero-dimensional monomial ideals.
#include "algebra/standard_monomials.h"

#include <gtest/gtest.h>

#include <random>

#include "algebra/error.h"

namespace locus::algebra {
namespace {

// The independent oracle: every exponent vector below the pure powers, tested one by one.
std::uint64_t walk_the_box(const std::vector<ExponentVector>& generators, std::size_t n) {
    std::vector<std::uint32_t> pure(n, 0);
    for (const ExponentVector& g : generators) {
        std::size_t support = 0, variable = 0;
        for (std::size_t v = 0; v < n; ++v) {
            if (g[v] != 0) {
                ++support;
                variable = v;
            }
        }
        if (support == 1 && (pure[variable] == 0 || g[variable] < pure[variable])) {
            pure[variable] = g[variable];
        }
    }
    std::vector<std::uint32_t> e(n, 0);
    std::uint64_t count = 0;
    while (true) {
        bool standard = true;
        for (const ExponentVector& g : generators) {
            bool divides = true;
            for (std::size_t v = 0; v < n && divides; ++v) {
                divides = g[v] <= e[v];
            }
            standard = standard && !divides;
        }
        count += standard ? 1 : 0;
        std::size_t v = 0;
        while (v < n && ++e[v] == pure[v]) {
            e[v] = 0;
            ++v;
        }
        if (v == n) {
            return count;
        }
    }
}

TEST(StandardMonomials, AgreeWithWalkingTheBoxOnRandomIdeals) {
    std::mt19937 rng(20261123);
    for (int trial = 0; trial < 300; ++trial) {
        const std::size_t n = 1 + rng() % 4;
        std::vector<ExponentVector> generators;
        for (std::size_t v = 0; v < n; ++v) {
            ExponentVector pure(n, 0);
            pure[v] = 1 + rng() % 7;
            generators.push_back(pure);
        }
        const int mixed = static_cast<int>(rng() % 6);
        for (int k = 0; k < mixed; ++k) {
            ExponentVector g(n);
            for (std::size_t v = 0; v < n; ++v) {
                g[v] = rng() % 5;
            }
            generators.push_back(g);
        }
        const std::uint64_t expected = walk_the_box(generators, n);
        const Integer counted = count_standard_monomials(generators, n);
        EXPECT_EQ(fmpz_get_ui(counted.get()), expected) << "trial " << trial;
    }
}

TEST(StandardMonomials, KnownCountsAndErrors) {
    // ⟨x², xy, y³⟩: 1, x, y, y² — four.
    EXPECT_EQ(fmpz_get_ui(count_standard_monomials({{2, 0}, {1, 1}, {0, 3}}, 2).get()), 4u);
    // A box of pure powers is a product: 12⁸, far too many points to walk.
    std::vector<ExponentVector> box;
    for (std::size_t v = 0; v < 8; ++v) {
        ExponentVector g(8, 0);
        g[v] = 12;
        box.push_back(g);
    }
    EXPECT_EQ(fmpz_get_ui(count_standard_monomials(box, 8).get()), 429981696u);
    // The unit ideal has none; a missing pure power means infinitely many.
    EXPECT_EQ(fmpz_get_ui(count_standard_monomials({{0, 0}, {1, 0}}, 2).get()), 0u);
    EXPECT_THROW(count_standard_monomials({{2, 0}, {1, 1}}, 2), InputError);
}

}  // namespace
}  // namespace locus::algebra
