// F4's linear algebra: rows reduced by the pivots through a dense accumulator.
#include "algebra/modular/detail/f4_engine.h"

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

std::optional<SparseRow> F4Engine::reduce_row(PivotRow row, std::vector<std::uint64_t>& acc,
                                              const Pivots& pivots, std::size_t rows) const {
    for (std::size_t k = 0; k < row.size; ++k) {
        acc[row.columns[k]] = row.coefficients[k];
    }
    SparseRow reduced = reduce_dense(acc, row.columns[0], pivots, rows);
    if (reduced.columns.empty()) {
        return std::nullopt;
    }
    const std::uint64_t inverse = field_.inverse(reduced.coefficients.front());
    for (std::uint32_t& c : reduced.coefficients) {
        c = static_cast<std::uint32_t>(field_.multiply(c, inverse));
    }
    return reduced;
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
