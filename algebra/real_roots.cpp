#include "algebra/real_roots.h"

#include <flint/fmpq_poly.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "algebra/exact_line_restriction.h"
#include "algebra/rational.h"

namespace locus::algebra {

void set_exact_double(fmpq_t out, double v) {
    int exponent = 0;
    const double mantissa = std::frexp(v, &exponent);
    fmpz_set_d(fmpq_numref(out), std::ldexp(mantissa, 53));  // an integer, exactly
    fmpz_one(fmpq_denref(out));
    const int shift = exponent - 53;
    if (shift >= 0) {
        fmpq_mul_2exp(out, out, static_cast<ulong>(shift));
    } else {
        fmpq_div_2exp(out, out, static_cast<ulong>(-shift));
    }
}

double nearest_double(const fmpq_t t) {
    // Numerator and denominator of at most 53 bits are doubles exactly, and IEEE division rounds
    // their quotient to nearest. No tie arises: a quotient halfway between two doubles has a
    // power of two below as denominator and then needs 54 bits above. Every coefficient of an
    // equation typed by hand takes this path (the search below allocates: 57 of the 600 page
    // faults of a whole `locus render` of a sphere).
    constexpr slong kExactBits = 53;
    const fmpz* numerator = fmpq_numref(t);
    const fmpz* denominator = fmpq_denref(t);
    if (!COEFF_IS_MPZ(*numerator) && !COEFF_IS_MPZ(*denominator) &&
        fmpz_bits(numerator) <= kExactBits && fmpz_bits(denominator) <= kExactBits) {
        return static_cast<double>(fmpz_get_si(numerator)) /
               static_cast<double>(fmpz_get_si(denominator));
    }
    const double guess = fmpq_get_d(t);
    if (!std::isfinite(guess)) {
        return guess;
    }
    double best = guess;
    fmpq_t candidate, distance, best_distance;
    fmpq_init(candidate);
    fmpq_init(distance);
    fmpq_init(best_distance);
    set_exact_double(candidate, guess);
    fmpq_sub(best_distance, candidate, t);
    fmpq_abs(best_distance, best_distance);
    for (const double other : {std::nextafter(guess, -INFINITY), std::nextafter(guess, INFINITY)}) {
        if (!std::isfinite(other)) {
            continue;
        }
        set_exact_double(candidate, other);
        fmpq_sub(distance, candidate, t);
        fmpq_abs(distance, distance);
        // Halfway between two doubles: the one with an even significand, as IEEE rounds.
        const int closer = fmpq_cmp(distance, best_distance);
        const bool even = (std::bit_cast<std::uint64_t>(other) & 1) == 0;
        if (closer < 0 || (closer == 0 && even)) {
            fmpq_swap(distance, best_distance);
            best = other;
        }
    }
    fmpq_clear(candidate);
    fmpq_clear(distance);
    fmpq_clear(best_distance);
    return best;
}

namespace {

using IntPoly = detail::FmpzPoly;

int sign_variations(const fmpz_poly_t p) {
    int variations = 0;
    int last = 0;
    for (slong i = 0; i < fmpz_poly_length(p); ++i) {
        const int s = fmpz_sgn(p->coeffs + i);
        if (s != 0) {
            if (last != 0 && s != last) {
                ++variations;
            }
            last = s;
        }
    }
    return variations;
}

// Descartes' bound on the roots of p in the open interval (0, 1): the sign variations of
// (x+1)^n · p(1/(x+1)).
int roots_in_unit_interval_bound(const fmpz_poly_t p) {
    const slong n = fmpz_poly_degree(p);
    IntPoly r;
    fmpz_poly_reverse(r.p, p, n + 1);
    fmpz_t one;
    fmpz_init_set_ui(one, 1);
    fmpz_poly_taylor_shift(r.p, r.p, one);
    fmpz_clear(one);
    return sign_variations(r.p);
}

// 2^n · p(x/2), made primitive: the left half of the current piece mapped to (0, 1).
void left_half(fmpz_poly_t out, const fmpz_poly_t p) {
    const slong n = fmpz_poly_degree(p);
    fmpz_poly_set(out, p);
    for (slong i = 0; i <= n; ++i) {
        fmpz_mul_2exp(out->coeffs + i, out->coeffs + i, static_cast<ulong>(n - i));
    }
    fmpz_poly_primitive_part(out, out);
}

bool is_root_at_one(const fmpz_poly_t p) {
    fmpz_t sum;
    fmpz_init(sum);
    for (slong i = 0; i < fmpz_poly_length(p); ++i) {
        fmpz_add(sum, sum, p->coeffs + i);
    }
    const bool zero = fmpz_is_zero(sum);
    fmpz_clear(sum);
    return zero;
}

// A piece [c/2^k, (c+1)/2^k] of the s-axis, with `poly` = the polynomial on it mapped to (0, 1);
// or, when `midpoint_marker`, the point (2c+1)/2^(k+1) to report if it is a root.
struct Piece {
    IntPoly poly;
    fmpz_t c;
    ulong k = 0;
    bool midpoint_root = false;
    Piece() { fmpz_init(c); }
    Piece(const Piece& o) : poly(o.poly), k(o.k), midpoint_root(o.midpoint_root) {
        fmpz_init_set(c, o.c);
    }
    Piece& operator=(const Piece&) = delete;
    ~Piece() { fmpz_clear(c); }
};

// t = lo + (hi − lo)·s.
void t_from_s(fmpq_t t, const fmpq_t s, const fmpq_t lo, const fmpq_t width) {
    fmpq_mul(t, s, width);
    fmpq_add(t, t, lo);
}

// s = (c + x) / 2^k.
void s_from_piece(fmpq_t s, const fmpz_t c, ulong k, const fmpq_t x) {
    fmpq_add_fmpz(s, x, c);
    fmpq_div_2exp(s, s, k);
}

// 2^(j·n)·p(m/2^j) for p of degree n: the value of p at the dyadic m/2^j times a positive
// power of two, in integers (Horner's scheme; FLINT's evaluation at a rational reduces every
// partial sum by a gcd).
void scaled_value_at(fmpz_t out, const fmpz_poly_t p, const fmpz_t m, ulong j, fmpz_t scratch) {
    const slong n = fmpz_poly_degree(p);
    fmpz_set(out, p->coeffs + n);
    for (slong i = n - 1; i >= 0; --i) {
        fmpz_mul(out, out, m);
        fmpz_mul_2exp(scratch, p->coeffs + i, j * static_cast<ulong>(n - i));
        fmpz_add(out, out, scratch);
    }
}

// An integer times 2^shift as a double mantissa and a wide exponent, for the secant's
// proposals (which need no more than a few correct bits).
struct Magnitude {
    double mantissa = 0.0;  // signed, 0.5 ≤ |mantissa| < 1, or 0
    slong exponent = 0;
};

Magnitude magnitude_of(const fmpz_t v, slong shift) {
    Magnitude m;
    if (!fmpz_is_zero(v)) {
        m.mantissa = fmpz_get_d_2exp(&m.exponent, v);
        m.exponent += shift;
    }
    return m;
}

// fa/(fa − fb) for values of opposite signs: where the secant through them crosses zero, as a
// fraction of the way from a to b.
double secant_fraction(const Magnitude& fa, const Magnitude& fb) {
    // fb/fa = (mb/ma)·2^(eb − ea) ≤ 0; r = 1/(1 − fb/fa).
    const slong gap = std::clamp<slong>(fb.exponent - fa.exponent, -1100, 1100);
    const double ratio = std::ldexp(fb.mantissa / fa.mantissa, static_cast<int>(gap));
    return 1.0 / (1.0 - ratio);
}

// Refines the single root of `poly` in (0, 1) (a sign change) until its enclosure in t rounds
// to one or two adjacent doubles. The enclosure [A, B]/2^J shrinks by exact signs at dyadic
// points: the Illinois variant of regula falsi proposes them (superlinear near a simple root),
// and a step that does not halve the enclosure is followed by a bisection, so the enclosure at
// least halves every two steps whatever the secant does.
double refine(const fmpz_poly_t poly, const fmpz_t c, ulong k, const fmpq_t lo,
              const fmpq_t width) {
    const slong n = fmpz_poly_degree(poly);
    Integer a_owned(0), b_owned(1), x_owned, value_owned, scratch_owned, gap_width_owned;
    fmpz* a = a_owned.get();
    fmpz* b = b_owned.get();
    fmpz* x = x_owned.get();
    fmpz* value = value_owned.get();
    fmpz* scratch = scratch_owned.get();
    fmpz* gap_width = gap_width_owned.get();
    ulong level = 0;  // the enclosure is [a, b]/2^level
    scaled_value_at(value, poly, a, 0, scratch);
    const int sign_at_a = fmpz_sgn(value);
    Magnitude fa = magnitude_of(value, 0);
    scaled_value_at(value, poly, b, 0, scratch);
    Magnitude fb = magnitude_of(value, 0);
    int last_kept = 0;  // −1: a was kept by the last step, +1: b, 0: a bisection
    bool bisect_next = sign_at_a == 0 || fb.mantissa == 0.0;
    const double width_d = std::abs(fmpq_get_d(width));
    const double lo_d = fmpq_get_d(lo);
    Rational x_q, s, t_lower, t_upper, mid;
    const auto t_of = [&](const fmpz_t numerator, fmpq_t t) {
        fmpz_one(scratch);
        fmpz_mul_2exp(scratch, scratch, level);
        fmpq_set_fmpz_frac(x_q.get(), numerator, scratch);
        s_from_piece(s.get(), c, k, x_q.get());
        t_from_s(t, s.get(), lo, width);
    };
    // Unreachable for finite doubles: the enclosure at least halves every two steps, and about
    // 2 200 halvings take any interval of doubles below 2^-8 of an ulp (2^1024 down to 2^-1082).
    constexpr int kIterations = 6000;
    Rational gap_q;
    double result = NAN;
    for (int iteration = 0; iteration < kIterations && std::isnan(result); ++iteration) {
        // Close to one ulp by the doubles' estimate: then the exact test.
        fmpz_sub(gap_width, b, a);
        slong e = 0;
        const double span = fmpz_get_d_2exp(&e, gap_width);
        const double t_span =
            std::ldexp(span * width_d,
                       static_cast<int>(std::max<slong>(e - static_cast<slong>(level + k), -4000)));
        // The ends' t in doubles (x = a/2^level, s = (c + x)/2^k), for the size of their ulp.
        const auto t_estimate = [&](const fmpz_t end) {
            slong end_exponent = 0;
            const double mantissa = fmpz_get_d_2exp(&end_exponent, end);
            const double x_d = std::ldexp(
                mantissa,
                static_cast<int>(std::max<slong>(end_exponent - static_cast<slong>(level), -4000)));
            return std::abs(lo_d + width_d * std::ldexp(fmpz_get_d(c) + x_d, -static_cast<int>(k)));
        };
        const double largest = std::max(t_estimate(a), t_estimate(b));
        const double ulp = std::nextafter(largest, INFINITY) - largest;
        if (!(t_span > 8.0 * ulp) || iteration % 64 == 63 || iteration + 1 == kIterations) {
            t_of(a, t_lower.get());
            t_of(b, t_upper.get());
            const double lower = nearest_double(t_lower.get());
            const double upper = nearest_double(t_upper.get());
            // Done when both ends round to the same double, or (a root on a rounding boundary)
            // when the enclosure is below 2^-8 of an ulp — compared exactly, since a quarter of
            // a subnormal's ulp is no double.
            fmpq_sub(mid.get(), t_upper.get(), t_lower.get());
            fmpq_abs(mid.get(), mid.get());
            set_exact_double(gap_q.get(),
                             std::nextafter(std::abs(lower), INFINITY) - std::abs(lower));
            fmpq_div_2exp(gap_q.get(), gap_q.get(), 8);
            if (lower == upper || fmpq_cmp(mid.get(), gap_q.get()) < 0 ||
                iteration + 1 == kIterations) {
                fmpq_add(mid.get(), t_lower.get(), t_upper.get());
                fmpq_div_2exp(mid.get(), mid.get(), 1);
                result = nearest_double(mid.get());
                break;
            }
        }
        // The next point: the secant's (at 2^-32 resolution within the enclosure), or the middle.
        constexpr ulong kSecantBits = 32;
        ulong bits = 1;
        double fraction = 0.5;
        if (!bisect_next) {
            fraction = secant_fraction(fa, fb);
            if (std::isfinite(fraction) && fraction > 0.0 && fraction < 1.0) {
                bits = kSecantBits;
            } else {
                fraction = 0.5;
            }
        }
        const double steps = std::ldexp(1.0, static_cast<int>(bits));
        const double chosen = std::clamp(std::round(fraction * steps), 1.0, steps - 1.0);
        fmpz_mul_2exp(a, a, bits);
        fmpz_mul_2exp(b, b, bits);
        level += bits;
        fmpz_sub(x, b, a);
        fmpz_mul_ui(x, x, static_cast<ulong>(chosen));
        fmpz_tdiv_q_2exp(x, x, bits);
        fmpz_add(x, x, a);
        // x = a + (b − a)·chosen/2^bits exactly, since b − a is a multiple of 2^bits now.
        scaled_value_at(value, poly, x, level, scratch);
        const int sign_at_x = fmpz_sgn(value);
        if (sign_at_x == 0) {
            t_of(x, t_lower.get());
            result = nearest_double(t_lower.get());
            break;
        }
        const Magnitude fx = magnitude_of(value, -static_cast<slong>(level) * n);
        const double kept_fraction = sign_at_x == sign_at_a ? 1.0 - chosen / steps : chosen / steps;
        if (sign_at_x == sign_at_a) {
            fmpz_swap(a, x);
            fa = fx;
            if (last_kept == 1) {
                fb.exponent -= 1;  // Illinois: b kept twice, its value halved
            }
            last_kept = bits == 1 ? 0 : 1;
        } else {
            fmpz_swap(b, x);
            fb = fx;
            if (last_kept == -1) {
                fa.exponent -= 1;
            }
            last_kept = bits == 1 ? 0 : -1;
        }
        bisect_next = bits != 1 && kept_fraction > 0.5;
    }
    return result;
}

}  // namespace

std::optional<double> first_real_root(const fmpz_poly_t p, const fmpq_t lo, const fmpq_t hi,
                                      bool lo_open) {
    Rational width;
    fmpq_sub(width.get(), hi, lo);
    // q(s) ∝ p(lo + width·s) = p((lo_n·w_d + w_n·lo_d·s)/(lo_d·w_d)): the interval becomes [0, 1].
    IntPoly q;
    {
        Integer a, b, d;
        fmpz_mul(a.get(), fmpq_numref(lo), fmpq_denref(width.get()));
        fmpz_mul(b.get(), fmpq_numref(width.get()), fmpq_denref(lo));
        fmpz_mul(d.get(), fmpq_denref(lo), fmpq_denref(width.get()));
        detail::compose_with_line(q.p, p, a.get(), b.get(), d.get());
    }
    fmpz_poly_primitive_part(q.p, q.p);

    if (fmpz_poly_degree(q.p) <= 0) {
        return std::nullopt;  // a non-zero constant
    }
    if (fmpz_is_zero(q.p->coeffs)) {
        if (!lo_open) {
            return nearest_double(lo);
        }
        fmpz_poly_shift_right(q.p, q.p, 1);  // square-free: the root at lo is simple
    }

    std::vector<Piece> stack(1);
    fmpz_poly_set(stack[0].poly.p, q.p);
    while (!stack.empty()) {
        Piece piece(stack.back());
        stack.pop_back();
        if (piece.midpoint_root) {
            Rational s, t;
            fmpz_t numerator, denominator;
            fmpz_init(numerator);
            fmpz_init(denominator);
            fmpz_mul_2exp(numerator, piece.c, 1);
            fmpz_add_ui(numerator, numerator, 1);
            fmpz_one(denominator);
            fmpz_mul_2exp(denominator, denominator, piece.k + 1);
            fmpq_set_fmpz_frac(s.get(), numerator, denominator);
            fmpz_clear(numerator);
            fmpz_clear(denominator);
            t_from_s(t.get(), s.get(), lo, width.get());
            return nearest_double(t.get());
        }
        if (fmpz_poly_degree(piece.poly.p) <= 0) {
            continue;
        }
        const int bound = roots_in_unit_interval_bound(piece.poly.p);
        if (bound == 0) {
            continue;
        }
        if (bound == 1) {
            return refine(piece.poly.p, piece.c, piece.k, lo, width.get());
        }
        // Split at the midpoint; push right, the midpoint (if a root), then left, so that the
        // left piece is examined first.
        Piece left, right;
        left_half(left.poly.p, piece.poly.p);
        fmpz_mul_2exp(left.c, piece.c, 1);
        left.k = piece.k + 1;
        fmpz_t one;
        fmpz_init_set_ui(one, 1);
        fmpz_poly_taylor_shift(right.poly.p, left.poly.p, one);
        fmpz_clear(one);
        fmpz_add_ui(right.c, left.c, 1);
        right.k = left.k;
        const bool midpoint_is_root = is_root_at_one(left.poly.p);
        if (midpoint_is_root) {
            fmpz_poly_shift_right(right.poly.p, right.poly.p, 1);  // drop the root at x = 0
        }
        stack.push_back(right);
        if (midpoint_is_root) {
            Piece marker;
            fmpz_set(marker.c, piece.c);
            marker.k = piece.k;
            marker.midpoint_root = true;
            stack.push_back(marker);
        }
        stack.push_back(left);
    }
    if (is_root_at_one(q.p)) {
        return nearest_double(hi);
    }
    return std::nullopt;
}

}  // namespace locus::algebra
