// Multivariate division by an ordered list of divisors (Cox–Little–O'Shea, IVA ch. 2 §3,
// Theorem 3): f = Σ qᵢ·fᵢ + r, where no monomial of r is divisible by any leading monomial,
// and lm(qᵢ·fᵢ) ≤ lm(f). The quotients are the certificate; check_division verifies it.
#pragma once

#include <span>
#include <vector>

#include "algebra/polynomial.h"

namespace locus::algebra {

struct DivisionResult {
    std::vector<Polynomial> quotients;  // one per divisor
    Polynomial remainder;
};

// Divides by the first divisor (in list order) whose leading monomial divides the current
// leading term, as CLO's algorithm does. Zero divisors get a zero quotient. Throws MixedRings.
DivisionResult divide(const Polynomial& f, std::span<const Polynomial> divisors);

// The remainder of divide(f, basis): for a Gröbner basis, the unique normal form of f.
Polynomial normal_form(const Polynomial& f, std::span<const Polynomial> basis);

// f == Σ qᵢ·fᵢ + r exactly, and r is reduced with respect to the divisors.
bool check_division(const Polynomial& f, std::span<const Polynomial> divisors,
                    const DivisionResult& result);

// f / g when g divides f exactly; throws InputError when it does not (or g is zero).
Polynomial exact_quotient(const Polynomial& f, const Polynomial& g);

}  // namespace locus::algebra
