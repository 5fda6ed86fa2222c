// Independent checks of Gröbner bases, shared by the tests and `locus groebner --check`.
//
// They use the rational division algorithm (division.h), not the fraction-free reducer that
// computed the basis, so a bug in one is not hidden by the same bug in the other. Buchberger's
// criterion (CLO, IVA ch. 2 §6, Theorem 6): G is a Gröbner basis iff every S-polynomial
// reduces to zero; pairs with coprime leading monomials are skipped (CLO ch. 2 §9, Prop. 4).
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>

#include "algebra/polynomial.h"

namespace locus::algebra {

// What certifying a basis cost (certify_groebner_basis; the modular algorithm reports the sum
// over its attempts): reduction steps, the residue lanes it ended on (the most any thread
// used), how often a reduction started again on more lanes, how often the pending values were
// rebuilt in full (groebner/detail/zero_reducer.h), and whether some reductions ran on GMP integers
// (too large for lanes). The one record of this work: BasisCheck, ModularStats and the zero
// reducers all use it.
struct CertificationWork {
    std::size_t reduction_steps = 0, lanes = 0, lane_restarts = 0, rebuilds = 0;
    // On residues: the reducers' terms the steps went through, the same counted once a lane,
    // the terms read (once for all the reductions of a group that take a row at the same
    // time), and the columns (monomials) numbered by the largest of the threads' reducers.
    std::size_t reducer_terms = 0, lane_terms = 0, row_terms = 0, columns = 0;
    bool exact_fallback = false;
    // Steps, restarts, rebuilds and terms add up; lanes and columns are the most used.
    CertificationWork& operator+=(const CertificationWork& other);
};

struct BasisCheck {
    bool ok = true;
    std::size_t generators_checked = 0, pairs_checked = 0;
    std::string failure;     // which generator or pair failed, when !ok
    CertificationWork work;  // certify_groebner_basis only
};

// Every S-polynomial of `basis` reduces to zero.
BasisCheck check_groebner_basis(std::span<const Polynomial> basis);
// check_groebner_basis(basis), and every generator reduces to zero, so the ideal of
// `generators` is contained in the ideal of `basis`. (The converse, basis ⊆ ideal, holds by
// construction for a computed basis; ideal_ops.h checks it when comparing ideals.)
BasisCheck check_groebner_basis(std::span<const Polynomial> basis,
                                std::span<const Polynomial> generators);

bool is_groebner_basis(std::span<const Polynomial> basis, std::span<const Polynomial> generators);

// The same statement as check_groebner_basis(basis, generators), for large bases: the S-pairs
// are those left by the Gebauer–Möller criteria (product and chain; Gebauer & Möller 1988
// show that these suffice) and reductions are fraction-free over Z, only far enough to decide
// zero, on residues modulo word primes with rigorous size bounds or on GMP integers
// (groebner/detail/zero_reducer.h). It certifies the results of the multi-modular algorithm, whose
// F4 code shares nothing with this reducer. On cyclic-6 it takes 3 ms where the rational
// check takes 0.8 s.
// Throws Timeout once `deadline` passes (checked every few reduction steps). The S-pairs are
// independent: with `threads` > 1 they are reduced on that many threads (oneTBB), and a
// failure reports the first failing pair in order, as on one thread. `progress`, when given, is
// told the S-pairs done and their number after each pair (one call at a time, from any thread;
// calls that would wait for another are skipped).
BasisCheck certify_groebner_basis(
    std::span<const Polynomial> basis, std::span<const Polynomial> generators,
    std::optional<std::chrono::steady_clock::time_point> deadline = std::nullopt, int threads = 1,
    const std::function<void(std::size_t done, std::size_t total)>& progress = {});
// Which vector kernels the certification's residue arithmetic runs on this processor:
// "avx512", "avx2" or "portable".
const char* certification_kernels();

// The same statement as check_groebner_basis(basis, generators) over GF(p) (p a prime below
// 2³¹): every generator and every S-pair with non-coprime leading monomials reduces to zero
// modulo p. Polynomials are stored over Q (IdealFile's convention): each coefficient stands
// for its residue (no denominator divisible by p); the basis as groebner_modulo returns it,
// with coefficients in [0, p). The reductions are the division algorithm's top-reductions
// over Q with every coefficient taken back to [0, p) after each step: nothing of the modular
// F4 (modular/f4.h) that computes such bases. Throws Timeout once `deadline` passes.
BasisCheck check_groebner_basis_modulo(
    std::span<const Polynomial> basis, std::span<const Polynomial> generators, std::uint32_t p,
    std::optional<std::chrono::steady_clock::time_point> deadline = std::nullopt);

// Monic, and no monomial of any element is divisible by another element's leading monomial.
bool is_reduced(std::span<const Polynomial> basis);
// S-polynomial over Q: (lcm/lt(f))·f − (lcm/lt(g))·g.
Polynomial s_polynomial(const Polynomial& f, const Polynomial& g);

}  // namespace locus::algebra
