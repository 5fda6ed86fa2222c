// F4's linear algebra: rows reduced by the pivots through a dense accumulator.
#include "algebra/modular/detail/f4_engine.h"

#include "algebra/modular/detail/dense_update.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <deque>
#include <span>

namespace locus::algebra::modular::detail {

namespace {

// One update of an accumulator entry by a product below p². Lazy: every sum stays below 2⁶⁴
// unreduced (small primes, bounded rows; see lazy_reduction), so there is nothing to test per
// entry. Otherwise entries are kept below 2p² by one conditional subtraction of 2p² per update
// (p < 2³¹: 2p² + p² < 2⁶⁴).
template <bool Lazy>
inline void update(std::uint64_t& target, std::uint64_t product, std::uint64_t limit) {
    if constexpr (Lazy) {
        target += product;
    } else {
        const std::uint64_t sum = target + product;
        target = sum >= limit ? sum - limit : sum;
    }
}

// body(k) for k in [begin, end), unrolled by four: the entries of a row are distinct, so the
// four updates are independent.
template <typename Body>
inline void unrolled_by_four(std::size_t begin, std::size_t end, const Body& body) {
    std::size_t k = begin;
    for (; k + 4 <= end; k += 4) {
        body(k);
        body(k + 1);
        body(k + 2);
        body(k + 3);
    }
    for (; k < end; ++k) {
        body(k);
    }
}

// acc −= value · row past its leading entry, as acc += (p − value) · entry.
template <bool Lazy>
void add_multiple(std::uint64_t* acc, const PivotRow& row, std::uint64_t factor,
                  std::uint64_t limit) {
    const std::uint32_t* columns = row.columns;
    const std::uint32_t* coefficients = row.coefficients;
    // The size in a local: a store to acc could otherwise alias it (both 64-bit) and reload it
    // every iteration.
    unrolled_by_four(1, row.size, [&](std::size_t k) {
        update<Lazy>(acc[columns[k]], factor * coefficients[k], limit);
    });
}

// Reads acc[from, end) in column order, leaving it zero: each entry non-zero modulo p goes to
// visit(column, value), value in [1, p). Every reduction here is this scan, subtracting a
// pivot or keeping the value at each column it visits.
template <typename Visit>
inline void for_each_residue(std::uint64_t* acc, std::size_t from, std::size_t end, std::uint64_t p,
                             const Visit& visit) {
    for (std::size_t c = from; c < end; ++c) {
        if (acc[c] == 0) {
            continue;
        }
        const std::uint64_t value = acc[c] % p;
        acc[c] = 0;
        if (value != 0) {
            visit(c, value);
        }
    }
}

template <bool Lazy>
SparseRow reduce_dense_with(std::vector<std::uint64_t>& acc, std::size_t from, const Pivots& pivots,
                            std::uint64_t p) {
    const std::uint64_t limit = 2 * p * p;
    std::uint64_t* entries = acc.data();
    SparseRow out;
    for_each_residue(entries, from, acc.size(), p, [&](std::size_t c, std::uint64_t value) {
        const std::int64_t pivot = pivots.of_column[c];
        if (pivot < 0) {
            out.columns.push_back(static_cast<std::uint32_t>(c));
            out.coefficients.push_back(static_cast<std::uint32_t>(value));
        } else {
            add_multiple<Lazy>(entries, pivots.rows[static_cast<std::size_t>(pivot)], p - value,
                               limit);
        }
    });
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

// One step's reducers, each split by the kind of its columns: the leading columns (those
// that lead a reducer) and the free ones (the rest, where new leading monomials can appear).
// Numbered apart, each kind has its own dense accumulator: a row's reduction by the reducers
// walks the leading columns only, and its updates of the free columns — half or more of all
// (cyclic-8 modulo 65 521: 1.5 of 2.7·10⁹, counted by a build instrumented for it) — go to an
// accumulator of a few kilobytes, as
// runs of 8 lanes wherever a reducer is dense there. That is Faugère and Lachartre's split
// of the Macaulay matrix into (A B; C D), without forming A⁻¹B: the multipliers come from
// the leading columns alone, row by row as before, and each row's reduction is unchanged.

// (index, coefficient) pairs, interleaved so that a row's update reads one stream, each
// pair in one 64-bit load (index in the low half): two loads and a store an update.
static_assert(std::endian::native == std::endian::little, "a pair is read as one 64-bit word");
template <bool Lazy>
inline void add_pairs(std::uint64_t* acc, const std::uint32_t* pairs, std::size_t n,
                      std::uint64_t factor, std::uint64_t limit) {
    unrolled_by_four(0, n, [&](std::size_t k) {
        std::uint64_t pair;
        std::memcpy(&pair, pairs + 2 * k, sizeof pair);
        update<Lazy>(acc[static_cast<std::uint32_t>(pair)], factor * (pair >> 32), limit);
    });
}

// A row's entries in the free columns: packed from `first` (zeros included) where at least a
// quarter of their span is non-zero, as (index, coefficient) pairs otherwise.
struct FreeLayout {
    bool dense = false;
    std::uint32_t first = 0;
    std::uint32_t count = 0;  // packed: the span; pairs: the entries

    static FreeLayout of(std::uint32_t first_index, std::uint32_t last_index, std::uint32_t n) {
        if (n == 0) {
            return {};
        }
        const std::uint32_t span = last_index - first_index + 1;
        if (n >= 8 && span <= 4 * n) {
            return {true, first_index, span};
        }
        return {false, 0, n};
    }
    std::size_t words() const { return dense ? count : 2 * std::size_t{count}; }

    // `out` holds words() zeros.
    void encode(std::uint32_t* out, std::uint32_t index, std::uint32_t coefficient,
                std::size_t k) const {
        if (dense) {
            out[index - first] = coefficient;
        } else {
            out[2 * k] = index;
            out[2 * k + 1] = coefficient;
        }
    }

    template <bool Lazy>
    void add_to(std::uint64_t* acc, const std::uint32_t* data, std::uint64_t factor,
                std::uint64_t limit) const {
        if (dense) {
            const auto f = static_cast<std::uint32_t>(factor);
            if constexpr (Lazy) {
                add_dense_lazy(acc + first, data, count, f);
            } else {
                add_dense_bounded(acc + first, data, count, f, limit);
            }
        } else {
            add_pairs<Lazy>(acc, data, count, factor, limit);
        }
    }
};

// A reduced row's residue in the free columns: (free index, value in [1, p)).
struct FreeResidue {
    std::vector<std::uint32_t> indices;
    std::vector<std::uint32_t> values;
};

// The free accumulator read by for_each_residue: `eliminate(j, value)` subtracts a pivot at
// free index j (true) or declines (false: the value stays in the residue).
template <typename Eliminate>
FreeResidue drain(std::uint64_t* free, std::size_t count, std::uint64_t p,
                  const Eliminate& eliminate) {
    FreeResidue out;
    for_each_residue(free, 0, count, p, [&](std::size_t j, std::uint64_t value) {
        if (!eliminate(j, value)) {
            out.indices.push_back(static_cast<std::uint32_t>(j));
            out.values.push_back(static_cast<std::uint32_t>(value));
        }
    });
    return out;
}

// A thread's two dense accumulators, zero between rows.
struct Accumulators {
    Accumulators(std::size_t leading_count, std::size_t free_count)
        : leading(leading_count, 0), free(free_count, 0) {}
    std::vector<std::uint64_t> leading;
    std::vector<std::uint64_t> free;

    FreeResidue take_free(std::uint64_t p) {
        return drain(free.data(), free.size(), p, [](std::size_t, std::uint64_t) { return false; });
    }
    void load_free(const FreeResidue& residue) {
        for (std::size_t k = 0; k < residue.indices.size(); ++k) {
            free[residue.indices[k]] = residue.values[k];
        }
    }
};

// The rows of this step that did not reduce to zero, as pivots of the free columns (their
// entries are all there, every reducer having been applied).
class FreeRows {
  public:
    explicit FreeRows(std::size_t free_count) : of_index_(free_count, -1) {}

    // `indices` ascending, the first the row's leading one (its coefficient 1, not stored).
    void add(const std::vector<std::uint32_t>& indices, const std::vector<std::uint32_t>& values) {
        of_index_[indices.front()] = static_cast<std::int64_t>(rows_.size());
        const auto n = static_cast<std::uint32_t>(indices.size() - 1);
        Row& row = rows_.emplace_back();
        row.layout = FreeLayout::of(n > 0 ? indices[1] : 0, indices.back(), n);
        row.data.assign(row.layout.words(), 0);
        for (std::uint32_t k = 0; k < n; ++k) {
            row.layout.encode(row.data.data(), indices[k + 1], values[k + 1], k);
        }
    }

    // Reduces the free accumulator by these rows and returns what is left (entries in
    // [1, p), by free index), leaving it zero.
    template <bool Lazy>
    FreeResidue reduce(std::uint64_t* free, std::size_t count, std::uint64_t p) const {
        const std::uint64_t limit = 2 * p * p;
        return drain(free, count, p, [&](std::size_t j, std::uint64_t value) {
            const std::int64_t pivot = of_index_[j];
            if (pivot < 0) {
                return false;
            }
            const Row& row = rows_[static_cast<std::size_t>(pivot)];
            row.layout.add_to<Lazy>(free, row.data.data(), p - value, limit);
            return true;
        });
    }

  private:
    struct Row {
        FreeLayout layout;
        std::vector<std::uint32_t> data;
    };
    std::vector<std::int64_t> of_index_;
    std::deque<Row> rows_;
};

class SplitReducers {
  public:
    static constexpr std::uint32_t kFree = std::uint32_t{1} << 31;

    // The reducers are multiples of `basis` elements, their monomials numbered by the step's
    // table; `column_of` numbers those monomials by column (descending monomials). `storage`
    // holds the split rows; kept from step to step, its pages are touched once per run rather
    // than once a step.
    SplitReducers(std::span<const RowSpec> reducers, const std::vector<Element>& basis,
                  const std::vector<std::uint32_t>& column_of, std::size_t width,
                  LargePageBuffer<std::uint32_t>& storage, int threads)
        : data_(storage) {
        std::vector<std::int64_t> reducer_of_column(width, -1);
        for (std::size_t r = 0; r < reducers.size(); ++r) {
            reducer_of_column[column_of[reducers[r].monomials.front()]] =
                static_cast<std::int64_t>(r);
        }
        std::vector<std::uint32_t> index_of_column(width);
        std::vector<std::size_t> reducer_of_leading;
        for (std::size_t c = 0; c < width; ++c) {
            if (reducer_of_column[c] >= 0) {
                index_of_column[c] = static_cast<std::uint32_t>(reducer_of_leading.size());
                reducer_of_leading.push_back(static_cast<std::size_t>(reducer_of_column[c]));
            } else {
                index_of_column[c] = kFree | static_cast<std::uint32_t>(free_columns_.size());
                free_columns_.push_back(static_cast<std::uint32_t>(c));
            }
        }
        // By monomial, so that a row's term is placed by one lookup (the table numbers only
        // this step's monomials, all of them columns).
        index_of_monomial_.resize(column_of.size());
        for (std::size_t m = 0; m < column_of.size(); ++m) {
            index_of_monomial_[m] = index_of_column[column_of[m]];
        }
        // Two passes over the reducers, by leading index, into one block of memory laid out
        // in the order a row's reduction reads it: the sizes, then the entries. The leading
        // entry itself (k = 0) is the pivot and is not stored.
        tails_.resize(reducer_of_leading.size());
        auto measure = [&](std::size_t i) {
            const RowSpec& row = reducers[reducer_of_leading[i]];
            std::uint32_t leading = 0;
            std::uint32_t free = 0;
            std::uint32_t first = 0;
            std::uint32_t last = 0;
            for (std::size_t k = 1; k < row.monomials.size(); ++k) {
                const std::uint32_t index = index_of_monomial_[row.monomials[k]];
                if ((index & kFree) == 0) {
                    ++leading;
                } else {
                    last = index & ~kFree;
                    first = free == 0 ? last : first;
                    ++free;
                }
            }
            tails_[i].leading_count = leading;
            tails_[i].free = FreeLayout::of(first, last, free);
        };
        auto fill = [&](std::size_t i) {
            const RowSpec& row = reducers[reducer_of_leading[i]];
            const std::uint32_t* coefficients = basis[row.element].poly.coefficients.data();
            const Tail& tail = tails_[i];
            std::uint32_t* pairs = data_.data() + tail.offset;
            std::uint32_t* free = pairs + 2 * std::size_t{tail.leading_count};
            if (tail.free.dense) {
                std::fill_n(free, tail.free.count, 0);
            }
            std::size_t leading_k = 0;
            std::size_t free_k = 0;
            for (std::size_t k = 1; k < row.monomials.size(); ++k) {
                const std::uint32_t index = index_of_monomial_[row.monomials[k]];
                if ((index & kFree) == 0) {
                    pairs[2 * leading_k] = index;
                    pairs[2 * leading_k + 1] = coefficients[k];
                    ++leading_k;
                } else {
                    tail.free.encode(free, index & ~kFree, coefficients[k], free_k++);
                }
            }
        };
        const std::size_t count = reducer_of_leading.size();
        for_each(count, threads, measure);
        std::size_t offset = 0;
        for (std::size_t i = 0; i < count; ++i) {
            tails_[i].offset = offset;
            offset += 2 * std::size_t{tails_[i].leading_count} + tails_[i].free.words();
        }
        data_.make_room(offset);
        for_each(count, threads, fill);
    }

    std::size_t leading_count() const { return tails_.size(); }
    std::size_t free_count() const { return free_columns_.size(); }
    std::uint32_t column_of_free(std::uint32_t index) const { return free_columns_[index]; }

    // Loads `row` (its coefficients `coefficients`) into the zero accumulators and reduces it
    // by the reducers: leaves the leading accumulator zero and the free one holding the row's
    // residue there (unreduced).
    template <bool Lazy>
    void reduce(const RowSpec& row, const std::uint32_t* coefficients, Accumulators& acc,
                std::uint64_t p) const {
        const std::uint64_t limit = 2 * p * p;
        std::uint64_t* leading = acc.leading.data();
        std::uint64_t* free = acc.free.data();
        const std::size_t count = tails_.size();
        std::size_t from = count;
        for (std::size_t k = 0; k < row.monomials.size(); ++k) {
            const std::uint32_t index = index_of_monomial_[row.monomials[k]];
            if ((index & kFree) == 0) {
                leading[index] = coefficients[k];
                from = std::min<std::size_t>(from, index);
            } else {
                free[index & ~kFree] = coefficients[k];
            }
        }
        const std::uint32_t* data = data_.data();
        // Every leading column has its reducer.
        for_each_residue(leading, from, count, p, [&](std::size_t i, std::uint64_t value) {
            const std::uint64_t factor = p - value;
            const Tail& tail = tails_[i];
            const std::uint32_t* pairs = data + tail.offset;
            add_pairs<Lazy>(leading, pairs, tail.leading_count, factor, limit);
            tail.free.add_to<Lazy>(free, pairs + 2 * std::size_t{tail.leading_count}, factor,
                                   limit);
        });
    }

  private:
    struct Tail {
        std::size_t offset = 0;  // in data_
        std::uint32_t leading_count = 0;
        FreeLayout free;
    };

    template <typename Body>
    static void for_each(std::size_t count, int threads, const Body& body) {
        if (threads > 1 && count >= 256) {
            tbb::task_arena arena(threads);
            arena.execute([&] { tbb::parallel_for(std::size_t{0}, count, body); });
        } else {
            for (std::size_t i = 0; i < count; ++i) {
                body(i);
            }
        }
    }

    std::vector<std::uint32_t> index_of_monomial_;  // leading index, or kFree | free index
    std::vector<std::uint32_t> free_columns_;       // by free index
    std::vector<Tail> tails_;                       // by leading index
    LargePageBuffer<std::uint32_t>& data_;
};

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

void F4Engine::reduce_rows(const std::vector<RowSpec>& reducers, const std::vector<RowSpec>& rows,
                           const std::vector<std::uint32_t>& column_of, std::size_t width,
                           std::vector<SparseRow>& fresh, std::vector<std::size_t>& useful) {
    const int threads = std::max(1, options_.threads);
    // Below this many rows a step is not worth the threads' start.
    constexpr std::size_t kRowsForThreads = 32;
    const bool side_by_side = threads > 1 && rows.size() >= kRowsForThreads;
    const SplitReducers split(reducers, basis_, column_of, width, split_storage_,
                              side_by_side ? threads : 1);
    const std::uint64_t p = field_.p;
    const bool lazy = lazy_reduction(p, reducers.size() + rows.size());
    FreeRows by_fresh(split.free_count());
    auto reduce_by_reducers = [&](const RowSpec& row, Accumulators& acc) {
        const std::uint32_t* coefficients = basis_[row.element].poly.coefficients.data();
        if (lazy) {
            split.reduce<true>(row, coefficients, acc, p);
        } else {
            split.reduce<false>(row, coefficients, acc, p);
        }
    };
    // With threads, by the reducers alone first, side by side (each thread has its own
    // accumulators); what is left is in the free columns.
    std::vector<FreeResidue> partial;
    if (side_by_side) {
        partial.resize(rows.size());
        tbb::enumerable_thread_specific<Accumulators> accumulators(
            [&split] { return Accumulators(split.leading_count(), split.free_count()); });
        tbb::task_arena arena(threads);
        arena.execute([&] {
            tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows.size(), 8),
                              [&](const tbb::blocked_range<std::size_t>& range) {
                                  Accumulators& acc = accumulators.local();
                                  for (std::size_t r = range.begin(); r < range.end(); ++r) {
                                      check_deadline();
                                      reduce_by_reducers(rows[r], acc);
                                      partial[r] = acc.take_free(p);
                                  }
                              });
        });
    }
    // In order, by the new rows (those before it that did not reduce to zero).
    Accumulators acc(split.leading_count(), split.free_count());
    for (std::size_t r = 0; r < rows.size(); ++r) {
        check_deadline();
        if (side_by_side) {
            acc.load_free(partial[r]);
            partial[r] = {};
        } else {
            reduce_by_reducers(rows[r], acc);
        }
        FreeResidue residue = lazy ? by_fresh.reduce<true>(acc.free.data(), acc.free.size(), p)
                                   : by_fresh.reduce<false>(acc.free.data(), acc.free.size(), p);
        if (residue.indices.empty()) {
            ++stats_.zero_rows;
            continue;
        }
        SparseRow row;
        row.columns.reserve(residue.indices.size());
        for (std::uint32_t j : residue.indices) {
            row.columns.push_back(split.column_of_free(j));
        }
        row.coefficients = std::move(residue.values);
        make_monic(row);
        by_fresh.add(residue.indices, row.coefficients);
        useful.push_back(r);
        fresh.push_back(std::move(row));
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
