// Internal to the Gröbner code: the reducer rows of a zero-reduction by a basis that does not
// change (ExactZeroReducer on GMP integers, ResidueZeroReducer on residues). Every monomial met
// is a column of a MonomialTable; the first time a column must be cancelled, the basis element
// whose leading monomial divides it (ReducerSearch: the same reducer as Reducer's) and the
// columns of the multiple's other terms are found and kept (F4's symbolic preprocessing, done
// lazily). The two reducers differ only in how they hold coefficients, so this part is shared.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "algebra/groebner/detail/reduction.h"
#include "algebra/monomial_table.h"

namespace locus::algebra::detail {

class ReducerRows {
  public:
    // A reducer row: the basis element and, for its terms after the leading one, the columns of
    // their products with the multiplier (columns() from `offset`, one per term).
    struct Row {
        std::size_t element;
        std::size_t offset;
    };
    static constexpr std::int32_t kIrreducible = -1;

    // Called for every new column, in the order they are numbered.
    void add_column() { row_of_column_.push_back(kNotLookedUp); }

    // Index in rows() of the row that cancels column `c` of `table`, or kIrreducible when no
    // leading monomial of `basis` divides it; found on first use. `number_column(m)` returns the
    // column of monomial m, numbering it (and calling add_column) when it is new. `multiplier`
    // and `product` are scratch monomials of layout.words() words.
    template <class NumberColumn>
    std::int32_t row_of(std::uint32_t c, const MonomialTable& table, const ReducerSearch& search,
                        const MonomialLayout& layout, const std::vector<BasisElement>& basis,
                        std::uint64_t* multiplier, std::uint64_t* product,
                        NumberColumn&& number_column) {
        if (row_of_column_[c] != kNotLookedUp) {
            return row_of_column_[c];
        }
        const std::size_t w = layout.words();
        // Copied: numbering new columns below may move the table's storage.
        const std::vector<std::uint64_t> monomial(table.at(c), table.at(c) + w);
        const long k = search.find(monomial.data(), layout);
        if (k < 0) {
            row_of_column_[c] = kIrreducible;
            return kIrreducible;
        }
        const IntegerPolynomial& g = basis[static_cast<std::size_t>(k)].poly;
        layout.divide(monomial.data(), g.monomial(0, w), multiplier);
        const Row row{static_cast<std::size_t>(k), columns_.size()};
        for (std::size_t j = 1; j < g.size(); ++j) {
            layout.multiply(g.monomial(j, w), multiplier, product);
            columns_.push_back(number_column(product));
        }
        rows_.push_back(row);
        row_of_column_[c] = static_cast<std::int32_t>(rows_.size() - 1);
        return row_of_column_[c];
    }

    const Row& row(std::int32_t index) const { return rows_[static_cast<std::size_t>(index)]; }
    // The columns of a row's terms after the leading one.
    const std::uint32_t* columns_of(const Row& row) const { return columns_.data() + row.offset; }

  private:
    static constexpr std::int32_t kNotLookedUp = -2;

    std::vector<std::int32_t> row_of_column_;
    std::vector<Row> rows_;
    std::vector<std::uint32_t> columns_;
};

}  // namespace locus::algebra::detail
