// Sparse multivariate polynomials over Q in a PolyRing.
//
// Invariant (checked by is_canonical() in tests): terms are strictly descending under the
// ring's order, no coefficient is zero, and every monomial is packed by the ring's layout.
// Coefficients are canonical fmpq values (rational.h), never doubles. The zero polynomial has
// no terms. Every binary operation requires both operands in equal rings (MixedRings).
//
// Multiplication uses Johnson's heap of |f| cursors (Monagan–Pearce, "Sparse polynomial
// division using a heap", 2011), so a product of n·m terms needs O(min(n, m)) extra memory.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "algebra/poly_ring.h"
#include "algebra/rational.h"

namespace locus::algebra {

// The most terms Polynomial::pow will build, and the most work it will do, counted in products
// of 64-bit limbs (a term product of two 640-bit coefficients counts 11): about a second here.
// The work bound is a build setting because the fuzz preset lowers it tenfold, as SQLite's fuzz
// harnesses lower its length limits: the sanitizers slow the products some 30-fold, and an input
// refused at the bound must still be refused within the fuzzer's 10 s. What the fuzzers check,
// that all work is counted and bounded, does not depend on the value.
#ifndef LOCUS_MAX_POWER_WORK
#define LOCUS_MAX_POWER_WORK 1e7
#endif
inline constexpr double kMaxPowerTerms = 1e7;
inline constexpr double kMaxPowerWork = LOCUS_MAX_POWER_WORK;

class Polynomial {
  public:
    explicit Polynomial(RingPtr ring) : ring_(std::move(ring)) {}
    static Polynomial constant(RingPtr ring, Rational value);
    static Polynomial variable(RingPtr ring, std::size_t var);
    // c · x^exponents.
    static Polynomial term(RingPtr ring, Rational c, std::span<const std::uint32_t> exponents);
    // From terms in any order; equal monomials are added and zero terms dropped.
    static Polynomial from_terms(
        RingPtr ring, std::vector<std::pair<Rational, std::vector<std::uint32_t>>> terms);

    const RingPtr& ring() const { return ring_; }
    std::size_t num_terms() const { return coefficients_.size(); }
    bool is_zero() const { return coefficients_.empty(); }
    bool is_constant() const;  // zero included
    // Bits of the widest coefficient, numerator and denominator together (0 for zero): what
    // the work bounds of powers and parsed expressions weigh a term product by.
    double widest_coefficient_bits() const;
    bool is_canonical() const;

    const Rational& coefficient(std::size_t i) const { return coefficients_[i]; }
    const std::uint64_t* monomial(std::size_t i) const {
        return monomials_.data() + i * ring_->words();
    }
    std::vector<std::uint32_t> exponents(std::size_t i) const;
    // Precondition: not zero.
    const Rational& leading_coefficient() const { return coefficients_.front(); }
    const std::uint64_t* leading_monomial() const { return monomials_.data(); }

    // Total degree (-1 for zero) and degree in one variable (-1 for zero).
    long total_degree() const;
    long degree(std::size_t var) const;

    Polynomial operator-() const;
    Polynomial& operator+=(const Polynomial& g) { return *this = *this + g; }
    Polynomial& operator-=(const Polynomial& g) { return *this = *this - g; }
    Polynomial& operator*=(const Polynomial& g) { return *this = *this * g; }
    Polynomial& operator*=(const Rational& c);
    friend Polynomial operator+(const Polynomial& f, const Polynomial& g);
    friend Polynomial operator-(const Polynomial& f, const Polynomial& g);
    friend Polynomial operator*(const Polynomial& f, const Polynomial& g);
    friend Polynomial operator*(Polynomial f, const Rational& c) { return f *= c; }
    friend Polynomial operator*(const Rational& c, Polynomial f) { return f *= c; }
    friend bool operator==(const Polynomial& f, const Polynomial& g);

    // f − c·m·g, the step of division and reduction, in one merge.
    Polynomial minus_term_times(const Rational& c, const std::uint64_t* m,
                                const Polynomial& g) const;
    // c·m·f.
    Polynomial times_term(const Rational& c, const std::uint64_t* m) const;
    // Throws ResourceLimit when the power could have more than kMaxPowerTerms terms (the
    // smaller of the multinomial count and the product of the degree ranges), or when its last
    // multiplication could take more than kMaxPowerWork limb products: (x+y+1)^32767,
    // (1+s^2+t^2)^555 and (1-t)^3015 are refused at once, not after gigabytes or seconds.
    Polynomial pow(unsigned exponent) const;

    Rational evaluate(std::span<const Rational> point) const;
    Polynomial derivative(std::size_t var) const;
    // f(values[0], …, values[n-1]); the values share one ring, which the result is in.
    // Precondition: values.size() == num_vars, values non-empty.
    Polynomial substitute(std::span<const Polynomial> values) const;
    // Positive rational c with f / c having coprime integer coefficients (0 for zero).
    Rational content() const;
    // f / content, then negated if needed so the leading coefficient is positive.
    Polynomial primitive_part() const;
    // f / leading coefficient; zero stays zero.
    Polynomial monic() const;
    // The same polynomial in another ring over the same variables (re-sorted by its order), or,
    // with `variable_map`, variable i of this ring becomes variable variable_map[i] of `target`.
    Polynomial in_ring(RingPtr target) const;
    Polynomial in_ring(RingPtr target, std::span<const std::size_t> variable_map) const;
    // Does variable `var` occur?
    bool contains_variable(std::size_t var) const;

    // Appends a term below all present ones (builders that produce terms in order).
    // Precondition: m is smaller than the last monomial and c != 0.
    void push_back_term(Rational c, const std::uint64_t* m);
    void reserve(std::size_t terms);

  private:
    RingPtr ring_;
    std::vector<std::uint64_t> monomials_;  // ring_->words() words per term
    std::vector<Rational> coefficients_;
};

// Throws MixedRings unless both polynomials live in equal rings.
void require_same_ring(const Polynomial& f, const Polynomial& g);

}  // namespace locus::algebra
