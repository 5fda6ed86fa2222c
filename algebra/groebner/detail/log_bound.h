// Internal to the Gröbner code: rigorous upper bounds on the size of integers, in 1/64 of a bit
// (|v| ≤ 2^(u/64)). The certification keeps integers as residues (residue_system.h), which
// determine an integer only while it is known to be small enough: these bounds are that
// knowledge. Every rounding goes the safe way, so a bound never falls below the truth.
//
// Why sixty-fourths: a bound that adds a whole bit per addition (max + 1) drifts by a bit for
// every term a column receives, hundreds in a long reduction; adding log2(1 + 2^−d) instead,
// rounded up to 1/64, drifts by at most 1/64 of a bit per addition.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include <flint/fmpz.h>
#include <gmp.h>

namespace locus::algebra::detail::log_bound {

using Units = std::int64_t;
constexpr Units kPerBit = 64;
// The bound of zero (log2 0 = −∞), far enough from the int64 limits that adding and
// subtracting real bounds to it cannot overflow.
constexpr Units kZero = INT64_MIN / 4;

// u ≥ 64·log2|v| (kZero for v = 0).
Units upper(mpz_srcptr v);
Units upper(const fmpz_t v);
// u ≤ 64·log2|v|, for v ≠ 0.
Units lower(mpz_srcptr v);

// kSumTable[d] ≥ 64·log2(1 + 2^(−d/64)): what adding a number d units below the larger one
// can add to it. Past the table (d of 1 024 units, 16 bits, and more) that is under 0.0015
// units, rounded up to one unit. Bytes, so that the whole table stays in the first-level cache
// (the reducer reads it for every term).
// The entries are the chords between nodes every kSumNodeStep units, rounded up:
//   kSumTable[d] = ⌈(kSumNodeStep·n_i + (n_{i+1} − n_i)·r) / kSumNodeStep⌉, d = kSumNodeStep·i + r,
// for the nodes n_i = kSumNodes[i] ≥ 64·log2(1 + 2^(−i·kSumNodeStep/64)). The function is convex,
// so a chord between values above it stays above it; and the certification's vector kernel
// computes the same entries from the 33 nodes with two permutes instead of gathering them from
// 1 024 (residue_lanes.cpp; perf put most of that kernel's bound samples behind the gather,
// though the whole run did not change measurably). The price: an entry is up to 2.11 units
// above the exact value (at d = 17), 2 units above the rounded-up exact value, where a table of
// rounded values was under one unit above (the test checks every entry against long double).
constexpr std::size_t kSumTableSize = 16 * kPerBit;
constexpr std::size_t kSumNodeStep = 32;
extern const std::array<std::int32_t, kSumTableSize / kSumNodeStep + 1> kSumNodes;
extern const std::array<std::uint8_t, kSumTableSize> kSumTable;

// A bound on |x + y| from bounds on |x| and |y|. Branch-free: kZero is so far below any real
// bound that the table's last entry, one unit, is all it adds.
inline Units of_sum(Units x, Units y) {
    const Units high = x > y ? x : y, low = x > y ? y : x;
    const Units gap = high - low < Units{kSumTableSize} ? high - low : Units{kSumTableSize} - 1;
    return high + kSumTable[static_cast<std::size_t>(gap)];
}

// A bound on |x·y| from bounds on |x| and |y| (kZero, or below, for a zero factor).
inline Units of_product(Units x, Units y) {
    return x + y;
}

// Whether a bound is that of zero (or of a zero factor times something).
inline bool is_zero(Units x) {
    return x <= kZero / 2;
}

}  // namespace locus::algebra::detail::log_bound
