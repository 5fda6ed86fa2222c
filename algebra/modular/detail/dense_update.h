// acc[j] += factor · coefficients[j] over a dense run of 32-bit residues into 64-bit
// accumulators: the update of F4's row reduction where a pivot row is dense (its entries in
// the columns that lead no reducer, packed). AVX-512, AVX2 or portable code, chosen once at
// start-up as residue_lanes.h does. Internal to algebra/modular/.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace locus::algebra::modular::detail {

// Lazy: the sums are left unreduced (the caller has shown they stay below 2⁶⁴).
// factor < 2³².
void add_dense_lazy(std::uint64_t* acc, const std::uint32_t* coefficients, std::size_t n,
                    std::uint32_t factor);

// Bounded: every entry, below `limit` before, stays below `limit` after, by one conditional
// subtraction of `limit` (the caller keeps limit + factor·max coefficient below 2⁶⁴).
void add_dense_bounded(std::uint64_t* acc, const std::uint32_t* coefficients, std::size_t n,
                       std::uint32_t factor, std::uint64_t limit);

// The kernels in use ("avx512", "avx2" or "portable"), those this processor runs, and, for
// the tests, a way to pick one (throws std::invalid_argument if the processor does not run it).
const char* dense_update_kernels();
std::vector<std::string> supported_dense_update_kernels();
void select_dense_update_kernels(const std::string& name);

}  // namespace locus::algebra::modular::detail
