#include "algebra/real_roots.h"

#include <flint/fmpq_poly.h>

#include <cmath>
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
        if (fmpq_cmp(distance, best_distance) < 0) {
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

// RAII holder for the FLINT polynomials used below (scalars are algebra::Rational).
struct IntPoly {
    fmpz_poly_t p;
    IntPoly() { fmpz_poly_init(p); }
    IntPoly(const IntPoly& o) {
        fmpz_poly_init(p);
        fmpz_poly_set(p, o.p);
    }
    IntPoly& operator=(const IntPoly&) = delete;
    ~IntPoly() { fmpz_poly_clear(p); }
};

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

// Refines the single root of `poly` in (0, 1) (a sign change) by exact bisection until its
// enclosure in t rounds to one or two adjacent doubles.
double refine(const fmpz_poly_t poly, const fmpz_t c, ulong k, const fmpq_t lo,
              const fmpq_t width) {
    Rational a, b, mid, value, s, t_lower, t_upper;
    fmpq_zero(a.get());
    fmpq_one(b.get());
    fmpz_poly_evaluate_fmpq(value.get(), poly, a.get());
    const int sign_at_a = fmpq_sgn(value.get());
    for (int iteration = 0; iteration < 4000; ++iteration) {
        s_from_piece(s.get(), c, k, a.get());
        t_from_s(t_lower.get(), s.get(), lo, width);
        s_from_piece(s.get(), c, k, b.get());
        t_from_s(t_upper.get(), s.get(), lo, width);
        const double lower = nearest_double(t_lower.get());
        const double upper = nearest_double(t_upper.get());
        // Done when both ends round to the same double, or (a root on a rounding boundary)
        // when the enclosure is far below one ulp.
        fmpq_sub(mid.get(), t_upper.get(), t_lower.get());
        const double gap = std::nextafter(std::abs(lower), INFINITY) - std::abs(lower);
        if (lower == upper || std::abs(fmpq_get_d(mid.get())) < gap / 256) {
            fmpq_add(mid.get(), t_lower.get(), t_upper.get());
            fmpq_div_2exp(mid.get(), mid.get(), 1);
            return nearest_double(mid.get());
        }
        fmpq_add(mid.get(), a.get(), b.get());
        fmpq_div_2exp(mid.get(), mid.get(), 1);
        fmpz_poly_evaluate_fmpq(value.get(), poly, mid.get());
        const int sign_at_mid = fmpq_sgn(value.get());
        if (sign_at_mid == 0) {
            s_from_piece(s.get(), c, k, mid.get());
            t_from_s(t_lower.get(), s.get(), lo, width);
            return nearest_double(t_lower.get());
        }
        if (sign_at_mid == sign_at_a) {
            fmpq_set(a.get(), mid.get());
        } else {
            fmpq_set(b.get(), mid.get());
        }
    }
    // Unreachable for finite doubles: each step halves the enclosure, and 4000 halvings take
    // any interval of doubles below one ulp.
    s_from_piece(s.get(), c, k, a.get());
    t_from_s(t_lower.get(), s.get(), lo, width);
    return nearest_double(t_lower.get());
}

}  // namespace

std::optional<double> first_real_root(const fmpz_poly_t p, const fmpq_t lo, const fmpq_t hi,
                                      bool lo_open) {
    Rational width;
    fmpq_sub(width.get(), hi, lo);
    // q(s) ∝ p(lo + width·s) = p((lo_n·w_d + w_n·lo_d·s)/(lo_d·w_d)): the interval becomes [0, 1].
    IntPoly q;
    {
        fmpz_t a, b, d;
        fmpz_init(a);
        fmpz_init(b);
        fmpz_init(d);
        fmpz_mul(a, fmpq_numref(lo), fmpq_denref(width.get()));
        fmpz_mul(b, fmpq_numref(width.get()), fmpq_denref(lo));
        fmpz_mul(d, fmpq_denref(lo), fmpq_denref(width.get()));
        detail::compose_with_line(q.p, p, a, b, d);
        fmpz_clear(a);
        fmpz_clear(b);
        fmpz_clear(d);
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
