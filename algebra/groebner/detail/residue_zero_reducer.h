// Internal to the Gröbner code: decides whether integer polynomials reduce to zero by a basis
// that does not change, for the certification of multi-modular results (verify.h, through
// zero_reducer.h), on residues of the integers.
//
// The steps are Reducer's (reduction.h): fraction-free, a·p − b·m·g with a = L/g, b = c/g for
// c the leading coefficient of p, L that of the reducer g_k and g = gcd(c, L); the same reducer
// for each term (ReducerSearch); only the leading terms are reduced, so the first term no
// element reduces ends the work (not zero). The steps are those of that computation (the same
// reducer on the same column, the same zero tests: the tests check it against ExactZeroReducer);
// the integers differ from it only by contents, divided out at other times. What differs is
// how they are held.
//
// - Every monomial met gets a column number (MonomialTable), once per certification; a
//   column's reducer and the columns of the multiple m·g that cancels it are found once and
//   kept (F4's symbolic preprocessing, done lazily).
// - A column's integer V is held as residues modulo K primes below 2^31 (residue_lanes.h), up
//   to a common factor Λ: the residues are those of V/Λ, which is p's coefficient in the
//   rational reduction by monic reducers, s ← s − (s_lc/L)·c·m. A step is then one vector
//   multiply-add per term of the reducer (no carries, no signs, no scaling of the other
//   columns: multiplying p by a only multiplies Λ), 4–6 ns a term on 24–32 lanes with AVX-512.
// - What keeps it exact: every column carries a rigorous bound on |V| (log_bound.h), raised by
//   each addition and by each a; V is determined by its residues while the bound stays below
//   capacity (M/4), and zero exactly when every residue is. gcd(c, L), which the bounds need,
//   comes from c mod L, computed from the residues (residue_system.h). When a bound would pass
//   the capacity, the pending columns are rebuilt in full, their content divided out (as
//   Reducer does every time the coefficients double) and their bounds made exact; if that is
//   not enough, the reduction starts again on more lanes.
// Why: on katsura-10 the certification makes 2.6 million steps over reducers of about 125
// terms, on integers of 300–800 bits. Held as GMP integers (fraction-free, with carries, signs
// and a multiplication of every other column whenever a ≠ 1) a term cost about 25 ns.
#pragma once

#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <vector>

#include <flint/fmpz.h>
#include <gmp.h>

#include "algebra/groebner/detail/log_bound.h"
#include "algebra/groebner/detail/reducer_rows.h"
#include "algebra/groebner/detail/reduction.h"
#include "algebra/groebner/detail/residue_system.h"
#include "algebra/monomial_table.h"

namespace locus::algebra::detail {

class ResidueZeroReducer {
  public:
    // Past this many lanes (about 7 900 bits) the integers are left to ExactZeroReducer: setting
    // up the lanes costs K² per coefficient and per step, which only long reductions repay.
    static constexpr std::size_t kMostLanes = 256;
    // Thrown by the reductions when the values need more lanes than that; the reducer is then
    // left with nothing pending. (The constructor starts on initial_lanes() whatever it is.)
    struct TooWide {};
    // The lanes the reducer starts on: room for the largest coefficient of the basis and 64
    // bits more, in multiples of 8, the width of the kernels (katsura-9: 16, katsura-10: 24).
    // Reductions whose values outgrow them start again on more.
    static std::size_t initial_lanes(const std::vector<BasisElement>& basis);

    // `basis` is read, not copied: it must outlive the reducer and not change. For the tests:
    // `lanes` (a multiple of 8) overrides initial_lanes(basis), and `learn` = false makes every
    // reduction begin there, instead of where those of its degree were found to fit.
    ResidueZeroReducer(const MonomialLayout& layout, const std::vector<BasisElement>& basis,
                       std::size_t lanes = 0, bool learn = true);
    ~ResidueZeroReducer();
    ResidueZeroReducer(const ResidueZeroReducer&) = delete;
    ResidueZeroReducer& operator=(const ResidueZeroReducer&) = delete;

    // Throws ReductionInterrupted once the deadline has passed (checked every 16 steps).
    void set_deadline(std::optional<std::chrono::steady_clock::time_point> deadline) {
        deadline_ = deadline;
    }

    // Whether p reduces to zero.
    bool reduces_to_zero(const IntegerPolynomial& p, ReductionCounts& counts);
    // Whether the S-polynomial of basis[i] and basis[j], whose leading monomials have the lcm
    // `lcm`, reduces to zero.
    bool s_polynomial_reduces_to_zero(std::size_t i, std::size_t j, const std::uint64_t* lcm,
                                      ReductionCounts& counts);

    // Columns numbered so far: a measure of the memory held.
    std::size_t columns() const { return table_.size(); }

    struct Statistics {
        std::size_t lanes = 0;     // residues per integer now
        std::size_t restarts = 0;  // reductions begun again on more lanes
        std::size_t rebuilds = 0;  // times the pending columns were rebuilt in full
        // The reducers' terms the steps went through, and the same counted once a lane: the
        // work and the data the row kernel streams.
        std::size_t reducer_terms = 0, lane_terms = 0;
        std::size_t columns = 0;  // numbered (columns())
    };
    Statistics statistics() const {
        Statistics s = statistics_;
        s.columns = columns();
        return s;
    }

  private:
    // What the reducer knows of a basis element's integers, independent of the lanes.
    struct Element {
        mpz_t leading;                              // L > 0
        log_bound::Units leading_lower = 0;         // ≤ log L
        std::vector<log_bound::Units> term_bounds;  // ≥ log |c_j|, j ≥ 1
        log_bound::Units largest_term_bound = log_bound::kZero;
    };
    // The same element on the current lanes.
    struct ElementLanes {
        std::vector<std::uint32_t> leading_inverse;     // L⁻¹, Montgomery form
        std::vector<std::uint32_t> rows;                // c_j for j ≥ 1, Montgomery form
        std::optional<ResidueSystem::Divisor> divisor;  // for L > 1
    };
    // Thrown when a value would not fit the lanes, to start again on more: `needed` is the
    // bound that did not fit.
    struct LanesExhausted {
        log_bound::Units needed;
    };
    // The basis and the values on one number of lanes. Reductions begin on the start level
    // and move up when their values outgrow it.
    struct Level {
        std::unique_ptr<ResidueSystem> system;
        std::vector<ElementLanes> elements;
        std::vector<std::uint32_t> values;  // lanes per column, of V/Λ
    };
    // Where the reductions of one degree begin, and how many begun there had to move up.
    struct Start {
        std::size_t lanes = 0, begun = 0, outgrown = 0;
    };

    std::uint32_t column(const std::uint64_t* m);
    // reducer_rows_.row_of for this reducer's table and basis.
    std::int32_t row_of(std::uint32_t column);
    Level& level() { return *active_; }
    std::uint32_t* value(std::uint32_t column) { return level().values.data() + column * lanes(); }
    std::size_t lanes() const { return active_->system->lanes(); }
    log_bound::Units true_bound(std::uint32_t column) const;
    void set_true_bound(std::uint32_t column, log_bound::Units bound);

    std::unique_ptr<Level> make_level(std::size_t lanes) const;
    // Makes the level of `lanes` lanes the one in use, building it first if need be.
    void activate(std::size_t lanes);
    // Λ = 1, no column pending.
    void begin();
    // value[column(m·t_j)] += multiplier·c_j for the terms j ≥ from of `p`, whose coefficients
    // are `rows` with bounds `bounds`.
    void add_multiple(const std::uint32_t* multiplier, log_bound::Units multiplier_bound,
                      const std::uint64_t* m, const IntegerPolynomial& p, std::size_t from,
                      const std::uint32_t* rows, const log_bound::Units* bounds);
    void push(std::uint32_t column);
    // Reduces what add_multiple loaded; leaves every column zero and the heap empty.
    bool reduce_loaded(ReductionCounts& counts);
    // Runs `load` and the reduction of a polynomial of degree `degree`, starting again on more
    // lanes when the values outgrow them.
    template <typename Load>
    bool reduce_with_retries(std::uint32_t degree, Load load, ReductionCounts& counts);
    // Rebuilds the values of the pending columns and of `lc` in full, divides out their
    // content and makes their bounds exact.
    void rebuild_pending(std::uint32_t lc);
    // Λ ← Λ·factor, for a factor given as Montgomery residues.
    void scale_lambda(const std::uint32_t* factor);
    // Zero every column still in the heap and empty it (after a failure or an interruption).
    void clear_pending();

    const MonomialLayout& layout_;
    const std::vector<BasisElement>& basis_;
    ReducerSearch search_;
    std::optional<std::chrono::steady_clock::time_point> deadline_;
    std::vector<Element> elements_;
    Statistics statistics_;

    MonomialTable table_;
    ReducerRows reducer_rows_;
    std::vector<std::uint32_t> heap_;    // columns, largest monomial on top
    std::vector<std::uint8_t> pending_;  // the column is in heap_
    std::vector<std::uint32_t> fresh_;   // columns a step made pending (reduce_loaded)
    // The columns in the monomial order, and for each a rank that grows with it, so that the
    // heap compares two integers instead of two monomials. New ranks go halfway between their
    // neighbours' (all are renumbered when there is no room): the heap stays valid because
    // renumbering keeps the order.
    struct MonomialLess {
        const ResidueZeroReducer* reducer;
        bool operator()(std::uint32_t x, std::uint32_t y) const {
            return reducer->layout_.compare(reducer->table_.at(x), reducer->table_.at(y)) < 0;
        }
    };
    std::set<std::uint32_t, MonomialLess> ordered_{MonomialLess{this}};
    std::vector<std::uint64_t> rank_;

    // The lanes and everything held on them.
    std::map<std::size_t, std::unique_ptr<Level>> levels_;  // by lanes
    Level* active_ = nullptr;
    std::size_t first_lanes_ = 0;
    bool learn_ = true;
    std::map<std::uint32_t, Start> starts_;  // by degree
    // Column bounds are kept relative to `offset_`: the true bound of a pending column is
    // bound_ + offset_, so multiplying every pending V by a adds log a to offset_ alone. A
    // column not pending is zero, with bound_ = kZero (which stays far below any real bound
    // whatever offset_ is added).
    std::vector<log_bound::Units> bound_;
    log_bound::Units offset_ = 0;
    log_bound::Units highest_bound_ = log_bound::kZero;  // ≥ every pending bound_
    std::vector<std::uint32_t> lambda_;                  // Λ, Montgomery form
    std::vector<std::uint32_t> lambda_digits_;           // Λ·digit_factors(), Montgomery form

    // Scratch.
    std::vector<std::uint32_t> multiplier_lanes_, quotients_, digits_, factor_;
    std::vector<std::uint32_t> load_rows_;
    std::vector<log_bound::Units> load_bounds_;
    std::vector<mp_limb_t> remainder_;
    std::vector<std::uint32_t> touched_;
    std::vector<log_bound::Units> touched_bounds_;
    mpz_t gcd_, cofactor_, scratch_;
    std::vector<std::uint64_t> product_, multiplier_;
};

}  // namespace locus::algebra::detail
