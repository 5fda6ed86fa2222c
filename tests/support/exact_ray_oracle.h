// An exact oracle for the first hit of a ray, written to share no code with what it checks: the
// equation is parsed by FLINT's own parser (decimals rewritten as fractions first), restricted
// to the ray over Q with FLINT, and the roots counted by a Sturm sequence over Q — where the
// renderer uses locus' parser, compiled doubles, Bernstein bounds and, for its exact tier,
// Descartes' rule with bisection (algebra/real_roots.cpp).
//
// The ray o + t·d has the exact rational values of the doubles given. The answer is the
// smallest root t* of F(t) = f(o + t·d) in (0, t_max], bracketed in [lower, upper] with
// upper − lower ≤ 1e-15·max(1, t*), or none.
#pragma once

#include <flint/fmpq_mpoly.h>
#include <flint/fmpq_poly.h>
#include <flint/fmpz_poly.h>

#include <array>
#include <cctype>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace locus::test {

class ExactRayOracle {
  public:
    struct Answer {
        bool hit = false;
        bool lies_in_surface = false;     // F ≡ 0
        double lower = 0.0, upper = 0.0;  // t* ∈ [lower, upper] (rounded outwards)
    };

    explicit ExactRayOracle(const std::string& equation) {
        fmpq_mpoly_ctx_init(ctx_, 3, ORD_LEX);
        fmpq_mpoly_init(f_, ctx_);
        const std::string text = fractions_for_decimals(equation);
        const char* names[] = {"x", "y", "z"};
        if (fmpq_mpoly_set_str_pretty(f_, text.c_str(), names, ctx_) != 0) {
            throw std::runtime_error("oracle: FLINT cannot parse " + text);
        }
    }
    ExactRayOracle(const ExactRayOracle&) = delete;
    ExactRayOracle& operator=(const ExactRayOracle&) = delete;
    ~ExactRayOracle() {
        fmpq_mpoly_clear(f_, ctx_);
        fmpq_mpoly_ctx_clear(ctx_);
    }

    // The smallest root in (0, t_max], bracketed by bisection (slow at high degree: for
    // measuring every method; the tests check answers with is_right).
    Answer first_root(const std::array<double, 3>& origin, const std::array<double, 3>& direction,
                      double t_max) const {
        Answer answer;
        const Restriction r = restrict(origin, direction);
        if (r.zero) {
            answer.hit = true;
            answer.lies_in_surface = true;
            return answer;
        }
        Q lo, hi, mid, width, scale;
        fmpq_zero(lo.q);
        exact(hi.q, t_max);
        int v_lo = r.variations(lo.q), v_hi = r.variations(hi.q);
        if (v_lo == v_hi) {
            return answer;
        }
        answer.hit = true;
        auto narrow_enough = [&] {
            fmpq_sub(width.q, hi.q, lo.q);
            fmpq_abs(scale.q, lo.q);
            if (fmpq_cmp_ui(scale.q, 1) < 0) {
                fmpq_one(scale.q);
            }
            fmpq_div(width.q, width.q, scale.q);
            return fmpq_get_d(width.q) <= 1e-15;
        };
        // Bisect, keeping the first root in (lo, hi] and none in (0, lo], until one root is
        // left; then by P's sign at hi alone (the root is simple in the square-free P).
        while (v_lo - v_hi > 1 && !narrow_enough()) {
            fmpq_add(mid.q, lo.q, hi.q);
            fmpq_div_2exp(mid.q, mid.q, 1);
            const int v_mid = r.variations(mid.q);
            if (v_lo - v_mid > 0) {
                fmpq_set(hi.q, mid.q);
                v_hi = v_mid;
            } else {
                fmpq_set(lo.q, mid.q);
                v_lo = v_mid;
            }
        }
        const int sign_hi = sign_at(r.chain[0].p, hi.q);
        if (sign_hi == 0) {
            fmpq_set(lo.q, hi.q);
        }
        while (!narrow_enough()) {
            fmpq_add(mid.q, lo.q, hi.q);
            fmpq_div_2exp(mid.q, mid.q, 1);
            const int s = sign_at(r.chain[0].p, mid.q);
            if (s == 0) {
                fmpq_set(lo.q, mid.q);
                fmpq_set(hi.q, mid.q);
            } else if (s == sign_hi) {
                fmpq_set(hi.q, mid.q);
            } else {
                fmpq_set(lo.q, mid.q);
            }
        }
        answer.lower = std::nextafter(fmpq_get_d(lo.q), -INFINITY);
        answer.upper = std::nextafter(fmpq_get_d(hi.q), INFINITY);
        return answer;
    }

    struct IntPoly {
        fmpz_poly_t p;
        IntPoly() { fmpz_poly_init(p); }
        IntPoly(IntPoly&& o) noexcept {
            fmpz_poly_init(p);
            fmpz_poly_swap(p, o.p);
        }
        IntPoly(const IntPoly&) = delete;
        IntPoly& operator=(const IntPoly&) = delete;
        ~IntPoly() { fmpz_poly_clear(p); }
    };

    // The sign of S(num/den) for den > 0: of Σ c_i num^i den^(n−i), in integers.
    static int sign_at(const fmpz_poly_struct* s, const fmpq_t x) {
        const slong n = fmpz_poly_degree(s);
        if (n < 0) {
            return 0;
        }
        fmpz_t acc, power;
        fmpz_init_set(acc, s->coeffs + n);
        fmpz_init_set_ui(power, 1);
        for (slong i = n - 1; i >= 0; --i) {
            fmpz_mul(power, power, fmpq_denref(x));
            fmpz_mul(acc, acc, fmpq_numref(x));
            fmpz_addmul(acc, s->coeffs + i, power);
        }
        const int sign = fmpz_sgn(acc);
        fmpz_clear(acc);
        fmpz_clear(power);
        return sign;
    }

    // F(t) = f(o + t·d) over Z: the primitive numerator's square-free part P and its Sturm
    // sequence by pseudo-remainders with the sign kept: S0 = P, S1 = P',
    // S(k+1) = −(positive multiple of rem(S(k−1), Sk)), each divided by its content.
    struct Restriction {
        bool zero = false;
        std::vector<IntPoly> chain;
        // Distinct roots in (a, b] = V(a) − V(b) (Sturm's theorem, P square-free).
        int variations(const fmpq_t x) const {
            int count = 0, last = 0;
            for (const IntPoly& poly : chain) {
                const int sign = sign_at(poly.p, x);
                if (sign != 0) {
                    count += last != 0 && sign != last ? 1 : 0;
                    last = sign;
                }
            }
            return count;
        }
    };

    // f(o + t·d) exactly, for the doubles o, d and t read exactly.
    void value_on_line(const std::array<double, 3>& origin, const std::array<double, 3>& direction,
                       double t, fmpq_t out) const {
        Poly F;
        compose(origin, direction, F.p);
        Q value;
        exact(value.q, t);
        fmpq_poly_evaluate_fmpq(out, F.p, value.q);
    }

    Restriction restrict(const std::array<double, 3>& origin,
                         const std::array<double, 3>& direction) const {
        Restriction r;
        Poly F;
        compose(origin, direction, F.p);
        if (fmpq_poly_is_zero(F.p)) {
            r.zero = true;
            return r;
        }
        IntPoly P, derivative, common;
        fmpq_poly_get_numerator(P.p, F.p);
        fmpz_poly_primitive_part(P.p, P.p);
        fmpz_poly_derivative(derivative.p, P.p);
        fmpz_poly_gcd(common.p, P.p, derivative.p);
        fmpz_poly_div(P.p, P.p, common.p);
        r.chain.resize(2);
        fmpz_poly_set(r.chain[0].p, P.p);
        fmpz_poly_derivative(r.chain[1].p, P.p);
        // Divided by the content, which is positive: FLINT's primitive part would also make
        // the leading coefficient positive, and the signs are what a Sturm sequence is for.
        auto divide_by_content = [](fmpz_poly_struct* q) {
            fmpz_t content;
            fmpz_init(content);
            fmpz_poly_content(content, q);
            if (!fmpz_is_zero(content)) {
                fmpz_poly_scalar_divexact_fmpz(q, q, content);
            }
            fmpz_clear(content);
        };
        divide_by_content(r.chain[1].p);
        while (fmpz_poly_degree(r.chain.back().p) > 0) {
            IntPoly next;
            const fmpz_poly_struct* a = r.chain[r.chain.size() - 2].p;
            const fmpz_poly_struct* b = r.chain.back().p;
            ulong d = 0;
            fmpz_poly_pseudo_rem(next.p, &d, a, b);
            // lc(b)^d·a = q·b + next: next is a positive multiple of rem unless lc(b)^d < 0.
            const bool flip = fmpz_sgn(fmpz_poly_lead(b)) < 0 && d % 2 == 1;
            if (!flip) {
                fmpz_poly_neg(next.p, next.p);
            }
            if (fmpz_poly_is_zero(next.p)) {
                break;
            }
            divide_by_content(next.p);
            r.chain.push_back(std::move(next));
        }
        return r;
    }

    // Whether a claimed answer keeps the contract, from two or three Sturm counts: a miss when
    // F has no root in (0, t_max]; a hit t when F has no root in (0, t − ε] and one in
    // (0, t + ε], ε = tolerance·max(1, |t|); any hit when F ≡ 0.
    static bool is_right(const Restriction& r, double t_max, bool hit, double t, double tolerance) {
        return is_right(r, 0.0, t_max, hit, t, tolerance);
    }
    // The same for the interval (t_min, t_max].
    static bool is_right(const Restriction& r, double t_min, double t_max, bool hit, double t,
                         double tolerance) {
        if (r.zero) {
            return hit;
        }
        Q start, end, before, after;
        exact(start.q, t_min);
        const int v_start = r.variations(start.q);
        if (!hit) {
            exact(end.q, t_max);
            return r.variations(end.q) == v_start;
        }
        const double slack = tolerance * std::max(1.0, std::abs(t));
        if (!(t + slack > t_min) || t - slack > t_max) {
            return false;
        }
        exact(after.q, std::min(t + slack, t_max));
        bool none_before = true;
        if (t - slack > t_min) {
            exact(before.q, t - slack);
            none_before = r.variations(before.q) == v_start;
        }
        return none_before && r.variations(after.q) < v_start;
    }

    // "2.5e-3" style decimals become "(25/10000)"; everything else is left to FLINT's parser.
    static std::string fractions_for_decimals(const std::string& text) {
        std::string out;
        for (std::size_t i = 0; i < text.size();) {
            const bool starts_number =
                std::isdigit(static_cast<unsigned char>(text[i])) &&
                (i == 0 ||
                 !(std::isalnum(static_cast<unsigned char>(text[i - 1])) || text[i - 1] == '_'));
            if (!starts_number) {
                out += text[i++];
                continue;
            }
            std::string digits;
            int scale = 0;
            while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) {
                digits += text[i++];
            }
            if (i < text.size() && text[i] == '.') {
                ++i;
                while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) {
                    digits += text[i++];
                    ++scale;
                }
            }
            if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
                std::size_t j = i + 1;
                int sign = 1;
                if (j < text.size() && (text[j] == '-' || text[j] == '+')) {
                    sign = text[j] == '-' ? -1 : 1;
                    ++j;
                }
                std::string exponent;
                while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j]))) {
                    exponent += text[j++];
                }
                if (!exponent.empty()) {
                    scale -= sign * std::stoi(exponent);
                    i = j;
                }
            }
            if (scale == 0) {
                out += digits;
            } else if (scale > 0) {
                out +=
                    "(" + digits + "/1" + std::string(static_cast<std::size_t>(scale), '0') + ")";
            } else {
                out += "(" + digits + std::string(static_cast<std::size_t>(-scale), '0') + ")";
            }
        }
        return out;
    }

    // Whether the ball b_i ± r_i (i ≤ n) holds the Bernstein coefficients of degree n of
    // G(σ) = F(t0 + σ·w) on σ ∈ [0, 1], computed exactly: −1 when it does, else the first i
    // outside (n + 1 when G's degree is above n).
    int ball_misses(const std::array<double, 3>& origin, const std::array<double, 3>& direction,
                    double t0, double w, const double* b, const double* r, int n) const {
        Poly F, line, G;
        compose(origin, direction, F.p);
        Q value, beta, term, coefficient, difference;
        exact(value.q, t0);
        fmpq_poly_set_coeff_fmpq(line.p, 0, value.q);
        exact(value.q, w);
        fmpq_poly_set_coeff_fmpq(line.p, 1, value.q);
        fmpq_poly_compose(G.p, F.p, line.p);
        if (fmpq_poly_degree(G.p) > n) {
            return n + 1;
        }
        fmpz_t choose_i, choose_n;
        fmpz_init(choose_i);
        fmpz_init(choose_n);
        int missed = -1;
        for (int i = 0; i <= n && missed < 0; ++i) {
            // β_i = Σ_{j ≤ i} C(i, j)/C(n, j)·g_j.
            fmpq_zero(beta.q);
            for (int j = 0; j <= i; ++j) {
                fmpq_poly_get_coeff_fmpq(coefficient.q, G.p, j);
                fmpz_bin_uiui(choose_i, static_cast<ulong>(i), static_cast<ulong>(j));
                fmpz_bin_uiui(choose_n, static_cast<ulong>(n), static_cast<ulong>(j));
                fmpq_mul_fmpz(term.q, coefficient.q, choose_i);
                fmpq_div_fmpz(term.q, term.q, choose_n);
                fmpq_add(beta.q, beta.q, term.q);
            }
            exact(value.q, b[i]);
            fmpq_sub(difference.q, beta.q, value.q);
            fmpq_abs(difference.q, difference.q);
            exact(value.q, r[i]);
            if (fmpq_cmp(difference.q, value.q) > 0) {
                missed = i;
            }
        }
        fmpz_clear(choose_i);
        fmpz_clear(choose_n);
        return missed;
    }

  private:
    // F(t) = f(o + t·d) over Q, for the doubles o and d read exactly.
    void compose(const std::array<double, 3>& origin, const std::array<double, 3>& direction,
                 fmpq_poly_t F) const {
        Poly line[3];
        fmpq_poly_struct* lines[3];
        Q value;
        for (int i = 0; i < 3; ++i) {
            exact(value.q, origin[i]);
            fmpq_poly_set_coeff_fmpq(line[i].p, 0, value.q);
            exact(value.q, direction[i]);
            fmpq_poly_set_coeff_fmpq(line[i].p, 1, value.q);
            lines[i] = line[i].p;
        }
        fmpq_mpoly_compose_fmpq_poly(F, f_, lines, ctx_);
    }

    struct Poly {
        fmpq_poly_t p;
        Poly() { fmpq_poly_init(p); }
        Poly(Poly&& o) noexcept {
            fmpq_poly_init(p);
            fmpq_poly_swap(p, o.p);
        }
        Poly(const Poly&) = delete;
        Poly& operator=(const Poly&) = delete;
        ~Poly() { fmpq_poly_clear(p); }
    };
    struct Q {
        fmpq_t q;
        Q() { fmpq_init(q); }
        Q(const Q&) = delete;
        Q& operator=(const Q&) = delete;
        ~Q() { fmpq_clear(q); }
    };

  public:
    // The exact value of a finite double (for tests that build exact data beside the oracle).
    static void exact(fmpq_t out, double v) {
        int exponent = 0;
        const double mantissa = std::frexp(v, &exponent);
        fmpz_set_d(fmpq_numref(out), std::ldexp(mantissa, 53));
        fmpz_one(fmpq_denref(out));
        if (exponent >= 53) {
            fmpq_mul_2exp(out, out, static_cast<ulong>(exponent - 53));
        } else {
            fmpq_div_2exp(out, out, static_cast<ulong>(53 - exponent));
        }
    }

  private:
    fmpq_mpoly_ctx_t ctx_;
    fmpq_mpoly_t f_;
};

}  // namespace locus::test
