// Reduced Gröbner bases over Q by Buchberger's algorithm (Buchberger 1965; Becker–Weispfenning,
// "Gröbner Bases", ch. 5) with
//   - the product and chain criteria installed as Gebauer–Möller (pair_criteria.h),
//   - normal selection refined by sugar (Giovini, Mora, Niesi, Robbiano, Traverso, "One sugar
//     cube, please", ISSAC 1991): the pair of least sugar degree, ties by least lcm, where
//     degrees are taken in the order's first weight row (total degree for grevlex),
//   - fraction-free reduction over Z with primitive parts (reduction.h),
//   - interreduction to the reduced basis (reduced_basis.cpp): monic, unique for the ideal and
//     the order.
//
// Example:
//     auto ring = PolyRing::make({"x", "y"}, MonomialOrder::grevlex(2));
//     std::vector<Polynomial> f = {parse_polynomial("x^2-y", ring),
//                                  parse_polynomial("x*y-1", ring)};
//     GroebnerResult r = buchberger(f);   // r.basis: y^2-x, x^2-y, x*y-1 (normalized)
#pragma once

#include <chrono>
#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "algebra/polynomial.h"

namespace locus::algebra {

enum class SelectionStrategy {
    automatic,  // per order kind, from measurements (see resolve_selection in buchberger.cpp)
    sugar,      // least sugar degree (in the order's first weight row), ties by least lcm
    degree,     // least first-row degree of the lcm, ties by least lcm
    normal,     // least lcm under the order (Buchberger's normal strategy)
};

enum class GroebnerOutcome {
    complete,         // basis is the reduced Gröbner basis
    stopped_timeout,  // deadline passed; basis generates the ideal but may not be Gröbner
    stopped_size,     // basis grew past max_basis_size; same guarantee as above
    unable,  // the algorithm cannot answer within its documented limits (the reason says which);
             // basis generates the ideal
};

// Which algorithm computed a basis: `auto` and the ideal operations choose among them.
enum class GroebnerAlgorithm {
    buchberger,  // buchberger() (buchberger.h)
    signature,   // signature_groebner() (signature_groebner.h)
    modular,     // modular_groebner() (modular/modular_groebner.h)
};

struct GroebnerStats {
    GroebnerAlgorithm algorithm = GroebnerAlgorithm::buchberger;
    std::size_t pairs_created = 0;
    std::size_t removed_by_product = 0;  // product (coprime leading monomials) criterion
    std::size_t removed_by_chain = 0;    // chain criterion (Gebauer–Möller M, F, B steps)
    // signature_groebner only: signatures skipped as those of syzygies, and by the rewrite
    // criterion.
    std::size_t removed_by_syzygy = 0;
    std::size_t removed_by_rewriting = 0;
    std::size_t reductions = 0;       // S-polynomials reduced
    std::size_t zero_reductions = 0;  // of which reduced to zero
    std::size_t reduction_steps = 0;  // single a·p − b·m·g steps
    std::size_t max_basis_size = 0;   // largest intermediate basis
    // signature_groebner on several threads: signatures attempted side by side in batches.
    std::size_t batched_signatures = 0;
    double seconds = 0;
};

struct GroebnerProgress {
    std::size_t pairs_done = 0, pairs_left = 0, basis_size = 0;
    std::uint32_t current_sugar = 0;
    // What is counted. pairs: Buchberger's and the signature algorithm's S-pairs. The modular
    // route's stages — f4: pairs_done steps of F4 modulo a prime, basis_size its basis so far;
    // primes: pairs_done primes used so far, basis_size the basis modulo the last;
    // certification: pairs_done of pairs_done + pairs_left S-pairs reduced to zero.
    enum class Stage { pairs, f4, primes, certification };
    Stage stage = Stage::pairs;
};

struct GroebnerOptions {
    SelectionStrategy selection = SelectionStrategy::automatic;
    // Stop (outcome stopped_timeout) when this instant passes; polled once per S-pair.
    std::optional<std::chrono::steady_clock::time_point> deadline;
    // Stop (outcome stopped_size) when the basis would exceed this many elements; 0 = no limit.
    std::size_t max_basis_size = 0;
    // Stop (outcome stopped_size) at the first S-pair (for the signature algorithm: signature)
    // after this many reduction steps (GroebnerStats::reduction_steps); 0 = no limit. A budget
    // of work rather than time, so that `auto`'s probe stops at the same point on every run and
    // every machine.
    std::size_t max_reduction_steps = 0;
    // Stop (outcome stopped_size) when an element whose coefficients reach b ≥ `growth_bits`
    // bits joins a basis of fewer than growth_basis·b/growth_bits elements (the line through
    // (growth_bits, growth_basis) and the origin: a growth rate, bits per element); 0 = no
    // limit. Watched by the signature algorithm only, for `auto`'s probe: coefficients that
    // grow while the basis is still small are what the computation over Q pays for and the
    // modular one does not.
    std::size_t growth_bits = 0;
    std::size_t growth_basis = 0;
    // Called after every S-pair with the state so far (for progress bars; throttle inside).
    std::function<void(const GroebnerProgress&)> progress;
    // For the multi-modular route of groebner_automatic: certify its result (false: the result
    // is probabilistic). `threads`: the signature algorithm attempts the signatures of a degree
    // side by side (signature_groebner.h), the modular route runs its replays and certification
    // on them; Buchberger's algorithm is sequential.
    bool certify = true;
    int threads = 1;
};

// Whether a run must stop now under `options`, with `basis_size` elements after `steps`
// reduction steps: stopped_timeout once the deadline has passed, stopped_size once the basis is
// past max_basis_size or the steps reach max_reduction_steps, else nothing. Polled by buchberger()
// before each S-pair and by signature_groebner() before each signature.
std::optional<GroebnerOutcome> requested_stop(const GroebnerOptions& options,
                                              std::size_t basis_size, std::size_t steps);

struct GroebnerResult {
    // complete: normalized (print.h), monic, leading monomials ascending. Stopped early:
    // leading monomials ascending, each element primitive over Z (no time is left to divide).
    std::vector<Polynomial> basis;
    GroebnerOutcome outcome = GroebnerOutcome::complete;
    std::string reason;  // for an outcome other than complete: why, in one line
    GroebnerStats stats;
};

// The reduced Gröbner basis of the ideal generated by `generators` under their ring's order.
// The zero ideal gives an empty basis, the unit ideal {1}. Throws MixedRings when the
// generators do not share a ring, ExponentOverflow when a product leaves the packed range.
GroebnerResult buchberger(std::span<const Polynomial> generators,
                          const GroebnerOptions& options = {});

// The same under another order: generators are moved to ring->with_order(order) first, and
// the basis lives in that ring.
GroebnerResult buchberger(std::span<const Polynomial> generators, const MonomialOrder& order,
                          const GroebnerOptions& options = {});

// Interreduces a Gröbner basis to the reduced one: drops elements whose leading monomial is
// divisible by another's, reduces every tail by the rest, makes each monic, sorts ascending.
// Precondition: `basis` is a Gröbner basis (for any other input the result still generates
// the same ideal but is not unique).
std::vector<Polynomial> reduced_basis(std::span<const Polynomial> basis);

}  // namespace locus::algebra
