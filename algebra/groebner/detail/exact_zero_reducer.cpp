#include "algebra/groebner/detail/exact_zero_reducer.h"
#include "algebra/deadline.h"

#include <algorithm>

#include <flint/fmpz.h>

namespace locus::algebra::detail {

namespace {

// The GMP integer behind a FLINT integer that is not a word. FLINT's COEFF_TO_PTR is this
// shift, spelled as an old-style cast that the warnings reject.
inline mpz_srcptr gmp_integer(fmpz v) {
    return reinterpret_cast<mpz_srcptr>(static_cast<ulong>(v) << 2);
}

// acc += f·c, with c a FLINT integer: a word (immediate) or a pointer to a GMP integer.
inline void addmul(mpz_ptr acc, mpz_srcptr f, const fmpz_t c) {
    const fmpz v = *c;
    if (!COEFF_IS_MPZ(v)) {
        if (v >= 0) {
            mpz_addmul_ui(acc, f, static_cast<unsigned long>(v));
        } else {
            mpz_submul_ui(acc, f, static_cast<unsigned long>(-v));
        }
    } else {
        mpz_addmul(acc, f, gmp_integer(v));
    }
}

}  // namespace

ExactZeroReducer::ExactZeroReducer(const MonomialLayout& layout,
                                   const std::vector<BasisElement>& basis)
    : layout_(layout), basis_(basis), table_(layout.words()) {
    search_.gather(basis, layout);
    leading_coefficients_.resize(basis.size());
    for (std::size_t k = 0; k < basis.size(); ++k) {
        mpz_init(&leading_coefficients_[k]);
        if (!basis[k].poly.empty()) {
            fmpz_get_mpz(&leading_coefficients_[k], basis[k].poly.coefficients[0].get());
        }
    }
    mpz_inits(gcd_, a_, b_, content_, nullptr);
    product_.resize(layout.words());
    multiplier_.resize(layout.words());
}

ExactZeroReducer::~ExactZeroReducer() {
    for (__mpz_struct& z : leading_coefficients_) {
        mpz_clear(&z);
    }
    for (__mpz_struct& z : values_) {
        mpz_clear(&z);
    }
    mpz_clears(gcd_, a_, b_, content_, nullptr);
}

std::uint32_t ExactZeroReducer::column(const std::uint64_t* m) {
    const std::uint32_t c = table_.insert(m);
    if (c == values_.size()) {
        // __mpz_struct is a plain struct (size, allocation, limb pointer): the vector may move
        // it when it grows.
        values_.emplace_back();
        mpz_init(&values_.back());
        pending_.push_back(0);
        reducer_rows_.add_column();
    }
    return c;
}

std::int32_t ExactZeroReducer::row_of(std::uint32_t c) {
    return reducer_rows_.row_of(c, table_, search_, layout_, basis_, multiplier_.data(),
                                product_.data(),
                                [this](const std::uint64_t* m) { return column(m); });
}

void ExactZeroReducer::push(std::uint32_t c) {
    if (pending_[c] == 0) {
        pending_[c] = 1;
        heap_.push_back(c);
        std::push_heap(heap_.begin(), heap_.end(), [this](std::uint32_t x, std::uint32_t y) {
            return layout_.compare(table_.at(x), table_.at(y)) < 0;
        });
    }
}

void ExactZeroReducer::add_multiple(const mpz_t factor, const std::uint64_t* m,
                                    const IntegerPolynomial& p, std::size_t from) {
    const std::size_t w = layout_.words();
    for (std::size_t j = from; j < p.size(); ++j) {
        layout_.multiply(p.monomial(j, w), m, product_.data());
        const std::uint32_t c = column(product_.data());
        addmul(&values_[c], factor, p.coefficients[j].get());
        push(c);
    }
}

void ExactZeroReducer::clear_pending() {
    for (const std::uint32_t c : heap_) {
        mpz_set_ui(&values_[c], 0);
        pending_[c] = 0;
    }
    heap_.clear();
}

bool ExactZeroReducer::reduce_loaded(ReductionCounts& counts) {
    const auto descending = [this](std::uint32_t x, std::uint32_t y) {
        return layout_.compare(table_.at(x), table_.at(y)) < 0;
    };
    std::size_t bits_after_content = 0;
    while (!heap_.empty()) {
        std::pop_heap(heap_.begin(), heap_.end(), descending);
        const std::uint32_t c = heap_.back();
        heap_.pop_back();
        pending_[c] = 0;
        if (mpz_sgn(&values_[c]) == 0) {
            continue;
        }
        const std::int32_t r = row_of(c);  // may number new columns: values_ may move
        __mpz_struct* values = values_.data();
        mpz_ptr lc = &values[c];
        if (r == ReducerRows::kIrreducible) {
            mpz_set_ui(lc, 0);
            clear_pending();
            return false;
        }
        // As in Reducer::reduce: divide out the content once the coefficients have doubled.
        const std::size_t bits = mpz_sizeinbase(lc, 2);
        if (bits_after_content == 0) {
            bits_after_content = bits;
        } else if (bits > 2 * bits_after_content + 64) {
            mpz_set(content_, lc);
            for (std::size_t h = 0; h < heap_.size() && mpz_cmp_ui(content_, 1) != 0; ++h) {
                mpz_gcd(content_, content_, &values[heap_[h]]);
            }
            mpz_abs(content_, content_);
            if (mpz_cmp_ui(content_, 1) != 0) {
                mpz_divexact(lc, lc, content_);
                for (const std::uint32_t h : heap_) {
                    mpz_divexact(&values[h], &values[h], content_);
                }
            }
            bits_after_content = mpz_sizeinbase(lc, 2);
        }
        const ReducerRows::Row row = reducer_rows_.row(r);
        mpz_srcptr reducer_lc = &leading_coefficients_[row.element];
        mpz_gcd(gcd_, lc, reducer_lc);
        mpz_divexact(a_, reducer_lc, gcd_);  // positive: leading coefficients are positive
        mpz_divexact(b_, lc, gcd_);
        mpz_neg(b_, b_);
        if (mpz_cmp_ui(a_, 1) != 0) {
            for (const std::uint32_t h : heap_) {
                mpz_mul(&values[h], &values[h], a_);
            }
        }
        mpz_set_ui(lc, 0);
        // a·p − b·m·g: the leading terms cancel; the rest of g lands on the row's columns.
        const IntegerPolynomial& g = basis_[row.element].poly;
        const std::uint32_t* columns = reducer_rows_.columns_of(row);
        for (std::size_t j = 1; j < g.size(); ++j) {
            const std::uint32_t column = columns[j - 1];
            addmul(&values[column], b_, g.coefficients[j].get());
            push(column);
        }
        ++counts.steps;
        if (counts.steps % 16 == 0 && deadline_passed(deadline_)) {
            clear_pending();
            throw ReductionInterrupted{};
        }
    }
    return true;
}

bool ExactZeroReducer::reduces_to_zero(const IntegerPolynomial& p, ReductionCounts& counts) {
    if (p.empty()) {
        return true;
    }
    std::fill(multiplier_.begin(), multiplier_.end(), 0);  // the monomial 1
    mpz_set_ui(a_, 1);
    add_multiple(a_, multiplier_.data(), p, 0);
    return reduce_loaded(counts);
}

bool ExactZeroReducer::s_polynomial_reduces_to_zero(std::size_t i, std::size_t j,
                                                    const std::uint64_t* lcm,
                                                    ReductionCounts& counts) {
    const std::size_t w = layout_.words();
    const IntegerPolynomial& f = basis_[i].poly;
    const IntegerPolynomial& g = basis_[j].poly;
    // s = a·mf·f − b·mg·g with a = lc(g)/d, b = lc(f)/d: the leading terms cancel.
    std::vector<std::uint64_t> mf(w), mg(w);
    layout_.divide(lcm, f.monomial(0, w), mf.data());
    layout_.divide(lcm, g.monomial(0, w), mg.data());
    mpz_gcd(gcd_, &leading_coefficients_[i], &leading_coefficients_[j]);
    mpz_divexact(a_, &leading_coefficients_[j], gcd_);
    mpz_divexact(b_, &leading_coefficients_[i], gcd_);
    mpz_neg(b_, b_);
    add_multiple(a_, mf.data(), f, 1);
    add_multiple(b_, mg.data(), g, 1);
    return reduce_loaded(counts);
}

}  // namespace locus::algebra::detail
