#include "implicit/verify.h"

#include <algorithm>
#include <span>

#include "algebra/division.h"
#include "algebra/flint_convert.h"

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

}  // namespace

bool vanishes_on(const Polynomial& f, const Parametrization& map) {
    // Over a common denominator Q = Π qᵢ with Pᵢ = pᵢ·Π_{j≠i} qⱼ, and D = deg f,
    //     g(u) = Σ c_α P(u)^α Q(u)^(D−|α|)   (f homogenized with Q)
    // is a polynomial whose degree in each parameter u_j is at most
    // B_j = D · max(maxᵢ deg_{u_j} Pᵢ, deg_{u_j} Q), and f vanishes on the map iff g = 0. A
    // polynomial of degree ≤ B_j in u_j that vanishes on a grid of B_j + 1 values per parameter
    // is zero, so evaluating g exactly on that grid is a proof, not a test. The bicubic patch's
    // degree-18 equation is checked on 55 × 55 points in seconds, where expanding g
    // symbolically took a minute. Grids beyond 200 000 points fall back to the expansion.
    const RingPtr& params = map.parameter_ring;
    const std::size_t n = map.coordinates.size();
    const std::size_t k = params->num_vars();
    const long total_degree = f.total_degree();
    if (total_degree <= 0) {
        return f.is_zero();
    }
    Polynomial common = Polynomial::constant(params, Rational(1));
    for (const auto& c : map.components) {
        common *= c.denominator();
    }
    std::vector<Polynomial> numerators;
    for (std::size_t i = 0; i < n; ++i) {
        Polynomial numerator = map.components[i].numerator();
        for (std::size_t j = 0; j < n; ++j) {
            if (j != i) {
                numerator *= map.components[j].denominator();
            }
        }
        numerators.push_back(std::move(numerator));
    }
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
    // f homogenized with an extra variable w (index n) standing for Q.
    std::vector<std::string> names = f.ring()->variable_names();
    names.push_back("w_homogenizing");
    const RingPtr homogeneous_ring =
        algebra::PolyRing::make(names, algebra::MonomialOrder::grevlex(n + 1));
    std::vector<std::pair<Rational, std::vector<std::uint32_t>>> terms;
    for (std::size_t t = 0; t < f.num_terms(); ++t) {
        std::vector<std::uint32_t> e = f.exponents(t);
        long degree = 0;
        for (const auto x : e) {
            degree += x;
        }
        e.push_back(static_cast<std::uint32_t>(total_degree - degree));
        terms.emplace_back(f.coefficient(t), std::move(e));
    }
    const Polynomial homogeneous = Polynomial::from_terms(homogeneous_ring, std::move(terms));
    algebra::FlintContext context(homogeneous_ring);
    algebra::FlintPolynomial flint_f = algebra::to_fmpq_mpoly(homogeneous, context);
    std::vector<Rational> values(n + 1), point(k);
    std::vector<fmpq*> value_pointers(n + 1);
    std::vector<long> index(k, 0);
    Rational result;
    while (true) {
        for (std::size_t j = 0; j < k; ++j) {
            point[j] = Rational(index[j] - bound[j] / 2);  // centred: smaller numbers
        }
        for (std::size_t i = 0; i < n; ++i) {
            values[i] = numerators[i].evaluate(point);
            value_pointers[i] = values[i].get();
        }
        values[n] = common.evaluate(point);
        value_pointers[n] = values[n].get();
        fmpq_mpoly_evaluate_all_fmpq(result.get(), flint_f.get(), value_pointers.data(),
                                     context.get());
        if (!result.is_zero()) {
            return false;
        }
        std::size_t j = 0;
        while (j < k && ++index[j] > bound[j]) {
            index[j] = 0;
            ++j;
        }
        if (j == k) {
            return true;
        }
    }
}

bool vanishes_on_map_as_written(const Polynomial& f, const Parametrization& map) {
    if (map.circle_components.empty()) {
        return vanishes_on(f, map);
    }
    return substituted(f, map.circle_components, map.circle_ring, map.circle_relations).is_zero();
}

}  // namespace locus::implicit
