// Implicitization by interpolation modulo primes (`--method interpolate`).
//
// For a plane curve or a surface, the implicit equation is the polynomial of least degree D that
// vanishes at every point of the image. Its coefficients span the kernel of the matrix whose
// rows are the monomials of degree ≤ D evaluated at sample points of the parametrization. Over
// F_p the samples are cheap and the kernel is word-size linear algebra (FLINT nmod_mat); D is
// found by trying D = 1, 2, … up to the Bézout bound (d for curves, d² for surfaces, d the
// degree of the map over a common denominator), and the first D with a kernel is the degree.
// A one-dimensional kernel, normalised at a fixed monomial, is computed modulo primes near
// 2^62, combined by the CRT, and lifted to Q by rational reconstruction once two lifts agree.
// The result is then proved by exact substitution (vanishes_on); a lift that fails the proof
// only means more primes are needed. Cost: a few (M + 8) × M eliminations mod p for M monomials
// (M = 220 for the cubic Bézier triangle, against a 2-second resultant). See Emiris, Kalinka,
// Konaxis, "Implicitization of curves and surfaces using predicted support" (2011) for the
// support-prediction refinements this does not use.
#include <flint/fmpq.h>
#include <flint/fmpz.h>
#include <flint/nmod_mat.h>
#include <flint/ulong_extras.h>

#include <array>
#include <chrono>
#include <optional>
#include <random>
#include <span>

#include "algebra/deadline.h"
#include "algebra/error.h"
#include "algebra/modular/modular_polynomial.h"
#include "algebra/modular/rational_lift.h"
#include "implicit/detail/modular_lifting.h"
#include "implicit/implicitize.h"

namespace locus::implicit {

using algebra::Polynomial;
using algebra::Rational;

namespace {

// The largest support tried: 1330 monomials is degree 18 in x, y, z, the implicit degree of a
// bicubic patch; one elimination modulo p then takes about a second.
constexpr std::size_t kMaxSupport = 1330;

using algebra::modular::PrimeField;
using algebra::modular::WideModularPolynomial;

// f at a point modulo p (the point's coordinates in the order of f's variables).
ulong evaluate(const WideModularPolynomial& f, const algebra::PolyRing& ring,
               const std::vector<ulong>& point, const PrimeField& field) {
    // One or two parameters (implicitize_by_interpolation checks): no allocation per point.
    std::array<std::uint32_t, 2> exponents{};
    const std::span<std::uint32_t> used(exponents.data(), ring.num_vars());
    ulong sum = 0;
    for (std::size_t i = 0; i < f.size(); ++i) {
        ring.layout().unpack(f.monomial(i, ring.words()), used);
        ulong term = f.coefficients[i];
        for (std::size_t k = 0; k < used.size(); ++k) {
            if (used[k] != 0) {
                term = field.multiply(term, field.power(point[k], used[k]));
            }
        }
        sum = field.add(sum, term);
    }
    return sum;
}

// Exponent vectors of all monomials of total degree ≤ degree in `vars` variables.
std::vector<std::vector<std::uint32_t>> monomials_up_to(std::size_t vars, unsigned degree) {
    std::vector<std::vector<std::uint32_t>> result;
    std::vector<std::uint32_t> e(vars, 0);
    auto recurse = [&](auto&& self, std::size_t k, unsigned left) -> void {
        if (k + 1 == vars) {
            for (unsigned d = 0; d <= left; ++d) {
                e[k] = d;
                result.push_back(e);
            }
            return;
        }
        for (unsigned d = 0; d <= left; ++d) {
            e[k] = d;
            self(self, k + 1, left - d);
        }
    };
    recurse(recurse, 0, degree);
    return result;
}

// The kernel of the sample matrix modulo p for monomials `support`: its dimension and, when it
// is one, the kernel vector. Returns dimension −1 when p is unusable (divides a denominator).
struct ModularKernel {
    long dimension = -1;
    std::vector<ulong> vector;
};

ModularKernel kernel_mod(const Parametrization& map,
                         const std::vector<std::vector<std::uint32_t>>& support, ulong p,
                         std::mt19937_64& rng) {
    const PrimeField field(p);
    std::vector<WideModularPolynomial> numerators, denominators;
    for (const auto& component : map.components) {
        auto numerator =
            algebra::modular::reduce_modulo<std::uint64_t>(component.numerator(), field);
        auto denominator =
            algebra::modular::reduce_modulo<std::uint64_t>(component.denominator(), field);
        if (!numerator || !denominator) {
            return {};
        }
        numerators.push_back(std::move(*numerator));
        denominators.push_back(std::move(*denominator));
    }
    const std::size_t columns = support.size();
    const std::size_t rows = columns + 8;
    const std::size_t num_params = map.parameter_ring->num_vars();
    nmod_mat_t matrix, kernel;
    nmod_mat_init(matrix, static_cast<slong>(rows), static_cast<slong>(columns), p);
    std::uniform_int_distribution<ulong> parameter(1, p - 1);
    std::vector<ulong> point(num_params), coordinates(map.components.size());
    for (std::size_t row = 0; row < rows; ++row) {
        bool defined = false;
        while (!defined) {
            for (auto& v : point) {
                v = parameter(rng);
            }
            defined = true;
            for (std::size_t i = 0; i < map.components.size(); ++i) {
                const ulong q = evaluate(denominators[i], *map.components[i].denominator().ring(),
                                         point, field);
                if (q == 0) {
                    defined = false;
                    break;
                }
                coordinates[i] = field.multiply(
                    evaluate(numerators[i], *map.components[i].numerator().ring(), point, field),
                    field.inverse(q));
            }
        }
        for (std::size_t j = 0; j < columns; ++j) {
            ulong value = 1;
            for (std::size_t k = 0; k < coordinates.size(); ++k) {
                value = field.multiply(value, field.power(coordinates[k], support[j][k]));
            }
            nmod_mat_entry(matrix, row, j) = value;
        }
    }
    nmod_mat_init(kernel, static_cast<slong>(columns), static_cast<slong>(columns), p);
    ModularKernel result;
    result.dimension = nmod_mat_nullspace(kernel, matrix);
    if (result.dimension == 1) {
        for (std::size_t j = 0; j < columns; ++j) {
            result.vector.push_back(nmod_mat_entry(kernel, j, 0));
        }
    }
    nmod_mat_clear(matrix);
    nmod_mat_clear(kernel);
    return result;
}

// Degree of the map over a common denominator: max(deg Pᵢ, deg Q) with xᵢ = Pᵢ/Q.
long map_degree(const Parametrization& map) {
    Polynomial common = map.components[0].denominator();
    for (std::size_t i = 1; i < map.components.size(); ++i) {
        const Polynomial& q = map.components[i].denominator();
        common = common * q;  // a multiple of the lcm: an upper bound is all we need
    }
    long degree = common.total_degree();
    for (const auto& component : map.components) {
        degree = std::max(degree, component.numerator().total_degree() + common.total_degree() -
                                      component.denominator().total_degree());
    }
    return degree;
}

}  // namespace

ImplicitResult implicitize_by_interpolation(
    const Parametrization& map, std::optional<std::chrono::steady_clock::time_point> deadline) {
    auto check_deadline = [&] {
        if (deadline_passed(deadline)) {
            throw Timeout("interpolation stopped at the deadline");
        }
    };
    const auto start = std::chrono::steady_clock::now();
    const std::size_t num_params = map.parameter_ring->num_vars();
    const std::size_t n = map.coordinates.size();
    if (!((num_params == 1 && n == 2) || (num_params == 2 && n == 3))) {
        throw InputError("method interpolate",
                         "applies to plane curves and surfaces (one equation); use groebner");
    }
    const long d = map_degree(map);
    const long bound = num_params == 1 ? d : d * d;
    std::mt19937_64 rng(20261123);
    algebra::modular::PrimeSequence primes(algebra::modular::PrimeSequence::Width::wide);
    ulong p = primes.next();
    // The least degree with a kernel.
    std::vector<std::vector<std::uint32_t>> support;
    ModularKernel first;
    for (long degree = 1; degree <= bound; ++degree) {
        check_deadline();
        support = monomials_up_to(n, static_cast<unsigned>(degree));
        if (support.size() > kMaxSupport) {
            throw Error("interpolation gave up: degree " + std::to_string(degree) + " needs " +
                        std::to_string(support.size()) + " monomials (limit " +
                        std::to_string(kMaxSupport) + ")");
        }
        first = kernel_mod(map, support, p, rng);
        while (first.dimension < 0) {
            p = primes.next();
            first = kernel_mod(map, support, p, rng);
        }
        if (first.dimension > 0) {
            break;
        }
    }
    if (first.dimension != 1) {
        throw Error(first.dimension == 0
                        ? "interpolation found no equation up to the degree bound"
                        : "the kernel has dimension " + std::to_string(first.dimension) +
                              ": the image is not a hypersurface, or the map is degenerate");
    }
    std::size_t pivot = 0;
    while (first.vector[pivot] == 0) {
        ++pivot;
    }
    detail::NormalizedLifting lifting(support.size(), pivot);
    ImplicitResult result;
    bool done = false;
    ModularKernel k = first;
    for (int prime_count = 0; prime_count < 400 && !done; ++prime_count) {
        if (prime_count > 0) {
            check_deadline();
            p = primes.next();
            k = kernel_mod(map, support, p, rng);
            if (k.dimension != 1 || k.vector[pivot] == 0) {
                continue;  // unlucky prime
            }
        }
        if (!lifting.add(k.vector, p)) {
            continue;
        }
        std::vector<std::pair<Rational, std::vector<std::uint32_t>>> terms;
        for (std::size_t j = 0; j < support.size(); ++j) {
            if (!lifting.values()[j].is_zero()) {
                terms.emplace_back(lifting.values()[j], support[j]);
            }
        }
        result.ring = algebra::PolyRing::make(map.coordinates, algebra::MonomialOrder::grevlex(n));
        const Polynomial equation =
            Polynomial::from_terms(result.ring, std::move(terms)).primitive_part();
        if (vanishes_on(equation, map)) {
            result.equation = equation;
            result.generators = {equation};
            result.proved_on_map = true;
            done = true;
        }
    }
    if (!done) {
        throw Error("interpolation did not converge within 400 primes");
    }
    result.image = ImageKind::hypersurface;
    result.method = "interpolate";
    result.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace locus::implicit
