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

    // -1, 0, 1 by the order.
    int compare(const std::uint64_t* a, const std::uint64_t* b) const {
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

    // A 64-bit mask with bit (i mod 64) set when variable i occurs: if mask(a) has a bit that
    // mask(b) lacks, a cannot divide b (Singular's short exponent vector).
    std::uint64_t divisibility_mask(const std::uint64_t* m) const;

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
};

}  // namespace locus::algebra
