#include "algebra/monomial.h"

#include <algorithm>
#include <string>

#include "algebra/error.h"

namespace locus::algebra {

MonomialLayout::MonomialLayout(const MonomialOrder& order) : order_(order) {
    const auto& fields = order_.fields();
    words_ = (fields.size() + fields_per_word - 1) / fields_per_word;
    if (words_ == 0) {
        words_ = 1;  // the ring with no variables still stores the monomial 1
    }
    compare_mask_.assign(words_, 0);
    variable_mask_.assign(words_, 0);
    field_of_variable_.assign(order_.num_vars(), 0);
    for (unsigned i = 0; i < fields_per_word; ++i) {
        guard_mask_ |= std::uint64_t{1} << (i * field_bits + field_bits - 1);
    }
    for (std::size_t f = 0; f < fields.size(); ++f) {
        const std::uint64_t value_bits = std::uint64_t{max_field_value} << shift(f);
        if (fields[f].is_variable()) {
            field_of_variable_[fields[f].variable] = f;
            variable_mask_[f / fields_per_word] |= value_bits;
            if (fields[f].negated) {
                compare_mask_[f / fields_per_word] |= value_bits;
            }
        }
    }
    // Up to 32 variables: min(64 / n, 16) bits each, as exponents in unary (Singular's short
    // exponent vectors). On eco-11 (11 variables, 5 bits each) the divisor searches then call
    // divides() on far fewer candidates than with one bit a variable, which only says whether
    // the variable occurs.
    if (order_.num_vars() >= 1 && order_.num_vars() <= 32) {
        mask_bits_per_variable_ =
            std::min<unsigned>(16, static_cast<unsigned>(64 / order_.num_vars()));
    }
    mask_table_.assign(words_, {});
    for (std::size_t i = 0; i < order_.num_vars(); ++i) {
        const std::size_t f = field_of_variable_[i];
        const unsigned slot = shift(f) / field_bits;
        for (unsigned pattern = 0; pattern < 16; ++pattern) {
            if ((pattern >> slot & 1u) != 0) {
                mask_table_[f / fields_per_word][pattern] |= std::uint64_t{1} << (i % 64);
            }
        }
    }
}

void MonomialLayout::throw_overflow() {
    throw ExponentOverflow("a packed exponent or weighted degree exceeds " +
                           std::to_string(max_field_value));
}

void MonomialLayout::pack(std::span<const std::uint32_t> e, std::uint64_t* out) const {
    const auto& fields = order_.fields();
    for (std::size_t w = 0; w < words_; ++w) {
        out[w] = 0;
    }
    for (std::size_t f = 0; f < fields.size(); ++f) {
        std::uint64_t value = 0;
        if (fields[f].is_variable()) {
            value = e[fields[f].variable];
        } else {
            for (std::size_t i = 0; i < e.size(); ++i) {
                value += static_cast<std::uint64_t>(fields[f].weights[i]) * e[i];
                if (value > max_field_value) {
                    break;
                }
            }
        }
        if (value > max_field_value) {
            throw_overflow();
        }
        out[f / fields_per_word] |= value << shift(f);
    }
}

void MonomialLayout::unpack(const std::uint64_t* m, std::span<std::uint32_t> e) const {
    for (std::size_t i = 0; i < num_vars(); ++i) {
        e[i] = field(m, field_of_variable_[i]);
    }
}

std::uint32_t MonomialLayout::exponent(const std::uint64_t* m, std::size_t var) const {
    return field(m, field_of_variable_[var]);
}

std::uint32_t MonomialLayout::total_degree(const std::uint64_t* m) const {
    std::uint32_t d = 0;
    for (std::size_t i = 0; i < num_vars(); ++i) {
        d += field(m, field_of_variable_[i]);
    }
    return d;
}

namespace {

// Per-field mask of the fields where a >= b (value bits set), from the guard-bit trick.
std::uint64_t fields_at_least(std::uint64_t a, std::uint64_t b, std::uint64_t guard) {
    const std::uint64_t ge = ((a | guard) - b) & guard;
    return ge - (ge >> (MonomialLayout::field_bits - 1));
}

}  // namespace

void MonomialLayout::lcm(const std::uint64_t* a, const std::uint64_t* b, std::uint64_t* out) const {
    for (std::size_t w = 0; w < words_; ++w) {
        const std::uint64_t a_ge_b = fields_at_least(a[w], b[w], guard_mask_);
        out[w] = (a[w] & a_ge_b) | (b[w] & ~a_ge_b & ~guard_mask_);
    }
    // Linear fields are not max-compatible: recompute them from the exponents.
    const auto& fields = order_.fields();
    for (std::size_t f = 0; f < fields.size(); ++f) {
        if (fields[f].is_variable()) {
            continue;
        }
        std::uint64_t value = 0;
        for (std::size_t i = 0; i < num_vars(); ++i) {
            value += static_cast<std::uint64_t>(fields[f].weights[i]) *
                     field(out, field_of_variable_[i]);
        }
        if (value > max_field_value) {
            throw_overflow();
        }
        const unsigned s = shift(f);
        out[f / fields_per_word] =
            (out[f / fields_per_word] & ~(std::uint64_t{0xFFFF} << s)) | (value << s);
    }
}

void MonomialLayout::gcd(const std::uint64_t* a, const std::uint64_t* b, std::uint64_t* out) const {
    for (std::size_t w = 0; w < words_; ++w) {
        const std::uint64_t a_ge_b = fields_at_least(a[w], b[w], guard_mask_);
        out[w] = (b[w] & a_ge_b) | (a[w] & ~a_ge_b & ~guard_mask_);
    }
    const auto& fields = order_.fields();
    for (std::size_t f = 0; f < fields.size(); ++f) {
        if (fields[f].is_variable()) {
            continue;
        }
        std::uint64_t value = 0;
        for (std::size_t i = 0; i < num_vars(); ++i) {
            value += static_cast<std::uint64_t>(fields[f].weights[i]) *
                     field(out, field_of_variable_[i]);
        }
        const unsigned s = shift(f);
        out[f / fields_per_word] =
            (out[f / fields_per_word] & ~(std::uint64_t{0xFFFF} << s)) | (value << s);
    }
}

bool MonomialLayout::coprime(const std::uint64_t* a, const std::uint64_t* b) const {
    // Coprime iff for every variable field one of the two is zero: min(a,b) == 0 per field.
    for (std::size_t w = 0; w < words_; ++w) {
        const std::uint64_t x = a[w] & variable_mask_[w], y = b[w] & variable_mask_[w];
        const std::uint64_t x_ge_y = fields_at_least(x, y, guard_mask_);
        const std::uint64_t minimum = (y & x_ge_y) | (x & ~x_ge_y & ~guard_mask_);
        if (minimum != 0) {
            return false;
        }
    }
    return true;
}

std::uint64_t MonomialLayout::divisibility_mask(const std::uint64_t* m) const {
    if (mask_bits_per_variable_ > 1) {
        const unsigned bits = mask_bits_per_variable_;
        const std::uint64_t full = (std::uint64_t{1} << bits) - 1;
        std::uint64_t mask = 0;
        for (std::size_t i = 0; i < field_of_variable_.size(); ++i) {
            const std::uint32_t e = field(m, field_of_variable_[i]);
            const std::uint64_t run = e >= bits ? full : (std::uint64_t{1} << e) - 1;
            mask |= run << (i * bits);
        }
        return mask;
    }
    std::uint64_t mask = 0;
    for (std::size_t w = 0; w < words_; ++w) {
        // A variable field x ≤ 32767 plus 32767 carries into its guard bit exactly when x ≠ 0,
        // and stays within its 16 bits; other fields add 0 to 0.
        const std::uint64_t nonzero =
            ((m[w] & variable_mask_[w]) + variable_mask_[w]) & guard_mask_;
        const std::uint64_t pattern = ((nonzero >> 15) & 1u) | ((nonzero >> 30) & 2u) |
                                      ((nonzero >> 45) & 4u) | ((nonzero >> 60) & 8u);
        mask |= mask_table_[w][pattern];
    }
    return mask;
}

}  // namespace locus::algebra
