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
//   columns: multiplying p by a only multiplies Λ), 2–3 ns a term on 24–32 lanes with AVX-512.
// - What keeps it exact: every column carries a rigorous bound on |V| (log_bound.h), raised by
//   each addition and by each a; V is determined by its residues while the bound stays below
//   capacity (M/4), and zero exactly when every residue is. gcd(c, L), which the bounds need,
//   comes from c mod L, computed from the residues (residue_system.h). When a bound would pass
//   the capacity, the pending columns are rebuilt in full, their content divided out (as
//   Reducer does every time the coefficients double) and their bounds made exact; if that is
//   not enough, the reduction starts again on more lanes.
// - Up to eight reductions run together (reduce_together), each in a slot of a shared table
//   (a column's slots side by side): they pop the columns from one heap, in the monomial order,
//   so a column's step is made by every reduction that has it pending at that moment, with one
//   read of the reducer's row (each reduction's own order of steps is unchanged: its largest
//   pending column is the heap's top whenever it has that column pending). On katsura-11 a row
//   serves 6.8 reductions (the pairs sorted by lcm, verify.cpp), and the rows (49 MB on 32
//   lanes) no longer stream from memory for every step: its certification went 29.9 -> 14 s
//   with this and the kernels' prefetching.
// Why: on katsura-10 the certification makes 2.6 million steps over reducers of about 125
// terms, on integers of 300–800 bits. Held as GMP integers (fraction-free, with carries, signs
// and a multiplication of every other column whenever a ≠ 1) a term cost about 25 ns.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <vector>

#include <flint/fmpz.h>
#include <gmp.h>

#include "algebra/detail/cache_aligned.h"
#include "algebra/groebner/detail/log_bound.h"
#include "algebra/groebner/detail/reducer_rows.h"
#include "algebra/groebner/detail/reduction.h"
#include "algebra/groebner/detail/residue_lanes.h"
#include "algebra/groebner/detail/residue_system.h"
#include "algebra/monomial_table.h"

namespace locus::algebra::detail {

class ResidueZeroReducer {
  public:
    // Past this many lanes (about 7 900 bits) the integers are left to ExactZeroReducer: setting
    // up the lanes costs K² per coefficient and per step, which only long reductions repay.
    static constexpr std::size_t kMostLanes = 256;
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

    // A polynomial to reduce: `polynomial` when it is set, otherwise the S-polynomial of
    // basis[first] and basis[second], whose leading monomials have the lcm `lcm`.
    struct Job {
        const IntegerPolynomial* polynomial = nullptr;
        std::size_t first = 0, second = 0;
        const std::uint64_t* lcm = nullptr;
    };
    enum class Verdict : std::uint8_t { zero, not_zero, too_wide };
    // Reduces the jobs together: each makes its own steps (the same as alone), but a column's
    // reducer row is read once for all the jobs that reduce that column at the same time, in
    // the monomial order (F4's order). Reductions of S-polynomials of one degree go through
    // mostly the same columns: on katsura-10, eight consecutive pairs take the same row in
    // 5.8 of every 6.8 steps, and katsura-11's rows (49 MB on 32 lanes) stream from memory.
    // verdicts[k] and counts[k] (steps added) are those of jobs[k]; too_wide when the values
    // need more than kMostLanes lanes (the job is then for ExactZeroReducer; the constructor
    // starts on initial_lanes() whatever it is).
    void reduce_together(std::span<const Job> jobs, std::span<Verdict> verdicts,
                         std::span<ReductionCounts> counts);

    // Columns numbered so far: a measure of the memory held.
    std::size_t columns() const { return table_.size(); }

    struct Statistics {
        std::size_t lanes = 0;     // residues per integer now
        std::size_t restarts = 0;  // reductions begun again on more lanes
        std::size_t rebuilds = 0;  // times the pending columns were rebuilt in full
        // The reducers' terms the steps went through, and the same counted once a lane: the
        // work and the data the row kernel streams.
        std::size_t reducer_terms = 0, lane_terms = 0;
        // The reducer terms read, once for all the jobs reduced together that take a row at
        // the same time (reducer_terms / row_terms: the jobs sharing a row, on average).
        std::size_t row_terms = 0;
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
        std::vector<std::uint32_t> minus_leading_inverse;  // −L⁻¹, Montgomery form
        CacheAlignedVector<std::uint32_t> rows;            // c_j for j ≥ 1, Montgomery form
        std::optional<ResidueSystem::Divisor> divisor;     // for L > 1
    };
    // The basis on one number of lanes, and the values of the reductions under way on them.
    // Reductions begin on the start level and move up when their values outgrow it.
    struct Level {
        std::unique_ptr<ResidueSystem> system;
        std::vector<ElementLanes> elements;
        std::vector<std::uint32_t> one;  // 1 in Montgomery form: Λ at the start
        // Column c's values of slot s at (c·kSlots + s)·lanes (residue_lanes.h), of V/Λ.
        CacheAlignedVector<std::uint32_t> values;
    };
    // Where the reductions of one degree begin, and how many begun there had to move up.
    struct Start {
        std::size_t lanes = 0, begun = 0, outgrown = 0;
    };
    // One reduction under way, in a slot of the shared tables. Between reductions every value
    // of a slot is zero, every bound kZero and nothing is pending.
    struct Reduction {
        enum class State : std::uint8_t { running, zero, not_zero, exhausted };
        std::size_t slot = 0;
        // Column bounds are kept relative to `offset`: the true bound of a pending column is
        // bound + offset, so multiplying every pending V by a adds log a to offset alone. A
        // column not pending is zero, with bound kZero (which stays far below any real bound
        // whatever offset is added).
        log_bound::Units offset = 0;
        log_bound::Units highest_bound = log_bound::kZero;  // ≥ every pending bound
        // The pending columns, and columns that were once (dropped by compact_pending).
        std::vector<std::uint32_t> pending_columns;
        std::size_t pending_count = 0;
        std::vector<std::uint32_t> lambda;         // Λ, Montgomery form
        std::vector<std::uint32_t> lambda_digits;  // Λ·digit_factors(), Montgomery form
        // The step being made (its multiplier is in multipliers_): the factor a = L/g of Λ
        // when `scaled`, and the offset and relative b bound after it.
        std::vector<std::uint32_t> factor;
        bool scaled = false;
        log_bound::Units step_offset = 0, relative_b = 0;
        std::size_t rebuilds = 0;
        bool just_rebuilt = false;
        State state = State::running;
        log_bound::Units needed = 0;  // when exhausted: the bound that did not fit
        std::size_t steps = 0;
    };

    std::uint32_t column(const std::uint64_t* m);
    // reducer_rows_.row_of for this reducer's table and basis.
    std::int32_t row_of(std::uint32_t column);
    Level& level() { return *active_; }
    std::size_t lanes() const { return active_->system->lanes(); }
    // r's place at a column in the shared tables (residue_lanes.h's layout): bound_ and
    // pending_ hold one entry there, the values lanes() of them.
    static std::size_t place(const Reduction& r, std::uint32_t column) {
        return static_cast<std::size_t>(column) * lanes::kSlots + r.slot;
    }
    std::uint32_t* value(const Reduction& r, std::uint32_t column) {
        return level().values.data() + place(r, column) * lanes();
    }
    log_bound::Units& bound(const Reduction& r, std::uint32_t column) {
        return bound_[place(r, column)];
    }
    std::uint8_t& pending(const Reduction& r, std::uint32_t column) {
        return pending_[place(r, column)];
    }
    log_bound::Units true_bound(const Reduction& r, std::uint32_t column) const {
        return bound_[place(r, column)] + r.offset;
    }

    std::unique_ptr<Level> make_level(std::size_t lanes) const;
    // Makes the level of `lanes` lanes the one in use, building it first if need be.
    void activate(std::size_t lanes);
    // The start of the reductions of `degree` (set from the degree below when new).
    Start& start_of(std::uint32_t degree);
    std::uint32_t degree_of(const Job& job) const;
    // Reduces jobs[k] for the k in `members` (at most kSlots) together on `lanes` lanes,
    // leaving each of the first members.size() reductions_ zero, not_zero or exhausted.
    void run_group(std::span<const Job> jobs, std::span<const std::size_t> members,
                   std::size_t lanes);
    // Loads job into r: Λ = 1 and the job's terms as pending values (or r exhausted).
    void load(Reduction& r, const Job& job);
    // r's value[column(m·t_j)] += multiplier·c_j for the terms j ≥ from of `p`, whose
    // coefficients are `rows` with bounds `bounds`. False (r exhausted) when a bound would
    // not fit the lanes, before anything changes.
    bool add_multiple(Reduction& r, const std::uint32_t* multiplier,
                      log_bound::Units multiplier_bound, const std::uint64_t* m,
                      const IntegerPolynomial& p, std::size_t from, const std::uint32_t* rows,
                      const log_bound::Units* bounds);
    void push(Reduction& r, std::uint32_t column);
    // Readies r's step on its pending column c (rebuilding its values when the bounds would
    // not fit). False when r is exhausted instead.
    bool prepare_step(Reduction& r, std::uint32_t c, const ReducerRows::Row& row);
    // Makes the prepared steps of `taking` on column c, one pass over the row for them all.
    void make_steps(std::span<Reduction* const> taking, std::uint32_t c,
                    const ReducerRows::Row& row);
    // pending_columns holds each pending column once and no other.
    void compact_pending(Reduction& r);
    // Rebuilds r's pending values and that of `lc` in full, divides out their content and
    // makes their bounds exact.
    void rebuild_pending(Reduction& r, std::uint32_t lc);
    // Λ ← Λ·factor, for a factor given as Montgomery residues.
    void scale_lambda(Reduction& r, const std::uint32_t* factor);
    // Λ = 1 (after a load, or a rebuild that left the values themselves in the residues).
    void reset_lambda(Reduction& r);
    // Puts column c in the heap unless it is there.
    void schedule(std::uint32_t c);
    // The heap's order: the largest monomial on top, compared by rank.
    auto by_rank() const {
        return [this](std::uint32_t x, std::uint32_t y) { return rank_[x] < rank_[y]; };
    }
    // Ends r (not_zero or exhausted): every value it holds back to zero.
    void finish(Reduction& r, Reduction::State state);
    // Zeroes every pending value and empties the heap (after an interruption).
    void abandon_group(std::size_t members);

    const MonomialLayout& layout_;
    const std::vector<BasisElement>& basis_;
    ReducerSearch search_;
    std::optional<std::chrono::steady_clock::time_point> deadline_;
    std::vector<Element> elements_;
    Statistics statistics_;

    MonomialTable table_;
    ReducerRows reducer_rows_;
    // kSlots a column: each slot's bound (relative to its reduction's offset) and whether the
    // column waits for its step there.
    std::vector<log_bound::Units> bound_;
    std::vector<std::uint8_t> pending_;
    // The columns some reduction of the group has pending, largest monomial on top, each once.
    std::vector<std::uint32_t> heap_;
    std::vector<std::uint8_t> in_heap_;
    // What the row kernel reads and writes beside the values (residue_lanes.h's SlotBounds):
    // each slot's multiplier and quotients (lanes() apart), offset, highest bound and the
    // columns a step made pending.
    CacheAlignedVector<std::uint32_t> multipliers_, quotients_;
    std::array<log_bound::Units, lanes::kSlots> slot_offsets_{}, slot_highest_{};
    std::array<std::size_t, lanes::kSlots> fresh_counts_{};
    std::vector<std::uint32_t> fresh_;
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
    // The reductions of a group, the first of them, reductions_[s] in slot s.
    std::array<Reduction, lanes::kSlots> reductions_;

    // Scratch.
    std::vector<std::uint32_t> digits_, load_multiplier_, load_quotients_;
    CacheAlignedVector<std::uint32_t> load_rows_;
    std::vector<log_bound::Units> load_bounds_;
    std::vector<mp_limb_t> remainder_;
    std::vector<std::uint32_t> touched_;
    std::vector<log_bound::Units> touched_bounds_;
    std::vector<Reduction*> taking_;  // the reductions that take the current column's step
    mpz_t gcd_, cofactor_, scratch_;
    std::vector<std::uint64_t> product_, multiplier_;
};

}  // namespace locus::algebra::detail
