#include "algebra/rational_function.h"

#include "algebra/division.h"
#include "algebra/error.h"
#include "algebra/flint_convert.h"

namespace locus::algebra {

RationalFunction::RationalFunction(Polynomial numerator, Polynomial denominator)
    : numerator_(std::move(numerator)), denominator_(std::move(denominator)) {
    require_same_ring(numerator_, denominator_);
    if (denominator_.is_zero()) {
        throw InputError("rational function", "the denominator is zero");
    }
    if (numerator_.is_zero()) {
        denominator_ = Polynomial::constant(ring(), Rational(1));
        return;
    }
    if (!denominator_.is_constant()) {
        const Polynomial g = gcd(numerator_, denominator_);
        if (!g.is_constant()) {
            numerator_ = exact_quotient(numerator_, g);
            denominator_ = exact_quotient(denominator_, g);
        }
    }
    Rational inverse;
    fmpq_inv(inverse.get(), denominator_.leading_coefficient().get());
    numerator_ *= inverse;
    denominator_ *= inverse;
}

RationalFunction::RationalFunction(Polynomial polynomial)
    : numerator_(std::move(polynomial)), denominator_(Polynomial::constant(ring(), Rational(1))) {}

RationalFunction RationalFunction::constant(RingPtr ring, Rational value) {
    return RationalFunction(Polynomial::constant(std::move(ring), std::move(value)));
}

RationalFunction RationalFunction::variable(RingPtr ring, std::size_t var) {
    return RationalFunction(Polynomial::variable(std::move(ring), var));
}

RationalFunction RationalFunction::operator-() const {
    RationalFunction r = *this;
    r.numerator_ = -r.numerator_;
    return r;
}

RationalFunction RationalFunction::pow(unsigned exponent) const {
    return RationalFunction(numerator_.pow(exponent), denominator_.pow(exponent));
}

RationalFunction operator+(const RationalFunction& a, const RationalFunction& b) {
    if (a.denominator_ == b.denominator_) {
        return RationalFunction(a.numerator_ + b.numerator_, a.denominator_);
    }
    return RationalFunction(a.numerator_ * b.denominator_ + b.numerator_ * a.denominator_,
                            a.denominator_ * b.denominator_);
}

RationalFunction operator-(const RationalFunction& a, const RationalFunction& b) {
    return a + (-b);
}

RationalFunction operator*(const RationalFunction& a, const RationalFunction& b) {
    return RationalFunction(a.numerator_ * b.numerator_, a.denominator_ * b.denominator_);
}

RationalFunction operator/(const RationalFunction& a, const RationalFunction& b) {
    if (b.is_zero()) {
        throw InputError("rational function", "division by zero");
    }
    return RationalFunction(a.numerator_ * b.denominator_, a.denominator_ * b.numerator_);
}

}  // namespace locus::algebra
