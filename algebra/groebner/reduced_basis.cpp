// Interreduction to the reduced Gröbner basis (Cox–Little–O'Shea, IVA ch. 2 §7, Prop. 6): the
// reduced basis is unique, so reducing every tail against the *original* other elements is
// enough: leading monomials never change, and tail irreducibility depends on them only.
#include <algorithm>
#include <memory>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "algebra/assert.h"
#include "algebra/flint_threads.h"
#include "algebra/groebner/buchberger.h"
#include "algebra/groebner/detail/reduction.h"

namespace locus::algebra {
namespace detail {

std::vector<IntegerPolynomial> interreduce(std::vector<BasisElement> basis,
                                           const MonomialLayout& layout, ReductionCounts& counts,
                                           int threads) {
    const std::size_t w = layout.words();
    // Minimal basis: an element goes when another (non-removed) one's leading monomial divides
    // its own; among equal leading monomials only the first stays.
    for (std::size_t i = 0; i < basis.size(); ++i) {
        basis[i].redundant = basis[i].poly.empty();
    }
    for (std::size_t i = 0; i < basis.size(); ++i) {
        if (basis[i].redundant) {
            continue;
        }
        for (std::size_t j = 0; j < basis.size(); ++j) {
            if (i == j || basis[j].redundant) {
                continue;
            }
            const auto* lm_i = basis[i].poly.monomial(0, w);
            const auto* lm_j = basis[j].poly.monomial(0, w);
            if (layout.divides(lm_j, lm_i) && (!layout.equal(lm_i, lm_j) || j < i)) {
                basis[i].redundant = true;
                break;
            }
        }
    }
    // Each tail is reduced by the others, none of which changes meanwhile: an admission that
    // refuses the element itself leaves the choice of reducers what it is among the others, and
    // the reductions are independent, so with threads > 1 they run side by side.
    std::vector<std::size_t> kept;
    for (std::size_t i = 0; i < basis.size(); ++i) {
        if (!basis[i].redundant) {
            kept.push_back(i);
        }
    }
    struct AllBut final : ReducerAdmission {
        explicit AllBut(std::size_t element) : excluded(element) {}
        bool admits(std::size_t element, const std::uint64_t*) const override {
            return element != excluded;
        }
        std::size_t excluded;
    };
    std::vector<IntegerPolynomial> reduced(kept.size());
    const auto reduce_tail = [&](Reducer& reducer, ReductionCounts& steps, std::size_t k) {
        const AllBut others(kept[k]);
        reduced[k] = reducer.reduce(basis[kept[k]].poly, basis, steps, true, &others);
    };
    // Below a few dozen elements threads cost more to start than the reductions take.
    constexpr std::size_t kLeastInParallel = 32;
    if (threads <= 1 || kept.size() < kLeastInParallel) {
        Reducer reducer(layout);
        for (std::size_t k = 0; k < kept.size(); ++k) {
            reduce_tail(reducer, counts, k);
        }
    } else {
        struct Worker {
            explicit Worker(const MonomialLayout& l) : reducer(l) {}
            Reducer reducer;
            ReductionCounts counts;
        };
        tbb::enumerable_thread_specific<std::unique_ptr<Worker>> workers([&layout] {
            release_flint_caches_at_thread_exit();  // made on the worker that uses it
            return std::make_unique<Worker>(layout);
        });
        tbb::task_arena arena(threads);
        arena.execute([&] {
            tbb::parallel_for(tbb::blocked_range<std::size_t>(0, kept.size(), 1),
                              [&](const tbb::blocked_range<std::size_t>& range) {
                                  Worker& worker = *workers.local();
                                  for (std::size_t k = range.begin(); k != range.end(); ++k) {
                                      reduce_tail(worker.reducer, worker.counts, k);
                                  }
                              });
        });
        for (const std::unique_ptr<Worker>& worker : workers) {
            counts.steps += worker->counts.steps;
        }
    }
    std::sort(reduced.begin(), reduced.end(),
              [&](const IntegerPolynomial& a, const IntegerPolynomial& b) {
                  return layout.compare(a.monomial(0, w), b.monomial(0, w)) < 0;
              });
    LOCUS_ASSERT(ascending_and_minimal(
        reduced.size(), [&](std::size_t i) { return reduced[i].monomial(0, w); }, layout));
    return reduced;
}

}  // namespace detail

std::vector<Polynomial> reduced_basis(std::span<const Polynomial> basis) {
    if (basis.empty()) {
        return {};
    }
    const RingPtr& ring = basis[0].ring();
    std::vector<detail::BasisElement> elements;
    for (const auto& g : basis) {
        require_same_ring(basis[0], g);
        if (!g.is_zero()) {
            elements.push_back({detail::to_integer_polynomial(g), false});
        }
    }
    detail::ReductionCounts counts;
    std::vector<Polynomial> out;
    for (const auto& p : detail::interreduce(std::move(elements), ring->layout(), counts)) {
        out.push_back(detail::to_monic_polynomial(p, ring));
    }
    return out;
}

}  // namespace locus::algebra
