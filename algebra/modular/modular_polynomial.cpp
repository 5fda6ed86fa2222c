#include "algebra/modular/modular_polynomial.h"

#include <flint/fmpz.h>
#include <flint/ulong_extras.h>

namespace locus::algebra::modular {

std::optional<std::uint64_t> PrimeField::residue(const fmpq* q) const {
    const std::uint64_t denominator = fmpz_fdiv_ui(fmpq_denref(q), p);
    if (denominator == 0) {
        return std::nullopt;
    }
    return multiply(fmpz_fdiv_ui(fmpq_numref(q), p), inverse(denominator));
}

std::uint32_t previous_prime(std::uint32_t bound) {
    std::uint64_t candidate = bound - 1;
    while (!n_is_prime(candidate)) {
        --candidate;
    }
    return static_cast<std::uint32_t>(candidate);
}

template <typename Coefficient>
std::optional<BasicModularPolynomial<Coefficient>> reduce_modulo(const Polynomial& f,
                                                                 const PrimeField& field) {
    const std::size_t words = f.ring()->words();
    BasicModularPolynomial<Coefficient> out;
    out.monomials.reserve(f.num_terms() * words);
    out.coefficients.reserve(f.num_terms());
    for (std::size_t i = 0; i < f.num_terms(); ++i) {
        const std::optional<std::uint64_t> c = field.residue(f.coefficient(i).get());
        if (!c) {
            return std::nullopt;
        }
        if (*c == 0) {
            continue;
        }
        out.coefficients.push_back(static_cast<Coefficient>(*c));
        const std::uint64_t* m = f.monomial(i);
        out.monomials.insert(out.monomials.end(), m, m + words);
    }
    return out;
}

template std::optional<ModularPolynomial> reduce_modulo<std::uint32_t>(const Polynomial&,
                                                                       const PrimeField&);
template std::optional<WideModularPolynomial> reduce_modulo<std::uint64_t>(const Polynomial&,
                                                                           const PrimeField&);

}  // namespace locus::algebra::modular
