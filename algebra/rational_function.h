// Quotients of polynomials over Q, kept in lowest terms: gcd(numerator, denominator) = 1 (FLINT
// gcd) and the denominator monic, so equal functions have equal representations. Used for
// rational parametrizations and their exact verification.
#pragma once

#include "algebra/polynomial.h"

namespace locus::algebra {

class RationalFunction {
  public:
    // Throws InputError when the denominator is zero.
    RationalFunction(Polynomial numerator, Polynomial denominator);
    explicit RationalFunction(Polynomial polynomial);
    static RationalFunction constant(RingPtr ring, Rational value);
    static RationalFunction variable(RingPtr ring, std::size_t var);

    const Polynomial& numerator() const { return numerator_; }
    const Polynomial& denominator() const { return denominator_; }
    const RingPtr& ring() const { return numerator_.ring(); }
    bool is_zero() const { return numerator_.is_zero(); }
    bool is_polynomial() const { return denominator_.is_constant(); }

    RationalFunction operator-() const;
    RationalFunction pow(unsigned exponent) const;
    friend RationalFunction operator+(const RationalFunction& a, const RationalFunction& b);
    friend RationalFunction operator-(const RationalFunction& a, const RationalFunction& b);
    friend RationalFunction operator*(const RationalFunction& a, const RationalFunction& b);
    // Throws InputError when b is zero.
    friend RationalFunction operator/(const RationalFunction& a, const RationalFunction& b);
    friend bool operator==(const RationalFunction& a, const RationalFunction& b) {
        return a.numerator_ == b.numerator_ && a.denominator_ == b.denominator_;
    }

  private:
    Polynomial numerator_, denominator_;
};

}  // namespace locus::algebra
