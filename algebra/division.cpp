#include "algebra/division.h"

#include "algebra/error.h"

namespace locus::algebra {
namespace {

// Index of the first divisor whose leading monomial divides m, or divisors.size().
std::size_t find_divisor(const std::uint64_t* m, std::span<const Polynomial> divisors,
                         const MonomialLayout& layout) {
    for (std::size_t k = 0; k < divisors.size(); ++k) {
        if (!divisors[k].is_zero() && layout.divides(divisors[k].leading_monomial(), m)) {
            return k;
        }
    }
    return divisors.size();
}

// The division loop; `quotients` may be null when only the remainder is wanted.
Polynomial divide_into(const Polynomial& f, std::span<const Polynomial> divisors,
                       std::vector<Polynomial>* quotients) {
    for (const auto& d : divisors) {
        require_same_ring(f, d);
    }
    const RingPtr& ring = f.ring();
    const MonomialLayout& layout = ring->layout();
    std::vector<std::uint64_t> m(ring->words());
    Polynomial p = f;
    Polynomial remainder(ring);
    // Quotient terms arrive in descending order per divisor, so they can be appended.
    while (!p.is_zero()) {
        const std::size_t k = find_divisor(p.leading_monomial(), divisors, layout);
        if (k == divisors.size()) {
            remainder.push_back_term(p.leading_coefficient(), p.leading_monomial());
            Polynomial rest(ring);
            rest.reserve(p.num_terms() - 1);
            for (std::size_t i = 1; i < p.num_terms(); ++i) {
                rest.push_back_term(p.coefficient(i), p.monomial(i));
            }
            p = std::move(rest);
            continue;
        }
        const Polynomial& g = divisors[k];
        layout.divide(p.leading_monomial(), g.leading_monomial(), m.data());
        const Rational c = p.leading_coefficient() / g.leading_coefficient();
        if (quotients) {
            (*quotients)[k].push_back_term(c, m.data());
        }
        p = p.minus_term_times(c, m.data(), g);
    }
    return remainder;
}

}  // namespace

DivisionResult divide(const Polynomial& f, std::span<const Polynomial> divisors) {
    DivisionResult result{std::vector<Polynomial>(divisors.size(), Polynomial(f.ring())),
                          Polynomial(f.ring())};
    result.remainder = divide_into(f, divisors, &result.quotients);
    return result;
}

Polynomial normal_form(const Polynomial& f, std::span<const Polynomial> basis) {
    return divide_into(f, basis, nullptr);
}

bool check_division(const Polynomial& f, std::span<const Polynomial> divisors,
                    const DivisionResult& result) {
    if (result.quotients.size() != divisors.size()) {
        return false;
    }
    Polynomial sum = result.remainder;
    for (std::size_t i = 0; i < divisors.size(); ++i) {
        sum += result.quotients[i] * divisors[i];
    }
    if (!(sum == f)) {
        return false;
    }
    const MonomialLayout& layout = f.ring()->layout();
    for (std::size_t i = 0; i < result.remainder.num_terms(); ++i) {
        if (find_divisor(result.remainder.monomial(i), divisors, layout) != divisors.size()) {
            return false;
        }
    }
    return true;
}

Polynomial exact_quotient(const Polynomial& f, const Polynomial& g) {
    if (g.is_zero()) {
        throw InputError("exact_quotient", "division by the zero polynomial");
    }
    const Polynomial divisors[] = {g};
    DivisionResult r = divide(f, divisors);
    if (!r.remainder.is_zero()) {
        throw InputError("exact_quotient", "the divisor does not divide the dividend");
    }
    return std::move(r.quotients[0]);
}

}  // namespace locus::algebra
