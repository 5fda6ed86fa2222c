#include "algebra/groebner/geobucket.h"

#include <algorithm>

#include "algebra/groebner/small_integer.h"

namespace locus::algebra::detail {

namespace {

// One packed monomial (w words) from `from` to `to`. Rings of up to seven variables under a
// degree order take two words: spelled out for one and two, a copy is two moves rather than a
// loop (std::copy_n with a run-time count was 4 % of eco-7's instructions).
inline void copy_monomial(const std::uint64_t* from, std::size_t w, std::uint64_t* to) {
    if (w == 2) {
        to[0] = from[0];
        to[1] = from[1];
    } else if (w == 1) {
        to[0] = from[0];
    } else {
        std::copy_n(from, w, to);
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
        b.clear();
    }
    if (p.empty()) {
        return;
    }
    const std::size_t level = level_for(p.size());
    if (buckets_.size() <= level) {
        buckets_.resize(level + 1);
    }
    buckets_[level].monomials = std::move(p.monomials);
    buckets_[level].coefficients = std::move(p.coefficients);
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
    if (source.size() == 0) {
        source.clear();
        return;
    }
    if (target.size() == 0) {
        std::swap(target, source);
        source.clear();
        return;
    }
    const std::size_t w = layout_.words();
    Bucket& out = scratch_;
    out.clear();
    // Monomials are written by index: an insert per term was a call to memmove for 1–2 words.
    out.coefficients.reserve(target.size() + source.size());
    std::uint64_t* written = out.monomial_storage((target.size() + source.size()) * w);
    std::size_t i = target.head, j = source.head;
    const std::size_t i_end = target.coefficients.size(), j_end = source.coefficients.size();
    auto take = [&](Bucket& from, std::size_t& k) {
        out.coefficients.emplace_back(std::move(from.coefficients[k]));
        copy_monomial(from.monomials.data() + k * w, w, written);
        written += w;
        ++k;
    };
    while (i < i_end && j < j_end) {
        const int order =
            layout_.compare(target.monomials.data() + i * w, source.monomials.data() + j * w);
        if (order > 0) {
            take(target, i);
        } else if (order < 0) {
            take(source, j);
        } else {
            Integer& sum = target.coefficients[i];
            add(sum.get(), source.coefficients[j].get());
            ++j;
            if (sum.is_zero()) {
                ++i;
            } else {
                take(target, i);
            }
        }
    }
    while (i < i_end) {
        take(target, i);
    }
    while (j < j_end) {
        take(source, j);
    }
    std::swap(target, out);
    source.clear();
}

void GeoBucket::subtract_multiple(const Integer& b, const std::uint64_t* m,
                                  const IntegerPolynomial& g, std::size_t from) {
    if (from >= g.size()) {
        return;
    }
    const std::size_t w = layout_.words();
    const std::size_t length = g.size() - from;
    const std::size_t level = level_for(length);
    if (buckets_.size() <= level) {
        buckets_.resize(level + 1);
    }
    Bucket& target = buckets_[level];
    Bucket& out = scratch_;
    out.clear();
    out.coefficients.reserve(target.size() + length);
    std::uint64_t* written = out.monomial_storage((target.size() + length) * w);
    product_.resize(w);
    fmpz_neg(negated_.get(), b.get());
    std::size_t i = target.head, j = from;
    const std::size_t i_end = target.coefficients.size();
    layout_.multiply(g.monomial(j, w), m, product_.data());
    while (i < i_end || j < g.size()) {
        int order;
        if (j == g.size()) {
            order = 1;
        } else if (i == i_end) {
            order = -1;
        } else {
            order = layout_.compare(target.monomials.data() + i * w, product_.data());
        }
        if (order > 0) {
            out.coefficients.emplace_back(std::move(target.coefficients[i]));
            copy_monomial(target.monomials.data() + i * w, w, written);
            written += w;
            ++i;
            continue;
        }
        if (order < 0) {
            out.coefficients.emplace_back();
            mul(out.coefficients.back().get(), g.coefficients[j].get(), negated_.get());
            copy_monomial(product_.data(), w, written);
            written += w;
        } else {
            Integer& c = target.coefficients[i];
            submul(c.get(), g.coefficients[j].get(), b.get());
            if (!c.is_zero()) {
                out.coefficients.emplace_back(std::move(c));
                copy_monomial(product_.data(), w, written);
                written += w;
            }
            ++i;
        }
        if (++j < g.size()) {
            layout_.multiply(g.monomial(j, w), m, product_.data());
        }
    }
    std::swap(target, out);
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
        copy_monomial(best->monomials.data() + best->head * w, w, monomial);
        fmpz_swap(coefficient.get(), best->coefficients[best->head].get());
        ++best->head;
        // Each bucket holds a monomial at most once, so at most one term per other bucket.
        for (Bucket& b : buckets_) {
            if (&b != best && b.size() != 0 &&
                layout_.equal(b.monomials.data() + b.head * w, monomial)) {
                add(coefficient.get(), b.coefficients[b.head].get());
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
        for (std::size_t k = b.head; k < b.coefficients.size(); ++k) {
            mul(b.coefficients[k].get(), b.coefficients[k].get(), a.get());
        }
    }
}

void GeoBucket::fold_content(Integer& g) const {
    for (const Bucket& b : buckets_) {
        for (std::size_t k = b.head; k < b.coefficients.size(); ++k) {
            fmpz_gcd(g.get(), g.get(), b.coefficients[k].get());
            if (g.is_one()) {
                return;
            }
        }
    }
}

void GeoBucket::divide_exactly(const Integer& g) {
    for (Bucket& b : buckets_) {
        for (std::size_t k = b.head; k < b.coefficients.size(); ++k) {
            fmpz_divexact(b.coefficients[k].get(), b.coefficients[k].get(), g.get());
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
