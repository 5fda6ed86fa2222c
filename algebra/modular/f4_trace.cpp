// F4's trace: the useful rows of each step recorded, and a step repeated modulo another prime
// on the recorded matrix (Traverso's tracing).
#include "algebra/modular/detail/f4_engine.h"

namespace locus::algebra::modular::detail {

// Keeps the useful rows of a step and the reducers they reach (through the monomials of
// the rows and, transitively, of those reducers), with their columns renumbered over the
// columns these rows use; the other rows only served S-halves that reduced to zero.
void F4Engine::record_step(const std::vector<RowSpec>& reducers, const std::vector<RowSpec>& rows,
                           const std::vector<std::size_t>& useful,
                           const std::vector<SparseRow>& fresh,
                           const std::vector<std::int64_t>& pivot_of_monomial,
                           const std::vector<std::uint32_t>& column_of,
                           const std::vector<std::uint64_t>& column_monomials) {
    std::vector<char> needed(reducers.size(), 0);
    std::vector<std::size_t> pending;
    std::vector<char> used(column_monomials.size() / words_, 0);
    auto reach = [&](const RowSpec& row) {
        for (std::uint32_t m : row.monomials) {
            used[column_of[m]] = 1;
            const std::int64_t pivot = pivot_of_monomial[m];
            if (pivot >= 0 && !needed[static_cast<std::size_t>(pivot)]) {
                needed[static_cast<std::size_t>(pivot)] = 1;
                pending.push_back(static_cast<std::size_t>(pivot));
            }
        }
    };
    for (std::size_t r : useful) {
        reach(rows[r]);
    }
    while (!pending.empty()) {
        const std::size_t r = pending.back();
        pending.pop_back();
        reach(reducers[r]);
    }
    F4Trace::Step step;
    std::vector<std::uint32_t> renumbered(used.size(), 0);
    for (std::size_t c = 0; c < used.size(); ++c) {
        if (used[c]) {
            renumbered[c] = static_cast<std::uint32_t>(step.column_monomials.size() / words_);
            step.column_monomials.insert(step.column_monomials.end(),
                                         column_monomials.begin() + c * words_,
                                         column_monomials.begin() + (c + 1) * words_);
        }
    }
    auto recorded = [&](const RowSpec& row) {
        F4Trace::Row out{static_cast<std::uint32_t>(row.element), {}};
        out.columns.reserve(row.monomials.size());
        for (std::uint32_t m : row.monomials) {
            out.columns.push_back(renumbered[column_of[m]]);
        }
        return out;
    };
    for (std::size_t r = 0; r < reducers.size(); ++r) {
        if (needed[r]) {
            step.reducers.push_back(recorded(reducers[r]));
        }
    }
    for (std::size_t k = 0; k < useful.size(); ++k) {
        step.rows.push_back(recorded(rows[useful[k]]));
        step.leading.push_back(renumbered[fresh[k].columns.front()]);
    }
    record_->steps.push_back(std::move(step));
}

// One recorded step modulo this prime, on the recorded matrix; false when it does not
// go as recorded (an element's support differs, or a row reduces to another column).
bool F4Engine::replay_step(const F4Trace::Step& step) {
    check_deadline();
    ++stats_.steps;
    const auto algebra_start = Clock::now();
    auto row_of = [&](const F4Trace::Row& r) -> std::optional<PivotRow> {
        if (r.element >= basis_.size() || !fits_trace_[r.element]) {
            return std::nullopt;
        }
        return row_view(r);
    };
    const std::size_t width = step.column_monomials.size() / words_;
    const std::size_t total_rows = step.reducers.size() + step.rows.size();
    Pivots pivots(width);
    pivots.rows.reserve(total_rows);
    for (const F4Trace::Row& r : step.reducers) {
        std::optional<PivotRow> row = row_of(r);
        if (!row) {
            return false;
        }
        pivots.add(*row);
    }
    std::vector<std::uint64_t> acc(width, 0);
    std::vector<SparseRow> fresh;
    fresh.reserve(step.rows.size());
    for (std::size_t k = 0; k < step.rows.size(); ++k) {
        check_deadline();
        std::optional<PivotRow> row = row_of(step.rows[k]);
        if (!row) {
            return false;
        }
        std::optional<SparseRow> reduced = reduce_row(*row, acc, pivots, total_rows);
        if (!reduced || reduced->columns.front() != step.leading[k]) {
            stats_.linear_algebra_seconds += seconds_since(algebra_start);
            return false;
        }
        fresh.push_back(std::move(*reduced));
        pivots.add(view_of(fresh.back()));
    }
    stats_.pairs_reduced += step.rows.size();
    stats_.linear_algebra_seconds += seconds_since(algebra_start);
    for (ModularPolynomial& poly : new_elements(fresh, step.column_monomials)) {
        append_element(std::move(poly));
    }
    return true;
}

}  // namespace locus::algebra::modular::detail
