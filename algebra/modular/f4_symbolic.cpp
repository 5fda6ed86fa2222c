// F4's symbolic preprocessing: the rows of a step's Macaulay matrix and their columns.
#include "algebra/modular/detail/f4_engine.h"

#include <algorithm>

#include "algebra/assert.h"

namespace locus::algebra::modular::detail {

RowSpec F4Engine::make_row(std::size_t element, const std::uint64_t* multiplier) {
    RowSpec row{element, {}};
    Element& e = basis_[element];
    LOCUS_ASSERT(!e.released);
    const ModularPolynomial& f = e.poly;
    if (e.term_hashes.empty()) {
        e.term_hashes.reserve(f.size());
        for (std::size_t i = 0; i < f.size(); ++i) {
            e.term_hashes.push_back(table_.hash(f.monomial(i, words_)));
        }
    }
    const std::uint64_t multiplier_hash = table_.hash(multiplier);
    row.monomials.reserve(f.size());
    for (std::size_t i = 0; i < f.size(); ++i) {
        layout_.multiply(multiplier, f.monomial(i, words_), scratch_.data());
        row.monomials.push_back(
            table_.insert_hashed(scratch_.data(), multiplier_hash + e.term_hashes[i]));
    }
    return row;
}

// The first non-redundant element whose leading monomial divides m (f4_engine.h).
std::optional<std::size_t> F4Engine::reducer_for(const std::uint64_t* m) const {
    const std::uint64_t mask = layout_.divisibility_mask(m);
    const std::size_t count = live_.index.size();
    for (std::size_t k = 0; k < count; ++k) {
        if ((live_.mask[k] & ~mask) == 0 && layout_.divides(live_.lead.data() + k * words_, m)) {
            return live_.index[k];
        }
    }
    return std::nullopt;
}

// Symbolic preprocessing: reducer rows for every monomial of `rows` (and of the reducers
// themselves) that some leading monomial divides. `pivot_of_monomial` maps table indices to
// the reducer row with that leading monomial (or −1).
void F4Engine::preprocess(std::vector<RowSpec>& reducers, std::vector<RowSpec>& rows,
                          std::vector<std::int64_t>& pivot_of_monomial, std::vector<char>& seen) {
    std::vector<std::uint32_t> work;
    auto note = [&](const RowSpec& row) {
        for (std::uint32_t m : row.monomials) {
            if (m >= seen.size()) {
                seen.resize(table_.size(), 0);
                pivot_of_monomial.resize(table_.size(), -1);
            }
            if (!seen[m]) {
                seen[m] = 1;
                work.push_back(m);
            }
        }
    };
    for (const RowSpec& r : reducers) {
        note(r);
    }
    for (const RowSpec& r : rows) {
        note(r);
    }
    std::vector<std::uint64_t> quotient(words_);
    for (std::size_t next = 0; next < work.size(); ++next) {
        const std::uint32_t m = work[next];
        if (pivot_of_monomial[m] >= 0) {
            continue;
        }
        const std::optional<std::size_t> g = reducer_for(table_.at(m));
        if (!g) {
            continue;
        }
        layout_.divide(table_.at(m), lead(*g), quotient.data());
        RowSpec row = make_row(*g, quotient.data());
        seen.resize(table_.size(), 0);
        pivot_of_monomial.resize(table_.size(), -1);
        pivot_of_monomial[m] = static_cast<std::int64_t>(reducers.size());
        note(row);
        reducers.push_back(std::move(row));
    }
}

// Columns: the seen monomials, descending under the order.
std::vector<std::uint32_t> F4Engine::order_columns(const std::vector<char>& seen,
                                                   std::vector<std::uint32_t>& column_of) const {
    std::vector<std::uint32_t> monomials;
    for (std::uint32_t m = 0; m < seen.size(); ++m) {
        if (seen[m]) {
            monomials.push_back(m);
        }
    }
    std::sort(monomials.begin(), monomials.end(), [&](std::uint32_t a, std::uint32_t b) {
        return layout_.compare(table_.at(a), table_.at(b)) > 0;
    });
    column_of.assign(table_.size(), 0);
    for (std::uint32_t c = 0; c < monomials.size(); ++c) {
        column_of[monomials[c]] = c;
    }
    return monomials;
}

std::vector<std::uint32_t> F4Engine::columns_of(const RowSpec& spec,
                                                const std::vector<std::uint32_t>& column_of) const {
    std::vector<std::uint32_t> columns;
    columns.reserve(spec.monomials.size());
    for (std::uint32_t m : spec.monomials) {
        columns.push_back(column_of[m]);
    }
    return columns;
}

}  // namespace locus::algebra::modular::detail
