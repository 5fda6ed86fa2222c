// The dense update of F4's row reduction (algebra/modular/detail/dense_update.h): every build
// of the kernels the machine runs (portable, AVX2, AVX-512) against the sum written out
// entry by entry (below 3p² < 2⁶⁴, so without wrapping), on random runs of every length up to 70
// and at every offset, lazy and bounded, with entries next to the bound.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "algebra/modular/detail/dense_update.h"

namespace locus::algebra::modular::detail {
namespace {

void expect_kernels_agree_with_the_sum() {
    std::mt19937_64 rng(2026);
    const std::uint64_t primes[] = {65521, 16777213, 2147483647};
    for (const std::uint64_t p : primes) {
        const std::uint64_t limit = 2 * p * p;
        std::uniform_int_distribution<std::uint64_t> below_p(0, p - 1);
        std::uniform_int_distribution<std::uint64_t> below_limit(0, limit - 1);
        for (std::size_t n = 0; n <= 70; ++n) {
            for (std::size_t offset = 0; offset < 3; ++offset) {
                std::vector<std::uint32_t> coefficients(n + offset);
                for (std::uint32_t& c : coefficients) {
                    c = static_cast<std::uint32_t>(below_p(rng));
                }
                const auto factor = static_cast<std::uint32_t>(below_p(rng));
                // Lazy: entries anywhere that leaves room for one product.
                std::vector<std::uint64_t> lazy(n + offset + 1);
                for (std::uint64_t& a : lazy) {
                    a = rng() >> 2;
                }
                std::vector<std::uint64_t> expected = lazy;
                for (std::size_t j = 0; j < n; ++j) {
                    expected[offset + j] += std::uint64_t{factor} * coefficients[offset + j];
                }
                add_dense_lazy(lazy.data() + offset, coefficients.data() + offset, n, factor);
                EXPECT_EQ(lazy, expected) << "p = " << p << ", n = " << n;
                // Bounded: entries below the limit, half of them just below it.
                std::vector<std::uint64_t> bounded(n + offset + 1);
                for (std::size_t j = 0; j < bounded.size(); ++j) {
                    bounded[j] = j % 2 == 0 ? below_limit(rng) : limit - 1 - (rng() % 4);
                }
                expected = bounded;
                for (std::size_t j = 0; j < n; ++j) {
                    const std::uint64_t sum =
                        expected[offset + j] + std::uint64_t{factor} * coefficients[offset + j];
                    ASSERT_LT(sum, 2 * limit);
                    expected[offset + j] = sum >= limit ? sum - limit : sum;
                }
                add_dense_bounded(bounded.data() + offset, coefficients.data() + offset, n, factor,
                                  limit);
                EXPECT_EQ(bounded, expected) << "p = " << p << ", n = " << n;
            }
        }
    }
}

TEST(DenseUpdate, EveryKernelTheProcessorRunsAgreesWithTheSum) {
    const std::string best = dense_update_kernels();
    const std::vector<std::string> supported = supported_dense_update_kernels();
    ASSERT_EQ(supported.front(), "portable");
    EXPECT_EQ(supported.back(), best);  // the best it runs is the one in use
    for (const std::string& name : supported) {
        SCOPED_TRACE(name);
        select_dense_update_kernels(name);
        EXPECT_EQ(dense_update_kernels(), name);
        expect_kernels_agree_with_the_sum();
    }
    select_dense_update_kernels(best);
    EXPECT_THROW(select_dense_update_kernels("sse9"), std::invalid_argument);
}

}  // namespace
}  // namespace locus::algebra::modular::detail
