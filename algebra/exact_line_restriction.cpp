#include "algebra/exact_line_restriction.h"

#include <algorithm>
#include <cmath>

#include "algebra/polynomial.h"

namespace locus::algebra::detail {

namespace {

// v = mantissa·2^exponent with an odd integer mantissa (v ≠ 0, finite).
struct Dyadic {
    double mantissa = 0.0;  // an integer below 2^53 in magnitude
    int exponent = 0;
};

Dyadic dyadic(double v) {
    int e = 0;
    double m = std::ldexp(std::frexp(v, &e), 53);  // an integer, exactly
    e -= 53;
    while (std::fmod(m, 2.0) == 0.0) {
        m *= 0.5;
        ++e;
    }
    return {m, e};
}

// The smallest exponent of the non-zero values, and 0 when that is positive: the values are
// then integers times 2^exponent.
template <std::size_t N>
int common_exponent(const std::array<double, N>& values) {
    int lowest = 0;
    for (const double v : values) {
        if (v != 0.0) {
            lowest = std::min(lowest, dyadic(v).exponent);
        }
    }
    return lowest;
}

// out = v / 2^exponent, an integer when exponent ≤ the exponent of v's odd mantissa.
void set_scaled(fmpz_t out, double v, int exponent) {
    if (v == 0.0) {
        fmpz_zero(out);
        return;
    }
    const Dyadic d = dyadic(v);
    fmpz_set_d(out, d.mantissa);
    fmpz_mul_2exp(out, out, static_cast<ulong>(d.exponent - exponent));
}

// The linear polynomial a + b·t with integer a, b.
struct IntegerLine {
    Integer a, b;
};

// p ← p·(a + b·t), in place.
void multiply_by_line(fmpz_poly_t p, const IntegerLine& line, fmpz_t scratch) {
    const fmpz* a = line.a.get();
    const fmpz* b = line.b.get();
    const slong length = fmpz_poly_length(p);
    if (length == 0) {
        return;
    }
    if (fmpz_is_zero(b)) {
        fmpz_poly_scalar_mul_fmpz(p, p, a);
        return;
    }
    fmpz_poly_fit_length(p, length + 1);
    fmpz* c = p->coeffs;
    fmpz_mul(c + length, c + length - 1, b);
    for (slong k = length - 1; k >= 1; --k) {
        fmpz_mul(scratch, c + k - 1, b);
        fmpz_mul(c + k, c + k, a);
        fmpz_add(c + k, c + k, scratch);
    }
    fmpz_mul(c, c, a);
    _fmpz_poly_set_length(p, length + 1);
    _fmpz_poly_normalise(p);
}

// p ← p + v.
void add_constant(fmpz_poly_t p, const fmpz_t v) {
    if (fmpz_poly_length(p) == 0) {
        fmpz_poly_set_fmpz(p, v);
        return;
    }
    fmpz_add(p->coeffs, p->coeffs, v);
    _fmpz_poly_normalise(p);
}

}  // namespace

ExactLineRestriction::ExactLineRestriction(const Polynomial& f) {
    // The common denominator D > 0 of the coefficients: the integers are D·c.
    Integer denominator;
    fmpz_one(denominator.get());
    for (std::size_t i = 0; i < f.num_terms(); ++i) {
        fmpz_lcm(denominator.get(), denominator.get(), fmpq_denref(f.coefficient(i).get()));
    }
    struct Entry {
        Term term;
        std::size_t index;
    };
    std::vector<Entry> entries;
    const std::size_t variables = f.ring()->num_vars();
    for (std::size_t i = 0; i < f.num_terms(); ++i) {
        const std::vector<std::uint32_t> e = f.exponents(i);
        const auto at = [&](std::size_t v) { return v < variables ? static_cast<int>(e[v]) : 0; };
        entries.push_back({{at(0), at(1), at(2)}, i});
        degree_ = std::max(degree_, at(0) + at(1) + at(2));
    }
    std::sort(entries.begin(), entries.end(), [](const Entry& p, const Entry& q) {
        return std::tie(p.term.ex, p.term.ey, p.term.ez) >
               std::tie(q.term.ex, q.term.ey, q.term.ez);
    });
    coefficients_.resize(entries.size());
    for (std::size_t k = 0; k < entries.size(); ++k) {
        terms_.push_back(entries[k].term);
        fmpz* c = coefficients_[k].get();
        const fmpq* q = f.coefficient(entries[k].index).get();
        fmpz_divexact(c, denominator.get(), fmpq_denref(q));
        fmpz_mul(c, c, fmpq_numref(q));
    }
}

void ExactLineRestriction::restrict(const std::array<double, 3>& origin,
                                    const std::array<double, 3>& direction, fmpz_poly_t out) const {
    // Every coordinate o_i + t·d_i is 2^e·(a_i + b_i·t) with integers a_i, b_i and one e ≤ 0;
    // with s = −e, 2^(n·s)·f(o + t·d) = Σ c_α·2^(s·(n − |α|))·Π (a_i + b_i·t)^α_i.
    const int e = common_exponent<6>(
        {origin[0], origin[1], origin[2], direction[0], direction[1], direction[2]});
    const auto s = static_cast<ulong>(-e);
    std::array<IntegerLine, 3> lines;
    for (int i = 0; i < 3; ++i) {
        set_scaled(lines[static_cast<std::size_t>(i)].a.get(), origin[static_cast<std::size_t>(i)],
                   e);
        set_scaled(lines[static_cast<std::size_t>(i)].b.get(),
                   direction[static_cast<std::size_t>(i)], e);
    }
    Integer scratch;
    FmpzPoly in_y, in_z;
    fmpz_poly_zero(out);
    // Horner in x over the groups of equal ex, in y over equal (ex, ey), in z over the terms.
    std::size_t k = 0;
    const std::size_t count = terms_.size();
    for (int ex = count > 0 ? terms_[0].ex : -1; ex >= 0; --ex) {
        multiply_by_line(out, lines[0], scratch.get());
        if (k == count || terms_[k].ex != ex) {
            continue;
        }
        fmpz_poly_zero(in_y.p);
        for (int ey = terms_[k].ey; ey >= 0; --ey) {
            multiply_by_line(in_y.p, lines[1], scratch.get());
            if (k == count || terms_[k].ex != ex || terms_[k].ey != ey) {
                continue;
            }
            fmpz_poly_zero(in_z.p);
            for (int ez = terms_[k].ez; ez >= 0; --ez) {
                multiply_by_line(in_z.p, lines[2], scratch.get());
                if (k < count && terms_[k].ex == ex && terms_[k].ey == ey && terms_[k].ez == ez) {
                    fmpz_mul_2exp(scratch.get(), coefficients_[k].get(),
                                  s * static_cast<ulong>(degree_ - ex - ey - ez));
                    add_constant(in_z.p, scratch.get());
                    ++k;
                }
            }
            fmpz_poly_add(in_y.p, in_y.p, in_z.p);
        }
        fmpz_poly_add(out, out, in_y.p);
    }
}

void compose_with_line(fmpz_poly_t out, const fmpz_poly_t p, const fmpz_t a, const fmpz_t b,
                       const fmpz_t d) {
    IntegerLine line;
    fmpz_set(line.a.get(), a);
    fmpz_set(line.b.get(), b);
    Integer scratch, power;
    FmpzPoly result;
    fmpz_one(power.get());
    // Σ p_i·d^(n − i)·(a + b·s)^i, by Horner.
    for (slong i = fmpz_poly_degree(p); i >= 0; --i) {
        multiply_by_line(result.p, line, scratch.get());
        fmpz_mul(scratch.get(), p->coeffs + i, power.get());
        add_constant(result.p, scratch.get());
        fmpz_mul(power.get(), power.get(), d);
    }
    fmpz_poly_swap(out, result.p);
}

}  // namespace locus::algebra::detail
