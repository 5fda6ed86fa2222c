// Conversions between locus polynomials and FLINT's fmpq_mpoly / fmpz_mpoly, for what FLINT does
// well (gcd, square-free decomposition, factorization) and as an independent oracle for the
// arithmetic in tests.
//
// A FlintContext owns an fmpq_mpoly_ctx for a ring's number of variables (FLINT orders terms by
// lex internally; locus re-sorts by its own order on the way back). FLINT variable i is locus
// variable i.
#pragma once

#include <flint/fmpq_mpoly.h>
#include <flint/fmpz_mpoly.h>

#include <vector>

#include "algebra/polynomial.h"

namespace locus::algebra {

class FlintContext {
  public:
    explicit FlintContext(RingPtr ring);
    FlintContext(const FlintContext&) = delete;
    FlintContext& operator=(const FlintContext&) = delete;
    ~FlintContext();

    const RingPtr& ring() const { return ring_; }
    fmpq_mpoly_ctx_struct* get() { return ctx_; }

  private:
    RingPtr ring_;
    fmpq_mpoly_ctx_t ctx_;
};

// Owning wrapper of one fmpq_mpoly in a FlintContext.
class FlintPolynomial {
  public:
    explicit FlintPolynomial(FlintContext& ctx);
    FlintPolynomial(const FlintPolynomial&) = delete;
    FlintPolynomial& operator=(const FlintPolynomial&) = delete;
    FlintPolynomial(FlintPolynomial&& o) noexcept;
    ~FlintPolynomial();
    fmpq_mpoly_struct* get() { return p_; }
    const fmpq_mpoly_struct* get() const { return p_; }

  private:
    FlintContext* ctx_;
    fmpq_mpoly_t p_;
};

FlintPolynomial to_fmpq_mpoly(const Polynomial& f, FlintContext& ctx);
Polynomial from_fmpq_mpoly(const fmpq_mpoly_struct* f, FlintContext& ctx);

// The resultant of f and g with respect to variable `var` (Sylvester, computed by FLINT); the
// result does not contain `var`.
Polynomial resultant(const Polynomial& f, const Polynomial& g, std::size_t var);

// Greatest common divisor, made monic (0 when both are 0).
Polynomial gcd(const Polynomial& f, const Polynomial& g);

// The irreducible factors over Q with multiplicities, each primitive with positive leading
// coefficient, and the rational constant in front: f = unit · Π factorᵢ^multiplicityᵢ.
struct Factorization {
    Rational unit;
    std::vector<std::pair<Polynomial, unsigned>> factors;
};
Factorization factor(const Polynomial& f);
// Product of the distinct irreducible factors (primitive; zero and constants map to
// themselves made primitive).
Polynomial square_free_part(const Polynomial& f);

}  // namespace locus::algebra
