#include "algebra/modular/modular_polynomial.h"

#include <flint/fmpz.h>
#include <flint/ulong_extras.h>

namespace locus::algebra::modular {

std::uint64_t PrimeField::inverse(std::uint64_t a) const {
    return n_invmod(a, p);
}

std::uint32_t previous_prime(std::uint32_t bound) {
    std::uint64_t candidate = bound - 1;
    while (!n_is_prime(candidate)) {
        --candidate;
    }
    return static_cast<std::uint32_t>(candidate);
}

std::optional<ModularPolynomial> reduce_modulo(const Polynomial& f, const PrimeField& field) {
    const std::size_t words = f.ring()->words();
    ModularPolynomial out;
    out.monomials.reserve(f.num_terms() * words);
    out.coefficients.reserve(f.num_terms());
    for (std::size_t i = 0; i < f.num_terms(); ++i) {
        const fmpq* c = f.coefficient(i).get();
        const std::uint64_t denominator = fmpz_fdiv_ui(fmpq_denref(c), field.p);
        if (denominator == 0) {
            return std::nullopt;
        }
        const std::uint64_t numerator = fmpz_fdiv_ui(fmpq_numref(c), field.p);
        if (numerator == 0) {
            continue;
        }
        out.coefficients.push_back(
            static_cast<std::uint32_t>(field.multiply(numerator, field.inverse(denominator))));
        const std::uint64_t* m = f.monomial(i);
        out.monomials.insert(out.monomials.end(), m, m + words);
    }
    return out;
}

}  // namespace locus::algebra::modular
