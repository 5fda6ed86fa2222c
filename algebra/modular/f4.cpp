#include "algebra/modular/f4.h"

#include <algorithm>
#include <numeric>

#include "algebra/assert.h"
#include "algebra/modular/detail/f4_engine.h"

namespace locus::algebra::modular {
namespace detail {

std::vector<ModularPolynomial> F4Engine::run(std::span<const ModularPolynomial> generators) {
    for (const ModularPolynomial& g : generators) {
        if (!g.is_zero()) {
            std::uint32_t degree = 0;
            for (std::size_t i = 0; i < g.size(); ++i) {
                degree = std::max(degree, layout_.leading_weight(g.monomial(i, words_)));
            }
            if (record_ != nullptr) {
                ++record_->generators;
            }
            add_element(monic(g), degree);
        }
    }
    while (!pairs_.empty()) {
        step();
    }
    return reduced_basis();
}

std::optional<std::vector<ModularPolynomial>> F4Engine::replay(
    const F4Trace& trace, std::span<const ModularPolynomial> generators) {
    replaying_ = &trace;
    for (const ModularPolynomial& g : generators) {
        if (!g.is_zero()) {
            append_element(monic(g));
        }
    }
    if (basis_.size() != trace.generators) {
        return std::nullopt;
    }
    for (const F4Trace::Step& step : trace.steps) {
        if (!replay_step(step)) {
            return std::nullopt;
        }
    }
    // The recorded last matrix holds only for the recorded supports.
    if (!trace.final_elements.empty() &&
        std::find(fits_trace_.begin(), fits_trace_.end(), 0) != fits_trace_.end()) {
        return std::nullopt;
    }
    return reduced_basis();
}

void F4Engine::step() {
    check_deadline();
    const auto symbolic_start = Clock::now();
    ++stats_.steps;
    // The monomials of this step alone: the table stays the size of one matrix's columns (a
    // few hundred kilobytes, in the caches) instead of every monomial of the run, and so do
    // the arrays indexed by it below. Nothing keeps a table index past its step: elements
    // keep their monomials and the hashes of their terms.
    table_.clear();
    std::uint32_t degree = 0;
    const std::vector<Pair> chosen = select_pairs(degree);
    // Both halves of every S-polynomial; a half that repeats is kept once, and the first
    // half with a given leading monomial serves as that column's pivot.
    std::vector<RowSpec> reducers, rows;
    std::vector<std::int64_t> pivot_of_monomial(table_.size(), -1);
    std::vector<char> seen(table_.size(), 0);
    std::vector<std::uint64_t> quotient(words_);
    std::vector<std::pair<std::size_t, std::uint32_t>> made;  // (element, multiplier index)
    for (const Pair& pair : chosen) {
        for (const std::size_t g : {pair.first, pair.second}) {
            layout_.divide(pair.lcm.data(), lead(g), quotient.data());
            const std::uint32_t multiplier = table_.insert(quotient.data());
            if (std::find(made.begin(), made.end(), std::pair{g, multiplier}) != made.end()) {
                continue;
            }
            made.emplace_back(g, multiplier);
            RowSpec row = make_row(g, quotient.data());
            const std::uint32_t leading = row.monomials.front();
            pivot_of_monomial.resize(table_.size(), -1);
            if (pivot_of_monomial[leading] < 0) {
                pivot_of_monomial[leading] = static_cast<std::int64_t>(reducers.size());
                reducers.push_back(std::move(row));
            } else {
                rows.push_back(std::move(row));
            }
        }
    }
    seen.resize(table_.size(), 0);
    preprocess(reducers, rows, pivot_of_monomial, seen);
    std::vector<std::uint32_t> column_of;
    const std::vector<std::uint32_t> columns = order_columns(seen, column_of);
    stats_.symbolic_seconds += seconds_since(symbolic_start);

    const auto algebra_start = Clock::now();
    const std::size_t width = columns.size();
    const std::size_t total_rows = reducers.size() + rows.size();
    if (total_rows > stats_.largest_rows) {
        stats_.largest_rows = total_rows;
        stats_.largest_columns = width;
        std::size_t entries = 0;
        for (const std::vector<RowSpec>* part : {&reducers, &rows}) {
            for (const RowSpec& row : *part) {
                entries += row.monomials.size();
            }
        }
        stats_.largest_density =
            static_cast<double>(entries) / (static_cast<double>(total_rows) * width);
    }
    // Reduce the S-halves by the reducers, then echelonize what is left among itself.
    std::vector<SparseRow> fresh;
    fresh.reserve(rows.size());
    std::vector<std::size_t> useful;  // rows that gave new elements, in order
    reduce_rows(reducers, rows, column_of, width, fresh, useful);
    stats_.linear_algebra_seconds += seconds_since(algebra_start);
    std::vector<std::uint64_t> column_monomials;
    column_monomials.reserve(columns.size() * words_);
    for (std::uint32_t m : columns) {
        column_monomials.insert(column_monomials.end(), table_.at(m), table_.at(m) + words_);
    }
    if (record_ != nullptr) {
        record_step(reducers, rows, useful, fresh, pivot_of_monomial, column_of, column_monomials);
    }
    for (ModularPolynomial& poly : new_elements(fresh, column_monomials)) {
        add_element(std::move(poly), degree);
    }
    // Under lex one pair a step: the scan of every pair each step would cost more than the
    // memory it gives back.
    if (batch_) {
        release_finished();
    }
    if (options_.progress) {
        options_.progress(stats_.steps, basis_.size());
    }
}

// The monic reduced basis: a minimal set of leading monomials, every tail reduced by one
// more Macaulay matrix. A replay takes that matrix from the trace: its leading monomials
// and supports are the recorded ones, so the symbolic preprocessing would be too.
std::vector<ModularPolynomial> F4Engine::reduced_basis() {
    std::vector<std::uint32_t> minimal;
    std::vector<PivotRow> rows;  // the matrix's pivots: the minimal elements first
    std::vector<std::vector<std::uint32_t>> reducer_columns;
    std::vector<std::uint64_t> column_monomials;
    if (replaying_ != nullptr && !replaying_->final_elements.empty()) {
        const F4Trace::Step& final_step = replaying_->final_step;
        minimal = replaying_->final_elements;
        for (const F4Trace::Row& r : final_step.reducers) {
            rows.push_back(row_view(r));
        }
        column_monomials = final_step.column_monomials;
    } else {
        for (std::size_t g = 0; g < basis_.size(); ++g) {
            bool divisible = false;
            for (std::size_t h = 0; h < basis_.size() && !divisible; ++h) {
                if (h == g || !layout_.divides(lead(h), lead(g))) {
                    continue;
                }
                // Equal leading monomials (generators only: F4's new elements have leading
                // monomials no earlier one divides): keep the last, the one add_element left
                // non-redundant (the earlier ones may be released).
                divisible = !layout_.equal(lead(h), lead(g)) || h > g;
            }
            if (!divisible) {
                minimal.push_back(static_cast<std::uint32_t>(g));
            }
        }
        for (Element& e : basis_) {
            e.redundant = true;
        }
        live_.clear();
        for (std::size_t g : minimal) {
            basis_[g].redundant = false;
            live_.add(g, basis_[g].mask, lead(g), words_);
        }
        std::vector<RowSpec> reducers, none;
        table_.clear();
        std::vector<std::int64_t> pivot_of_monomial(table_.size(), -1);
        std::vector<char> seen(table_.size(), 0);
        std::vector<std::uint64_t> one(words_, 0);
        for (std::size_t g : minimal) {
            RowSpec row = make_row(g, one.data());
            pivot_of_monomial.resize(table_.size(), -1);
            pivot_of_monomial[row.monomials.front()] = static_cast<std::int64_t>(reducers.size());
            reducers.push_back(std::move(row));
        }
        seen.resize(table_.size(), 0);
        preprocess(reducers, none, pivot_of_monomial, seen);
        std::vector<std::uint32_t> column_of;
        const std::vector<std::uint32_t> columns = order_columns(seen, column_of);
        for (const std::uint32_t m : columns) {
            column_monomials.insert(column_monomials.end(), table_.at(m), table_.at(m) + words_);
        }
        reducer_columns.reserve(reducers.size());
        for (const RowSpec& reducer : reducers) {
            reducer_columns.push_back(columns_of(reducer, column_of));
            rows.push_back(row_view(reducer, reducer_columns.back()));
        }
        if (record_ != nullptr) {
            record_->final_elements = minimal;
            record_->final_step = {};
            for (std::size_t r = 0; r < reducers.size(); ++r) {
                record_->final_step.reducers.push_back(
                    {static_cast<std::uint32_t>(reducers[r].element), reducer_columns[r]});
            }
            record_->final_step.column_monomials = column_monomials;
        }
    }
    Pivots pivots(column_monomials.size() / words_);
    for (const PivotRow& row : rows) {
        pivots.add(row);
    }
    std::vector<std::uint64_t> acc(pivots.of_column.size(), 0);
    std::vector<ModularPolynomial> out;
    for (std::size_t k = 0; k < minimal.size(); ++k) {
        check_deadline();
        const PivotRow& row = pivots.rows[k];
        for (std::size_t i = 1; i < row.size; ++i) {
            acc[row.columns[i]] = row.coefficients[i];
        }
        const SparseRow tail =
            row.size > 1 ? reduce_dense(acc, row.columns[1], pivots, rows.size()) : SparseRow{};
        ModularPolynomial poly;
        poly.coefficients.push_back(1);
        const std::uint64_t* leading = column_monomials.data() + row.columns[0] * words_;
        poly.monomials.assign(leading, leading + words_);
        for (std::size_t i = 0; i < tail.columns.size(); ++i) {
            poly.coefficients.push_back(tail.coefficients[i]);
            const std::uint64_t* m = column_monomials.data() + tail.columns[i] * words_;
            poly.monomials.insert(poly.monomials.end(), m, m + words_);
        }
        out.push_back(std::move(poly));
    }
    std::sort(out.begin(), out.end(), [&](const ModularPolynomial& a, const ModularPolynomial& b) {
        return layout_.compare(a.monomials.data(), b.monomials.data()) < 0;
    });
    LOCUS_ASSERT(ascending_and_minimal(
        out.size(), [&](std::size_t i) { return out[i].monomials.data(); }, layout_));
    return out;
}

}  // namespace detail

std::vector<ModularPolynomial> f4(std::span<const ModularPolynomial> generators,
                                  const MonomialLayout& layout, const PrimeField& field,
                                  const F4Options& options, F4Stats* stats, F4Trace* record) {
    F4Stats local;
    if (record != nullptr) {
        *record = F4Trace{};
    }
    detail::F4Engine engine(layout, field, options, stats != nullptr ? *stats : local, record);
    return engine.run(generators);
}

std::optional<std::vector<ModularPolynomial>> f4_replay(
    const F4Trace& trace, std::span<const ModularPolynomial> generators,
    const MonomialLayout& layout, const PrimeField& field, const F4Options& options,
    F4Stats* stats) {
    F4Stats local;
    detail::F4Engine engine(layout, field, options, stats != nullptr ? *stats : local);
    return engine.replay(trace, generators);
}

}  // namespace locus::algebra::modular
