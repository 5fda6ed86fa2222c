#include "algebra/polynomial.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "algebra/assert.h"
#include "algebra/error.h"

namespace locus::algebra {

void require_same_ring(const Polynomial& f, const Polynomial& g) {
    if (!same_ring(f.ring(), g.ring())) {
        throw MixedRings();
    }
}

Polynomial Polynomial::constant(RingPtr ring, Rational value) {
    Polynomial p(std::move(ring));
    if (!value.is_zero()) {
        p.monomials_.assign(p.ring_->words(), 0);
        p.coefficients_.push_back(std::move(value));
    }
    return p;
}

Polynomial Polynomial::variable(RingPtr ring, std::size_t var) {
    std::vector<std::uint32_t> e(ring->num_vars(), 0);
    e.at(var) = 1;
    return term(std::move(ring), Rational(1), e);
}

Polynomial Polynomial::term(RingPtr ring, Rational c, std::span<const std::uint32_t> exponents) {
    Polynomial p(std::move(ring));
    if (!c.is_zero()) {
        p.monomials_.resize(p.ring_->words());
        p.ring_->layout().pack(exponents, p.monomials_.data());
        p.coefficients_.push_back(std::move(c));
    }
    return p;
}

Polynomial Polynomial::from_terms(
    RingPtr ring, std::vector<std::pair<Rational, std::vector<std::uint32_t>>> terms) {
    const MonomialLayout& layout = ring->layout();
    const std::size_t w = ring->words();
    std::vector<std::uint64_t> packed(terms.size() * w);
    for (std::size_t i = 0; i < terms.size(); ++i) {
        layout.pack(terms[i].second, packed.data() + i * w);
    }
    std::vector<std::size_t> idx(terms.size());
    std::iota(idx.begin(), idx.end(), 0);
    std::sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) {
        return layout.compare(packed.data() + a * w, packed.data() + b * w) > 0;
    });
    Polynomial p(std::move(ring));
    for (std::size_t k = 0; k < idx.size();) {
        Rational sum = std::move(terms[idx[k]].first);
        std::size_t j = k + 1;
        while (j < idx.size() &&
               layout.equal(packed.data() + idx[j] * w, packed.data() + idx[k] * w)) {
            sum += terms[idx[j]].first;
            ++j;
        }
        if (!sum.is_zero()) {
            p.push_back_term(std::move(sum), packed.data() + idx[k] * w);
        }
        k = j;
    }
    return p;
}

bool Polynomial::is_constant() const {
    return is_zero() || (num_terms() == 1 && ring_->layout().is_one(monomial(0)));
}

bool Polynomial::is_canonical() const {
    const auto& layout = ring_->layout();
    if (monomials_.size() != coefficients_.size() * ring_->words()) {
        return false;
    }
    for (std::size_t i = 0; i < num_terms(); ++i) {
        if (coefficients_[i].is_zero()) {
            return false;
        }
        if (i > 0 && layout.compare(monomial(i - 1), monomial(i)) <= 0) {
            return false;
        }
    }
    return true;
}

std::vector<std::uint32_t> Polynomial::exponents(std::size_t i) const {
    std::vector<std::uint32_t> e(ring_->num_vars());
    ring_->layout().unpack(monomial(i), e);
    return e;
}

long Polynomial::total_degree() const {
    long d = -1;
    for (std::size_t i = 0; i < num_terms(); ++i) {
        d = std::max<long>(d, ring_->layout().total_degree(monomial(i)));
    }
    return d;
}

long Polynomial::degree(std::size_t var) const {
    long d = -1;
    for (std::size_t i = 0; i < num_terms(); ++i) {
        d = std::max<long>(d, ring_->layout().exponent(monomial(i), var));
    }
    return d;
}

void Polynomial::push_back_term(Rational c, const std::uint64_t* m) {
    // Canonical form: non-zero coefficients, monomials strictly decreasing, guard bits clear.
    LOCUS_ASSERT(!c.is_zero());
    LOCUS_ASSERT(ring_->layout().guards_clear(m));
    LOCUS_ASSERT(is_zero() || ring_->layout().compare(monomial(num_terms() - 1), m) > 0);
    monomials_.insert(monomials_.end(), m, m + ring_->words());
    coefficients_.push_back(std::move(c));
}

void Polynomial::reserve(std::size_t terms) {
    monomials_.reserve(terms * ring_->words());
    coefficients_.reserve(terms);
}

Polynomial Polynomial::operator-() const {
    Polynomial r = *this;
    for (auto& c : r.coefficients_) {
        fmpq_neg(c.get(), c.get());
    }
    return r;
}

Polynomial& Polynomial::operator*=(const Rational& c) {
    if (c.is_zero()) {
        monomials_.clear();
        coefficients_.clear();
        return *this;
    }
    for (auto& a : coefficients_) {
        a *= c;
    }
    return *this;
}

namespace {

// Merge f + sign·(c·m·g) for the three additive operations; m == nullptr means 1, c == nullptr
// means 1.
Polynomial merge(const Polynomial& f, const Polynomial& g, bool subtract, const Rational* c,
                 const std::uint64_t* m) {
    require_same_ring(f, g);
    const auto& layout = f.ring()->layout();
    const std::size_t w = f.ring()->words();
    Polynomial r(f.ring());
    r.reserve(f.num_terms() + g.num_terms());
    std::vector<std::uint64_t> gm(w);
    Rational gc;
    std::size_t i = 0, j = 0;
    auto load_g = [&](std::size_t k) {
        if (m) {
            layout.multiply(g.monomial(k), m, gm.data());
        } else {
            std::copy(g.monomial(k), g.monomial(k) + w, gm.begin());
        }
        gc = g.coefficient(k);
        if (c) {
            gc *= *c;
        }
        if (subtract) {
            fmpq_neg(gc.get(), gc.get());
        }
    };
    if (j < g.num_terms()) {
        load_g(j);
    }
    while (i < f.num_terms() || j < g.num_terms()) {
        int cmp;
        if (i == f.num_terms()) {
            cmp = -1;
        } else if (j == g.num_terms()) {
            cmp = 1;
        } else {
            cmp = layout.compare(f.monomial(i), gm.data());
        }
        if (cmp > 0) {
            r.push_back_term(f.coefficient(i), f.monomial(i));
            ++i;
        } else if (cmp < 0) {
            r.push_back_term(std::move(gc), gm.data());
            if (++j < g.num_terms()) {
                load_g(j);
            }
        } else {
            gc += f.coefficient(i);
            if (!gc.is_zero()) {
                r.push_back_term(std::move(gc), gm.data());
            }
            ++i;
            if (++j < g.num_terms()) {
                load_g(j);
            }
        }
    }
    return r;
}

}  // namespace

Polynomial operator+(const Polynomial& f, const Polynomial& g) {
    return merge(f, g, false, nullptr, nullptr);
}

Polynomial operator-(const Polynomial& f, const Polynomial& g) {
    return merge(f, g, true, nullptr, nullptr);
}

Polynomial Polynomial::minus_term_times(const Rational& c, const std::uint64_t* m,
                                        const Polynomial& g) const {
    return merge(*this, g, true, &c, m);
}

Polynomial Polynomial::times_term(const Rational& c, const std::uint64_t* m) const {
    Polynomial r(ring_);
    if (c.is_zero()) {
        return r;
    }
    r.reserve(num_terms());
    std::vector<std::uint64_t> prod(ring_->words());
    for (std::size_t i = 0; i < num_terms(); ++i) {
        ring_->layout().multiply(monomial(i), m, prod.data());
        r.push_back_term(coefficients_[i] * c, prod.data());
    }
    return r;
}

bool operator==(const Polynomial& f, const Polynomial& g) {
    require_same_ring(f, g);
    return f.monomials_ == g.monomials_ && f.coefficients_ == g.coefficients_;
}

Polynomial operator*(const Polynomial& a, const Polynomial& b) {
    require_same_ring(a, b);
    // Johnson's heap: one cursor per term of the shorter factor `f`, walking along `g`.
    const Polynomial& f = a.num_terms() <= b.num_terms() ? a : b;
    const Polynomial& g = a.num_terms() <= b.num_terms() ? b : a;
    Polynomial r(f.ring());
    if (f.is_zero()) {
        return r;
    }
    const auto& layout = f.ring()->layout();
    const std::size_t w = f.ring()->words();
    const std::size_t n = f.num_terms();
    std::vector<std::size_t> cursor(n, 0);      // next term of g for row i
    std::vector<std::uint64_t> current(n * w);  // monomial f_i · g_cursor[i]
    std::vector<std::size_t> heap;              // rows, max-heap by current monomial
    heap.reserve(n);
    auto less = [&](std::size_t x, std::size_t y) {
        return layout.compare(current.data() + x * w, current.data() + y * w) < 0;
    };
    for (std::size_t i = 0; i < n; ++i) {
        layout.multiply(f.monomial(i), g.monomial(0), current.data() + i * w);
        heap.push_back(i);
    }
    std::make_heap(heap.begin(), heap.end(), less);
    std::vector<std::uint64_t> top(w);
    Rational sum, product;
    while (!heap.empty()) {
        const std::size_t row0 = heap.front();
        std::copy(current.data() + row0 * w, current.data() + (row0 + 1) * w, top.begin());
        fmpq_zero(sum.get());
        // Pop every cursor sitting on this monomial, advance it, and push it back.
        while (!heap.empty() && layout.equal(current.data() + heap.front() * w, top.data())) {
            std::pop_heap(heap.begin(), heap.end(), less);
            const std::size_t row = heap.back();
            heap.pop_back();
            fmpq_mul(product.get(), f.coefficient(row).get(), g.coefficient(cursor[row]).get());
            sum += product;
            if (++cursor[row] < g.num_terms()) {
                layout.multiply(f.monomial(row), g.monomial(cursor[row]), current.data() + row * w);
                heap.push_back(row);
                std::push_heap(heap.begin(), heap.end(), less);
            }
        }
        if (!sum.is_zero()) {
            r.push_back_term(sum, top.data());
        }
    }
    return r;
}

double Polynomial::widest_coefficient_bits() const {
    double widest = 0.0;
    for (const Rational& c : coefficients_) {
        widest = std::max(
            widest, static_cast<double>(fmpz_bits(c.numerator()) + fmpz_bits(c.denominator())));
    }
    return widest;
}

Polynomial Polynomial::pow(unsigned exponent) const {
    if (exponent > 1 && num_terms() > 1) {
        // Terms of p^j: at most C(n + j − 1, j) for n terms, and at most Π (j·deg_v + 1).
        const auto terms_bound = [this](unsigned j) {
            double multinomial = 1.0;
            const double n = static_cast<double>(num_terms());
            for (unsigned i = 1; i <= j && multinomial <= kMaxPowerTerms; ++i) {
                multinomial *= (n - 1.0 + i) / i;
            }
            double ranges = 1.0;
            for (std::size_t v = 0; v < ring_->num_vars() && ranges <= kMaxPowerTerms; ++v) {
                ranges *= static_cast<double>(j) * std::max<long>(0, degree(v)) + 1.0;
            }
            return std::min(multinomial, ranges);
        };
        const std::string what = "a power of a polynomial with " + std::to_string(num_terms()) +
                                 " terms to the exponent " + std::to_string(exponent);
        if (terms_bound(exponent) > kMaxPowerTerms) {
            throw ResourceLimit(what + " could have more than " +
                                std::to_string(static_cast<long>(kMaxPowerTerms)) +
                                " terms (the limit)");
        }
        // The last multiplication of binary powering pairs the terms of two halves, and each
        // product multiplies coefficients that grew with the exponent: a coefficient of p^j has
        // at most j·(log2 n + b) bits, b the widest coefficient of p (numerator and
        // denominator). Counting a product as one unit per 64-bit limb of the wider half keeps
        // the bound in seconds whether the work is in the count ((1+s^2+t^2)^555: 1.5e9
        // products) or in the width ((1-t)^3015: 2.3e6 products of 1500-bit numbers, 5 s).
        const unsigned upper_half = exponent - exponent / 2;
        const double limbs_per_product =
            1.0 + upper_half *
                      (std::log2(static_cast<double>(num_terms())) + widest_coefficient_bits()) /
                      64.0;
        if (terms_bound(upper_half) * terms_bound(exponent / 2) * limbs_per_product >
            kMaxPowerWork) {
            throw ResourceLimit(what + " would take more than " +
                                std::to_string(static_cast<long>(kMaxPowerWork)) +
                                " limb products to expand (the limit)");
        }
    }
    Polynomial result = constant(ring_, Rational(1));
    Polynomial base = *this;
    while (exponent > 0) {
        if (exponent & 1u) {
            result *= base;
        }
        exponent >>= 1;
        if (exponent > 0) {
            base *= base;
        }
    }
    return result;
}

Rational Polynomial::evaluate(std::span<const Rational> point) const {
    if (point.size() != ring_->num_vars()) {
        throw InputError("evaluate", "the point needs one value per variable");
    }
    Rational total, term_value, power;
    std::vector<std::uint32_t> e(ring_->num_vars());
    for (std::size_t i = 0; i < num_terms(); ++i) {
        ring_->layout().unpack(monomial(i), e);
        term_value = coefficients_[i];
        for (std::size_t v = 0; v < e.size(); ++v) {
            if (e[v] != 0) {
                fmpq_pow_si(power.get(), point[v].get(), e[v]);
                term_value *= power;
            }
        }
        total += term_value;
    }
    return total;
}

Polynomial Polynomial::derivative(std::size_t var) const {
    if (var >= ring_->num_vars()) {
        throw InputError("derivative", "no variable with index " + std::to_string(var));
    }
    Polynomial r(ring_);
    std::vector<std::uint32_t> e(ring_->num_vars());
    std::vector<std::uint64_t> m(ring_->words());
    // Lowering one exponent keeps the relative order of the surviving terms (multiplicativity
    // of the order: a > b and x | a, x | b imply a/x > b/x).
    for (std::size_t i = 0; i < num_terms(); ++i) {
        ring_->layout().unpack(monomial(i), e);
        if (e[var] == 0) {
            continue;
        }
        const Rational factor(static_cast<long>(e[var]));
        --e[var];
        ring_->layout().pack(e, m.data());
        r.push_back_term(coefficients_[i] * factor, m.data());
    }
    return r;
}

Polynomial Polynomial::substitute(std::span<const Polynomial> values) const {
    if (values.size() != ring_->num_vars() || values.empty()) {
        throw InputError("substitute", "needs one polynomial per variable");
    }
    const RingPtr& target = values[0].ring();
    for (const auto& v : values) {
        if (!same_ring(v.ring(), target)) {
            throw MixedRings();
        }
    }
    // Powers are cached per variable; the sum is accumulated term by term.
    std::vector<std::vector<Polynomial>> powers(values.size());
    auto power = [&](std::size_t v, std::uint32_t k) -> const Polynomial& {
        auto& cache = powers[v];
        if (cache.empty()) {
            cache.push_back(constant(target, Rational(1)));
        }
        while (cache.size() <= k) {
            cache.push_back(cache.back() * values[v]);
        }
        return cache[k];
    };
    Polynomial result(target);
    std::vector<std::uint32_t> e(ring_->num_vars());
    for (std::size_t i = 0; i < num_terms(); ++i) {
        ring_->layout().unpack(monomial(i), e);
        Polynomial t = constant(target, coefficients_[i]);
        for (std::size_t v = 0; v < e.size(); ++v) {
            if (e[v] != 0) {
                t *= power(v, e[v]);
            }
        }
        result += t;
    }
    return result;
}

Rational Polynomial::content() const {
    if (is_zero()) {
        return Rational();
    }
    Integer num_gcd, den_lcm(1);
    for (const auto& c : coefficients_) {
        fmpz_gcd(num_gcd.get(), num_gcd.get(), c.numerator());
        fmpz_lcm(den_lcm.get(), den_lcm.get(), c.denominator());
    }
    return Rational(num_gcd, den_lcm);
}

Polynomial Polynomial::primitive_part() const {
    if (is_zero()) {
        return *this;
    }
    Rational c = content();
    if (leading_coefficient().sign() < 0) {
        c = -c;
    }
    Rational inverse;
    fmpq_inv(inverse.get(), c.get());
    return *this * inverse;
}

Polynomial Polynomial::monic() const {
    if (is_zero()) {
        return *this;
    }
    Rational inverse;
    fmpq_inv(inverse.get(), leading_coefficient().get());
    return *this * inverse;
}

Polynomial Polynomial::in_ring(RingPtr target) const {
    if (target->num_vars() != ring_->num_vars()) {
        throw MixedRings();
    }
    std::vector<std::size_t> identity(ring_->num_vars());
    std::iota(identity.begin(), identity.end(), 0);
    return in_ring(std::move(target), identity);
}

Polynomial Polynomial::in_ring(RingPtr target, std::span<const std::size_t> variable_map) const {
    std::vector<std::pair<Rational, std::vector<std::uint32_t>>> terms;
    terms.reserve(num_terms());
    std::vector<std::uint32_t> e(ring_->num_vars());
    for (std::size_t i = 0; i < num_terms(); ++i) {
        ring_->layout().unpack(monomial(i), e);
        std::vector<std::uint32_t> mapped(target->num_vars(), 0);
        for (std::size_t v = 0; v < e.size(); ++v) {
            if (e[v] != 0) {
                mapped.at(variable_map[v]) += e[v];
            }
        }
        terms.emplace_back(coefficients_[i], std::move(mapped));
    }
    return from_terms(std::move(target), std::move(terms));
}

bool Polynomial::contains_variable(std::size_t var) const {
    for (std::size_t i = 0; i < num_terms(); ++i) {
        if (ring_->layout().exponent(monomial(i), var) != 0) {
            return true;
        }
    }
    return false;
}

}  // namespace locus::algebra
