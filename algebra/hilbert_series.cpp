#include "algebra/hilbert_series.h"

#include <flint/fmpz.h>

#include <algorithm>

#include "algebra/deadline.h"
#include "algebra/detail/monomial_ideal.h"
#include "algebra/error.h"

namespace locus::algebra {
namespace {

// a += t^shift · b
void add_shifted(IntegerCoefficients& a, const IntegerCoefficients& b, std::size_t shift) {
    if (a.size() < b.size() + shift) {
        a.resize(b.size() + shift, Integer(0));
    }
    for (std::size_t i = 0; i < b.size(); ++i) {
        fmpz_add(a[i + shift].get(), a[i + shift].get(), b[i].get());
    }
}

void trim(IntegerCoefficients& a) {
    while (!a.empty() && fmpz_is_zero(a.back().get())) {
        a.pop_back();
    }
}

// a · (1 − t^k)
IntegerCoefficients times_one_minus_power(const IntegerCoefficients& a, std::size_t k) {
    IntegerCoefficients out = a;
    out.resize(a.size() + k, Integer(0));
    for (std::size_t i = 0; i < a.size(); ++i) {
        fmpz_sub(out[i + k].get(), out[i + k].get(), a[i].get());
    }
    trim(out);
    return out;
}

class SeriesNumerator {
  public:
    SeriesNumerator(std::size_t n, std::optional<std::chrono::steady_clock::time_point> deadline)
        : n_(n), deadline_(deadline) {}

    // K(M) with HS(S/M) = K/(1−t)^n.
    IntegerCoefficients of(std::vector<ExponentVector> generators) {
        if ((++calls_ & 0xff) == 0 && deadline_passed(deadline_)) {
            throw Timeout("the Hilbert series was not complete at the deadline");
        }
        detail::minimalize(generators);
        for (const ExponentVector& g : generators) {
            if (detail::support_of(g).size == 0) {
                return {};  // the unit ideal: S/M = 0
            }
        }
        const std::optional<std::size_t> pivot = detail::pivot_variable(generators, n_);
        if (!pivot) {
            // Pure powers x_i^{a_i}: a complete intersection, K = Π (1 − t^{a_i}).
            IntegerCoefficients k = {Integer(1)};
            for (const ExponentVector& g : generators) {
                const std::size_t v = detail::support_of(g).variable;
                k = times_one_minus_power(k, g[v]);
            }
            return k;
        }
        const std::size_t x = *pivot;
        IntegerCoefficients k = of(detail::plus_variable(generators, x, n_));
        const IntegerCoefficients with_x = of(detail::colon_variable(std::move(generators), x));
        add_shifted(k, with_x, 1);
        trim(k);
        return k;
    }

  private:
    std::size_t n_;
    std::optional<std::chrono::steady_clock::time_point> deadline_;
    std::uint64_t calls_ = 0;
};

Integer value_at_one(const IntegerCoefficients& a) {
    Integer sum(0);
    for (const Integer& c : a) {
        fmpz_add(sum.get(), sum.get(), c.get());
    }
    return sum;
}

// a / (1 − t), exact when a(1) = 0: a = (1 − t)·q gives q_i = a_i + q_{i−1}.
IntegerCoefficients divided_by_one_minus_t(const IntegerCoefficients& a) {
    IntegerCoefficients q(a.size() > 0 ? a.size() - 1 : 0);
    Integer running(0);
    for (std::size_t i = 0; i + 1 < a.size(); ++i) {
        fmpz_add(running.get(), running.get(), a[i].get());
        q[i] = running;
    }
    trim(q);
    return q;
}

// Σ_i q_i · C(s − i + d − 1, d − 1) as a polynomial in s (d ≥ 1).
RationalCoefficients hilbert_polynomial_of(const IntegerCoefficients& q, std::size_t d) {
    RationalCoefficients hp(d, Rational(0));
    Integer factorial(1);
    for (std::size_t j = 2; j < d; ++j) {
        fmpz_mul_ui(factorial.get(), factorial.get(), j);
    }
    for (std::size_t i = 0; i < q.size(); ++i) {
        // Π_{j=1}^{d−1} (s + j − i), expanded in s.
        std::vector<Rational> product = {Rational(1)};
        for (std::size_t j = 1; j < d; ++j) {
            const Rational shift(static_cast<long>(j) - static_cast<long>(i));
            std::vector<Rational> next(product.size() + 1, Rational(0));
            for (std::size_t e = 0; e < product.size(); ++e) {
                next[e + 1] += product[e];
                next[e] += product[e] * shift;
            }
            product = std::move(next);
        }
        for (std::size_t e = 0; e < product.size(); ++e) {
            hp[e] += product[e] * Rational(q[i]);
        }
    }
    for (Rational& c : hp) {
        c = c / Rational(factorial);
    }
    while (!hp.empty() && hp.back().is_zero()) {
        hp.pop_back();
    }
    return hp;
}

// A set of `d` variables that contains the support of no generator (depth-first, smallest
// indices first); such a set exists when d is the dimension.
bool find_independent(const std::vector<ExponentVector>& generators, std::size_t n, std::size_t d,
                      std::size_t from, std::vector<std::size_t>& chosen,
                      std::vector<bool>& in_set) {
    if (chosen.size() == d) {
        return true;
    }
    for (std::size_t v = from; v < n && n - v >= d - chosen.size(); ++v) {
        in_set[v] = true;
        const bool independent =
            std::none_of(generators.begin(), generators.end(), [&](const ExponentVector& g) {
                for (std::size_t w = 0; w < n; ++w) {
                    if (g[w] != 0 && !in_set[w]) {
                        return false;
                    }
                }
                return true;
            });
        if (independent) {
            chosen.push_back(v);
            if (find_independent(generators, n, d, v + 1, chosen, in_set)) {
                return true;
            }
            chosen.pop_back();
        }
        in_set[v] = false;
    }
    return false;
}

}  // namespace

HilbertData hilbert_data(std::vector<ExponentVector> generators, std::size_t n,
                         std::optional<std::chrono::steady_clock::time_point> deadline) {
    for (const ExponentVector& g : generators) {
        if (g.size() != n) {
            throw InputError("Hilbert series", "an exponent vector of the wrong length");
        }
    }
    HilbertData data;
    data.variables = n;
    detail::minimalize(generators);
    data.numerator = SeriesNumerator(n, deadline).of(generators);
    if (data.numerator.empty()) {
        data.unit = true;
        return data;
    }
    IntegerCoefficients q = data.numerator;
    std::size_t poles_removed = 0;
    while (fmpz_is_zero(value_at_one(q).get())) {
        q = divided_by_one_minus_t(q);
        ++poles_removed;
    }
    data.dimension = n - poles_removed;
    data.degree = value_at_one(q);
    data.reduced_numerator = q;
    const std::size_t d = data.dimension;
    if (d > 0) {
        data.hilbert_polynomial = hilbert_polynomial_of(q, d);
    }
    const std::size_t q_degree = q.size() - 1;
    data.regularity = q_degree + 1 > d ? q_degree + 1 - d : 0;
    std::vector<std::size_t> chosen;
    std::vector<bool> in_set(n, false);
    if (!find_independent(generators, n, d, 0, chosen, in_set)) {
        throw Error("Hilbert series: no independent set of the dimension (a bug)");
    }
    data.independent_set = std::move(chosen);
    return data;
}

Integer hilbert_function(const HilbertData& data, std::size_t s) {
    Integer value(0);
    if (data.unit) {
        return value;
    }
    const std::size_t n = data.variables;
    Integer binomial;
    for (std::size_t i = 0; i < data.numerator.size() && i <= s; ++i) {
        // C(s − i + n − 1, n − 1) monomials of degree s − i in n variables.
        if (n == 0) {
            if (s == i) {
                fmpz_add(value.get(), value.get(), data.numerator[i].get());
            }
            continue;
        }
        fmpz_bin_uiui(binomial.get(), s - i + n - 1, n - 1);
        fmpz_addmul(value.get(), data.numerator[i].get(), binomial.get());
    }
    return value;
}

}  // namespace locus::algebra
