// check_groebner_basis_modulo (verify.h): Buchberger's criterion over GF(p).
#include <flint/fmpq.h>
#include <flint/fmpz.h>
#include <flint/ulong_extras.h>

#include <string>
#include <vector>

#include "algebra/deadline.h"
#include "algebra/error.h"
#include "algebra/groebner/verify.h"
#include "algebra/print.h"

namespace locus::algebra {
namespace {

using Deadline = std::optional<std::chrono::steady_clock::time_point>;

std::uint64_t residue(const Rational& c, std::uint32_t p) {
    const std::uint64_t numerator = fmpz_fdiv_ui(fmpq_numref(c.get()), p);
    const std::uint64_t denominator = fmpz_fdiv_ui(fmpq_denref(c.get()), p);
    if (denominator == 0) {
        throw InputError("coefficient " + c.to_string(),
                         "its denominator is divisible by the characteristic " + std::to_string(p));
    }
    return numerator * n_invmod(denominator, p) % p;  // both below 2³¹: no overflow
}

// f with every coefficient replaced by its residue in [0, p), zero residues dropped.
Polynomial residues(const Polynomial& f, std::uint32_t p) {
    Polynomial r(f.ring());
    r.reserve(f.num_terms());
    for (std::size_t i = 0; i < f.num_terms(); ++i) {
        const std::uint64_t c = residue(f.coefficient(i), p);
        if (c != 0) {
            r.push_back_term(Rational(static_cast<long>(c)), f.monomial(i));
        }
    }
    return r;
}

void check_deadline(const Deadline& deadline) {
    if (deadline_passed(deadline)) {
        throw Timeout("the check modulo p stopped at the deadline");
    }
}

// Top-reduces h (in residue form) by the basis modulo p: true when it reaches zero, false when
// a leading term no leading monomial of the basis divides is left.
bool reduces_to_zero(Polynomial h, const std::vector<Polynomial>& basis,
                     const std::vector<std::uint64_t>& inverse_leads, std::uint32_t p,
                     std::size_t& steps, const Deadline& deadline) {
    const MonomialLayout& layout = h.ring()->layout();
    std::vector<std::uint64_t> quotient(layout.words());
    while (!h.is_zero()) {
        std::size_t k = 0;
        while (k < basis.size() &&
               !layout.divides(basis[k].leading_monomial(), h.leading_monomial())) {
            ++k;
        }
        if (k == basis.size()) {
            return false;
        }
        layout.divide(h.leading_monomial(), basis[k].leading_monomial(), quotient.data());
        const std::uint64_t c = residue(h.leading_coefficient(), p) * inverse_leads[k] % p;
        h = residues(h.minus_term_times(Rational(static_cast<long>(c)), quotient.data(), basis[k]),
                     p);
        if (++steps % 256 == 0) {
            check_deadline(deadline);
        }
    }
    return true;
}

}  // namespace

BasisCheck check_groebner_basis_modulo(std::span<const Polynomial> basis_given,
                                       std::span<const Polynomial> generators, std::uint32_t p,
                                       Deadline deadline) {
    if (p < 2 || !n_is_prime(p)) {
        throw InputError("characteristic " + std::to_string(p), "expected a prime below 2^31");
    }
    BasisCheck check;
    std::vector<Polynomial> basis;
    std::vector<std::uint64_t> inverse_leads;
    for (const Polynomial& g : basis_given) {
        Polynomial r = residues(g, p);
        if (!r.is_zero()) {
            inverse_leads.push_back(n_invmod(residue(r.leading_coefficient(), p), p));
            basis.push_back(std::move(r));
        }
    }
    for (std::size_t i = 0; i < generators.size(); ++i) {
        ++check.generators_checked;
        if (!reduces_to_zero(residues(generators[i], p), basis, inverse_leads, p,
                             check.work.reduction_steps, deadline)) {
            check.ok = false;
            check.failure = "generator " + std::to_string(i + 1) + " (" + to_string(generators[i]) +
                            ") does not reduce to zero modulo " + std::to_string(p);
            return check;
        }
    }
    for (std::size_t i = 0; i < basis.size(); ++i) {
        const MonomialLayout& layout = basis[i].ring()->layout();
        std::vector<std::uint64_t> lcm(layout.words()), mi(layout.words()), mj(layout.words());
        for (std::size_t j = i + 1; j < basis.size(); ++j) {
            if (layout.coprime(basis[i].leading_monomial(), basis[j].leading_monomial())) {
                continue;
            }
            layout.lcm(basis[i].leading_monomial(), basis[j].leading_monomial(), lcm.data());
            layout.divide(lcm.data(), basis[i].leading_monomial(), mi.data());
            layout.divide(lcm.data(), basis[j].leading_monomial(), mj.data());
            const Polynomial s =
                residues(basis[i]
                             .times_term(Rational(static_cast<long>(inverse_leads[i])), mi.data())
                             .minus_term_times(Rational(static_cast<long>(inverse_leads[j])),
                                               mj.data(), basis[j]),
                         p);
            ++check.pairs_checked;
            if (!reduces_to_zero(s, basis, inverse_leads, p, check.work.reduction_steps,
                                 deadline)) {
                check.ok = false;
                check.failure = "the S-polynomial of elements " + std::to_string(i + 1) + " and " +
                                std::to_string(j + 1) + " does not reduce to zero modulo " +
                                std::to_string(p);
                return check;
            }
        }
    }
    return check;
}

}  // namespace locus::algebra
