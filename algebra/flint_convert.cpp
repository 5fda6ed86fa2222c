#include "algebra/flint_convert.h"

#include <flint/fmpq_mpoly_factor.h>

#include <algorithm>

#include "algebra/error.h"

namespace locus::algebra {

FlintContext::FlintContext(RingPtr ring) : ring_(std::move(ring)) {
    // FLINT needs at least one variable; a ring with none uses a dummy that never occurs.
    fmpq_mpoly_ctx_init(ctx_, static_cast<slong>(std::max<std::size_t>(1, ring_->num_vars())),
                        ORD_LEX);
}

FlintContext::~FlintContext() {
    fmpq_mpoly_ctx_clear(ctx_);
}

FlintPolynomial::FlintPolynomial(FlintContext& ctx) : ctx_(&ctx) {
    fmpq_mpoly_init(p_, ctx.get());
}

FlintPolynomial::FlintPolynomial(FlintPolynomial&& o) noexcept : ctx_(o.ctx_) {
    fmpq_mpoly_init(p_, ctx_->get());
    fmpq_mpoly_swap(p_, o.p_, ctx_->get());
}

FlintPolynomial::~FlintPolynomial() {
    fmpq_mpoly_clear(p_, ctx_->get());
}

FlintPolynomial to_fmpq_mpoly(const Polynomial& f, FlintContext& ctx) {
    require_same_ring(Polynomial(ctx.ring()), f);
    FlintPolynomial out(ctx);
    std::vector<ulong> e(std::max<std::size_t>(1, f.ring()->num_vars()), 0);
    for (std::size_t i = 0; i < f.num_terms(); ++i) {
        const auto exps = f.exponents(i);
        std::copy(exps.begin(), exps.end(), e.begin());
        fmpq_mpoly_push_term_fmpq_ui(out.get(), f.coefficient(i).get(), e.data(), ctx.get());
    }
    fmpq_mpoly_sort_terms(out.get(), ctx.get());
    fmpq_mpoly_combine_like_terms(out.get(), ctx.get());
    return out;
}

Polynomial from_fmpq_mpoly(const fmpq_mpoly_struct* f, FlintContext& ctx) {
    const slong n = fmpq_mpoly_length(f, ctx.get());
    const std::size_t vars = ctx.ring()->num_vars();
    std::vector<std::pair<Rational, std::vector<std::uint32_t>>> terms;
    terms.reserve(static_cast<std::size_t>(n));
    std::vector<ulong> e(std::max<std::size_t>(1, vars));
    for (slong i = 0; i < n; ++i) {
        Rational c;
        fmpq_mpoly_get_term_coeff_fmpq(c.get(), f, i, ctx.get());
        fmpq_mpoly_get_term_exp_ui(e.data(), f, i, ctx.get());
        std::vector<std::uint32_t> exps(vars);
        for (std::size_t v = 0; v < vars; ++v) {
            if (e[v] > MonomialLayout::max_field_value) {
                throw ExponentOverflow("from_fmpq_mpoly");
            }
            exps[v] = static_cast<std::uint32_t>(e[v]);
        }
        terms.emplace_back(std::move(c), std::move(exps));
    }
    return Polynomial::from_terms(ctx.ring(), std::move(terms));
}

Polynomial gcd(const Polynomial& f, const Polynomial& g) {
    require_same_ring(f, g);
    FlintContext ctx(f.ring());
    FlintPolynomial a = to_fmpq_mpoly(f, ctx), b = to_fmpq_mpoly(g, ctx), r(ctx);
    if (!fmpq_mpoly_gcd(r.get(), a.get(), b.get(), ctx.get())) {
        throw Error("FLINT could not compute a gcd");
    }
    return from_fmpq_mpoly(r.get(), ctx).monic();
}

Polynomial resultant(const Polynomial& f, const Polynomial& g, std::size_t var) {
    require_same_ring(f, g);
    if (var >= f.ring()->num_vars()) {
        throw InputError("resultant", "no variable with index " + std::to_string(var));
    }
    FlintContext ctx(f.ring());
    FlintPolynomial a = to_fmpq_mpoly(f, ctx), b = to_fmpq_mpoly(g, ctx), r(ctx);
    if (!fmpq_mpoly_resultant(r.get(), a.get(), b.get(), static_cast<slong>(var), ctx.get())) {
        throw Error("FLINT could not compute a resultant");
    }
    return from_fmpq_mpoly(r.get(), ctx);
}

namespace {

Factorization run_factorization(const Polynomial& f, bool square_free_only) {
    FlintContext ctx(f.ring());
    FlintPolynomial a = to_fmpq_mpoly(f, ctx);
    fmpq_mpoly_factor_t fac;
    fmpq_mpoly_factor_init(fac, ctx.get());
    const int ok = square_free_only ? fmpq_mpoly_factor_squarefree(fac, a.get(), ctx.get())
                                    : fmpq_mpoly_factor(fac, a.get(), ctx.get());
    if (!ok) {
        fmpq_mpoly_factor_clear(fac, ctx.get());
        throw Error("FLINT could not factor the polynomial");
    }
    Factorization result;
    fmpq_mpoly_factor_get_constant_fmpq(result.unit.get(), fac, ctx.get());
    FlintPolynomial base(ctx);
    for (slong i = 0; i < fmpq_mpoly_factor_length(fac, ctx.get()); ++i) {
        fmpq_mpoly_factor_get_base(base.get(), fac, i, ctx.get());
        const Polynomial p = from_fmpq_mpoly(base.get(), ctx);
        const Polynomial primitive = p.primitive_part();
        // unit · p^k = unit · (c·primitive)^k: move c^k into the unit.
        const auto k = static_cast<unsigned>(fmpq_mpoly_factor_get_exp_si(fac, i, ctx.get()));
        Rational c = p.leading_coefficient() / primitive.leading_coefficient();
        Rational ck;
        fmpq_pow_si(ck.get(), c.get(), static_cast<slong>(k));
        result.unit *= ck;
        result.factors.emplace_back(primitive, k);
    }
    fmpq_mpoly_factor_clear(fac, ctx.get());
    return result;
}

}  // namespace

Factorization factor(const Polynomial& f) {
    if (f.is_zero()) {
        throw InputError("factor", "the zero polynomial has no factorization");
    }
    return run_factorization(f, false);
}

Polynomial square_free_part(const Polynomial& f) {
    if (f.is_constant()) {
        return f.primitive_part();
    }
    const Factorization sq = run_factorization(f, true);
    Polynomial product = Polynomial::constant(f.ring(), Rational(1));
    for (const auto& [p, k] : sq.factors) {
        product *= p;
    }
    return product.primitive_part();
}

}  // namespace locus::algebra
