#include "algebra/groebner/verify.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <memory>
#include <mutex>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "algebra/division.h"
#include "algebra/error.h"
#include "algebra/flint_threads.h"
#include "algebra/groebner/detail/pair_criteria.h"
#include "algebra/groebner/detail/reduction.h"
#include "algebra/groebner/detail/residue_lanes.h"
#include "algebra/groebner/detail/zero_reducer.h"
#include "algebra/print.h"

namespace locus::algebra {

Polynomial s_polynomial(const Polynomial& f, const Polynomial& g) {
    require_same_ring(f, g);
    const MonomialLayout& layout = f.ring()->layout();
    std::vector<std::uint64_t> lcm(layout.words()), mf(layout.words()), mg(layout.words());
    layout.lcm(f.leading_monomial(), g.leading_monomial(), lcm.data());
    layout.divide(lcm.data(), f.leading_monomial(), mf.data());
    layout.divide(lcm.data(), g.leading_monomial(), mg.data());
    Rational cf, cg;
    fmpq_inv(cf.get(), f.leading_coefficient().get());
    fmpq_inv(cg.get(), g.leading_coefficient().get());
    return f.times_term(cf, mf.data()).minus_term_times(cg, mg.data(), g);
}

BasisCheck check_groebner_basis(std::span<const Polynomial> basis) {
    BasisCheck check;
    for (std::size_t i = 0; i < basis.size(); ++i) {
        for (std::size_t j = i + 1; j < basis.size(); ++j) {
            const MonomialLayout& layout = basis[i].ring()->layout();
            if (basis[i].is_zero() || basis[j].is_zero() ||
                layout.coprime(basis[i].leading_monomial(), basis[j].leading_monomial())) {
                continue;
            }
            ++check.pairs_checked;
            const Polynomial r = normal_form(s_polynomial(basis[i], basis[j]), basis);
            if (!r.is_zero()) {
                check.ok = false;
                check.failure = "S-polynomial of elements " + std::to_string(i + 1) + " and " +
                                std::to_string(j + 1) + " has normal form " + to_string(r);
                return check;
            }
        }
    }
    return check;
}

BasisCheck check_groebner_basis(std::span<const Polynomial> basis,
                                std::span<const Polynomial> generators) {
    BasisCheck check;
    for (std::size_t i = 0; i < generators.size(); ++i) {
        ++check.generators_checked;
        const Polynomial r = normal_form(generators[i], basis);
        if (!r.is_zero()) {
            check.ok = false;
            check.failure =
                "generator " + std::to_string(i + 1) + " has normal form " + to_string(r);
            return check;
        }
    }
    BasisCheck pairs = check_groebner_basis(basis);
    pairs.generators_checked = check.generators_checked;
    return pairs;
}

BasisCheck certify_groebner_basis(std::span<const Polynomial> basis,
                                  std::span<const Polynomial> generators,
                                  std::optional<std::chrono::steady_clock::time_point> deadline,
                                  int threads,
                                  const std::function<void(std::size_t, std::size_t)>& progress) {
    BasisCheck check;
    // Zero elements add nothing to the ideal and have no leading monomial: left out, as
    // check_groebner_basis leaves them out of its pairs. `position` maps the others back to
    // their places in `basis` for the failure message.
    std::vector<std::size_t> position;
    for (std::size_t i = 0; i < basis.size(); ++i) {
        if (!basis[i].is_zero()) {
            position.push_back(i);
        }
    }
    if (position.empty()) {
        for (const Polynomial& g : generators) {
            ++check.generators_checked;
            if (!g.is_zero()) {
                check.ok = false;
                check.failure = "generator " + std::to_string(check.generators_checked) +
                                " is not in the zero ideal";
                return check;
            }
        }
        return check;
    }
    const RingPtr& ring = basis[position.front()].ring();
    const MonomialLayout& layout = ring->layout();
    std::vector<detail::BasisElement> elements;
    std::vector<detail::CriticalPair> pairs;
    detail::CriteriaCounts counts;
    for (const std::size_t i : position) {
        elements.push_back({detail::to_integer_polynomial(basis[i]), false});
        detail::gebauer_moller_update(elements, pairs, elements.size() - 1, layout, counts);
    }
    // The pairs by the degree of their lcm, and within a degree from the largest lcm down:
    // consecutive pairs are reduced together (below), and pairs of nearby lcms reach the same
    // columns (katsura-11: each reducer row read for 6.8 reductions instead of 6.1, its
    // certification 14.5 -> 13.6–13.9 s; ascending within a degree 6.6 and 14.8 s; cyclic-8
    // and katsura-10 unchanged).
    std::stable_sort(pairs.begin(), pairs.end(),
                     [&](const detail::CriticalPair& x, const detail::CriticalPair& y) {
                         const std::uint32_t dx = layout.total_degree(x.lcm.data());
                         const std::uint32_t dy = layout.total_degree(y.lcm.data());
                         return dx != dy ? dx < dy : layout.compare(x.lcm.data(), y.lcm.data()) > 0;
                     });
    // One list of jobs: the generators (each must reduce to zero: the input lies in the ideal
    // of the basis), then the pairs. On several threads the generators are checked beside the
    // pairs: one of cyclic-8's (its degree-7 sum, 0.28 s of the eight's 0.3) held one core
    // while the other was idle.
    std::vector<detail::IntegerPolynomial> inputs;
    inputs.reserve(generators.size());
    for (const Polynomial& g : generators) {
        inputs.push_back(detail::to_integer_polynomial(g));
    }
    const std::size_t jobs = inputs.size() + pairs.size();
    std::vector<detail::ZeroReducer::Job> all_jobs(jobs);
    for (std::size_t k = 0; k < jobs; ++k) {
        if (k < inputs.size()) {
            all_jobs[k].polynomial = &inputs[k];
        } else {
            const detail::CriticalPair& pair = pairs[k - inputs.size()];
            all_jobs[k] = {nullptr, pair.first, pair.second, pair.lcm.data()};
        }
    }
    // Consecutive jobs are reduced together (ZeroReducer::reduce_together): with the pairs
    // sorted as above, those of a group share most of their reducer rows.
    constexpr std::size_t kGroup = detail::ZeroReducer::kGroup;
    const std::size_t groups = (jobs + kGroup - 1) / kGroup;
    // Group g: jobs [g·kGroup, end_of(g)).
    const auto end_of = [&](std::size_t g) { return std::min(jobs, (g + 1) * kGroup); };
    // Reduces group g; returns its first job that does not reduce to zero, or `jobs`.
    auto group_fails = [&](detail::ZeroReducer& r, std::size_t g,
                           detail::ReductionCounts& group_steps) {
        const std::size_t from = g * kGroup;
        const std::span<const detail::ZeroReducer::Job> group(all_jobs.data() + from,
                                                              end_of(g) - from);
        std::array<bool, kGroup> zero{};
        std::array<detail::ReductionCounts, kGroup> job_counts{};
        r.reduce_together(group, std::span(zero.data(), group.size()),
                          std::span(job_counts.data(), group.size()));
        std::size_t failed = jobs;
        for (std::size_t k = 0; k < group.size(); ++k) {
            group_steps.steps += job_counts[k].steps;
            if (!zero[k] && failed == jobs) {
                failed = from + k;
            }
        }
        return failed;
    };
    detail::ReductionCounts steps;
    try {
        const auto add_statistics = [&](const detail::ZeroReducer& r) {
            check.work += r.statistics();
        };
        // Progress after each group: one report at a time; a thread that finds another
        // reporting goes on without waiting (so the last report may be skipped: the count is
        // reported once more when all are done).
        std::atomic<std::size_t> pairs_done{0};
        std::mutex reporting;
        const auto report = [&](std::size_t g) {
            const std::size_t first_pair = std::max(g * kGroup, inputs.size());
            if (end_of(g) <= first_pair) {
                return;
            }
            const std::size_t done = pairs_done += end_of(g) - first_pair;
            if (progress && reporting.try_lock()) {
                progress(done, pairs.size());
                reporting.unlock();
            }
        };
        std::size_t failed = jobs;  // the first job, in order, that does not reduce
        if (threads <= 1 || groups < 2) {
            // One thread's reducer, built here only: on several threads each builds its own
            // below, and one built here as well cost a serial 0.03–0.04 s on katsura-10 (the
            // residues of every element in every lane) before the threads began.
            detail::ZeroReducer reducer(layout, elements);
            reducer.set_deadline(deadline);
            for (std::size_t g = 0; g < groups && failed == jobs; ++g) {
                failed = group_fails(reducer, g, steps);
                report(g);
            }
            add_statistics(reducer);
        } else {
            std::atomic<std::size_t> first_failure{jobs};
            // Each thread numbers its own columns and finds its own reducer rows.
            tbb::enumerable_thread_specific<std::unique_ptr<detail::ZeroReducer>> reducers([&] {
                release_flint_caches_at_thread_exit();  // made on the worker that uses it
                auto r = std::make_unique<detail::ZeroReducer>(layout, elements);
                r->set_deadline(deadline);
                return r;
            });
            tbb::enumerable_thread_specific<detail::ReductionCounts> thread_steps;
            tbb::task_arena arena(threads);
            arena.execute([&] {
                tbb::parallel_for(
                    tbb::blocked_range<std::size_t>(0, groups, 1),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                        detail::ZeroReducer& local = *reducers.local();
                        detail::ReductionCounts& local_steps = thread_steps.local();
                        for (std::size_t g = range.begin(); g < range.end(); ++g) {
                            // Groups after a known failure need no check.
                            if (g * kGroup > first_failure.load(std::memory_order_relaxed)) {
                                return;
                            }
                            const std::size_t k = group_fails(local, g, local_steps);
                            if (k < jobs) {
                                std::size_t seen = first_failure.load();
                                while (k < seen && !first_failure.compare_exchange_weak(seen, k)) {
                                }
                            }
                            report(g);
                        }
                    });
            });
            failed = first_failure.load();
            for (const std::unique_ptr<detail::ZeroReducer>& r : reducers) {
                add_statistics(*r);
            }
            // Each thread counted its own steps: gathered here, after the threads are done.
            for (const detail::ReductionCounts& c : thread_steps) {
                steps.steps += c.steps;
            }
        }
        if (progress) {
            progress(pairs_done.load(), pairs.size());
        }
        check.work.reduction_steps = steps.steps;
        // Counted as the one-thread order would: every job up to the first failure.
        const std::size_t checked = failed < jobs ? failed + 1 : jobs;
        check.generators_checked = std::min(checked, inputs.size());
        check.pairs_checked = checked - check.generators_checked;
        if (failed < inputs.size()) {
            check.ok = false;
            check.failure = "generator " + std::to_string(failed + 1) + " does not reduce to zero";
        } else if (failed < jobs) {
            const detail::CriticalPair& pair = pairs[failed - inputs.size()];
            check.ok = false;
            check.failure = "S-polynomial of elements " + std::to_string(position[pair.first] + 1) +
                            " and " + std::to_string(position[pair.second] + 1) +
                            " does not reduce to zero";
        }
    } catch (const detail::ReductionInterrupted&) {
        throw Timeout("certification of the modular result");
    }
    return check;
}

const char* certification_kernels() {
    return detail::lanes::kernel_name();
}

bool is_groebner_basis(std::span<const Polynomial> basis, std::span<const Polynomial> generators) {
    return check_groebner_basis(basis, generators).ok;
}

bool is_reduced(std::span<const Polynomial> basis) {
    for (std::size_t i = 0; i < basis.size(); ++i) {
        if (basis[i].is_zero() || !basis[i].leading_coefficient().is_one()) {
            return false;
        }
        const MonomialLayout& layout = basis[i].ring()->layout();
        for (std::size_t j = 0; j < basis.size(); ++j) {
            if (i == j) {
                continue;
            }
            for (std::size_t t = 0; t < basis[i].num_terms(); ++t) {
                if (layout.divides(basis[j].leading_monomial(), basis[i].monomial(t))) {
                    return false;
                }
            }
        }
    }
    return true;
}

CertificationWork& CertificationWork::operator+=(const CertificationWork& other) {
    reduction_steps += other.reduction_steps;
    lanes = std::max(lanes, other.lanes);
    lane_restarts += other.lane_restarts;
    rebuilds += other.rebuilds;
    reducer_terms += other.reducer_terms;
    lane_terms += other.lane_terms;
    row_terms += other.row_terms;
    columns = std::max(columns, other.columns);
    exact_fallback = exact_fallback || other.exact_fallback;
    return *this;
}

}  // namespace locus::algebra
