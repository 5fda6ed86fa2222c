// F4's linear algebra: rows reduced by the pivots through a dense accumulator.
#include "algebra/modular/detail/f4_engine.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstdint>

namespace locus::algebra::modular::detail {

namespace {

// acc −= value · row past its leading entry, as acc += (p − value) · entry. Unrolled by four:
// the columns of a row are distinct, so the four updates are independent.
//
// Lazy: every sum stays below 2⁶⁴ unreduced (small primes, bounded rows; see
// lazy_reduction), so there is nothing to test per entry. Otherwise entries are kept below
// 2p² by one conditional subtraction of 2p² per update (p < 2³¹: 2p² + p² < 2⁶⁴).
template <bool Lazy>
void add_multiple(std::uint64_t* acc, const PivotRow& row, std::uint64_t factor,
                  std::uint64_t limit) {
    const std::uint32_t* columns = row.columns;
    const std::uint32_t* coefficients = row.coefficients;
    auto update = [&](std::size_t k) {
        std::uint64_t& target = acc[columns[k]];
        if constexpr (Lazy) {
            target += factor * coefficients[k];
        } else {
            const std::uint64_t sum = target + factor * coefficients[k];
            target = sum >= limit ? sum - limit : sum;
        }
    };
    // In locals: a store to acc could otherwise alias the row's size (both 64-bit) and reload
    // it every iteration.
    const std::size_t size = row.size;
    std::size_t k = 1;
    for (; k + 4 <= size; k += 4) {
        update(k);
        update(k + 1);
        update(k + 2);
        update(k + 3);
    }
    for (; k < size; ++k) {
        update(k);
    }
}

template <bool Lazy>
SparseRow reduce_dense_with(std::vector<std::uint64_t>& acc, std::size_t from, const Pivots& pivots,
                            std::uint64_t p) {
    const std::uint64_t limit = 2 * p * p;
    std::uint64_t* entries = acc.data();
    const std::size_t width = acc.size();
    SparseRow out;
    for (std::size_t c = from; c < width; ++c) {
        if (entries[c] == 0) {
            continue;
        }
        const std::uint64_t value = entries[c] % p;
        entries[c] = 0;
        if (value == 0) {
            continue;
        }
        const std::int64_t pivot = pivots.of_column[c];
        if (pivot < 0) {
            out.columns.push_back(static_cast<std::uint32_t>(c));
            out.coefficients.push_back(static_cast<std::uint32_t>(value));
            continue;
        }
        add_multiple<Lazy>(entries, pivots.rows[static_cast<std::size_t>(pivot)], p - value, limit);
    }
    return out;
}

// Whether a row's reduction may sum without reducing: an entry starts below p and gains less
// than p² per pivot, at most one update per pivot, and there are fewer pivots than `rows`.
// True for p = 65 521 (msolve's and the literature's usual prime) on any matrix below 2³²
// rows; for 31-bit primes only on matrices of at most three rows.
bool lazy_reduction(std::uint64_t p, std::size_t rows) {
    const std::uint64_t square = (p - 1) * (p - 1);  // p < 2³²
    return rows + 1 <= (UINT64_MAX - p) / square;
}

}  // namespace

SparseRow F4Engine::reduce_dense(std::vector<std::uint64_t>& acc, std::size_t from,
                                 const Pivots& pivots, std::size_t rows) const {
    return lazy_reduction(field_.p, rows) ? reduce_dense_with<true>(acc, from, pivots, field_.p)
                                          : reduce_dense_with<false>(acc, from, pivots, field_.p);
}

void F4Engine::make_monic(SparseRow& row) const {
    const std::uint64_t inverse = field_.inverse(row.coefficients.front());
    for (std::uint32_t& c : row.coefficients) {
        c = static_cast<std::uint32_t>(field_.multiply(c, inverse));
    }
}

SparseRow F4Engine::reduce_loaded_row(PivotRow row, std::vector<std::uint64_t>& acc,
                                      const Pivots& pivots, std::size_t rows) const {
    for (std::size_t k = 0; k < row.size; ++k) {
        acc[row.columns[k]] = row.coefficients[k];
    }
    return reduce_dense(acc, row.columns[0], pivots, rows);
}

std::optional<SparseRow> F4Engine::reduce_row(PivotRow row, std::vector<std::uint64_t>& acc,
                                              const Pivots& pivots, std::size_t rows) const {
    SparseRow reduced = reduce_loaded_row(row, acc, pivots, rows);
    if (reduced.columns.empty()) {
        return std::nullopt;
    }
    make_monic(reduced);
    return reduced;
}

void F4Engine::reduce_rows(const std::vector<RowSpec>& rows,
                           const std::vector<std::uint32_t>& column_of, Pivots& pivots,
                           std::size_t total_rows, std::vector<SparseRow>& fresh,
                           std::vector<std::size_t>& useful) {
    const std::size_t width = pivots.of_column.size();
    const int threads = std::max(1, options_.threads);
    // Below this many rows a step is not worth the threads' start.
    constexpr std::size_t kRowsForThreads = 32;
    const bool side_by_side = threads > 1 && rows.size() >= kRowsForThreads;
    // With threads, by the reducers alone first, side by side (the pivots hold only the
    // reducers until the pass in order; each thread has its own accumulator).
    std::vector<SparseRow> partial;
    if (side_by_side) {
        partial.resize(rows.size());
        tbb::enumerable_thread_specific<std::vector<std::uint64_t>> accumulators(
            [width] { return std::vector<std::uint64_t>(width, 0); });
        tbb::task_arena arena(threads);
        arena.execute([&] {
            tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows.size(), 8),
                              [&](const tbb::blocked_range<std::size_t>& range) {
                                  std::vector<std::uint64_t>& acc = accumulators.local();
                                  for (std::size_t r = range.begin(); r < range.end(); ++r) {
                                      check_deadline();
                                      const std::vector<std::uint32_t> row_columns =
                                          columns_of(rows[r], column_of);
                                      partial[r] = reduce_loaded_row(row_view(rows[r], row_columns),
                                                                     acc, pivots, total_rows);
                                  }
                              });
        });
    }
    // In order, by the reducers and the new rows (after the first pass: by what the new rows
    // bring, and the reducers again for that).
    std::vector<std::uint64_t> acc(width, 0);
    std::vector<std::uint32_t> row_columns;
    for (std::size_t r = 0; r < rows.size(); ++r) {
        check_deadline();
        SparseRow row;
        if (!side_by_side) {
            row_columns = columns_of(rows[r], column_of);
            row = reduce_loaded_row(row_view(rows[r], row_columns), acc, pivots, total_rows);
        } else if (!partial[r].columns.empty() && !fresh.empty()) {
            row = reduce_loaded_row(view_of(partial[r]), acc, pivots, total_rows);
        } else {
            row = std::move(partial[r]);
        }
        if (row.columns.empty()) {
            ++stats_.zero_rows;
            continue;
        }
        make_monic(row);
        useful.push_back(r);
        fresh.push_back(std::move(row));
        pivots.add(view_of(fresh.back()));
    }
}

// The reduced rows as polynomials, smallest leading monomial first (the order in which
// they join the basis, which a replay repeats).
std::vector<ModularPolynomial> F4Engine::new_elements(
    std::vector<SparseRow>& fresh, const std::vector<std::uint64_t>& column_monomials) const {
    std::sort(fresh.begin(), fresh.end(), [](const SparseRow& a, const SparseRow& b) {
        return a.columns.front() > b.columns.front();
    });
    std::vector<ModularPolynomial> out;
    for (const SparseRow& row : fresh) {
        ModularPolynomial poly;
        poly.coefficients = row.coefficients;
        poly.monomials.reserve(row.columns.size() * words_);
        for (std::uint32_t c : row.columns) {
            const std::uint64_t* m = column_monomials.data() + c * words_;
            poly.monomials.insert(poly.monomials.end(), m, m + words_);
        }
        out.push_back(std::move(poly));
    }
    return out;
}

}  // namespace locus::algebra::modular::detail
