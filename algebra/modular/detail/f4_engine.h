// The F4 engine modulo one prime (f4.h), shared by the files that implement its phases, as
// msolve divides them: f4.cpp drives the steps and the final reduction, f4_pairs.cpp the pair
// update (Gebauer–Möller) and selection, f4_symbolic.cpp the symbolic preprocessing (reducer
// rows, columns), f4_linear_algebra.cpp the row reduction, f4_trace.cpp the trace record and
// replay. Internal to algebra/modular/.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "algebra/deadline.h"
#include "algebra/error.h"
#include "algebra/modular/detail/large_page_buffer.h"
#include "algebra/modular/f4.h"
#include "algebra/monomial_table.h"

namespace locus::algebra::modular::detail {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

struct Element {
    ModularPolynomial poly;  // monic
    std::uint64_t mask;      // divisibility mask of the leading monomial
    bool redundant = false;  // a later element's leading monomial divides its own
    // Redundant and in no pending pair: only its leading monomial is kept (release_finished).
    bool released = false;
    std::uint32_t sugar = 0;
    // The monomial table's hashes of its terms, filled when it is first multiplied (make_row):
    // a product's hash is the multiplier's plus the term's.
    std::vector<std::uint64_t> term_hashes;
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

// A pivot of the linear algebra, monic: a view of columns and coefficients held elsewhere. A
// reducer row is a multiple of a basis element, so its coefficients are the element's own,
// shared by every multiple of it in the matrix (as in msolve) instead of copied per row.
struct PivotRow {
    const std::uint32_t* columns;
    const std::uint32_t* coefficients;
    std::size_t size;
};

inline PivotRow view_of(const SparseRow& row) {
    return {row.columns.data(), row.coefficients.data(), row.columns.size()};
}

// The pivots of one matrix, indexed by column.
struct Pivots {
    explicit Pivots(std::size_t width) : of_column(width, -1) {}
    void add(PivotRow row) {
        of_column[row.columns[0]] = static_cast<std::int64_t>(rows.size());
        rows.push_back(row);
    }
    std::vector<PivotRow> rows;
    std::vector<std::int64_t> of_column;  // row index, or −1
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

    std::vector<ModularPolynomial> run(std::span<const ModularPolynomial> generators);

    std::optional<std::vector<ModularPolynomial>> replay(
        const F4Trace& trace, std::span<const ModularPolynomial> generators);

  private:
    ModularPolynomial monic(ModularPolynomial f) const {
        const std::uint64_t inverse = field_.inverse(f.coefficients.front());
        for (std::uint32_t& c : f.coefficients) {
            c = static_cast<std::uint32_t>(field_.multiply(c, inverse));
        }
        return f;
    }

    const std::uint64_t* lead(std::size_t i) const { return basis_[i].poly.monomials.data(); }

    void check_deadline() const {
        if (deadline_passed(options_.deadline)) {
            throw Timeout("F4 modulo " + std::to_string(field_.p));
        }
    }

    // Pair update and selection (f4_pairs.cpp).
    // An element without pairs (a replay repeats the recorded steps instead).
    // In a replay, also notes whether its support is the recorded one.
    void append_element(ModularPolynomial poly);
    // Gebauer–Möller (Becker–Weispfenning's UPDATE) for the element just appended.
    void add_element(ModularPolynomial poly, std::uint32_t sugar);
    std::vector<Pair> select_pairs(std::uint32_t& degree);
    // Frees the terms of the redundant elements that no pending pair needs, keeping their
    // leading monomials (the final reduction compares them): such an element is never multiplied
    // again, a reducer being looked for among the others first and always found there. Called
    // by step(), which a replay does not run (its recorded rows name elements by index).
    void release_finished();

    // Symbolic preprocessing (f4_symbolic.cpp).
    RowSpec make_row(std::size_t element, const std::uint64_t* multiplier);
    // The first non-redundant basis element whose leading monomial divides m. (A redundant one
    // never need be looked at: the element that made it redundant, or the one that made that
    // one redundant, and so on, divides m too and is not.)
    std::optional<std::size_t> reducer_for(const std::uint64_t* m) const;
    // Symbolic preprocessing: reducer rows for every monomial of `rows` (and of the reducers
    // themselves) that some leading monomial divides. `pivot_of_monomial` maps table indices to
    // the reducer row with that leading monomial (or −1).
    void preprocess(std::vector<RowSpec>& reducers, std::vector<RowSpec>& rows,
                    std::vector<std::int64_t>& pivot_of_monomial, std::vector<char>& seen);
    // Columns: the seen monomials, descending under the order.
    std::vector<std::uint32_t> order_columns(const std::vector<char>& seen,
                                             std::vector<std::uint32_t>& column_of) const;
    // The columns of a row; its coefficients are its element's.
    std::vector<std::uint32_t> columns_of(const RowSpec& spec,
                                          const std::vector<std::uint32_t>& column_of) const;
    PivotRow row_view(const RowSpec& spec, const std::vector<std::uint32_t>& columns) const {
        return {columns.data(), basis_[spec.element].poly.coefficients.data(), columns.size()};
    }
    // A recorded row (a replay): its element's coefficients on the recorded columns.
    // Precondition: the element exists.
    PivotRow row_view(const F4Trace::Row& row) const {
        return {row.columns.data(), basis_[row.element].poly.coefficients.data(),
                row.columns.size()};
    }

    // Linear algebra (f4_linear_algebra.cpp).
    // Reduces `acc` (dense) from column `from` on by the pivots; returns the reduced row
    // (entries in [1, p)) of the columns without a pivot, and leaves `acc` zero. `rows` bounds
    // the number of rows of the matrix (see lazy_reduction).
    SparseRow reduce_dense(std::vector<std::uint64_t>& acc, std::size_t from, const Pivots& pivots,
                           std::size_t rows) const;
    // Loads `row` into the zeroed dense accumulator `acc` and reduces it by the pivots (the
    // result not made monic; empty when it reduces to 0).
    SparseRow reduce_loaded_row(PivotRow row, std::vector<std::uint64_t>& acc, const Pivots& pivots,
                                std::size_t rows) const;
    // Reduces `row` (a view; using the zeroed dense accumulator `acc`) by the pivots; a
    // non-zero result is made monic. Nothing when it reduces to 0.
    std::optional<SparseRow> reduce_row(PivotRow row, std::vector<std::uint64_t>& acc,
                                        const Pivots& pivots, std::size_t rows) const;
    // A step's S-halves reduced in order, each by the reducers (one per pivot column) and by
    // the rows before it that did not reduce to zero (`fresh`, monic; `useful` their indices
    // in `rows`). The reducers are first split by column (f4_linear_algebra.cpp): a row is
    // reduced by them over the columns that lead a reducer, its remainder gathered in the
    // others, and that remainder is then reduced by the new rows. With several threads the
    // first part runs side by side — most of the work: three rows in four reduce to zero —,
    // the second in order: the same rows result, a row's reduction by a set of pivots with
    // distinct leading columns being unique.
    void reduce_rows(const std::vector<RowSpec>& reducers, const std::vector<RowSpec>& rows,
                     const std::vector<std::uint32_t>& column_of, std::size_t width,
                     std::vector<SparseRow>& fresh, std::vector<std::size_t>& useful);
    void make_monic(SparseRow& row) const;
    // The reduced rows as polynomials, smallest leading monomial first (the order in which
    // they join the basis, which a replay repeats).
    std::vector<ModularPolynomial> new_elements(
        std::vector<SparseRow>& fresh, const std::vector<std::uint64_t>& column_monomials) const;

    // Trace record and replay (f4_trace.cpp).
    // Keeps the useful rows of a step and the reducers they reach (through the monomials of
    // the rows and, transitively, of those reducers), with their columns renumbered over the
    // columns these rows use; the other rows only served S-halves that reduced to zero.
    void record_step(const std::vector<RowSpec>& reducers, const std::vector<RowSpec>& rows,
                     const std::vector<std::size_t>& useful, const std::vector<SparseRow>& fresh,
                     const std::vector<std::int64_t>& pivot_of_monomial,
                     const std::vector<std::uint32_t>& column_of,
                     const std::vector<std::uint64_t>& column_monomials);
    // One recorded step modulo this prime, on the recorded matrix; false when it does not
    // go as recorded (an element's support differs, or a row reduces to another column).
    bool replay_step(const F4Trace::Step& step);

    // The driver (f4.cpp).
    void step();
    // The monic reduced basis: a minimal set of leading monomials, every tail reduced by one
    // more Macaulay matrix. A replay takes that matrix from the trace: its leading monomials
    // and supports are the recorded ones, so the symbolic preprocessing would be too.
    std::vector<ModularPolynomial> reduced_basis();

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
    // The non-redundant elements, ascending, with their masks and leading monomials side by
    // side: the searches for a reducer (one for every column of every step) and for new pairs
    // read these few kilobytes instead of every element (cyclic-8 modulo 65 521: 372 of 1 780).
    struct LiveElements {
        std::vector<std::uint32_t> index;
        std::vector<std::uint64_t> mask;
        std::vector<std::uint64_t> lead;  // words_ a element
        void add(std::size_t element, std::uint64_t element_mask, const std::uint64_t* monomial,
                 std::size_t words) {
            index.push_back(static_cast<std::uint32_t>(element));
            mask.push_back(element_mask);
            lead.insert(lead.end(), monomial, monomial + words);
        }
        void clear() {
            index.clear();
            mask.clear();
            lead.clear();
        }
        // Drops the elements e with leaves(e), keeping the others in order.
        template <typename Leaves>
        void erase_if(Leaves leaves, std::size_t words) {
            std::size_t kept = 0;
            for (std::size_t k = 0; k < index.size(); ++k) {
                if (leaves(index[k])) {
                    continue;
                }
                index[kept] = index[k];
                mask[kept] = mask[k];
                std::copy_n(lead.data() + k * words, words, lead.data() + kept * words);
                ++kept;
            }
            index.resize(kept);
            mask.resize(kept);
            lead.resize(kept * words);
        }
    };
    LiveElements live_;
    std::vector<Pair> pairs_;
    std::vector<std::uint64_t> scratch_ = std::vector<std::uint64_t>(words_);
    LargePageBuffer<std::uint32_t> split_storage_;  // a step's reducers, split (reduce_rows)
    bool batch_ = true;
    bool by_lcm_only_ = false;
};

}  // namespace locus::algebra::modular::detail
