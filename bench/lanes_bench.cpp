// `locus-bench lanes`: the certification's row kernel (algebra/groebner/detail/residue_lanes.h)
// on synthetic data, so that the figures design.md gives for it come from a command. Each case
// is a lane count and a number of columns; a step adds one row of 200 terms, on random
// distinct columns, to eight reductions. The reference, measured in the same run, is the way
// before reductions ran together: one call of the row kernel a reduction, each in a table of
// its own (no bounds). Rows: ns a reduction and term for that reference on cache-line-aligned
// tables and on tables 16 bytes past a line (malloc's alignment), and for the slots' kernel
// (with its bounds), and the slots' kernel over the aligned reference.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "algebra/detail/cache_aligned.h"
#include "algebra/groebner/detail/log_bound.h"
#include "algebra/groebner/detail/residue_lanes.h"
#include "bench/bench_options.h"
#include "bench/benches.h"
#include "cli/exit_codes.h"

namespace locus::bench {
namespace {

using algebra::detail::CacheAlignedVector;
using algebra::detail::LanePrimes;
namespace lanes = algebra::detail::lanes;

struct LanesBenchArgs {
    SuiteOptions suite;
    std::vector<int> lane_counts{24, 32, 48};
    std::vector<int> column_counts{4546, 11495};
};

constexpr std::size_t kTerms = 200;  // a reducer row (katsura-10's average is 125, -11's 200)
constexpr std::size_t kSets = 64;    // column sets cycled through
constexpr std::size_t kSlots = lanes::kSlots;

// Nanoseconds a reduction and term of `step` (one row added to kSlots reductions), repeated
// until `min_seconds` have passed (at least 200 steps).
template <class Step>
double ns_per_slot_term(const Step& step, double min_seconds) {
    std::size_t steps = 0;
    const auto start = std::chrono::steady_clock::now();
    double seconds = 0.0;
    do {
        for (int k = 0; k < 100; ++k) {
            step(steps++);
        }
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    } while (steps < 200 || seconds < min_seconds);
    return seconds * 1e9 / static_cast<double>(steps * kTerms * kSlots);
}

int run_lanes_bench(const LanesBenchArgs& args) {
    check_suite_options(args.suite);
    if (args.suite.csv) {
        std::printf("lanes,columns,alone_ns,alone_unaligned_ns,together_ns,ratio\n");
    } else {
        std::printf("%5s %8s %10s %14s %12s %7s\n", "lanes", "columns", "alone ns", "16 B off ns",
                    "together ns", "ratio");
    }
    std::mt19937 rng(1);
    for (const int lane_count : args.lane_counts) {
        for (const int column_count : args.column_counts) {
            if (lane_count <= 0 || lane_count % 8 != 0 || column_count < static_cast<int>(kTerms)) {
                std::fprintf(stderr,
                             "locus-bench lanes: lanes a positive multiple of 8, at "
                             "least %zu columns\n",
                             kTerms);
                return cli::exit_input;
            }
            const auto width = static_cast<std::size_t>(lane_count);
            const auto columns = static_cast<std::size_t>(column_count);
            const LanePrimes primes(width, [](std::uint32_t) { return true; });
            CacheAlignedVector<std::uint32_t> rows(kTerms * width), b(kSlots * width),
                quotients(kSlots * width);
            for (std::size_t i = 0; i < rows.size(); ++i) {
                rows[i] = static_cast<std::uint32_t>(rng() % primes.prime(i % width));
            }
            for (std::size_t s = 0; s < kSlots; ++s) {
                for (std::size_t l = 0; l < width; ++l) {
                    b[s * width + l] = static_cast<std::uint32_t>(rng() % primes.prime(l));
                }
                lanes::shoup_quotients(quotients.data() + s * width, b.data() + s * width, primes);
            }
            std::vector<std::vector<std::uint32_t>> sets(kSets);
            std::vector<std::uint32_t> all(columns);
            std::iota(all.begin(), all.end(), 0u);
            for (std::vector<std::uint32_t>& set : sets) {
                std::shuffle(all.begin(), all.end(), rng);
                set.assign(all.begin(), all.begin() + static_cast<long>(kTerms));
            }
            // The reference: a table a reduction, aligned or 16 bytes (4 lanes) past a line.
            const auto alone = [&](std::size_t offset) {
                std::vector<CacheAlignedVector<std::uint32_t>> tables(
                    kSlots, CacheAlignedVector<std::uint32_t>(columns * width + offset, 0));
                return ns_per_slot_term(
                    [&](std::size_t step) {
                        for (std::size_t s = 0; s < kSlots; ++s) {
                            lanes::add_scaled_rows(tables[s].data() + offset,
                                                   sets[step % kSets].data(), kTerms, rows.data(),
                                                   b.data() + s * width,
                                                   quotients.data() + s * width, primes);
                        }
                    },
                    args.suite.min_seconds);
            };
            const double aligned = alone(0), unaligned = alone(4);
            // The slots' kernel on one shared table, its bounds and pending bytes.
            CacheAlignedVector<std::uint32_t> table(columns * kSlots * width, 0);
            std::vector<std::int64_t> bound(columns * kSlots, 0), term(kTerms, 100);
            std::vector<std::uint8_t> pending(columns * kSlots, 1);
            std::vector<std::uint32_t> fresh(kTerms * kSlots);
            std::vector<std::int64_t> offsets(kSlots, 0), highest(kSlots, 0);
            std::vector<std::size_t> fresh_counts(kSlots, 0);
            const double together = ns_per_slot_term(
                [&](std::size_t step) {
                    lanes::SlotBounds bounds{bound.data(),   term.data(),  offsets.data(),
                                             pending.data(), fresh.data(), fresh_counts.data(),
                                             highest.data()};
                    lanes::add_scaled_rows_together(table.data(), sets[step % kSets].data(), kTerms,
                                                    rows.data(), (1u << kSlots) - 1, b.data(),
                                                    quotients.data(), primes, bounds);
                },
                args.suite.min_seconds);
            if (args.suite.csv) {
                std::printf("%zu,%zu,%.3f,%.3f,%.3f,%.3f\n", width, columns, aligned, unaligned,
                            together, together / aligned);
            } else {
                std::printf("%5zu %8zu %10.2f %14.2f %12.2f %7.2f\n", width, columns, aligned,
                            unaligned, together, together / aligned);
            }
        }
    }
    std::printf("(kernels: %s)\n", lanes::kernel_name());
    return cli::exit_ok;
}

}  // namespace

void add_lanes_bench(CLI::App& app, cli::CommandContext& context) {
    auto args = std::make_shared<LanesBenchArgs>();
    CLI::App* cmd = add_suite_command(
        app, context, "lanes",
        "The certification's row kernel on synthetic rows: eight reductions together against "
        "one call a reduction, in the same run",
        args, run_lanes_bench);
    // Synthetic rows: no suite files to read or cases to choose.
    cmd->remove_option(cmd->get_option("--data"));
    cmd->remove_option(cmd->get_option("--cases"));
    cmd->add_option("--lanes", args->lane_counts, "lane counts, multiples of 8 (24 32 48)");
    cmd->add_option("--columns", args->column_counts,
                    "columns of the table (4546 11495: katsura-10's and -11's)");
}

}  // namespace locus::bench
