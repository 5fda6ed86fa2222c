// Double-double ("double-word") arithmetic: a real kept as an unevaluated sum hi + lo of two
// doubles with |lo| ≤ ulp(hi)/2, about 106 bits of precision, for the certified evaluations
// that doubles cannot decide: CompiledPolynomial::enclose_on_line here, and the renderer's
// double-double restrictions of a surface to a ray (render/ray_restriction.h) — the number type
// of the compiled-polynomial interface, beside compiled.h.
//
// The algorithms and their relative error bounds, with u = 2^-53 and no underflow or overflow,
// are those of Joldes, Muller and Popescu, "Tight and rigorous error bounds for basic building
// blocks of double-word arithmetic", ACM TOMS 44 (2017): add (their Algorithm 6, accurate sum)
// ≤ 3u² + 13u³, multiply (Algorithm 12, with FMA) ≤ 4u². kOperationError bounds both. The
// error-free transformations (two_sum, two_product) are exact.
#pragma once

#include <cmath>

namespace locus::algebra {

struct DoubleDouble {
    double hi = 0.0;
    double lo = 0.0;
};

// A bound on the relative error of one add or multiply below: 4u² + 13u³ < 5u².
inline constexpr double kOperationError = 5.0 * 0x1.0p-106;

// s + e = a + b exactly (Knuth's TwoSum, no precondition).
inline DoubleDouble two_sum(double a, double b) {
    const double s = a + b;
    const double t = s - a;
    return {s, (a - (s - t)) + (b - t)};
}

// s + e = a + b exactly when |a| ≥ |b| or a = 0 (Dekker's Fast2Sum).
inline DoubleDouble fast_two_sum(double a, double b) {
    const double s = a + b;
    return {s, b - (s - a)};
}

// p + e = a·b exactly (barring underflow), with one FMA.
inline DoubleDouble two_product(double a, double b) {
    const double p = a * b;
    return {p, std::fma(a, b, -p)};
}

inline DoubleDouble operator+(const DoubleDouble& x, const DoubleDouble& y) {
    const DoubleDouble s = two_sum(x.hi, y.hi);
    const DoubleDouble t = two_sum(x.lo, y.lo);
    const DoubleDouble v = fast_two_sum(s.hi, s.lo + t.hi);
    return fast_two_sum(v.hi, t.lo + v.lo);
}

// x + y for a double y: Joldes, Muller and Popescu, "Tight and rigorous error bounds for
// basic building blocks of double-word arithmetic", ACM TOMS 44 (2017), Algorithm 4
// (DWPlusFP), relative error at most 2u², within kOperationError — half the operations of the
// sum of two double-doubles.
inline DoubleDouble operator+(const DoubleDouble& x, double y) {
    const DoubleDouble s = two_sum(x.hi, y);
    return fast_two_sum(s.hi, x.lo + s.lo);
}

inline DoubleDouble operator*(const DoubleDouble& x, const DoubleDouble& y) {
    const DoubleDouble c = two_product(x.hi, y.hi);
    const double low_parts = std::fma(x.lo, y.hi, std::fma(x.hi, y.lo, x.lo * y.lo));
    return fast_two_sum(c.hi, c.lo + low_parts);
}

inline DoubleDouble from_double(double v) {
    return {v, 0.0};
}

}  // namespace locus::algebra
