#include "algebra/modular/f4.h"

#include <algorithm>
#include <numeric>

#include "algebra/assert.h"
#include "algebra/deadline.h"
#include "algebra/error.h"
#include "algebra/monomial_table.h"

namespace locus::algebra::modular {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

struct Element {
    ModularPolynomial poly;  // monic
    std::uint64_t mask;      // divisibility mask of the leading monomial
    bool redundant = false;  // a later element's leading monomial divides its own
    std::uint32_t sugar = 0;
};

// `degree` is the sugar of the S-polynomial (Giovini et al. 1991): the degree it would have
// if the input were homogenized, measured in the order's first weight row as buchberger.cpp
// does (total degree for grevlex, the eliminated block's degree for elim). Selecting by it rather
// than by the lcm's degree keeps F4 from running off into high degrees under lex and other
// non-graded orders, where the lcm's degree says little about the work.
struct Pair {
    std::size_t first, second;
    std::vector<std::uint64_t> lcm;
    std::uint32_t degree;
};

// A row of the Macaulay matrix: multiplier · basis[element], as table indices of its monomials.
struct RowSpec {
    std::size_t element;
    std::vector<std::uint32_t> monomials;  // table indices, descending
};

// A sparse row over columns, columns ascending (monomials descending).
struct SparseRow {
    std::vector<std::uint32_t> columns;
    std::vector<std::uint32_t> coefficients;
};

class F4Engine {
  public:
    F4Engine(const MonomialLayout& layout, const PrimeField& field, const F4Options& options,
             F4Stats& stats, F4Trace* record = nullptr)
        : record_(record),
          layout_(layout),
          words_(layout.words()),
          field_(field),
          options_(options),
          stats_(stats),
          table_(layout.words()) {
        // Batches of equal sugar pay off for degree orders. Under lex, elimination and other
        // orders whose first row is not positive, a batch runs into high degrees (a case of the
        // Singular oracle overflowed the exponents at 16 082 × 48 228 after 20 s); one pair at a
        // time by least sugar still took 1–19 s per prime on two oracle cases, and one pair at a
        // time by least lcm (Buchberger's normal strategy, which buchberger.cpp also uses for
        // lex) takes milliseconds.
        batch_ = layout.order().is_degree_order();
        // Under elimination and matrix orders least lcm alone does not finish (an elim(x,y)
        // case of the review ran past 60 s; buchberger.cpp found the same): least sugar first.
        by_lcm_only_ = layout.order().kind() == MonomialOrder::Kind::lex;
    }

    std::vector<ModularPolynomial> run(std::span<const ModularPolynomial> generators) {
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

    std::optional<std::vector<ModularPolynomial>> replay(
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

  private:
    ModularPolynomial monic(ModularPolynomial f) const {
        const std::uint64_t inverse = field_.inverse(f.coefficients.front());
        for (std::uint32_t& c : f.coefficients) {
            c = static_cast<std::uint32_t>(field_.multiply(c, inverse));
        }
        return f;
    }

    const std::uint64_t* lead(std::size_t i) const { return basis_[i].poly.monomials.data(); }

    // An element without pairs (a replay repeats the recorded steps instead).
    // In a replay, also notes whether its support is the recorded one.
    void append_element(ModularPolynomial poly) {
        const std::size_t h = basis_.size();
        fits_trace_.push_back(replaying_ != nullptr && h < replaying_->supports.size() &&
                              poly.monomials == replaying_->supports[h]);
        basis_.push_back({std::move(poly), 0, false, 0});
        basis_[h].mask = layout_.divisibility_mask(lead(h));
    }

    // Gebauer–Möller (Becker–Weispfenning's UPDATE) for the element just appended.
    void add_element(ModularPolynomial poly, std::uint32_t sugar) {
        check_deadline();  // each call is quadratic in the basis size
        const std::size_t h = basis_.size();
        if (record_ != nullptr) {
            record_->supports.push_back(poly.monomials);
        }
        basis_.push_back({std::move(poly), 0, false, sugar});
        basis_[h].mask = layout_.divisibility_mask(lead(h));
        std::vector<Pair> fresh;
        for (std::size_t g = 0; g < h; ++g) {
            if (basis_[g].redundant) {
                continue;
            }
            Pair pair{g, h, std::vector<std::uint64_t>(words_), 0};
            layout_.lcm(lead(g), lead(h), pair.lcm.data());
            const std::uint32_t lcm_degree = layout_.leading_weight(pair.lcm.data());
            pair.degree = std::max(basis_[g].sugar + lcm_degree - layout_.leading_weight(lead(g)),
                                   sugar + lcm_degree - layout_.leading_weight(lead(h)));
            fresh.push_back(std::move(pair));
            ++stats_.pairs_created;
        }
        // Chain criterion among the new pairs (M and F): drop (g, h) when another new pair's
        // lcm properly divides its lcm, or equals it and comes first.
        // The comparison is quadratic in the basis size, so a divisibility mask rejects most
        // non-divisors first (with hundreds of variables the word-by-word test dominated).
        std::vector<char> keep(fresh.size(), 1);
        std::vector<std::uint64_t> lcm_mask(fresh.size());
        for (std::size_t a = 0; a < fresh.size(); ++a) {
            lcm_mask[a] = layout_.divisibility_mask(fresh[a].lcm.data());
        }
        for (std::size_t a = 0; a < fresh.size(); ++a) {
            for (std::size_t b = 0; b < fresh.size() && keep[a]; ++b) {
                if (a == b || !keep[b] || (lcm_mask[b] & ~lcm_mask[a]) != 0) {
                    continue;
                }
                if (layout_.divides(fresh[b].lcm.data(), fresh[a].lcm.data()) &&
                    (!layout_.equal(fresh[b].lcm.data(), fresh[a].lcm.data()) || b < a)) {
                    keep[a] = 0;
                    ++stats_.removed_by_chain;
                }
            }
        }
        // Old pairs (B): drop (g1, g2) when lm(h) divides their lcm and both lcm(gi, h) differ.
        std::vector<std::uint64_t> scratch(words_);
        std::erase_if(pairs_, [&](const Pair& pair) {
            if (!layout_.divides(lead(h), pair.lcm.data())) {
                return false;
            }
            layout_.lcm(lead(pair.first), lead(h), scratch.data());
            if (layout_.equal(scratch.data(), pair.lcm.data())) {
                return false;
            }
            layout_.lcm(lead(pair.second), lead(h), scratch.data());
            if (layout_.equal(scratch.data(), pair.lcm.data())) {
                return false;
            }
            ++stats_.removed_by_chain;
            return true;
        });
        // Product criterion on the survivors.
        for (std::size_t a = 0; a < fresh.size(); ++a) {
            if (!keep[a]) {
                continue;
            }
            if (layout_.coprime(lead(fresh[a].first), lead(h))) {
                ++stats_.removed_by_product;
                continue;
            }
            pairs_.push_back(std::move(fresh[a]));
        }
        for (std::size_t g = 0; g < h; ++g) {
            if (!basis_[g].redundant && layout_.divides(lead(h), lead(g))) {
                basis_[g].redundant = true;
            }
        }
    }

    std::uint32_t product_index(const std::uint64_t* a, const std::uint64_t* b) {
        layout_.multiply(a, b, scratch_.data());
        return table_.insert(scratch_.data());
    }

    RowSpec make_row(std::size_t element, const std::uint64_t* multiplier) {
        RowSpec row{element, {}};
        const ModularPolynomial& f = basis_[element].poly;
        row.monomials.reserve(f.size());
        for (std::size_t i = 0; i < f.size(); ++i) {
            row.monomials.push_back(product_index(multiplier, f.monomial(i, words_)));
        }
        return row;
    }

    // A basis element whose leading monomial divides m (non-redundant ones first).
    std::optional<std::size_t> reducer_for(const std::uint64_t* m) const {
        const std::uint64_t mask = layout_.divisibility_mask(m);
        std::optional<std::size_t> redundant;
        for (std::size_t g = 0; g < basis_.size(); ++g) {
            if ((basis_[g].mask & ~mask) != 0 || !layout_.divides(lead(g), m)) {
                continue;
            }
            if (!basis_[g].redundant) {
                return g;
            }
            if (!redundant) {
                redundant = g;
            }
        }
        return redundant;
    }

    void check_deadline() const {
        if (deadline_passed(options_.deadline)) {
            throw Timeout("F4 modulo " + std::to_string(field_.p));
        }
    }

    // Symbolic preprocessing: reducer rows for every monomial of `rows` (and of the reducers
    // themselves) that some leading monomial divides. `pivot_of_monomial` maps table indices to
    // the reducer row with that leading monomial (or −1).
    void preprocess(std::vector<RowSpec>& reducers, std::vector<RowSpec>& rows,
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
    std::vector<std::uint32_t> order_columns(const std::vector<char>& seen,
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

    SparseRow to_sparse(const RowSpec& spec, const std::vector<std::uint32_t>& column_of) const {
        SparseRow row;
        row.columns.reserve(spec.monomials.size());
        for (std::uint32_t m : spec.monomials) {
            row.columns.push_back(column_of[m]);
        }
        row.coefficients = basis_[spec.element].poly.coefficients;
        return row;
    }

    // Reduces `acc` (dense, entries < 2p²) from column `from` on by the pivot rows; returns the
    // reduced row (entries in [1, p)) of the columns without a pivot.
    SparseRow reduce_dense(std::vector<std::uint64_t>& acc, std::size_t from,
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

    void step() {
        check_deadline();
        const auto symbolic_start = Clock::now();
        ++stats_.steps;
        std::uint32_t degree = pairs_.front().degree;
        for (const Pair& pair : pairs_) {
            degree = std::min(degree, pair.degree);
        }
        std::vector<Pair> chosen;
        if (!batch_) {
            std::size_t best = pairs_.size();
            for (std::size_t i = 0; i < pairs_.size(); ++i) {
                const bool better =
                    best == pairs_.size() ||
                    (!by_lcm_only_ && pairs_[i].degree != pairs_[best].degree
                         ? pairs_[i].degree < pairs_[best].degree
                         : layout_.compare(pairs_[i].lcm.data(), pairs_[best].lcm.data()) < 0);
                if (better) {
                    best = i;
                }
            }
            degree = pairs_[best].degree;  // the sugar of what this step makes
            chosen.push_back(std::move(pairs_[best]));
            pairs_.erase(pairs_.begin() + static_cast<long>(best));
        } else {
            std::erase_if(pairs_, [&](Pair& pair) {
                if (pair.degree != degree) {
                    return false;
                }
                chosen.push_back(std::move(pair));
                return true;
            });
        }
        stats_.pairs_reduced += chosen.size();
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
        std::vector<SparseRow> pivots;
        pivots.reserve(reducers.size());
        std::vector<std::int64_t> pivot_of_column(width, -1);
        std::size_t entries = 0;
        for (std::size_t r = 0; r < reducers.size(); ++r) {
            pivots.push_back(to_sparse(reducers[r], column_of));
            pivot_of_column[pivots.back().columns.front()] = static_cast<std::int64_t>(r);
            entries += pivots.back().columns.size();
        }
        const std::size_t total_rows = reducers.size() + rows.size();
        if (total_rows > stats_.largest_rows) {
            stats_.largest_rows = total_rows;
            stats_.largest_columns = width;
            for (const RowSpec& row : rows) {
                entries += row.monomials.size();
            }
            stats_.largest_density =
                static_cast<double>(entries) / (static_cast<double>(total_rows) * width);
        }
        // Reduce the S-halves by the reducers, then echelonize what is left among itself.
        std::vector<std::uint64_t> acc(width, 0);
        std::vector<SparseRow> fresh;
        std::vector<std::size_t> useful;  // rows that gave new elements, in order
        for (std::size_t r = 0; r < rows.size(); ++r) {
            check_deadline();
            std::optional<SparseRow> reduced =
                reduce_row(to_sparse(rows[r], column_of), acc, pivot_of_column, pivots);
            if (!reduced) {
                ++stats_.zero_rows;
                continue;
            }
            useful.push_back(r);
            fresh.push_back(std::move(*reduced));
        }
        stats_.linear_algebra_seconds += seconds_since(algebra_start);
        std::vector<std::uint64_t> column_monomials;
        column_monomials.reserve(columns.size() * words_);
        for (std::uint32_t m : columns) {
            column_monomials.insert(column_monomials.end(), table_.at(m), table_.at(m) + words_);
        }
        if (record_ != nullptr) {
            record_step(reducers, rows, useful, fresh, pivot_of_monomial, column_of,
                        column_monomials);
        }
        for (ModularPolynomial& poly : new_elements(fresh, column_monomials)) {
            add_element(std::move(poly), degree);
        }
    }

    // Reduces `row` by the pivots (using the zeroed dense accumulator `acc`); a non-zero result
    // is made monic and becomes the pivot of its leading column. Nothing when it reduces to 0.
    std::optional<SparseRow> reduce_row(const SparseRow& row, std::vector<std::uint64_t>& acc,
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
    std::vector<ModularPolynomial> new_elements(
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

    // Keeps the useful rows of a step and the reducers they reach (through the monomials of
    // the rows and, transitively, of those reducers), with their columns renumbered over the
    // columns these rows use; the other rows only served S-halves that reduced to zero.
    void record_step(const std::vector<RowSpec>& reducers, const std::vector<RowSpec>& rows,
                     const std::vector<std::size_t>& useful, const std::vector<SparseRow>& fresh,
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
    bool replay_step(const F4Trace::Step& step) {
        check_deadline();
        ++stats_.steps;
        const auto algebra_start = Clock::now();
        auto row_of = [&](const F4Trace::Row& r) -> std::optional<SparseRow> {
            if (r.element >= basis_.size() || !fits_trace_[r.element]) {
                return std::nullopt;
            }
            return SparseRow{r.columns, basis_[r.element].poly.coefficients};
        };
        const std::size_t width = step.column_monomials.size() / words_;
        std::vector<SparseRow> pivots;
        pivots.reserve(step.reducers.size() + step.rows.size());
        std::vector<std::int64_t> pivot_of_column(width, -1);
        for (const F4Trace::Row& r : step.reducers) {
            std::optional<SparseRow> row = row_of(r);
            if (!row) {
                return false;
            }
            pivot_of_column[row->columns.front()] = static_cast<std::int64_t>(pivots.size());
            pivots.push_back(std::move(*row));
        }
        std::vector<std::uint64_t> acc(width, 0);
        std::vector<SparseRow> fresh;
        for (std::size_t k = 0; k < step.rows.size(); ++k) {
            check_deadline();
            std::optional<SparseRow> row = row_of(step.rows[k]);
            if (!row) {
                return false;
            }
            std::optional<SparseRow> reduced = reduce_row(*row, acc, pivot_of_column, pivots);
            if (!reduced || reduced->columns.front() != step.leading[k]) {
                stats_.linear_algebra_seconds += seconds_since(algebra_start);
                return false;
            }
            fresh.push_back(std::move(*reduced));
        }
        stats_.pairs_reduced += step.rows.size();
        stats_.linear_algebra_seconds += seconds_since(algebra_start);
        for (ModularPolynomial& poly : new_elements(fresh, step.column_monomials)) {
            append_element(std::move(poly));
        }
        return true;
    }

    // The monic reduced basis: a minimal set of leading monomials, every tail reduced by one
    // more Macaulay matrix. A replay takes that matrix from the trace: its leading monomials
    // and supports are the recorded ones, so the symbolic preprocessing would be too.
    std::vector<ModularPolynomial> reduced_basis() {
        std::vector<std::uint32_t> minimal;
        std::vector<SparseRow> pivots;
        std::vector<std::uint64_t> column_monomials;
        if (replaying_ != nullptr && !replaying_->final_elements.empty()) {
            const F4Trace::Step& final_step = replaying_->final_step;
            minimal = replaying_->final_elements;
            for (const F4Trace::Row& r : final_step.reducers) {
                pivots.push_back(SparseRow{r.columns, basis_[r.element].poly.coefficients});
            }
            column_monomials = final_step.column_monomials;
        } else {
            for (std::size_t g = 0; g < basis_.size(); ++g) {
                bool divisible = false;
                for (std::size_t h = 0; h < basis_.size() && !divisible; ++h) {
                    if (h == g || !layout_.divides(lead(h), lead(g))) {
                        continue;
                    }
                    // Equal leading monomials: keep the first.
                    divisible = !layout_.equal(lead(h), lead(g)) || h < g;
                }
                if (!divisible) {
                    minimal.push_back(static_cast<std::uint32_t>(g));
                }
            }
            for (Element& e : basis_) {
                e.redundant = true;
            }
            for (std::size_t g : minimal) {
                basis_[g].redundant = false;
            }
            std::vector<RowSpec> reducers, rows;
            std::vector<std::int64_t> pivot_of_monomial(table_.size(), -1);
            std::vector<char> seen(table_.size(), 0);
            std::vector<std::uint64_t> one(words_, 0);
            for (std::size_t g : minimal) {
                RowSpec row = make_row(g, one.data());
                pivot_of_monomial.resize(table_.size(), -1);
                pivot_of_monomial[row.monomials.front()] =
                    static_cast<std::int64_t>(reducers.size());
                reducers.push_back(std::move(row));
            }
            seen.resize(table_.size(), 0);
            preprocess(reducers, rows, pivot_of_monomial, seen);
            std::vector<std::uint32_t> column_of;
            const std::vector<std::uint32_t> columns = order_columns(seen, column_of);
            for (const std::uint32_t m : columns) {
                column_monomials.insert(column_monomials.end(), table_.at(m),
                                        table_.at(m) + words_);
            }
            for (const RowSpec& reducer : reducers) {
                pivots.push_back(to_sparse(reducer, column_of));
            }
            if (record_ != nullptr) {
                record_->final_elements = minimal;
                record_->final_step = {};
                for (std::size_t r = 0; r < reducers.size(); ++r) {
                    record_->final_step.reducers.push_back(
                        {static_cast<std::uint32_t>(reducers[r].element), pivots[r].columns});
                }
                record_->final_step.column_monomials = column_monomials;
            }
        }
        std::vector<std::int64_t> pivot_of_column(column_monomials.size() / words_, -1);
        for (std::size_t r = 0; r < pivots.size(); ++r) {
            pivot_of_column[pivots[r].columns.front()] = static_cast<std::int64_t>(r);
        }
        std::vector<std::uint64_t> acc(pivot_of_column.size(), 0);
        std::vector<ModularPolynomial> out;
        for (std::size_t k = 0; k < minimal.size(); ++k) {
            check_deadline();
            const SparseRow& row = pivots[k];
            for (std::size_t i = 1; i < row.columns.size(); ++i) {
                acc[row.columns[i]] = row.coefficients[i];
            }
            const SparseRow tail = row.columns.size() > 1
                                       ? reduce_dense(acc, row.columns[1], pivot_of_column, pivots)
                                       : SparseRow{};
            ModularPolynomial poly;
            poly.coefficients.push_back(1);
            const std::uint64_t* leading = column_monomials.data() + row.columns.front() * words_;
            poly.monomials.assign(leading, leading + words_);
            for (std::size_t i = 0; i < tail.columns.size(); ++i) {
                poly.coefficients.push_back(tail.coefficients[i]);
                const std::uint64_t* m = column_monomials.data() + tail.columns[i] * words_;
                poly.monomials.insert(poly.monomials.end(), m, m + words_);
            }
            out.push_back(std::move(poly));
        }
        std::sort(out.begin(), out.end(),
                  [&](const ModularPolynomial& a, const ModularPolynomial& b) {
                      return layout_.compare(a.monomials.data(), b.monomials.data()) < 0;
                  });
        LOCUS_ASSERT(ascending_and_minimal(
            out.size(), [&](std::size_t i) { return out[i].monomials.data(); }, layout_));
        return out;
    }

    F4Trace* record_;
    const F4Trace* replaying_ = nullptr;
    std::vector<char> fits_trace_;  // per element, in a replay: its support is the recorded one
    const MonomialLayout& layout_;
    std::size_t words_;
    PrimeField field_;
    const F4Options& options_;
    F4Stats& stats_;
    MonomialTable table_;
    std::vector<Element> basis_;
    std::vector<Pair> pairs_;
    std::vector<std::uint64_t> scratch_ = std::vector<std::uint64_t>(words_);
    bool batch_ = true;
    bool by_lcm_only_ = false;
};

}  // namespace

std::vector<ModularPolynomial> f4(std::span<const ModularPolynomial> generators,
                                  const MonomialLayout& layout, const PrimeField& field,
                                  const F4Options& options, F4Stats* stats, F4Trace* record) {
    F4Stats local;
    if (record != nullptr) {
        *record = F4Trace{};
    }
    F4Engine engine(layout, field, options, stats != nullptr ? *stats : local, record);
    return engine.run(generators);
}

std::optional<std::vector<ModularPolynomial>> f4_replay(
    const F4Trace& trace, std::span<const ModularPolynomial> generators,
    const MonomialLayout& layout, const PrimeField& field, const F4Options& options,
    F4Stats* stats) {
    F4Stats local;
    F4Engine engine(layout, field, options, stats != nullptr ? *stats : local);
    return engine.replay(trace, generators);
}

}  // namespace locus::algebra::modular
