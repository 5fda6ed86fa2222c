#include "algebra/groebner/detail/geobucket.h"

#include <algorithm>
#include <array>

#include "algebra/error.h"
#include "algebra/groebner/detail/small_integer.h"

namespace locus::algebra::detail {

namespace {

// MonomialLayout::multiply's exception for the first m·g[j], j ≥ from, that overflows (out of
// line: inlined into a kernel of fixed width, GCC sees writes past a one-word product that the
// run-time width never reaches).
[[noreturn, gnu::noinline]] void throw_product_overflow(const MonomialLayout& layout,
                                                        const std::uint64_t* m,
                                                        const IntegerPolynomial& g,
                                                        std::size_t from) {
    std::vector<std::uint64_t> product(layout.words());
    for (std::size_t j = from; j < g.size(); ++j) {
        layout.multiply(g.monomial(j, layout.words()), m, product.data());
    }
    throw ExponentOverflow("a product in a reduction");  // not reached: one of them overflows
}

// The monomial operations of a merge, with the number of words fixed at compile time (W > 0)
// or read from the layout (W = 0). Rings of up to 15 variables under a degree order take one
// to four words; MonomialLayout's own loops (and std::copy_n, a call to memmove) were a fifth
// of eco-11's time in the merges.
template <std::size_t W>
class Words {
  public:
    explicit Words(const MonomialLayout& layout) : layout_(layout), guard_(layout.guard_mask()) {
        if constexpr (W > 0) {
            std::copy_n(layout.compare_mask(), W, mask_.begin());
        }
    }
    std::size_t count() const {
        if constexpr (W > 0) {
            return W;
        } else {
            return layout_.words();
        }
    }
    int compare(const std::uint64_t* a, const std::uint64_t* b) const {
        if constexpr (W == 0) {
            return layout_.compare(a, b);
        } else {
            for (std::size_t w = 0; w < W; ++w) {
                const std::uint64_t x = a[w] ^ mask_[w], y = b[w] ^ mask_[w];
                if (x != y) {
                    return x > y ? 1 : -1;
                }
            }
            return 0;
        }
    }
    // out = a·b, returning the words OR-ed together: a merge ORs them over all its products
    // and checks overflowed() once, at its end, instead of throwing from the middle of it,
    // where the products made so far would belong to nobody (checking every product in a pass
    // before the merge cost 2–3 % of eco-11).
    std::uint64_t multiply(const std::uint64_t* a, const std::uint64_t* b,
                           std::uint64_t* out) const {
        std::uint64_t any = 0;
        for (std::size_t w = 0; w < count(); ++w) {
            out[w] = a[w] + b[w];
            any |= out[w];
        }
        return any;
    }
    bool overflowed(std::uint64_t products) const { return (products & guard_) != 0; }
    void copy(const std::uint64_t* from, std::uint64_t* to) const {
        if constexpr (W == 0) {
            std::copy_n(from, layout_.words(), to);
        } else {
            for (std::size_t w = 0; w < W; ++w) {
                to[w] = from[w];
            }
        }
    }

  private:
    const MonomialLayout& layout_;
    std::uint64_t guard_;
    std::array<std::uint64_t, (W > 0 ? W : 1)> mask_{};
};

// Calls f.template operator()<W>() for the layout's word count.
template <typename F>
void with_words(const MonomialLayout& layout, F&& f) {
    switch (layout.words()) {
    case 1:
        f.template operator()<1>();
        break;
    case 2:
        f.template operator()<2>();
        break;
    case 3:
        f.template operator()<3>();
        break;
    case 4:
        f.template operator()<4>();
        break;
    default:
        f.template operator()<0>();
        break;
    }
}

}  // namespace

std::size_t GeoBucket::level_for(std::size_t length) {
    std::size_t level = 0;
    while (capacity(level) < length) {
        ++level;
    }
    return level;
}

void GeoBucket::assign(IntegerPolynomial p) {
    for (Bucket& b : buckets_) {
        b.release();
    }
    if (p.empty()) {
        return;
    }
    const std::size_t level = level_for(p.size());
    if (buckets_.size() <= level) {
        buckets_.resize(level + 1);
    }
    Bucket& bucket = buckets_[level];
    bucket.monomials = std::move(p.monomials);
    if (bucket.coefficients.size() < p.size()) {
        bucket.coefficients.resize(p.size());
    }
    // The coefficients change hands: p keeps zeros, which own nothing.
    for (std::size_t k = 0; k < p.size(); ++k) {
        bucket.coefficients[k] = *p.coefficients[k].get();
        *p.coefficients[k].get() = 0;
    }
    bucket.count = p.size();
}

void GeoBucket::carry(std::size_t level) {
    // A bucket over its capacity moves up, merging with the next one.
    while (buckets_[level].size() > capacity(level)) {
        if (buckets_.size() <= level + 1) {
            buckets_.resize(level + 2);
        }
        merge(buckets_[level + 1], buckets_[level]);
        ++level;
    }
}

void GeoBucket::merge(Bucket& target, Bucket& source) {
    with_words(layout_, [&]<std::size_t W>() { merge_words<W>(target, source); });
}

template <std::size_t W>
void GeoBucket::merge_words(Bucket& target, Bucket& source) {
    if (source.size() == 0) {
        source.forget();
        return;
    }
    if (target.size() == 0) {
        target.forget();
        target.swap(source);
        return;
    }
    const Words<W> words(layout_);
    const std::size_t w = words.count();
    Bucket& out = scratch_;
    out.make_room(target.size() + source.size(), w);
    fmpz* out_coefficients = out.coefficients.data();
    std::uint64_t* out_monomials = out.monomials.data();
    std::size_t n = 0;
    fmpz* const t_coefficients = target.coefficients.data();
    fmpz* const s_coefficients = source.coefficients.data();
    const std::uint64_t* const t_monomials = target.monomials.data();
    const std::uint64_t* const s_monomials = source.monomials.data();
    std::size_t i = target.head, j = source.head;
    const std::size_t i_end = target.count, j_end = source.count;
    auto take = [&](fmpz* coefficients, const std::uint64_t* monomials, std::size_t& k) {
        out_coefficients[n] = coefficients[k];
        words.copy(monomials + k * w, out_monomials + n * w);
        ++n;
        ++k;
    };
    while (i < i_end && j < j_end) {
        const int order = words.compare(t_monomials + i * w, s_monomials + j * w);
        if (order > 0) {
            take(t_coefficients, t_monomials, i);
        } else if (order < 0) {
            take(s_coefficients, s_monomials, j);
        } else {
            // FLINT keeps a zero as the word 0, owning nothing: a cancelled term is dropped.
            add(&t_coefficients[i], &s_coefficients[j]);
            fmpz_clear(&s_coefficients[j]);
            ++j;
            if (fmpz_is_zero(&t_coefficients[i])) {
                ++i;
            } else {
                take(t_coefficients, t_monomials, i);
            }
        }
    }
    while (i < i_end) {
        take(t_coefficients, t_monomials, i);
    }
    while (j < j_end) {
        take(s_coefficients, s_monomials, j);
    }
    out.count = n;
    target.forget();
    source.forget();
    target.swap(out);
}

void GeoBucket::subtract_multiple(const Integer& b, const std::uint64_t* m,
                                  const IntegerPolynomial& g, std::size_t from) {
    if (from >= g.size()) {
        return;
    }
    with_words(layout_, [&]<std::size_t W>() { subtract_multiple_words<W>(b, m, g, from); });
}

template <std::size_t W>
void GeoBucket::subtract_multiple_words(const Integer& b, const std::uint64_t* m,
                                        const IntegerPolynomial& g, std::size_t from) {
    const Words<W> words(layout_);
    const std::size_t w = words.count();
    const std::size_t length = g.size() - from;
    const std::size_t level = level_for(length);
    if (buckets_.size() <= level) {
        buckets_.resize(level + 1);
    }
    Bucket& target = buckets_[level];
    Bucket& out = scratch_;
    out.make_room(target.size() + length, w);
    fmpz* out_coefficients = out.coefficients.data();
    std::uint64_t* out_monomials = out.monomials.data();
    std::size_t n = 0;
    fmpz* const t_coefficients = target.coefficients.data();
    const std::uint64_t* const t_monomials = target.monomials.data();
    product_.resize(w);
    std::uint64_t* const product = product_.data();
    fmpz_neg(negated_.get(), b.get());
    std::size_t i = target.head, j = from;
    const std::size_t i_end = target.count, j_end = g.size();
    std::uint64_t products = words.multiply(g.monomial(j, w), m, product);
    while (i < i_end || j < j_end) {
        int order;
        if (j == j_end) {
            order = 1;
        } else if (i == i_end) {
            order = -1;
        } else {
            order = words.compare(t_monomials + i * w, product);
        }
        if (order > 0) {
            out_coefficients[n] = t_coefficients[i];
            words.copy(t_monomials + i * w, out_monomials + n * w);
            ++n;
            ++i;
            continue;
        }
        if (order < 0) {
            out_coefficients[n] = 0;
            mul(&out_coefficients[n], g.coefficients[j].get(), negated_.get());
            words.copy(product, out_monomials + n * w);
            ++n;
        } else {
            fmpz* c = &t_coefficients[i];
            submul(c, g.coefficients[j].get(), b.get());
            if (!fmpz_is_zero(c)) {
                out_coefficients[n] = *c;
                words.copy(product, out_monomials + n * w);
                ++n;
            }
            ++i;
        }
        if (++j < j_end) {
            products |= words.multiply(g.monomial(j, w), m, product);
        }
    }
    if (words.overflowed(products)) {
        // The merge ran on wrapped exponents and is dropped. The target still owns every term
        // it had (its coefficients changed, which no longer matters: the reduction ends here);
        // the products made fresh belong to nobody and are cleared.
        for (std::size_t k = 0; k < n; ++k) {
            if (COEFF_IS_MPZ(out_coefficients[k]) &&
                std::find(t_coefficients + target.head, t_coefficients + i_end,
                          out_coefficients[k]) == t_coefficients + i_end) {
                fmpz_clear(&out_coefficients[k]);
            }
        }
        throw_product_overflow(layout_, m, g, from);
    }
    out.count = n;
    target.forget();
    target.swap(out);
    carry(level);
}

bool GeoBucket::pop_leading(std::uint64_t* monomial, Integer& coefficient) {
    const std::size_t w = layout_.words();
    for (;;) {
        Bucket* best = nullptr;
        for (Bucket& b : buckets_) {
            if (b.size() != 0 &&
                (best == nullptr || layout_.compare(b.monomials.data() + b.head * w,
                                                    best->monomials.data() + best->head * w) > 0)) {
                best = &b;
            }
        }
        if (best == nullptr) {
            return false;
        }
        std::copy_n(best->monomials.data() + best->head * w, w, monomial);
        // The term's coefficient changes hands.
        fmpz_clear(coefficient.get());
        *coefficient.get() = best->coefficients[best->head];
        ++best->head;
        // Each bucket holds a monomial at most once, so at most one term per other bucket.
        for (Bucket& b : buckets_) {
            if (&b != best && b.size() != 0 &&
                layout_.equal(b.monomials.data() + b.head * w, monomial)) {
                add(coefficient.get(), &b.coefficients[b.head]);
                fmpz_clear(&b.coefficients[b.head]);
                ++b.head;
            }
        }
        if (!coefficient.is_zero()) {
            return true;
        }
    }
}

void GeoBucket::scale(const Integer& a) {
    for (Bucket& b : buckets_) {
        for (std::size_t k = b.head; k < b.count; ++k) {
            mul(&b.coefficients[k], &b.coefficients[k], a.get());
        }
    }
}

void GeoBucket::fold_content(Integer& g) const {
    for (const Bucket& b : buckets_) {
        for (std::size_t k = b.head; k < b.count; ++k) {
            fmpz_gcd(g.get(), g.get(), &b.coefficients[k]);
            if (g.is_one()) {
                return;
            }
        }
    }
}

void GeoBucket::divide_exactly(const Integer& g) {
    for (Bucket& b : buckets_) {
        for (std::size_t k = b.head; k < b.count; ++k) {
            fmpz_divexact(&b.coefficients[k], &b.coefficients[k], g.get());
        }
    }
}

void GeoBucket::drain_into(IntegerPolynomial& out) {
    std::vector<std::uint64_t> monomial(layout_.words());
    Integer coefficient;
    while (pop_leading(monomial.data(), coefficient)) {
        out.coefficients.emplace_back(std::move(coefficient));
        out.monomials.insert(out.monomials.end(), monomial.begin(), monomial.end());
    }
}

}  // namespace locus::algebra::detail
