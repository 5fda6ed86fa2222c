// F4's linear algebra: rows reduced by the pivots through a dense accumulator.
#include "algebra/modular/detail/f4_engine.h"

#include <algorithm>

namespace locus::algebra::modular::detail {

// Reduces `acc` (dense, entries < 2p²) from column `from` on by the pivot rows; returns the
// reduced row (entries in [1, p)) of the columns without a pivot.
SparseRow F4Engine::reduce_dense(std::vector<std::uint64_t>& acc, std::size_t from,
                                 const std::vector<std::int64_t>& pivot_of_column,
                                 const std::vector<SparseRow>& pivots) const {
    const std::uint64_t p = field_.p;
    const std::uint64_t limit = 2 * p * p;
    SparseRow out;
    for (std::size_t c = from; c < acc.size(); ++c) {
        if (acc[c] == 0) {
            continue;
        }
        const std::uint64_t value = acc[c] % p;
        acc[c] = 0;
        if (value == 0) {
            continue;
        }
        const std::int64_t pivot = pivot_of_column[c];
        if (pivot < 0) {
            out.columns.push_back(static_cast<std::uint32_t>(c));
            out.coefficients.push_back(static_cast<std::uint32_t>(value));
            continue;
        }
        // acc −= value · pivot row (monic): add (p − value) times each later entry.
        const SparseRow& row = pivots[static_cast<std::size_t>(pivot)];
        const std::uint64_t factor = p - value;
        for (std::size_t k = 1; k < row.columns.size(); ++k) {
            std::uint64_t& target = acc[row.columns[k]];
            target += factor * row.coefficients[k];
            if (target >= limit) {
                target -= limit;
            }
        }
    }
    return out;
}

// Reduces `row` by the pivots (using the zeroed dense accumulator `acc`); a non-zero result
// is made monic and becomes the pivot of its leading column. Nothing when it reduces to 0.
std::optional<SparseRow> F4Engine::reduce_row(const SparseRow& row, std::vector<std::uint64_t>& acc,
                                              std::vector<std::int64_t>& pivot_of_column,
                                              std::vector<SparseRow>& pivots) const {
    for (std::size_t k = 0; k < row.columns.size(); ++k) {
        acc[row.columns[k]] = row.coefficients[k];
    }
    SparseRow reduced = reduce_dense(acc, row.columns.front(), pivot_of_column, pivots);
    if (reduced.columns.empty()) {
        return std::nullopt;
    }
    const std::uint64_t inverse = field_.inverse(reduced.coefficients.front());
    for (std::uint32_t& c : reduced.coefficients) {
        c = static_cast<std::uint32_t>(field_.multiply(c, inverse));
    }
    pivot_of_column[reduced.columns.front()] = static_cast<std::int64_t>(pivots.size());
    pivots.push_back(reduced);
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
