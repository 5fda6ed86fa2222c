// Internal to the Gröbner code: fraction-free reduction of integer polynomials by a basis.
//
// One step replaces p by a·p − b·m·g, where lt(m·g) and lt(p) have the same monomial and
// a = lc(g)/gcd, b = lc(p)/gcd, so no fractions appear; terms already moved to the result are
// scaled by a as well, so the result stays a multiple of p modulo the ideal. Among the basis
// elements whose leading monomial divides, the one with the smallest leading coefficient is
// used (ties: the oldest): every step multiplies p by that coefficient. Choosing the shortest
// reducer instead let coefficients double with each new element on cyclic-6 (over 2 million
// bits after 140 pairs, a minute of work); smallest-lc or oldest finish it in about 2 s.
// p lives in a geobucket (geobucket.h), so a step costs about the reducer's length.
#pragma once

#include <chrono>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "algebra/groebner/detail/geobucket.h"
#include "algebra/groebner/detail/pair_criteria.h"

namespace locus::algebra::detail {

struct ReductionCounts {
    std::size_t steps = 0;  // a·p − b·m·g operations
};

// Thrown by Reducer::reduce when its deadline has passed (checked every 16 steps, a few
// microseconds even on small coefficients): a single reduction can run for minutes on large
// inputs (a bicubic patch's elimination), far past a deadline that is otherwise polled once
// per S-pair.
struct ReductionInterrupted {};

// Which multiples of basis elements a reduction may use. Buchberger's reduction uses every
// element whose leading monomial divides the term; the signature-based algorithm
// (signature_groebner.h) only multiples of smaller signature than the polynomial reduced.
class ReducerAdmission {
  public:
    // May multiplier·basis[element] reduce a term of the polynomial being reduced?
    virtual bool admits(std::size_t element, const std::uint64_t* multiplier) const = 0;

  protected:
    ~ReducerAdmission() = default;
};

// Which basis element reduces a term: among the non-redundant elements whose leading monomial
// divides it (and that `admission` admits, when given), the one with the smallest leading
// coefficient (ties: the oldest). Reducer and ZeroReducer (zero_reducer.h) choose the same way.
class ReducerSearch {
  public:
    // Reads `basis`'s non-redundant elements; call again when the basis changes.
    void gather(const std::vector<BasisElement>& basis, const MonomialLayout& layout);
    // Index in the gathered basis of the element that reduces m, or -1. With an admission,
    // `multiplier` (words() words) receives m / lm of each divisor tried, so on success it holds
    // the multiplier of the element returned.
    long find(const std::uint64_t* m, const MonomialLayout& layout,
              const ReducerAdmission* admission = nullptr,
              std::uint64_t* multiplier = nullptr) const {
        const std::uint64_t mask = layout.divisibility_mask(m);
        const std::size_t w = layout.words();
        for (std::size_t k = 0; k < masks_.size(); ++k) {
            const std::uint64_t* lm = monomials_.data() + k * w;
            if ((masks_[k] & ~mask) == 0 && layout.divides(lm, m)) {
                if (admission == nullptr) {
                    return static_cast<long>(indices_[k]);
                }
                layout.divide(m, lm, multiplier);
                if (admission->admits(indices_[k], multiplier)) {
                    return static_cast<long>(indices_[k]);
                }
            }
        }
        return -1;
    }

  private:
    // The candidates' leading masks, monomials and indices, contiguous and in the order of
    // preference, so that the first divisor found is the one to use: every popped term
    // searches them, and walking the basis itself (a pointer to each element's monomials, a
    // size computed per divisor, no early exit) was 13 % of eco-7's instructions.
    std::vector<std::uint64_t> masks_, monomials_;
    std::vector<std::size_t> indices_;
    std::vector<std::pair<std::size_t, std::size_t>> order_;  // (leading-coefficient bits, index)
};

class Reducer {
  public:
    explicit Reducer(const MonomialLayout& layout) : layout_(layout), bucket_(layout) {}
    void set_deadline(std::optional<std::chrono::steady_clock::time_point> deadline) {
        deadline_ = deadline;
    }

    // Fully reduces p (leading and tail terms) by the non-redundant elements of `basis`, using
    // only the multiples that `admission` admits when one is given; the result is primitive
    // with positive leading coefficient, sugar updated, or empty.
    IntegerPolynomial reduce(IntegerPolynomial p, const std::vector<BasisElement>& basis,
                             ReductionCounts& counts, bool tail = true,
                             const ReducerAdmission* admission = nullptr);

    // The S-polynomial of basis[i] and basis[j] (fraction-free), with sugar `sugar`.
    IntegerPolynomial s_polynomial(const IntegerPolynomial& f, const IntegerPolynomial& g,
                                   const std::uint64_t* lcm, std::uint32_t sugar);

  private:
    // Whether the deadline has passed, polled after each reduction step and before each
    // content division. The clock is read every 16 cheap steps (read at every step, it cost
    // 2 % of small reductions) and at every costly one: on coefficients of 10⁶ bits a single
    // step takes up to seconds, and 16 of them ran 6 s past the deadline (a fuzzer's input).
    bool deadline_passed(bool costly_step);

    // out = a·p[from..] − b·m·g[1..] (g's leading term cancels against p's, skipped by caller).
    void combine(IntegerPolynomial& p, std::size_t from, const Integer& a, const Integer& b,
                 const std::uint64_t* m, const IntegerPolynomial& g);

    const MonomialLayout& layout_;
    std::optional<std::chrono::steady_clock::time_point> deadline_;
    int steps_to_check_ = 16;
    IntegerPolynomial scratch_;
    std::vector<std::uint64_t> product_;
    // reduce's working polynomial and monomials, kept to reuse their storage.
    GeoBucket bucket_;
    std::vector<std::uint64_t> leading_, multiplier_;
    ReducerSearch search_;
};

// Reduced-basis step (reduced_basis.cpp): drops elements whose leading monomial is divisible by
// another's (of equal ones, the first is kept), reduces each tail by the others, and returns
// the survivors sorted by leading monomial ascending, on `threads` threads. Precondition: a
// Gröbner basis.
std::vector<IntegerPolynomial> interreduce(std::vector<BasisElement> basis,
                                           const MonomialLayout& layout, ReductionCounts& counts,
                                           int threads = 1);

}  // namespace locus::algebra::detail
