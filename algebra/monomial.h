// Packed monomials: the exponent vector of a monomial, stored in 64-bit words together with the
// comparison fields of its order so that comparing, multiplying and testing divisibility are a
// few word operations (the layout of Singular's and FLINT's packed exponents).
//
// Each field is 16 bits: 15 value bits and a guard bit on top. The fields are the order's
// comparison fields (monomial_order.h) in order, most significant first, so that comparing two
// monomials is comparing words as unsigned integers after XOR with a mask that flips negated
// fields. Multiplication adds words and reads the guard bits to detect overflow (reported as
// ExponentOverflow, never wrapped); divisibility and lcm/gcd use the guard bits to compare all
// fields of a word at once. Invariant: guard bits are zero in every stored monomial.
//
// A monomial here knows nothing of coefficients; a MonomialLayout is immutable and shared.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "algebra/monomial_order.h"

namespace locus::algebra {

class MonomialLayout {
  public:
    static constexpr unsigned field_bits = 16;
    static constexpr std::uint32_t max_field_value = (1u << (field_bits - 1)) - 1;  // 32767
    static constexpr unsigned fields_per_word = 64 / field_bits;

    explicit MonomialLayout(const MonomialOrder& order);

    const MonomialOrder& order() const { return order_; }
    std::size_t num_vars() const { return order_.num_vars(); }
    std::size_t words() const { return words_; }

    // Exponents → packed words (`out` has words() entries); throws ExponentOverflow when an
    // exponent or a weighted degree exceeds max_field_value.
    void pack(std::span<const std::uint32_t> exponents, std::uint64_t* out) const;
    void unpack(const std::uint64_t* m, std::span<std::uint32_t> exponents) const;
    std::uint32_t exponent(const std::uint64_t* m, std::size_t var) const;
    std::uint32_t total_degree(const std::uint64_t* m) const;
    // The first comparison field: the degree under the order's first weight row (total degree
    // for grlex/grevlex, the weighted degree for weights(..), the degree in the eliminated
    // block for elim(..), the first variable's exponent for lex). The sugar degree of the
    // Gröbner code is measured in it.
    std::uint32_t leading_weight(const std::uint64_t* m) const { return field(m, 0); }

    // -1, 0, 1 by the order. Two words (up to seven variables under a degree order) are spelled
    // out: the loop's bookkeeping was a third of the comparisons' instructions in Buchberger's
    // geobucket merges.
    int compare(const std::uint64_t* a, const std::uint64_t* b) const {
        if (words_ == 2) {
            const std::uint64_t* mask = compare_mask_.data();
            const std::uint64_t x0 = a[0] ^ mask[0], y0 = b[0] ^ mask[0];
            if (x0 != y0) {
                return x0 > y0 ? 1 : -1;
            }
            const std::uint64_t x1 = a[1] ^ mask[1], y1 = b[1] ^ mask[1];
            return x1 == y1 ? 0 : (x1 > y1 ? 1 : -1);
        }
        for (std::size_t w = 0; w < words_; ++w) {
            const std::uint64_t x = a[w] ^ compare_mask_[w], y = b[w] ^ compare_mask_[w];
            if (x != y) {
                return x > y ? 1 : -1;
            }
        }
        return 0;
    }
    bool equal(const std::uint64_t* a, const std::uint64_t* b) const {
        for (std::size_t w = 0; w < words_; ++w) {
            if (a[w] != b[w]) {
                return false;
            }
        }
        return true;
    }
    // The invariant of every stored monomial (LOCUS_ASSERT checks it where terms are stored).
    bool guards_clear(const std::uint64_t* a) const {
        for (std::size_t w = 0; w < words_; ++w) {
            if ((a[w] & guard_mask_) != 0) {
                return false;
            }
        }
        return true;
    }
    bool is_one(const std::uint64_t* a) const {
        for (std::size_t w = 0; w < words_; ++w) {
            if (a[w] != 0) {
                return false;
            }
        }
        return true;
    }
    // out = a·b; throws ExponentOverflow. `out` may alias a or b.
    void multiply(const std::uint64_t* a, const std::uint64_t* b, std::uint64_t* out) const {
        if (words_ == 2) {
            const std::uint64_t p0 = a[0] + b[0], p1 = a[1] + b[1];
            out[0] = p0;
            out[1] = p1;
            if (((p0 | p1) & guard_mask_) != 0) {
                throw_overflow();
            }
            return;
        }
        std::uint64_t overflow = 0;
        for (std::size_t w = 0; w < words_; ++w) {
            out[w] = a[w] + b[w];
            overflow |= out[w];
        }
        if (overflow & guard_mask_) {
            throw_overflow();
        }
    }
    // Does a divide b?
    bool divides(const std::uint64_t* a, const std::uint64_t* b) const {
        for (std::size_t w = 0; w < words_; ++w) {
            if ((((b[w] | guard_mask_) - a[w]) & guard_mask_) != guard_mask_) {
                return false;
            }
        }
        return true;
    }
    // out = b / a; precondition: a divides b.
    void divide(const std::uint64_t* b, const std::uint64_t* a, std::uint64_t* out) const {
        for (std::size_t w = 0; w < words_; ++w) {
            out[w] = b[w] - a[w];
        }
    }
    void lcm(const std::uint64_t* a, const std::uint64_t* b, std::uint64_t* out) const;
    void gcd(const std::uint64_t* a, const std::uint64_t* b, std::uint64_t* out) const;
    // gcd(a, b) == 1, tested on the variable fields only.
    bool coprime(const std::uint64_t* a, const std::uint64_t* b) const;

    // What compare() and multiply() use, for kernels that fix the number of words at compile
    // time (geobucket.cpp): a monomial's words XOR compare_mask() compare as unsigned integers,
    // most significant word first; a product with a bit of guard_mask() set has overflowed.
    const std::uint64_t* compare_mask() const { return compare_mask_.data(); }
    std::uint64_t guard_mask() const { return guard_mask_; }

    // A 64-bit filter for divisibility (Singular's short exponent vector): if mask(a) has a bit
    // that mask(b) lacks, a cannot divide b. Up to 32 variables, variable i owns the
    // mask_bits_per_variable() bits from i·that, of which the lowest min(e_i, that) are set;
    // with more, bit (i mod 64) is set when variable i occurs.
    std::uint64_t divisibility_mask(const std::uint64_t* m) const;
    // 1 past 32 variables.
    unsigned mask_bits_per_variable() const { return mask_bits_per_variable_; }

  private:
    [[noreturn]] static void throw_overflow();
    std::uint32_t field(const std::uint64_t* m, std::size_t f) const {
        return static_cast<std::uint32_t>(m[f / fields_per_word] >> shift(f)) & 0xFFFFu;
    }
    static unsigned shift(std::size_t f) {
        return static_cast<unsigned>((fields_per_word - 1 - f % fields_per_word) * field_bits);
    }

    MonomialOrder order_;
    std::size_t words_ = 0;
    std::vector<std::uint64_t> compare_mask_;
    std::uint64_t guard_mask_ = 0;
    std::vector<std::size_t> field_of_variable_;  // variable index → field index
    std::vector<std::uint64_t> variable_mask_;    // per word: value bits of variable fields
    // Per word, for each pattern of its four fields being non-zero (bit k: the field whose guard
    // bit is 16k + 15), the divisibility_mask bits of the variables among them: the mask then
    // costs a few word operations per word. Reading the fields one variable at a time took 140
    // instructions a call on eco-7 (3 % of Buchberger's instructions there).
    std::vector<std::array<std::uint64_t, 16>> mask_table_;  // past 32 variables
    unsigned mask_bits_per_variable_ = 1;
};

// The shape of a reduced (or minimal) basis: the leading monomials lead(0), …, lead(n − 1) are
// strictly ascending and none divides another. For LOCUS_ASSERT: quadratic in n.
template <class LeadingMonomial>
bool ascending_and_minimal(std::size_t n, LeadingMonomial lead, const MonomialLayout& layout) {
    for (std::size_t i = 0; i < n; ++i) {
        if (i + 1 < n && layout.compare(lead(i), lead(i + 1)) >= 0) {
            return false;
        }
        for (std::size_t j = 0; j < n; ++j) {
            if (i != j && layout.divides(lead(i), lead(j))) {
                return false;
            }
        }
    }
    return true;
}

}  // namespace locus::algebra
