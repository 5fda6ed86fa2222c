#include "algebra/groebner/detail/reduction.h"
#include "algebra/deadline.h"

#include <algorithm>

namespace locus::algebra::detail {

void ReducerSearch::gather(const std::vector<BasisElement>& basis, const MonomialLayout& layout) {
    const std::size_t w = layout.words();
    order_.clear();
    for (std::size_t k = 0; k < basis.size(); ++k) {
        if (!basis[k].redundant) {
            order_.push_back({fmpz_bits(basis[k].poly.coefficients[0].get()), k});
        }
    }
    std::sort(order_.begin(), order_.end());
    masks_.clear();
    monomials_.clear();
    indices_.clear();
    for (const auto& [bits, k] : order_) {
        const IntegerPolynomial& g = basis[k].poly;
        masks_.push_back(g.leading_mask);
        monomials_.insert(monomials_.end(), g.monomial(0, w), g.monomial(0, w) + w);
        indices_.push_back(k);
    }
}

void Reducer::combine(IntegerPolynomial& p, std::size_t from, const Integer& a, const Integer& b,
                      const std::uint64_t* m, const IntegerPolynomial& g) {
    const std::size_t w = layout_.words();
    IntegerPolynomial& out = scratch_;
    out.monomials.clear();
    out.coefficients.clear();
    out.monomials.reserve((p.size() - from + g.size()) * w);
    out.coefficients.reserve(p.size() - from + g.size());
    product_.resize(w);
    const bool scale = !a.is_one();
    std::size_t i = from, j = 1;
    if (j < g.size()) {
        layout_.multiply(g.monomial(j, w), m, product_.data());
    }
    while (i < p.size() || j < g.size()) {
        int cmp;
        if (i == p.size()) {
            cmp = -1;
        } else if (j == g.size()) {
            cmp = 1;
        } else {
            cmp = layout_.compare(p.monomial(i, w), product_.data());
        }
        if (cmp > 0) {
            out.coefficients.emplace_back(std::move(p.coefficients[i]));
            if (scale) {
                fmpz_mul(out.coefficients.back().get(), out.coefficients.back().get(), a.get());
            }
            out.monomials.insert(out.monomials.end(), p.monomial(i, w), p.monomial(i, w) + w);
            ++i;
            continue;
        }
        if (cmp < 0) {
            out.coefficients.emplace_back();
            fmpz_mul(out.coefficients.back().get(), g.coefficients[j].get(), b.get());
            fmpz_neg(out.coefficients.back().get(), out.coefficients.back().get());
            out.monomials.insert(out.monomials.end(), product_.begin(), product_.end());
        } else {
            Integer& c = p.coefficients[i];
            if (scale) {
                fmpz_mul(c.get(), c.get(), a.get());
            }
            fmpz_submul(c.get(), g.coefficients[j].get(), b.get());
            if (!c.is_zero()) {
                out.coefficients.emplace_back(std::move(c));
                out.monomials.insert(out.monomials.end(), product_.begin(), product_.end());
            }
            ++i;
        }
        if (++j < g.size()) {
            layout_.multiply(g.monomial(j, w), m, product_.data());
        }
    }
    std::swap(p.monomials, out.monomials);
    std::swap(p.coefficients, out.coefficients);
}

bool Reducer::deadline_passed(bool costly_step) {
    if (!deadline_ || (!costly_step && --steps_to_check_ > 0)) {
        return false;
    }
    steps_to_check_ = 16;
    return locus::deadline_passed(*deadline_);
}

IntegerPolynomial Reducer::reduce(IntegerPolynomial p, const std::vector<BasisElement>& basis,
                                  ReductionCounts& counts, bool tail,
                                  const ReducerAdmission* admission) {
    const std::size_t w = layout_.words();
    IntegerPolynomial result;
    result.sugar = p.sugar;
    std::size_t bits_after_content = p.empty() ? 0 : fmpz_bits(p.coefficients[0].get());
    GeoBucket& bucket = bucket_;
    bucket.assign(std::move(p));
    std::vector<std::uint64_t>& lm = leading_;
    std::vector<std::uint64_t>& m = multiplier_;
    lm.resize(w);
    m.resize(w);
    Integer lc, g, a, b;
    search_.gather(basis, layout_);
    while (bucket.pop_leading(lm.data(), lc)) {
        // Fraction-free steps multiply everything by a each time, but much of that growth is a
        // common factor: divide it out whenever the coefficients have doubled in size since
        // the last time (Singular does the same with p_Content during long reductions).
        std::size_t bits = fmpz_bits(lc.get());
        if (!result.empty()) {
            bits = std::max<std::size_t>(bits, fmpz_bits(result.coefficients[0].get()));
        }
        if (bits > 2 * bits_after_content + 64) {
            // A gcd over every coefficient: on 10⁶-bit coefficients it takes seconds.
            if (deadline_passed(true)) {
                throw ReductionInterrupted{};
            }
            Integer content(lc);
            for (const Integer& c : result.coefficients) {
                fmpz_gcd(content.get(), content.get(), c.get());
            }
            bucket.fold_content(content);
            fmpz_abs(content.get(), content.get());
            if (!content.is_one() && !content.is_zero()) {
                fmpz_divexact(lc.get(), lc.get(), content.get());
                for (Integer& c : result.coefficients) {
                    fmpz_divexact(c.get(), c.get(), content.get());
                }
                bucket.divide_exactly(content);
            }
            bits_after_content = fmpz_bits(lc.get());
            if (!result.empty()) {
                bits_after_content = std::max<std::size_t>(bits_after_content,
                                                           fmpz_bits(result.coefficients[0].get()));
            }
        }
        const long k = search_.find(lm.data(), layout_, admission, m.data());
        if (k < 0) {
            result.coefficients.emplace_back(std::move(lc));
            result.monomials.insert(result.monomials.end(), lm.begin(), lm.end());
            if (!tail) {
                bucket.drain_into(result);  // top reduction only: keep the rest as it is
                break;
            }
            continue;
        }
        const IntegerPolynomial& r = basis[static_cast<std::size_t>(k)].poly;
        layout_.divide(lm.data(), r.monomial(0, w), m.data());
        fmpz_gcd(g.get(), lc.get(), r.coefficients[0].get());
        fmpz_divexact(a.get(), r.coefficients[0].get(), g.get());
        fmpz_divexact(b.get(), lc.get(), g.get());
        if (a.sign() < 0) {
            fmpz_neg(a.get(), a.get());
            fmpz_neg(b.get(), b.get());
        }
        // a·p − b·m·r: the leading terms cancel, leaving a·(p − lt p) − b·m·(r − lt r); the
        // terms already moved to the result are scaled by a as well.
        if (!a.is_one()) {
            for (auto& c : result.coefficients) {
                fmpz_mul(c.get(), c.get(), a.get());
            }
            bucket.scale(a);
        }
        const std::uint32_t sugar = layout_.leading_weight(m.data()) + r.sugar;
        result.sugar = std::max(result.sugar, sugar);
        bucket.subtract_multiple(b, m.data(), r, 1);
        ++counts.steps;
        if (deadline_passed(bits + fmpz_bits(r.coefficients[0].get()) > 4096)) {
            throw ReductionInterrupted{};
        }
    }
    make_primitive(result);
    if (!result.empty()) {
        result.leading_mask = layout_.divisibility_mask(result.monomials.data());
    }
    return result;
}

IntegerPolynomial Reducer::s_polynomial(const IntegerPolynomial& f, const IntegerPolynomial& g,
                                        const std::uint64_t* lcm, std::uint32_t sugar) {
    const std::size_t w = layout_.words();
    std::vector<std::uint64_t> mf(w), mg(w);
    layout_.divide(lcm, f.monomial(0, w), mf.data());
    layout_.divide(lcm, g.monomial(0, w), mg.data());
    Integer d, a, b;
    fmpz_gcd(d.get(), f.coefficients[0].get(), g.coefficients[0].get());
    fmpz_divexact(a.get(), g.coefficients[0].get(), d.get());  // multiplies f
    fmpz_divexact(b.get(), f.coefficients[0].get(), d.get());  // multiplies g
    // s = a·mf·f − b·mg·g; build a·mf·f[1..] and combine with g.
    IntegerPolynomial s;
    s.sugar = sugar;
    s.monomials.resize(f.size() * w);
    s.coefficients.resize(f.size());
    for (std::size_t i = 0; i < f.size(); ++i) {
        layout_.multiply(f.monomial(i, w), mf.data(), s.monomials.data() + i * w);
        fmpz_mul(s.coefficients[i].get(), f.coefficients[i].get(), a.get());
    }
    combine(s, 1, Integer(1), b, mg.data(), g);
    return s;
}

}  // namespace locus::algebra::detail
