// Buchberger's main loop. Selection (resolve_selection below): the pair with least key (sugar,
// lcm degree or nothing) and then least lcm, chosen by a linear scan; the pair set stays small next
// to the reduction work (a few thousand pairs on cyclic-6), so a heap would not pay for its upkeep
// under the Gebauer–Möller deletions.
#include "algebra/groebner/buchberger.h"
#include "algebra/deadline.h"

#include <algorithm>

#include "algebra/error.h"
#include "algebra/groebner/detail/pair_criteria.h"
#include "algebra/groebner/detail/reduction.h"

namespace locus::algebra {

namespace {

using detail::BasisElement;
using detail::CriticalPair;
using detail::IntegerPolynomial;

// Index of the pair to reduce next.
std::size_t select_pair(const std::vector<CriticalPair>& pairs, SelectionStrategy strategy,
                        const MonomialLayout& layout) {
    std::size_t best = 0;
    for (std::size_t k = 1; k < pairs.size(); ++k) {
        const CriticalPair& p = pairs[k];
        const CriticalPair& q = pairs[best];
        const std::uint32_t key_p = strategy == SelectionStrategy::sugar    ? p.sugar
                                    : strategy == SelectionStrategy::degree ? p.lcm_degree
                                                                            : 0;
        const std::uint32_t key_q = strategy == SelectionStrategy::sugar    ? q.sugar
                                    : strategy == SelectionStrategy::degree ? q.lcm_degree
                                                                            : 0;
        if (key_p != key_q) {
            if (key_p < key_q) {
                best = k;
            }
            continue;
        }
        const int c = layout.compare(p.lcm.data(), q.lcm.data());
        if (c < 0 ||
            (c == 0 && (p.second < q.second || (p.second == q.second && p.first < q.first)))) {
            best = k;
        }
    }
    return best;
}

struct ResolvedSelection {
    SelectionStrategy strategy;
    bool true_degree_sugar = false;  // a new element's sugar is its own degree
};

// What `automatic` means, per order kind, from measurements (docs/history.md); degrees are
// always taken in the order's first weight row (MonomialLayout::leading_weight), which is the
// total degree for grevlex and grlex:
//  - degree orders (first row all positive): sugar, and a new element's sugar is its own
//    degree rather than the phantom degree it picked up from reducers. cyclic-6 takes 0.9 s
//    this way and 2.3 s with phantom sugar.
//  - lex: Buchberger's normal strategy. katsura-5 in lex takes 0.4 s this way, 347 s with
//    phantom sugar, and does not finish in a minute with true-degree sugar (the first row of
//    lex only sees the first variable).
//  - block and other matrix orders: phantom sugar in the first-row degree. A random elim(x,z)
//    ideal (groebner_test seed 5) takes 0.2 s this way and does not finish in a minute with the
//    normal strategy or with true-degree sugar; measured in total degree instead, sugar walked
//    into endless chains on lex and matrix oracle cases.
ResolvedSelection resolve_selection(SelectionStrategy requested, const MonomialOrder& order) {
    if (requested != SelectionStrategy::automatic) {
        return {requested, false};
    }
    const bool degree_order = order.is_degree_order();
    if (degree_order) {
        return {SelectionStrategy::sugar, true};
    }
    if (order.kind() == MonomialOrder::Kind::lex) {
        return {SelectionStrategy::normal, false};
    }
    return {SelectionStrategy::sugar, false};
}

std::vector<Polynomial> unit_basis(const RingPtr& ring) {
    return {Polynomial::constant(ring, Rational(1))};
}

}  // namespace

std::optional<GroebnerOutcome> requested_stop(const GroebnerOptions& options,
                                              std::size_t basis_size, std::size_t steps) {
    if (locus::deadline_passed(options.deadline)) {
        return GroebnerOutcome::stopped_timeout;
    }
    if ((options.max_basis_size != 0 && basis_size > options.max_basis_size) ||
        (options.max_reduction_steps != 0 && steps >= options.max_reduction_steps)) {
        return GroebnerOutcome::stopped_size;
    }
    return std::nullopt;
}

GroebnerResult buchberger(std::span<const Polynomial> generators, const GroebnerOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    GroebnerResult result;
    if (generators.empty()) {
        return result;
    }
    const RingPtr& ring = generators[0].ring();
    const MonomialLayout& layout = ring->layout();
    const std::size_t w = layout.words();
    auto finish = [&](GroebnerResult& r) {
        r.stats.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };

    std::vector<BasisElement> basis;
    std::vector<CriticalPair> pairs;
    detail::CriteriaCounts criteria;
    detail::ReductionCounts reduction;
    detail::Reducer reducer(layout);

    std::vector<IntegerPolynomial> inputs = detail::sorted_integer_generators(generators);

    bool unit = false;
    auto add_to_basis = [&](IntegerPolynomial h) {
        if (layout.is_one(h.monomial(0, w))) {
            unit = true;
            return;
        }
        basis.push_back({std::move(h), false});
        gebauer_moller_update(basis, pairs, basis.size() - 1, layout, criteria);
        result.stats.max_basis_size = std::max(result.stats.max_basis_size, basis.size());
    };
    for (auto& f : inputs) {
        // Top-reduce each input by those before it so the initial basis has no obvious
        // redundancy; the tail is left for the final interreduction.
        IntegerPolynomial h = reducer.reduce(std::move(f), basis, reduction, /*tail=*/false);
        if (!h.empty()) {
            add_to_basis(std::move(h));
        }
        if (unit) {
            break;
        }
    }

    // Inputs are reduced without a deadline (the partial basis must keep every generator); the
    // S-pair reductions below can be interrupted.
    reducer.set_deadline(options.deadline);
    const ResolvedSelection selection = resolve_selection(options.selection, ring->order());
    std::size_t pairs_done = 0;
    while (!pairs.empty() && !unit) {
        if (const auto stop = requested_stop(options, basis.size(), reduction.steps)) {
            result.outcome = *stop;
            break;
        }
        const std::size_t k = select_pair(pairs, selection.strategy, layout);
        CriticalPair pair = std::move(pairs[k]);
        pairs[k] = std::move(pairs.back());
        pairs.pop_back();
        ++pairs_done;
        if (options.progress) {
            options.progress({pairs_done, pairs.size(), basis.size(), pair.sugar});
        }

        IntegerPolynomial s = reducer.s_polynomial(basis[pair.first].poly, basis[pair.second].poly,
                                                   pair.lcm.data(), pair.sugar);
        IntegerPolynomial h;
        try {
            h = reducer.reduce(std::move(s), basis, reduction);
        } catch (const detail::ReductionInterrupted&) {
            // The pair is dropped unprocessed: the basis still generates the ideal.
            result.outcome = GroebnerOutcome::stopped_timeout;
            break;
        }
        ++result.stats.reductions;
        if (h.empty()) {
            ++result.stats.zero_reductions;
            continue;
        }
        if (selection.true_degree_sugar) {
            // Drop the phantom degree of the reducers h met: its sugar is its own degree.
            h.sugar = 0;
            for (std::size_t i = 0; i < h.size(); ++i) {
                h.sugar = std::max(h.sugar, layout.leading_weight(h.monomial(i, w)));
            }
        }
        add_to_basis(std::move(h));
    }

    result.stats.pairs_created = criteria.pairs_created;
    result.stats.removed_by_product = criteria.removed_by_product;
    result.stats.removed_by_chain = criteria.removed_by_chain;
    if (unit) {
        result.basis = unit_basis(ring);
        result.outcome = GroebnerOutcome::complete;
        result.stats.reduction_steps = reduction.steps;
        finish(result);
        return result;
    }
    if (result.outcome != GroebnerOutcome::complete) {
        // Stopped early: return what generates the ideal (every element, primitive over Z,
        // sorted), without claiming the reduced-basis properties, and at once: the deadline
        // has passed.
        std::vector<Polynomial> partial;
        for (const auto& e : basis) {
            partial.push_back(detail::to_primitive_polynomial(e.poly, ring));
        }
        std::sort(partial.begin(), partial.end(), [&](const Polynomial& a, const Polynomial& b) {
            return layout.compare(a.leading_monomial(), b.leading_monomial()) < 0;
        });
        result.basis = std::move(partial);
        result.stats.reduction_steps = reduction.steps;
        finish(result);
        return result;
    }
    for (const auto& p : detail::interreduce(std::move(basis), layout, reduction)) {
        result.basis.push_back(detail::to_monic_polynomial(p, ring));
    }
    result.stats.reduction_steps = reduction.steps;
    finish(result);
    return result;
}

GroebnerResult buchberger(std::span<const Polynomial> generators, const MonomialOrder& order,
                          const GroebnerOptions& options) {
    if (generators.empty()) {
        return {};
    }
    const RingPtr target = generators[0].ring()->with_order(order);
    std::vector<Polynomial> moved;
    moved.reserve(generators.size());
    for (const auto& g : generators) {
        moved.push_back(g.in_ring(target));
    }
    return buchberger(moved, options);
}

}  // namespace locus::algebra
