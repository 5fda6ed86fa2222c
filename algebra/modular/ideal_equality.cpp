#include "algebra/modular/ideal_equality.h"

#include <algorithm>
#include <utility>
#include <vector>

#include <flint/fmpq.h>
#include <flint/fmpz.h>

#include "algebra/error.h"
#include "algebra/hilbert_series.h"
#include "algebra/ideal_ops.h"
#include "algebra/modular/modular_groebner.h"
#include "algebra/modular/rational_lift.h"
#include "algebra/standard_monomials.h"

namespace locus::algebra {

namespace {

using Clock = std::chrono::steady_clock;

// Primes tried for q: one that divides a denominator of the input is passed over
// (divides_a_denominator) for the next. Two denominators among the inputs cannot share every prime
// below 2²⁴, so a few suffice.
constexpr int kPrimeAttempts = 8;

long term_degree(const Polynomial& f, std::size_t i) {
    return f.ring()->layout().total_degree(f.monomial(i));
}

bool is_homogeneous(const Polynomial& f) {
    const long degree = f.total_degree();
    for (std::size_t i = 0; i < f.num_terms(); ++i) {
        if (term_degree(f, i) != degree) {
            return false;
        }
    }
    return true;
}

std::vector<ExponentVector> leading_exponents(std::span<const Polynomial> basis) {
    std::vector<ExponentVector> leading;
    leading.reserve(basis.size());
    for (const Polynomial& g : basis) {
        leading.push_back(g.exponents(0));
    }
    return leading;
}

// f^h = h^deg f · f(x/h) in `target`, whose variables are f's variables `kept` (f has no
// other) in that order, then h.
Polynomial homogenized(const Polynomial& f, std::span<const std::size_t> kept,
                       const RingPtr& target) {
    const long degree = f.total_degree();
    std::vector<std::pair<Rational, std::vector<std::uint32_t>>> terms;
    terms.reserve(f.num_terms());
    for (std::size_t i = 0; i < f.num_terms(); ++i) {
        const std::vector<std::uint32_t> all = f.exponents(i);
        std::vector<std::uint32_t> e;
        e.reserve(kept.size() + 1);
        for (std::size_t v : kept) {
            e.push_back(all[v]);
        }
        e.push_back(static_cast<std::uint32_t>(degree - term_degree(f, i)));
        terms.emplace_back(f.coefficient(i), std::move(e));
    }
    return Polynomial::from_terms(target, std::move(terms));
}

// The terms of f of its total degree.
Polynomial top_form(const Polynomial& f) {
    const long degree = f.total_degree();
    Polynomial top(f.ring());
    for (std::size_t i = 0; i < f.num_terms(); ++i) {
        if (term_degree(f, i) == degree) {
            top.push_back_term(f.coefficient(i), f.monomial(i));
        }
    }
    return top;
}

bool divides_a_denominator(std::span<const Polynomial> inputs, std::uint32_t q) {
    for (const Polynomial& f : inputs) {
        for (std::size_t i = 0; i < f.num_terms(); ++i) {
            if (fmpz_fdiv_ui(fmpq_denref(f.coefficient(i).get()), q) == 0) {
                return true;
            }
        }
    }
    return false;
}

// The reduced basis of `inputs` modulo the first usable prime (q divides no denominator), with
// that prime; F4 under the inputs' ring's order.
std::pair<std::vector<Polynomial>, std::uint32_t> basis_modulo_fresh_prime(
    std::span<const Polynomial> inputs, std::optional<Clock::time_point> deadline, int threads,
    std::span<const std::uint32_t> forced) {
    modular::PrimeSequence primes(modular::PrimeSequence::Width::unreduced,
                                  std::vector<std::uint64_t>(forced.begin(), forced.end()));
    modular::F4Options options;
    options.deadline = deadline;
    options.threads = threads;
    for (int attempt = 0; attempt < kPrimeAttempts; ++attempt) {
        const auto q = static_cast<std::uint32_t>(primes.next());
        if (!divides_a_denominator(inputs, q)) {
            return {groebner_modulo(inputs, q, options), q};
        }
    }
    return {{}, 0};
}

}  // namespace

const char* ideal_equality_status_name(IdealEquality::Status status) {
    switch (status) {
    case IdealEquality::Status::proven:
        return "proven";
    case IdealEquality::Status::refuted:
        return "refuted";
    case IdealEquality::Status::not_applicable:
        return "not applicable";
    case IdealEquality::Status::not_proven:
        return "not proven";
    }
    return "?";
}

namespace {

IdealEquality prove_or_overflow(std::span<const Polynomial> basis,
                                std::span<const Polynomial> generators,
                                std::optional<Clock::time_point> deadline, int threads,
                                std::span<const std::uint32_t> primes) {
    const auto start = Clock::now();
    IdealEquality out;
    const auto finish = [&](IdealEquality::Status status, std::string argument) {
        out.status = status;
        out.argument = std::move(argument);
        out.seconds = std::chrono::duration<double>(Clock::now() - start).count();
        return out;
    };
    std::vector<Polynomial> inputs;
    for (const Polynomial& f : generators) {
        if (!f.is_zero()) {
            inputs.push_back(f);
        }
    }
    if (inputs.empty() || basis.empty()) {
        // The zero ideal: its basis is empty (a certified basis of a non-zero input is not).
        return inputs.empty() && basis.empty()
                   ? finish(IdealEquality::Status::proven, "both ideals are zero")
                   : finish(IdealEquality::Status::refuted,
                            "one of the ideals is zero and the other not");
    }
    const RingPtr ring = inputs.front().ring();
    const std::size_t n = ring->num_vars();
    const bool homogeneous = std::all_of(inputs.begin(), inputs.end(), is_homogeneous) &&
                             std::all_of(basis.begin(), basis.end(), is_homogeneous);
    const std::vector<ExponentVector> leading = leading_exponents(basis);
    if (homogeneous) {
        // Case 1: the Hilbert series of the input modulo q (under grevlex, the fastest order:
        // a homogeneous ideal's series does not depend on the order) against that of LT(G).
        const RingPtr graded = ring->with_order(MonomialOrder::grevlex(n));
        std::vector<Polynomial> moved;
        for (const Polynomial& f : inputs) {
            moved.push_back(f.in_ring(graded));
        }
        auto [modular_basis, q] = basis_modulo_fresh_prime(moved, deadline, threads, primes);
        out.prime = q;
        if (q == 0) {
            return finish(IdealEquality::Status::not_proven,
                          "every prime tried divides a denominator of the input");
        }
        const HilbertData of_basis = hilbert_data(leading, n, deadline);
        const HilbertData modulo_q = hilbert_data(leading_exponents(modular_basis), n, deadline);
        if (of_basis.numerator == modulo_q.numerator) {
            return finish(IdealEquality::Status::proven, "homogeneous: the input modulo " +
                                                             std::to_string(q) +
                                                             " has the basis's Hilbert series");
        }
        return finish(IdealEquality::Status::not_proven,
                      "homogeneous, but the input modulo " + std::to_string(q) +
                          " has another Hilbert series than the basis");
    }
    if (!has_finitely_many_standard_monomials(leading, n)) {
        return finish(IdealEquality::Status::not_applicable,
                      "the input is not homogeneous and the basis has infinitely many standard "
                      "monomials");
    }
    const Integer standard = count_standard_monomials(leading, n, deadline);
    const bool unit = standard == Integer(0);
    if (!unit && inputs.size() < n) {
        // Krull's height theorem: every minimal prime of an ideal of m < n generators has
        // height at most m, so the ideal, not the unit ideal since ⟨G⟩ is not, has dimension
        // n − m > 0, and G has finitely many standard monomials.
        return finish(IdealEquality::Status::refuted,
                      "the basis's ideal is zero-dimensional, the input's " +
                          std::to_string(inputs.size()) + " generators in " + std::to_string(n) +
                          " variables cannot make one (Krull's height theorem)");
    }
    for (std::size_t v = 0; !unit && v < n; ++v) {
        // An ideal whose generators do not use v is not the unit ideal (⟨G⟩ is not) and
        // contains no polynomial in v alone: the basis's, which has a power of v, is larger.
        if (std::none_of(inputs.begin(), inputs.end(),
                         [&](const Polynomial& f) { return f.contains_variable(v); })) {
            return finish(IdealEquality::Status::refuted,
                          "the basis's ideal is zero-dimensional, and no generator uses " +
                              ring->variable_name(v));
        }
    }
    // Case 2: the top-degree forms modulo q.
    const RingPtr graded = ring->with_order(MonomialOrder::grevlex(n));
    std::vector<Polynomial> top_forms;
    for (const Polynomial& f : inputs) {
        top_forms.push_back(top_form(f).in_ring(graded));
    }
    auto [top_basis, q] = basis_modulo_fresh_prime(top_forms, deadline, threads, primes);
    out.prime = q;
    if (q == 0) {
        return finish(IdealEquality::Status::not_proven,
                      "every prime tried divides a denominator of the input");
    }
    const std::vector<ExponentVector> top_leading = leading_exponents(top_basis);
    if (has_finitely_many_standard_monomials(top_leading, n)) {
        const Integer top_standard = count_standard_monomials(top_leading, n, deadline);
        if (top_standard == standard) {
            return finish(IdealEquality::Status::proven,
                          "the input's top-degree forms modulo " + std::to_string(q) + " leave " +
                              standard.to_string() +
                              " standard monomials, as many as the basis: no zeros at infinity");
        }
        if (inputs.size() == n) {
            // No zeros at infinity: the top forms are a regular sequence over Q, hence (Macaulay)
            // they generate the ideal of the top forms of I, and dim Q[x]/I is Bézout's bound,
            // which they leave modulo q too.
            return finish(IdealEquality::Status::refuted,
                          "the input has no zeros at infinity (its top-degree forms modulo " +
                              std::to_string(q) + "), so " + top_standard.to_string() +
                              " solutions, and the basis " + standard.to_string());
        }
        if (!unit) {
            return finish(IdealEquality::Status::not_proven,
                          "the input's top-degree forms modulo " + std::to_string(q) + " leave " +
                              top_standard.to_string() + " standard monomials, the basis " +
                              standard.to_string());
        }
    } else if (!unit) {
        return finish(IdealEquality::Status::not_applicable,
                      "the input has zeros at infinity (its top-degree forms modulo " +
                          std::to_string(q) + " leave infinitely many standard monomials)");
    }
    // Case 3, G = {1}: the homogenized input modulo q must have no zeros at all. Only in the
    // variables that occur: the others would be zeros of any homogenization, and the input
    // generates the unit ideal exactly when it does so in its own variables.
    std::vector<std::size_t> kept;
    std::vector<std::string> names;
    for (std::size_t v = 0; v < n; ++v) {
        if (std::any_of(inputs.begin(), inputs.end(),
                        [&](const Polynomial& f) { return f.contains_variable(v); })) {
            kept.push_back(v);
            names.push_back(ring->variable_name(v));
        }
    }
    const std::size_t closure_vars = kept.size() + 1;
    const RingPtr with_h =
        ring_with_extra_variable(
            PolyRing::make(std::move(names), MonomialOrder::grevlex(kept.size())), "h")
            ->with_order(MonomialOrder::grevlex(closure_vars));
    std::vector<Polynomial> homogeneous_inputs;
    for (const Polynomial& f : inputs) {
        homogeneous_inputs.push_back(homogenized(f, kept, with_h));
    }
    auto [closure_basis, closure_prime] =
        basis_modulo_fresh_prime(homogeneous_inputs, deadline, threads, primes);
    out.prime = closure_prime;
    if (closure_prime == 0) {
        return finish(IdealEquality::Status::not_proven,
                      "every prime tried divides a denominator of the input");
    }
    const HilbertData closure =
        hilbert_data(leading_exponents(closure_basis), closure_vars, deadline);
    if (closure.unit || closure.dimension == 0) {
        return finish(IdealEquality::Status::proven,
                      "the unit ideal: the homogenized input has no zeros modulo " +
                          std::to_string(closure_prime));
    }
    return finish(IdealEquality::Status::not_proven,
                  "the basis is {1} but the homogenized input has zeros modulo " +
                      std::to_string(closure_prime));
}

}  // namespace

IdealEquality prove_ideal_equality(std::span<const Polynomial> basis,
                                   std::span<const Polynomial> generators,
                                   std::optional<Clock::time_point> deadline, int threads,
                                   std::span<const std::uint32_t> primes) {
    try {
        return prove_or_overflow(basis, generators, deadline, threads, primes);
    } catch (const ExponentOverflow& overflow) {
        // The proof's rings (grevlex, one variable more for the homogenization) pack exponents
        // in other widths than the input's: an input the route could compute may not fit them.
        IdealEquality out;
        out.status = IdealEquality::Status::not_proven;
        out.argument = std::string("the proof's exponents do not fit (") + overflow.what() + ")";
        return out;
    }
}

}  // namespace locus::algebra
