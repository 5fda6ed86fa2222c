#include "implicit/verify.h"

#include "implicit/implicitize.h"

#include <flint/fmpq.h>
#include <flint/fmpz.h>
#include <flint/nmod_vec.h>
#include <flint/ulong_extras.h>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <map>
#include <span>

#include "algebra/division.h"
#include "algebra/flint_convert.h"
#include "algebra/flint_threads.h"

namespace locus::implicit {

using algebra::Polynomial;
using algebra::Rational;
using algebra::RationalFunction;
using algebra::RingPtr;

namespace {

// Σ c_α Π pᵢ^αᵢ qᵢ^(dᵢ−αᵢ) for xᵢ = pᵢ/qᵢ (dᵢ the degree of f in xᵢ): f with the map
// substituted, times the denominators' powers, in the components' ring; every product reduced
// modulo `relations` (a Gröbner basis) when there are any.
Polynomial substituted(const Polynomial& f, std::span<const RationalFunction> components,
                       const RingPtr& ring, std::span<const Polynomial> relations) {
    const std::size_t n = components.size();
    std::vector<long> degree(n);
    for (std::size_t i = 0; i < n; ++i) {
        degree[i] = std::max<long>(0, f.degree(i));
    }
    const auto reduce = [&](const Polynomial& p) {
        return relations.empty() ? p : algebra::normal_form(p, relations);
    };
    // Powers of numerators and denominators, cached.
    std::vector<std::vector<Polynomial>> num_pow(n), den_pow(n);
    // Returns a reference into the cache: a copy per term and coordinate would dominate.
    auto power = [&](std::vector<Polynomial>& cache, const Polynomial& base,
                     long e) -> const Polynomial& {
        if (cache.empty()) {
            cache.push_back(Polynomial::constant(ring, Rational(1)));
        }
        while (static_cast<long>(cache.size()) <= e) {
            cache.push_back(reduce(cache.back() * base));
        }
        return cache[static_cast<std::size_t>(e)];
    };
    Polynomial total(ring);
    for (std::size_t t = 0; t < f.num_terms(); ++t) {
        const auto e = f.exponents(t);
        Polynomial term = Polynomial::constant(ring, f.coefficient(t));
        for (std::size_t i = 0; i < n; ++i) {
            term = reduce(term * power(num_pow[i], components[i].numerator(), e[i]));
            term = reduce(term * power(den_pow[i], components[i].denominator(), degree[i] - e[i]));
        }
        total += term;
    }
    return reduce(total);
}

// Terms of a polynomial with integer coefficients (the polynomial times `scale`).
struct IntegerTerms {
    std::vector<algebra::Integer> coefficients;
    std::vector<std::vector<std::uint32_t>> exponents;
};

IntegerTerms integer_terms(const Polynomial& f, const algebra::Integer& scale) {
    IntegerTerms r;
    for (std::size_t i = 0; i < f.num_terms(); ++i) {
        const fmpq* q = f.coefficient(i).get();
        algebra::Integer c;
        fmpz_divexact(c.get(), scale.get(), fmpq_denref(q));
        fmpz_mul(c.get(), c.get(), fmpq_numref(q));
        r.coefficients.push_back(std::move(c));
        r.exponents.push_back(f.exponents(i));
    }
    return r;
}

void lcm_of_denominators(const Polynomial& f, algebra::Integer& lcm) {
    for (std::size_t i = 0; i < f.num_terms(); ++i) {
        fmpz_lcm(lcm.get(), lcm.get(), fmpq_denref(f.coefficient(i).get()));
    }
}

// f's coefficients laid out in the order of a nested Horner scheme over the monomials of total
// degree ≤ D: for the first variable from exponent D down to 0, and within each, the same for
// the remaining variables with the degree left. `horner` walks the layout in that order.
void horner_layout(std::size_t k, std::size_t vars, long degree, std::vector<std::uint32_t>& e,
                   std::map<std::vector<std::uint32_t>, std::size_t>& position) {
    for (long d = degree; d >= 0; --d) {
        e[k] = static_cast<std::uint32_t>(d);
        if (k + 1 == vars) {
            const std::size_t next = position.size();
            position.emplace(e, next);
        } else {
            horner_layout(k + 1, vars, degree - d, e, position);
        }
    }
    e[k] = 0;
}

// f at `kLanes` points at once: the lanes' Horner chains are independent, so the latency of
// one modular multiplication overlaps with the others'.
constexpr std::size_t kLanes = 4;
using Lanes = std::array<ulong, kLanes>;

Lanes horner(const ulong*& coefficient, std::size_t k, std::size_t vars, long degree,
             const std::vector<Lanes>& x, nmod_t mod) {
    Lanes result{};
    for (long d = degree; d >= 0; --d) {
        Lanes inner;
        if (k + 1 == vars) {
            inner.fill(*coefficient++);
        } else {
            inner = horner(coefficient, k + 1, vars, degree - d, x, mod);
        }
        for (std::size_t l = 0; l < kLanes; ++l) {
            result[l] = nmod_add(nmod_mul(result[l], x[k][l], mod), inner[l], mod);
        }
    }
    return result;
}

// g = Σ c_α P^α Q^(D−|α|) (f homogenized with the common denominator Q) is zero iff it
// vanishes on the grid Π {0, …, B_j}; at a grid point its value is an integer once P and Q are
// scaled to integer coefficients, and every coefficient of g is at most
//     H = Σ |c_α| Π ‖Pᵢ‖₁^αᵢ ‖Q‖₁^(D−|α|)
// in absolute value (‖·‖₁ the sum of the absolute values of the coefficients, which is
// submultiplicative). So g = 0 iff g ≡ 0 modulo primes whose product exceeds H, and g ≡ 0 mod
// p iff g vanishes on the grid over F_p (p > B_j): word-size evaluations, a proof.
bool vanishes_on_grid(const Polynomial& f, const std::vector<Polynomial>& numerators,
                      const Polynomial& common, const std::vector<long>& bound, int threads) {
    const std::size_t n = numerators.size();
    const std::size_t k = bound.size();
    const long total_degree = f.total_degree();
    algebra::Integer map_scale(1), f_scale(1);
    for (const auto& p : numerators) {
        lcm_of_denominators(p, map_scale);
    }
    lcm_of_denominators(common, map_scale);
    lcm_of_denominators(f, f_scale);
    std::vector<IntegerTerms> map_terms;  // P₁ … P_n, then Q
    for (const auto& p : numerators) {
        map_terms.push_back(integer_terms(p, map_scale));
    }
    map_terms.push_back(integer_terms(common, map_scale));
    IntegerTerms f_terms = integer_terms(f, f_scale);
    // Where a point has Q ≠ 0, g = Q^D · f(P/Q) and f is evaluated by a Horner scheme (one
    // multiplication per monomial); the homogeneous sum is the fallback where Q = 0.
    std::map<std::vector<std::uint32_t>, std::size_t> position;
    {
        std::vector<std::uint32_t> e(n, 0);
        horner_layout(0, n, total_degree, e, position);
    }
    std::vector<std::size_t> term_position;
    for (const auto& e : f_terms.exponents) {
        term_position.push_back(position.at(e));
    }
    for (std::size_t t = 0; t < f_terms.exponents.size(); ++t) {
        long degree = 0;
        for (const auto e : f_terms.exponents[t]) {
            degree += e;
        }
        f_terms.exponents[t].push_back(static_cast<std::uint32_t>(total_degree - degree));
    }
    // The bound H, exactly.
    std::vector<std::vector<algebra::Integer>> norm_powers(n + 1);
    for (std::size_t i = 0; i <= n; ++i) {
        algebra::Integer norm;
        for (const auto& c : map_terms[i].coefficients) {
            fmpz_t a;
            fmpz_init(a);
            fmpz_abs(a, c.get());
            fmpz_add(norm.get(), norm.get(), a);
            fmpz_clear(a);
        }
        norm_powers[i].push_back(algebra::Integer(1));
        for (long e = 1; e <= total_degree; ++e) {
            norm_powers[i].push_back(norm_powers[i].back() * norm);
        }
    }
    algebra::Integer bound_h, term;
    for (std::size_t t = 0; t < f_terms.coefficients.size(); ++t) {
        fmpz_abs(term.get(), f_terms.coefficients[t].get());
        for (std::size_t i = 0; i <= n; ++i) {
            fmpz_mul(term.get(), term.get(), norm_powers[i][f_terms.exponents[t][i]].get());
        }
        fmpz_add(bound_h.get(), bound_h.get(), term.get());
    }
    // The primes, then one independent check per prime (on `threads` threads); the first
    // prime that sees a non-zero value settles the answer.
    std::vector<ulong> primes;
    algebra::Integer product(1);
    for (ulong p = n_nextprime(UWORD(1) << 62, 1); fmpz_cmp(product.get(), bound_h.get()) <= 0;
         p = n_nextprime(p, 1)) {
        primes.push_back(p);
        fmpz_mul_ui(product.get(), product.get(), p);
    }
    std::atomic<bool> nonzero{false};
    const auto vanishes_modulo = [&](ulong p) {
        algebra::release_flint_caches_at_thread_exit();  // on oneTBB's workers
        nmod_t mod;
        nmod_init(&mod, p);
        std::vector<ulong> layout(position.size()), f_mod(f_terms.coefficients.size());
        for (std::size_t t = 0; t < f_mod.size(); ++t) {
            f_mod[t] = fmpz_fdiv_ui(f_terms.coefficients[t].get(), p);
            layout[term_position[t]] = f_mod[t];
        }
        std::vector<std::vector<ulong>> map_mod(n + 1);
        for (std::size_t i = 0; i <= n; ++i) {
            for (const auto& c : map_terms[i].coefficients) {
                map_mod[i].push_back(fmpz_fdiv_ui(c.get(), p));
            }
        }
        std::vector<std::vector<ulong>> parameter_powers(k), value_powers(n + 1);
        std::vector<Lanes> quotients(n);
        std::vector<ulong> values(n + 1);
        std::size_t lanes_used = 0;
        std::vector<long> index(k, 0);
        for (std::size_t point = 0;; ++point) {
            if (point % 256 == 0 && nonzero.load(std::memory_order_relaxed)) {
                return false;  // another prime has already answered
            }
            for (std::size_t j = 0; j < k; ++j) {
                parameter_powers[j].assign(1, 1);
            }
            for (std::size_t i = 0; i <= n; ++i) {
                ulong sum = 0;
                for (std::size_t t = 0; t < map_mod[i].size(); ++t) {
                    ulong v = map_mod[i][t];
                    for (std::size_t j = 0; j < k; ++j) {
                        const std::uint32_t e = map_terms[i].exponents[t][j];
                        auto& powers = parameter_powers[j];
                        while (powers.size() <= e) {
                            powers.push_back(
                                nmod_mul(powers.back(), static_cast<ulong>(index[j]), mod));
                        }
                        v = nmod_mul(v, powers[e], mod);
                    }
                    sum = nmod_add(sum, v, mod);
                }
                values[i] = sum;
            }
            ulong g = 0;
            if (values[n] != 0) {
                const ulong inverse = n_invmod(values[n], p);
                for (std::size_t i = 0; i < n; ++i) {
                    quotients[i][lanes_used] = nmod_mul(values[i], inverse, mod);
                }
                ++lanes_used;
            } else {
                for (std::size_t i = 0; i <= n; ++i) {
                    value_powers[i].assign(1, 1);
                    for (long e = 1; e <= total_degree; ++e) {
                        value_powers[i].push_back(nmod_mul(value_powers[i].back(), values[i], mod));
                    }
                }
                for (std::size_t t = 0; t < f_mod.size(); ++t) {
                    ulong v = f_mod[t];
                    const auto& e = f_terms.exponents[t];
                    for (std::size_t i = 0; i <= n; ++i) {
                        v = nmod_mul(v, value_powers[i][e[i]], mod);
                    }
                    g = nmod_add(g, v, mod);
                }
            }
            std::size_t j = 0;
            while (j < k && ++index[j] > bound[j]) {
                index[j] = 0;
                ++j;
            }
            const bool last = j == k;
            if (lanes_used == kLanes || (last && lanes_used > 0)) {
                for (std::size_t l = lanes_used; l < kLanes; ++l) {  // pad with a used lane
                    for (std::size_t i = 0; i < n; ++i) {
                        quotients[i][l] = quotients[i][0];
                    }
                }
                const ulong* walk = layout.data();
                const Lanes at = horner(walk, 0, n, total_degree, quotients, mod);
                for (const ulong v : at) {
                    g |= v;
                }
                lanes_used = 0;
            }
            if (g != 0) {
                nonzero = true;
                return false;
            }
            if (last) {
                return true;
            }
        }
    };
    if (threads <= 1 || primes.size() == 1) {
        for (const ulong p : primes) {
            if (!vanishes_modulo(p)) {
                return false;
            }
        }
        return true;
    }
    tbb::task_arena arena(threads);
    arena.execute([&] {
        tbb::parallel_for(std::size_t{0}, primes.size(),
                          [&](std::size_t i) { vanishes_modulo(primes[i]); });
    });
    return !nonzero.load();
}

}  // namespace

bool vanishes_on(const Polynomial& f, const Parametrization& map, int threads) {
    // Over a common denominator Q (over_common_denominator: xᵢ = Pᵢ/Q), and D = deg f,
    //     g(u) = Σ c_α P(u)^α Q(u)^(D−|α|)   (f homogenized with Q)
    // is a polynomial whose degree in each parameter u_j is at most
    // B_j = D · max(maxᵢ deg_{u_j} Pᵢ, deg_{u_j} Q), and f vanishes on the map iff g = 0. A
    // polynomial of degree ≤ B_j in u_j that vanishes on a grid of B_j + 1 values per parameter
    // is zero, so checking that g vanishes on that grid is a proof, not a test; it is checked
    // modulo enough primes to exceed a bound on g's coefficients (vanishes_on_grid). The bicubic
    // patch's degree-18 equation is checked on 55 × 55 points; grids beyond 200 000 points fall
    // back to the symbolic expansion.
    const RingPtr& params = map.parameter_ring;
    const std::size_t k = params->num_vars();
    const long total_degree = f.total_degree();
    if (total_degree <= 0) {
        return f.is_zero();
    }
    CommonDenominatorForm form = over_common_denominator(map);
    const Polynomial& common = form.denominator;
    const std::vector<Polynomial>& numerators = form.numerators;
    std::vector<long> bound(k);
    double points = 1.0;
    for (std::size_t j = 0; j < k; ++j) {
        long d = std::max<long>(0, common.degree(j));
        for (const auto& p : numerators) {
            d = std::max<long>(d, p.degree(j));
        }
        bound[j] = total_degree * d;
        points *= static_cast<double>(bound[j] + 1);
    }
    if (points > 200000) {
        return substituted(f, map.components, map.parameter_ring, {}).is_zero();
    }
    return vanishes_on_grid(f, numerators, common, bound, threads);
}

bool vanishes_on_map_as_written(const Polynomial& f, const Parametrization& map) {
    if (map.circle_components.empty()) {
        return vanishes_on(f, map);
    }
    return substituted(f, map.circle_components, map.circle_ring, map.circle_relations).is_zero();
}

std::optional<algebra::Polynomial> first_not_vanishing(const ImplicitResult& result,
                                                       const Parametrization& map) {
    if (result.equation) {
        const bool proved = result.proved_on_map && map.circle_components.empty();
        if (!proved && !vanishes_on_map_as_written(*result.equation, map)) {
            return result.equation;
        }
        return std::nullopt;
    }
    for (const algebra::Polynomial& g : result.generators) {
        if (!vanishes_on_map_as_written(g, map)) {
            return g;
        }
    }
    return std::nullopt;
}

}  // namespace locus::implicit
