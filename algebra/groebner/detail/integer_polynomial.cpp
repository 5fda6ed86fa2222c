#include "algebra/groebner/detail/integer_polynomial.h"

#include <algorithm>

#include "algebra/error.h"

namespace locus::algebra::detail {

std::vector<IntegerPolynomial> sorted_integer_generators(std::span<const Polynomial> generators) {
    std::vector<IntegerPolynomial> inputs;
    if (generators.empty()) {
        return inputs;
    }
    for (const Polynomial& g : generators) {
        require_same_ring(generators[0], g);
        if (!g.is_zero()) {
            inputs.push_back(to_integer_polynomial(g));
        }
    }
    const MonomialLayout& layout = generators[0].ring()->layout();
    const std::size_t w = layout.words();
    std::sort(inputs.begin(), inputs.end(),
              [&](const IntegerPolynomial& a, const IntegerPolynomial& b) {
                  return layout.compare(a.monomial(0, w), b.monomial(0, w)) < 0;
              });
    return inputs;
}

IntegerPolynomial to_integer_polynomial(const Polynomial& f) {
    IntegerPolynomial p;
    const std::size_t w = f.ring()->words();
    Integer den_lcm(1);
    for (std::size_t i = 0; i < f.num_terms(); ++i) {
        fmpz_lcm(den_lcm.get(), den_lcm.get(), f.coefficient(i).denominator());
    }
    p.monomials.reserve(f.num_terms() * w);
    p.coefficients.reserve(f.num_terms());
    Integer c;
    for (std::size_t i = 0; i < f.num_terms(); ++i) {
        fmpz_divexact(c.get(), den_lcm.get(), f.coefficient(i).denominator());
        fmpz_mul(c.get(), c.get(), f.coefficient(i).numerator());
        p.coefficients.push_back(c);
        p.monomials.insert(p.monomials.end(), f.monomial(i), f.monomial(i) + w);
    }
    make_primitive(p);
    if (!p.empty()) {
        for (std::size_t i = 0; i < p.size(); ++i) {
            p.sugar = std::max(p.sugar, f.ring()->layout().leading_weight(p.monomial(i, w)));
        }
        p.leading_mask = f.ring()->layout().divisibility_mask(p.monomials.data());
    }
    return p;
}

Polynomial to_monic_polynomial(const IntegerPolynomial& f, const RingPtr& ring) {
    Polynomial p(ring);
    p.reserve(f.size());
    const std::size_t w = ring->words();
    for (std::size_t i = 0; i < f.size(); ++i) {
        p.push_back_term(Rational(f.coefficients[i], f.coefficients[0]), f.monomial(i, w));
    }
    return p;
}

Polynomial to_primitive_polynomial(const IntegerPolynomial& f, const RingPtr& ring) {
    Polynomial p(ring);
    p.reserve(f.size());
    const std::size_t w = ring->words();
    for (std::size_t i = 0; i < f.size(); ++i) {
        p.push_back_term(Rational(f.coefficients[i]), f.monomial(i, w));
    }
    return p;
}

void make_primitive(IntegerPolynomial& f) {
    if (f.empty()) {
        return;
    }
    Integer g;
    for (const auto& c : f.coefficients) {
        fmpz_gcd(g.get(), g.get(), c.get());
        if (g.is_one()) {
            break;
        }
    }
    if (f.coefficients[0].sign() < 0) {
        fmpz_neg(g.get(), g.get());
    }
    if (!g.is_one()) {
        for (auto& c : f.coefficients) {
            fmpz_divexact(c.get(), c.get(), g.get());
        }
    }
}

}  // namespace locus::algebra::detail
