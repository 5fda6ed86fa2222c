// Ideal operations over Q built on Gröbner bases (Cox–Little–O'Shea, IVA ch. 3–4; Becker–
// Weispfenning ch. 6). An ideal is given by generators in one ring; results are reduced Gröbner
// bases under that ring's order (normalized as in print.h), so they can be compared directly.
// The bases are computed by the signature-based algorithm (signature_groebner.h); GroebnerOptions'
// selection strategy therefore has no effect here.
// `options` reach every Gröbner basis an operation computes; none can use a partial basis, so
// one stopped at options.deadline throws Timeout (and one past options.max_basis_size,
// Error). The cofactor search of ideal_membership (division by the generators, and where that
// leaves a remainder a plain Buchberger run that tracks cofactors) honours only the deadline,
// read before each S-pair.
//
// Auxiliary variables (intersection, saturation, radical membership) are added in a larger ring
// with a fresh name and eliminated; they never appear in a result.
//
// The zero ideal's reduced basis is empty, and operations return it so (an intersection with a
// zero generator, an elimination that keeps nothing). Sum, product, intersection and
// containment take it back as an argument where the answer needs no ring: I + 0 = I, I·0 = 0,
// I ∩ 0 = 0, 0 ⊆ I, and J ⊆ 0 iff every generator of J is zero. Operations that need the ring
// and have no generator to read it from throw InputError.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "algebra/groebner/buchberger.h"
#include "algebra/hilbert_series.h"
#include "algebra/polynomial.h"

namespace locus::algebra {

using Generators = std::span<const Polynomial>;

struct MembershipCertificate {
    bool is_member = false;
    // When a member: f == Σ cofactors[i]·generators[i] exactly (checked before returning).
    std::vector<Polynomial> cofactors;
    // The normal form of f by the reduced basis (zero iff a member).
    Polynomial remainder;
};

// Is f in ⟨generators⟩? The certificate comes from a Buchberger run that tracks how each basis
// element is made from the generators (Singular's `lift`).
MembershipCertificate ideal_membership(const Polynomial& f, Generators generators,
                                       const GroebnerOptions& options = {});

// The reduced basis of ⟨generators⟩ under their ring's order, complete: the signature algorithm
// (Buchberger's where a signature overflows); Timeout at options.deadline, Error past
// options.max_basis_size. The basis every operation below starts from.
std::vector<Polynomial> basis_of(Generators generators, const GroebnerOptions& options = {});

// I ∩ Q[remaining variables]: the reduced basis (under the ring's order) of the elements
// free of `variables` in a basis for the elimination order elim(variables) (CLO ch. 3 §1).
std::vector<Polynomial> eliminate(Generators generators, std::span<const std::size_t> variables,
                                  const GroebnerOptions& options = {});

std::vector<Polynomial> ideal_sum(Generators i, Generators j, const GroebnerOptions& options = {});
std::vector<Polynomial> ideal_product(Generators i, Generators j,
                                      const GroebnerOptions& options = {});
// I ∩ J = (t·I + (1−t)·J) ∩ Q[x] (CLO ch. 4 §3, Theorem 11).
std::vector<Polynomial> ideal_intersection(Generators i, Generators j,
                                           const GroebnerOptions& options = {});
// I : J = ∩ₖ (I : gₖ), with I : g = (1/g)·(I ∩ ⟨g⟩) (CLO ch. 4 §4, Theorem 11).
std::vector<Polynomial> ideal_quotient(Generators i, Generators j,
                                       const GroebnerOptions& options = {});
// I : J^∞ = ∩ₖ (I + ⟨1 − t·gₖ⟩) ∩ Q[x] (CLO ch. 4 §4, Theorem 14).
std::vector<Polynomial> saturation(Generators i, Generators j, const GroebnerOptions& options = {});
// f ∈ √I iff 1 ∈ I + ⟨1 − y·f⟩ (CLO ch. 4 §2, Proposition 8).
bool radical_membership(const Polynomial& f, Generators generators,
                        const GroebnerOptions& options = {});
// J ⊆ I: every generator of J reduces to zero by a Gröbner basis of I.
bool ideal_contains(Generators i, Generators j, const GroebnerOptions& options = {});
bool ideal_equal(Generators i, Generators j, const GroebnerOptions& options = {});

enum class Dimension { unit_ideal, zero_dimensional, positive };
struct DimensionReport {
    Dimension kind = Dimension::positive;
    // For zero-dimensional ideals: dim_Q Q[x]/I, the number of solutions with multiplicity.
    std::optional<std::size_t> quotient_dimension;
};
// Finite-solution test: I is zero-dimensional iff for every variable some leading monomial of
// its Gröbner basis is a pure power of it (CLO ch. 5 §3, Theorem 6).
DimensionReport zero_dimension_test(Generators generators, const GroebnerOptions& options = {});

// Krull dimension, degree, Hilbert series and polynomial and a maximal independent set of
// Q[x]/I (hilbert_series.h), from the leading monomials of I's reduced basis under grevlex (the
// ring's own order when it compares total degree first: the data are the same for every such
// order). `ring`
// is needed for the zero ideal (no generators: dimension n, degree 1). For a zero-dimensional
// ideal the degree is the number of solutions with multiplicity (Singular's vdim).
HilbertData ideal_hilbert_data(const RingPtr& ring, Generators generators,
                               const GroebnerOptions& options = {});

// The ring of `ring` with one more variable appended, named `base` or base + digits so that it
// is fresh, under elim(new variable). Used by the operations above; public for tests.
RingPtr ring_with_extra_variable(const RingPtr& ring, const std::string& base);

}  // namespace locus::algebra
