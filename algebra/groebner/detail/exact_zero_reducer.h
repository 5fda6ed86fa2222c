// Internal to the Gröbner code: decides whether integer polynomials reduce to zero by a basis
// that does not change, for the certification of multi-modular results (verify.h), on GMP
// integers. ZeroReducer (zero_reducer.h) uses it where the integers are too large for
// ResidueZeroReducer's lanes (thousands of digits, a few steps), and the tests as an
// independent check of the residue arithmetic: both make the same steps on the same integers.
//
// The steps are Reducer's (reduction.h): fraction-free, a·p − b·m·g, the same reducer for each
// term (ReducerSearch), the content divided out when the coefficients have doubled; only the
// leading terms are reduced, so the first term no element reduces ends the work (not zero).
// What differs is the bookkeeping, because the basis is fixed:
// - every monomial met gets a column number (MonomialTable), once per certification;
// - a column's reducer and the columns of the multiple m·g that cancels it are found once and
//   kept (F4's symbolic preprocessing, done lazily): katsura-10's certification takes 2.6
//   million steps on 4 500 distinct columns;
// - the polynomial being reduced is an array of GMP integers indexed by column, which keep
//   their limbs when they cancel to zero, with a heap of its columns in descending order.
// Why: on katsura-9's certification a step's reducer has about 80 terms of about 80 bits and
// the multiplier about 260 bits, so the arithmetic is cheap; Reducer's geobucket spent more on
// merging buckets, multiplying and comparing monomials and allocating a GMP integer for every
// new term, which cancels again a few steps later (58 ns a term in all).
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <vector>

#include <gmp.h>

#include "algebra/groebner/detail/reducer_rows.h"
#include "algebra/groebner/detail/reduction.h"
#include "algebra/monomial_table.h"

namespace locus::algebra::detail {

class ExactZeroReducer {
  public:
    // `basis` is read, not copied: it must outlive the reducer and not change.
    ExactZeroReducer(const MonomialLayout& layout, const std::vector<BasisElement>& basis);
    ~ExactZeroReducer();
    ExactZeroReducer(const ExactZeroReducer&) = delete;
    ExactZeroReducer& operator=(const ExactZeroReducer&) = delete;

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

  private:
    std::uint32_t column(const std::uint64_t* m);
    // reducer_rows_.row_of for this reducer's table and basis.
    std::int32_t row_of(std::uint32_t column);
    // acc[column(m·t)] += factor·c for every term c·t of `p` from `from` on.
    void add_multiple(const mpz_t factor, const std::uint64_t* m, const IntegerPolynomial& p,
                      std::size_t from);
    void push(std::uint32_t column);
    // Reduces what add_multiple loaded; leaves every column zero and the heap empty.
    bool reduce_loaded(ReductionCounts& counts);
    // Zero every column still in the heap and empty it (after a failure or an interruption).
    void clear_pending();

    const MonomialLayout& layout_;
    const std::vector<BasisElement>& basis_;
    ReducerSearch search_;
    std::optional<std::chrono::steady_clock::time_point> deadline_;
    std::vector<__mpz_struct> leading_coefficients_;  // of the basis elements

    MonomialTable table_;
    std::vector<__mpz_struct> values_;   // by column; zero outside a reduction
    std::vector<std::uint8_t> pending_;  // the column is in heap_
    ReducerRows reducer_rows_;
    std::vector<std::uint32_t> heap_;  // columns, largest monomial on top

    mpz_t gcd_, a_, b_, content_;
    std::vector<std::uint64_t> product_, multiplier_;
};

}  // namespace locus::algebra::detail
