#include "algebra/modular/modular_groebner.h"

#include <algorithm>
#include <atomic>
#include <deque>
#include <memory>
#include <mutex>
#include <random>
#include <string>

#include <flint/fmpq.h>
#include <flint/fmpz.h>
#include <flint/ulong_extras.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "algebra/deadline.h"
#include "algebra/error.h"
#include "algebra/flint_threads.h"
#include "algebra/groebner/verify.h"
#include "algebra/modular/detail/fglm.h"
#include "algebra/modular/rational_lift.h"

namespace locus::algebra {

namespace {

using Clock = std::chrono::steady_clock;
using modular::ModularPolynomial;
using modular::PrimeField;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// One coefficient being lifted (modular/rational_lift.h): its residues modulo the group's
// primes, 0 where a prime's basis lacks the term.
struct LiftedTerm {
    std::vector<std::uint64_t> monomial;
    modular::LiftedNumber coefficient;
};
using LiftedElement = std::vector<LiftedTerm>;  // terms descending

// The primes whose bases share one set of leading monomials, and their bases' residues.
struct Group {
    std::vector<std::uint64_t> signature;
    std::vector<LiftedElement> elements;
    modular::RationalLift lift;
    std::size_t first_prime_position = 0;  // ties in the majority go to the earlier group
    std::optional<std::vector<Polynomial>> candidate;
    // The coefficient whose reconstruction failed last (element, term): tried first next time.
    std::size_t hard_element = 0, hard_term = 0;
    // Per element, a denominator its coefficients share (the lcm of those found so far, or
    // one found by simultaneous reconstruction): see reconstruct_term.
    std::vector<Integer> denominators;
    double lattice_seconds = 0.0;  // spent by the attempts on lattices (see reconstruct)
    std::size_t primes() const { return lift.primes(); }
};

std::vector<std::uint64_t> signature_of(const std::vector<ModularPolynomial>& basis,
                                        std::size_t words) {
    std::vector<std::uint64_t> signature;
    for (const ModularPolynomial& g : basis) {
        signature.insert(signature.end(), g.monomials.begin(), g.monomials.begin() + words);
    }
    return signature;
}

// body(begin, end) over the elements [0, count): on `threads` threads when there are several
// and enough elements (each element's coefficients are independent of the others'), else in
// order on this thread.
template <typename Body>
void over_elements(int threads, std::size_t count, const Body& body) {
    if (threads <= 1 || count < 16) {
        body(std::size_t{0}, count);
        return;
    }
    tbb::task_arena arena(threads);
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 4),
                          [&](const tbb::blocked_range<std::size_t>& range) {
                              release_flint_caches_at_thread_exit();
                              body(range.begin(), range.end());
                          });
    });
}

// Appends one prime's residue. The vectors start with room for 32 primes: grown from one, each
// of katsura-10's 15 000 coefficients was copied into a new block six times in 18 primes.
void append_residue(modular::LiftedNumber& number, mp_limb_t residue) {
    std::vector<mp_limb_t>& residues = number.residues;
    if (residues.size() == residues.capacity()) {
        residues.reserve(std::max<std::size_t>(32, 2 * residues.size()));
    }
    residues.push_back(residue);
}

// Appends the residues of g, one element of a basis modulo a new prime, to the element's
// residues modulo the `primes_before` primes before it; monomials missing on one side have
// residue 0 there.
void add_to_element(LiftedElement& old, const ModularPolynomial& g, std::size_t primes_before,
                    const MonomialLayout& layout) {
    const std::size_t words = layout.words();
    // The usual case: the same monomials as before.
    bool same_support = old.size() == g.size();
    for (std::size_t i = 0; same_support && i < g.size(); ++i) {
        same_support =
            std::equal(old[i].monomial.begin(), old[i].monomial.end(), g.monomial(i, words));
    }
    if (same_support) {
        for (std::size_t i = 0; i < g.size(); ++i) {
            append_residue(old[i].coefficient, g.coefficients[i]);
        }
        return;
    }
    LiftedElement merged;
    merged.reserve(std::max(old.size(), g.size()));
    std::size_t a = 0, b = 0;
    while (a < old.size() || b < g.size()) {
        int order = 0;  // > 0: old term first, < 0: new term first
        if (a == old.size()) {
            order = -1;
        } else if (b == g.size()) {
            order = 1;
        } else {
            order = layout.compare(old[a].monomial.data(), g.monomial(b, words));
        }
        LiftedTerm term;
        mp_limb_t residue = 0;
        if (order >= 0) {
            term = std::move(old[a++]);
            if (order == 0) {
                residue = g.coefficients[b++];
            }
        } else {
            const std::uint64_t* m = g.monomial(b, words);
            term.monomial.assign(m, m + words);
            term.coefficient.residues.assign(primes_before, 0);
            residue = g.coefficients[b++];
        }
        append_residue(term.coefficient, residue);
        merged.push_back(std::move(term));
    }
    old = std::move(merged);
}

// Appends a basis modulo p to the group's residues, its elements on `threads` threads.
void add_to_group(Group& group, const std::vector<ModularPolynomial>& basis, std::uint32_t p,
                  const MonomialLayout& layout, int threads) {
    if (group.primes() == 0) {
        group.elements.assign(basis.size(), LiftedElement{});
        group.denominators.assign(basis.size(), Integer(1));
    }
    over_elements(threads, basis.size(), [&](std::size_t begin, std::size_t end) {
        for (std::size_t e = begin; e < end; ++e) {
            add_to_element(group.elements[e], basis[e], group.primes(), layout);
        }
    });
    group.lift.add_prime(p);
}

// One coefficient of element e, sharing the element's denominator (rational_lift.h's
// reconstruct_sharing), with seven more coefficients of the element near it as companions for a
// lattice (companions_near). Why: the coefficients of an element of a reduced basis
// over Q share most of their denominator, and the numerators over it need about half the bits
// of the rationals (cyclic-8: 672 of 1 334 bits, katsura-10: 407 of 800), but a denominator
// found from one coefficient costs the full bits again (1 309 for cyclic-8 even taking the
// cheapest coefficients first); eight together find it at about 760 (four: 840; cyclic-8 needs
// 27 primes with eight, 30 with four, katsura-11 25 and 29, for 0.1–0.2 s more of lattices). `hint`
// is the last denominator this thread found: elements share denominators, or most of them
// (cyclic-8: 128 distinct among 372 elements), and on katsura-10 the hint took the lattice
// reductions from 296 (0.24 s) to 31. Each element is reconstructed by one thread at a time.
bool reconstruct_term(modular::RationalLift::Attempt& attempt, Group& group, std::size_t e,
                      std::size_t t, Integer& hint) {
    constexpr std::size_t kCompanions = 7;
    LiftedElement& element = group.elements[e];
    return attempt.reconstruct_sharing(element[t].coefficient, group.denominators[e], hint, [&] {
        // Term 0 is the monic leading coefficient.
        return modular::companions_near(
            t, element.size(), kCompanions, 0,
            [&](std::size_t u) -> modular::LiftedNumber& { return element[u].coefficient; });
    });
}

// Rational reconstruction of every coefficient; nothing when one fails. The coefficient that
// failed last time is tried first: it usually fails again until enough primes are in, so an
// attempt after every prime costs one reconstruction, and the lift is taken as soon as the
// primes suffice (attempts after 1, 2, 3, 4, 6, 9, 13, 19, … primes, as before, used up to
// half as many primes again as needed). Past it, the elements are taken in order, from the
// hard one on, and the attempt ends at the first that fails. That order is lazy on purpose: a
// value once found is checked against every later prime (rational_lift.h), so reconstructing
// values long before the lift needs them costs checks at every attempt after (katsura-11:
// 383 000 coefficients, each reconstructed once; taking every value as soon as its primes
// allowed made the lifting 2.2 → 2.7 s).
// On `threads` threads, each with its own attempt, the elements are handed out in the same
// order, one at a time, and none past a known failure: the coefficients are independent. The
// basis does not depend on the threads; through each thread's hint (reconstruct_term) the
// denominators tried may, and with them which coefficient fails first and the number of
// primes.
// Polls `deadline` per element (the last reconstruction of a large basis takes a quarter of a
// second: katsura-10).
// The lattices of simultaneous reconstruction (reconstruct_term) save primes, and they pay where
// a prime is dear; where primes are cheap they cost more than the primes they save: katsura5
// under lex, whose primes take 60 µs each (a replay and FGLM), spent 4.6 of its 6.6 ms in
// twelve lattices of 9 × 9 at up to 365 bits (80–650 µs each, FLINT's LLL) to use 14 primes,
// and takes 2.3 ms in all without them on 18. So the group's lattices may take no more time
// than the primes have taken so far (`prime_seconds`); the expensive cases stay far below it
// (katsura-10: 36 lattices, 23 ms, against 0.3 s of primes). The number of primes then may
// change from run to run with the clock, as it does with the random primes; the basis, unique
// and certified, does not.
std::optional<std::vector<Polynomial>> reconstruct(
    Group& group, const RingPtr& ring, int threads, double prime_seconds,
    const std::optional<std::chrono::steady_clock::time_point>& deadline) {
    if (!group.lift.attempt_due()) {
        return std::nullopt;
    }
    const bool lattices = group.lattice_seconds < prime_seconds;
    const std::size_t count = group.elements.size();
    if (group.hard_element < count && group.hard_term < group.elements[group.hard_element].size()) {
        modular::RationalLift::Attempt attempt(group.lift, lattices);
        Integer hint(1);
        const bool found =
            reconstruct_term(attempt, group, group.hard_element, group.hard_term, hint);
        group.lattice_seconds += attempt.lattice_seconds();
        if (!found) {
            return std::nullopt;
        }
    }
    // Position i is element (first + i) mod count.
    const std::size_t first = group.hard_element < count ? group.hard_element : 0;
    std::vector<Polynomial> basis(count, Polynomial(ring));
    std::atomic<std::size_t> next{0};
    std::atomic<bool> stopped{false};
    std::mutex failure_mutex;
    std::size_t failed_at = count;  // the earliest position that failed
    auto work = [&] {
        release_flint_caches_at_thread_exit();
        modular::RationalLift::Attempt attempt(group.lift, lattices);
        struct CountLattices {  // on every way out of the loop
            modular::RationalLift::Attempt& attempt;
            Group& group;
            std::mutex& mutex;
            ~CountLattices() {
                const std::lock_guard<std::mutex> lock(mutex);
                group.lattice_seconds += attempt.lattice_seconds();
            }
        } count_lattices{attempt, group, failure_mutex};
        Integer hint(1);  // the last denominator found by this thread
        for (;;) {
            const std::size_t i = next++;
            {
                const std::lock_guard<std::mutex> lock(failure_mutex);
                if (i >= failed_at) {
                    return;
                }
            }
            if (deadline_passed(deadline)) {
                stopped = true;  // thrown below, outside the attempt
                return;
            }
            const std::size_t e = (first + i) % count;
            Polynomial& poly = basis[e];
            for (std::size_t t = 0; t < group.elements[e].size(); ++t) {
                LiftedTerm& term = group.elements[e][t];
                if (!reconstruct_term(attempt, group, e, t, hint)) {
                    const std::lock_guard<std::mutex> lock(failure_mutex);
                    if (i < failed_at) {
                        failed_at = i;
                        group.hard_element = e;
                        group.hard_term = t;
                    }
                    return;
                }
                if (!fmpq_is_zero(term.coefficient.value.get())) {
                    poly.push_back_term(term.coefficient.value, term.monomial.data());
                }
            }
        }
    };
    if (threads <= 1) {
        work();
    } else {
        tbb::task_arena arena(threads);
        arena.execute([&] { tbb::parallel_for(0, threads, [&](int) { work(); }); });
    }
    if (stopped) {
        throw Timeout("rational reconstruction");
    }
    if (failed_at < count) {
        return std::nullopt;
    }
    return basis;
}

// Does the candidate over Q reduce to exactly this basis modulo p?
bool agrees_modulo(const std::vector<Polynomial>& candidate,
                   const std::vector<ModularPolynomial>& basis, const PrimeField& field,
                   int threads) {
    if (candidate.size() != basis.size()) {
        return false;
    }
    std::atomic<bool> differs{false};
    over_elements(threads, basis.size(), [&](std::size_t begin, std::size_t end) {
        for (std::size_t e = begin; e < end && !differs.load(std::memory_order_relaxed); ++e) {
            const std::optional<ModularPolynomial> reduced =
                modular::reduce_modulo(candidate[e], field);
            if (!reduced || reduced->coefficients != basis[e].coefficients ||
                reduced->monomials != basis[e].monomials) {
                differs = true;
            }
        }
    });
    return !differs;
}

// The basis when the run stops without an answer: the generators themselves, which generate
// the ideal (the outcome says the basis is not a Gröbner basis).
GroebnerResult stopped_with_generators(std::span<const Polynomial> generators,
                                       GroebnerOutcome outcome, std::string reason) {
    GroebnerResult result;
    result.stats.algorithm = GroebnerAlgorithm::modular;
    result.basis.assign(generators.begin(), generators.end());
    result.outcome = outcome;
    result.reason = std::move(reason);
    return result;
}

GroebnerResult modular_groebner_or_throw(std::span<const Polynomial> generators,
                                         const ModularOptions& options, ModularStats& s) {
    const auto start = Clock::now();
    const int threads = std::max(1, options.threads);
    std::vector<Polynomial> inputs;
    for (const Polynomial& f : generators) {
        if (!inputs.empty()) {
            require_same_ring(inputs.front(), f);
        }
        if (!f.is_zero()) {
            inputs.push_back(f);
        }
    }
    GroebnerResult result;
    result.stats.algorithm = GroebnerAlgorithm::modular;
    if (inputs.empty()) {
        result.stats.seconds = seconds_since(start);
        return result;
    }
    const RingPtr ring = inputs.front().ring();
    const MonomialLayout& layout = ring->layout();
    modular::F4Options f4_options;
    f4_options.deadline = options.deadline;
    f4_options.threads = threads;
    if (options.progress) {
        // F4's steps on a prime (the first prime's run is the long one before any replay).
        f4_options.progress = [&](std::size_t steps, std::size_t basis_size) {
            GroebnerProgress report;
            report.stage = GroebnerProgress::Stage::f4;
            report.pairs_done = steps;
            report.basis_size = basis_size;
            options.progress(report);
        };
    }
    // Under lex and other non-degree orders a zero-dimensional ideal is computed under grevlex
    // and converted by FGLM; `via_grevlex` is dropped as soon as the ideal turns out not to be
    // zero-dimensional.
    // Only where grevlex's total-degree field (32 767) can be expected to hold the work:
    // Macaulay's bound Σ(dᵢ − 1) + 1, which the grevlex basis of a system without zeros at
    // infinity does not pass, below it. An input of total degree 40 000 under lex, which lex
    // packs variable by variable, overflowed there and was refused as bad input. (A basis that
    // passes the bound all the same still overflows, as under grevlex itself.)
    long macaulay_bound = 1;
    for (const Polynomial& f : inputs) {
        macaulay_bound += std::max(0L, f.total_degree() - 1);
    }
    bool via_grevlex = !ring->order().is_degree_order() &&
                       macaulay_bound <= static_cast<long>(MonomialLayout::max_field_value);
    const RingPtr grevlex_ring = ring->with_order(MonomialOrder::grevlex(ring->num_vars()));
    std::vector<Polynomial> grevlex_inputs;
    if (via_grevlex) {
        for (const Polynomial& f : inputs) {
            grevlex_inputs.push_back(f.in_ring(grevlex_ring));
        }
    }

    std::vector<Group> groups;
    modular::PrimeSequence primes(
        modular::PrimeSequence::Width::small,
        std::vector<std::uint64_t>(options.primes.begin(), options.primes.end()));
    bool tracing = options.trace;
    std::optional<modular::F4Trace> trace;  // of the first prime F4 ran on
    // The first prime (unless the caller forces primes) is one whose F4 sums the products of
    // a row reduction without reducing them (below 2²⁴: f4_linear_algebra.cpp), twice as fast
    // as the conditional subtraction 31-bit primes need (cyclic-8's linear algebra on the first
    // prime 1.74 → 0.92 s, katsura-10's 0.21 → 0.13 s). Every other prime replays that F4, so
    // its 7 bits fewer cost at most one replay more (0.15 s on cyclic-8).
    modular::PrimeSequence unreduced_primes(modular::PrimeSequence::Width::unreduced);
    bool first_draw = options.primes.empty();
    // Primes whose inputs are reduced and, once a trace exists, whose replays are done: the
    // replays run in batches on lanes, one residue a prime (f4_replay_lanes), 3.5–4.5 times
    // faster than one prime at a time (cyclic-7: 16 replays 0.30 → 0.07 s). A batch may hold
    // primes the lift turns out not to need: batches of 8 keep that small (with 16 after the
    // first, cyclic-8's 26 replays took 40, since its lift needs half the primes it did: 10.9
    // against 9.7 s; katsura-11's cost per replay is the same either way).
    struct Prepared {
        std::uint32_t p;
        std::vector<ModularPolynomial> reduced, reduced_grevlex;
        bool replay_tried = false;
        // Its batch's bases (shared with the batch's other primes) and its lane there: the
        // basis is made from them when this prime's turn comes (LaneBases, f4.h).
        std::shared_ptr<const modular::LaneBases> batch;
        std::size_t lane = 0;
        bool replayed() const { return batch != nullptr && batch->has(lane); }
    };
    std::deque<Prepared> ready;
    // The next prime that divides no leading coefficient or denominator of the inputs, with
    // the inputs modulo it; the others are counted as unlucky.
    auto next_usable = [&]() -> std::optional<Prepared> {
        while (s.primes_used.size() + ready.size() < options.max_primes) {
            const auto p =
                static_cast<std::uint32_t>(first_draw ? unreduced_primes.next() : primes.next());
            first_draw = false;
            const PrimeField field{p};
            Prepared item{p, {}, {}, false, nullptr, 0};
            bool usable = true;
            for (const Polynomial& f : inputs) {
                // A prime that divides a leading coefficient changes the input's leading
                // monomials (and a product of two such primes could make both agree on a
                // wrong ideal).
                std::optional<ModularPolynomial> g = modular::reduce_modulo(f, field);
                if (!g || fmpz_fdiv_ui(fmpq_numref(f.leading_coefficient().get()), p) == 0) {
                    usable = false;
                    break;
                }
                item.reduced.push_back(std::move(*g));
            }
            if (!usable) {
                s.primes_used.push_back(p);
                ++s.unlucky_primes;
                continue;
            }
            if (via_grevlex) {
                for (const Polynomial& f : grevlex_inputs) {
                    item.reduced_grevlex.push_back(*modular::reduce_modulo(f, field));
                }
            }
            return item;
        }
        return std::nullopt;
    };
    while (s.primes_used.size() < options.max_primes) {
        // Without certification the prime that confirms a candidate runs F4 afresh, so that
        // a replay of an unlucky first prime cannot confirm its own lift.
        const bool confirming =
            !options.certify && std::any_of(groups.begin(), groups.end(),
                                            [](const Group& g) { return g.candidate.has_value(); });
        if (ready.empty()) {
            const std::size_t batch = tracing && trace && !confirming ? 8 : 1;
            // With several threads, that many batches at once, each on its own thread: the
            // replays of different primes share nothing but the (read-only) trace.
            // At most four batches at once: each holds a basis a prime until the lift has
            // seen it (cyclic-8: two batches, 0.55 GB).
            const std::size_t parallel =
                batch > 1 ? std::min<std::size_t>(4, static_cast<std::size_t>(threads)) : 1;
            while (ready.size() < batch * parallel) {
                std::optional<Prepared> item = next_usable();
                if (!item) {
                    break;
                }
                ready.push_back(std::move(*item));
            }
            if (ready.empty()) {
                break;
            }
            if (batch > 1) {
                const auto replay_start = Clock::now();
                const std::size_t group_count = (ready.size() + batch - 1) / batch;
                auto replay_group = [&](std::size_t g) {
                    release_flint_caches_at_thread_exit();
                    const std::size_t begin = g * batch;
                    const std::size_t end = std::min(ready.size(), begin + batch);
                    std::vector<std::uint32_t> batch_primes;
                    std::vector<std::vector<ModularPolynomial>> batch_inputs;
                    for (std::size_t i = begin; i < end; ++i) {
                        batch_primes.push_back(ready[i].p);
                        batch_inputs.push_back(via_grevlex ? ready[i].reduced_grevlex
                                                           : ready[i].reduced);
                    }
                    auto replayed =
                        std::make_shared<const modular::LaneBases>(modular::f4_replay_lanes(
                            *trace, batch_inputs, batch_primes,
                            via_grevlex ? grevlex_ring->layout() : layout, f4_options));
                    for (std::size_t i = begin; i < end; ++i) {
                        ready[i].replay_tried = true;
                        ready[i].batch = replayed;
                        ready[i].lane = i - begin;
                    }
                };
                if (group_count == 1) {
                    replay_group(0);
                } else {
                    tbb::task_arena arena(static_cast<int>(parallel));
                    arena.execute(
                        [&] { tbb::parallel_for(std::size_t{0}, group_count, replay_group); });
                }
                const double seconds = seconds_since(replay_start);
                s.modular_seconds += seconds;
                s.replay_seconds += seconds;
            }
        }
        Prepared item = std::move(ready.front());
        ready.pop_front();
        const std::uint32_t p = item.p;
        s.primes_used.push_back(p);
        // A replay that left the recording (a coefficient vanishing modulo this prime, or an
        // unlucky prime) is set aside: running F4 afresh for it costs as much as the first
        // prime (cyclic-8: 2 s, against 0.14 s a replay), and the lift needs its residues no
        // more than any other prime's. Only when refusals are common, which is what an unlucky
        // first prime looks like, does F4 run afresh (a new group for the vote).
        if (item.replay_tried && !item.replayed() && !confirming &&
            s.replays_refused_set_aside < 1 + s.replayed / 8) {
            ++s.replays_refused;
            ++s.replays_refused_set_aside;
            continue;
        }
        const PrimeField field{p};
        const std::vector<ModularPolynomial>& reduced = item.reduced;
        const auto f4_start = Clock::now();
        modular::F4Stats f4_stats;
        auto run_f4 = [&](const std::vector<ModularPolynomial>& polys, const MonomialLayout& l) {
            bool record = tracing && !trace;
            if (item.replay_tried) {
                if (item.replayed() && !confirming) {
                    ++s.replayed;
                    std::vector<ModularPolynomial> basis = *item.batch->basis(item.lane);
                    item.batch.reset();  // the last prime of the batch frees it
                    return basis;
                }
                if (!item.replayed()) {
                    ++s.replays_refused;
                    // Refused beyond the primes that may be set aside: most likely the recording
                    // itself left the common path — a coefficient of one of its many
                    // new rows vanishing modulo its prime, about 7 % of cyclic-8's primes
                    // below 2²⁴ (1.15 million coefficients), after which every replay was
                    // refused and F4 ran afresh on every prime (86 s against 13). Record
                    // this run instead and replay it; the replays already made from the old
                    // recording are dropped with their primes.
                    record = tracing;
                }
            }
            if (record) {
                trace.emplace();
                ++s.traces_recorded;
                if (s.traces_recorded > 1) {
                    ready.clear();
                }
                return modular::f4(polys, l, field, f4_options, &f4_stats, &*trace);
            }
            return modular::f4(polys, l, field, f4_options, &f4_stats);
        };
        std::optional<std::vector<ModularPolynomial>> converted;
        if (via_grevlex) {
            converted =
                modular::fglm(run_f4(item.reduced_grevlex, grevlex_ring->layout()),
                              grevlex_ring->layout(), layout, field, 3000, options.deadline);
            if (!converted && trace) {
                trace.reset();  // recorded under grevlex: no use under the ring's own order
                ready.clear();  // nor are the replays made from it
            }
            via_grevlex = converted.has_value();
            if (converted) {
                s.fglm = true;
            }
        }
        const std::vector<ModularPolynomial> basis =
            converted ? std::move(*converted) : run_f4(reduced, layout);
        if (s.primes_used.size() == 1 || s.f4.steps == 0) {
            s.f4 = f4_stats;
        }
        s.modular_seconds += seconds_since(f4_start);

        const auto lift_start = Clock::now();
        const std::vector<std::uint64_t> signature = signature_of(basis, layout.words());
        auto group = std::find_if(groups.begin(), groups.end(),
                                  [&](const Group& g) { return g.signature == signature; });
        if (group == groups.end()) {
            Group fresh;
            fresh.signature = signature;
            fresh.first_prime_position = s.primes_used.size();
            groups.push_back(std::move(fresh));
            group = groups.end() - 1;
        }
        // The candidate of this group, built from other primes, meets a fresh prime; it is
        // accepted only from a group at least as large as every other (the majority vote).
        std::size_t largest_other = 0;
        for (const Group& g : groups) {
            if (&g != &*group) {
                largest_other = std::max(largest_other, g.primes());
            }
        }
        if (group->candidate && group->primes() + 1 > largest_other &&
            agrees_modulo(*group->candidate, basis, field, threads)) {
            s.lift_seconds += seconds_since(lift_start);
            std::vector<Polynomial> candidate = *group->candidate;
            if (options.certify) {
                const auto certify_start = Clock::now();
                std::function<void(std::size_t, std::size_t)> certifying;
                if (options.progress) {
                    certifying = [&](std::size_t done, std::size_t total) {
                        GroebnerProgress report;
                        report.stage = GroebnerProgress::Stage::certification;
                        report.pairs_done = done;
                        report.pairs_left = total - done;
                        report.basis_size = candidate.size();
                        options.progress(report);
                    };
                }
                const BasisCheck check = certify_groebner_basis(candidate, inputs, options.deadline,
                                                                threads, certifying);
                s.certify_seconds += seconds_since(certify_start);
                s.certification += check.work;
                if (check.ok) {
                    // The other inclusion, where a Hilbert function argument gives it; a
                    // refutation is a failed certification like the other. After the
                    // certificate, on every thread: run beside it, it had one thread (its F4
                    // modulo q is a whole basis of a homogeneous input), could take a core past
                    // --threads (a task of the caller's arena), and outlived a failed certificate
                    // (review of 2026-11-29; it saved 22 ms of katsura-10's 1.2 s).
                    s.equality = prove_ideal_equality(candidate, inputs, options.deadline, threads);
                }
                if (!check.ok || s.equality->status == IdealEquality::Status::refuted) {
                    // Stable but wrong. Replays of an unlucky first prime would keep making
                    // the same wrong lift: start again from fresh F4 runs on more primes.
                    if (s.replayed > 0) {
                        tracing = false;
                        trace.reset();
                        groups.clear();
                        ready.clear();
                    } else {
                        group->candidate.reset();
                    }
                    continue;
                }
                s.certified = true;
            }
            std::size_t in_group = group->primes();
            s.unlucky_primes = s.primes_used.size() - 1 - in_group - s.replays_refused_set_aside;
            result.basis = std::move(candidate);
            result.stats.seconds = seconds_since(start);
            result.stats.max_basis_size = result.basis.size();
            result.stats.pairs_created = s.f4.pairs_created;
            result.stats.removed_by_product = s.f4.removed_by_product;
            result.stats.removed_by_chain = s.f4.removed_by_chain;
            result.stats.reductions = s.f4.pairs_reduced;
            result.stats.zero_reductions = s.f4.zero_rows;
            return result;
        }
        add_to_group(*group, basis, p, layout, threads);
        const double lattices_before = group->lattice_seconds;
        group->candidate = reconstruct(*group, ring, threads, s.modular_seconds, options.deadline);
        s.lattice_seconds += group->lattice_seconds - lattices_before;
        if (options.progress) {
            GroebnerProgress progress;
            progress.stage = GroebnerProgress::Stage::primes;
            progress.pairs_done = s.primes_used.size();
            progress.basis_size = basis.size();
            options.progress(progress);
        }
        s.lift_seconds += seconds_since(lift_start);
    }
    return stopped_with_generators(
        generators, GroebnerOutcome::unable,
        "modular Gröbner basis: no stable lift after " + std::to_string(options.max_primes) +
            " primes (coefficients of about 15 bits per prime; the computation over Q, by the "
            "signature algorithm or Buchberger's, does not guess sizes)");
}

}  // namespace

GroebnerResult modular_groebner(std::span<const Polynomial> generators,
                                const ModularOptions& options, ModularStats* stats) {
    ModularStats local;
    ModularStats& s = stats != nullptr ? *stats : local;
    s = ModularStats{};
    try {
        return modular_groebner_or_throw(generators, options, s);
    } catch (const Timeout& stop) {
        return stopped_with_generators(generators, GroebnerOutcome::stopped_timeout, stop.what());
    }
}

namespace {

// The product of the generators' total degrees, Bézout's bound on the solutions of a square
// system (saturating far above any threshold).
double bezout_bound(std::span<const Polynomial> generators) {
    double product = 1.0;
    for (const Polynomial& g : generators) {
        product *= static_cast<double>(std::max(1L, g.total_degree()));
        if (product > 1e12) {
            break;
        }
    }
    return product;
}

}  // namespace

double automatic_shape(std::span<const Polynomial> generators) {
    if (generators.empty()) {
        return 0.0;
    }
    return bezout_bound(generators) * static_cast<double>(generators.front().ring()->num_vars());
}

// `auto` decides from the input's shape, a budget of work and the growth of coefficients, never
// from elapsed time, so that the same input takes the same route on every run and every
// machine. Measured one thread, this machine, the signature algorithm (over Z) against the
// modular one, with Bézout's bound B (the product of the generators' degrees) and n variables:
// below B·n = 4500 the signature algorithm wins or ties (eco-7 1.3 ms against 3.6 ms, katsura-9
// 0.27 s against 0.38 s, cyclic-6 7 ms against 7 ms) and runs with a budget of 80 000 reduction
// steps (katsura-9 needs 60 896). Above it what separates the cases is coefficient growth,
// which the computation over Q pays for and the modular one does not (2026-11-27, the largest
// coefficient of the basis so far): katsura-10 reaches 128 bits with 32 elements (signatures
// 4.1 s, modular 2.9 s), cyclic-7 with 277 (1.9 s against 0.44 s), cyclic-8 with 439, while
// eco-10 ends at 101 bits (0.33 s against 0.62 s), noon-7 at 40 (0.09 s against 0.36 s) and
// eco-11 reaches 128 bits only with 961 elements (3.6 s against 8.9 s). Read as a rate, the
// cases that belong to the modular route grow faster than a bit per four elements (cyclic-8:
// 69 bits with 216 elements, cyclic-7: 68 with 218, katsura-10: 72 with 29) and the others do
// not (eco-10: 69 bits with 466, 101 with 477; eco-11: 69 with 864, 156 with 964; noon-7: 38
// with 523). So above the shape the signature algorithm runs until an element of b ≥ 32 bits
// joins a basis of fewer than 4·b elements, or 2 000 000 reduction steps, and the modular
// algorithm takes over. Where the cases first pass 32 bits (elements then): cyclic-7 86 and
// cyclic-8 114, below the line of 128 (and below it again at 40 bits: 162 and 163 against 176
// and 184), katsura-10 18; eco-10 319, eco-11 477, noon-7 490, 2.5–3.8 times above it (and
// above it at every larger size: eco-10 388 at 41 bits, 466 at 69; read with a throwaway
// print). The probe costs cyclic-7 0.006 s and cyclic-8 0.036 s (`--stats` prints it; the line
// at 64 bits cost them about 0.09 s and 0.25 s, at 128 bits within 512 elements cyclic-8 1.7 s).
// Neither a budget of steps alone (cyclic-7 spent 1 s in it) nor the size of a basis modulo p
// separated these cases. Under lex and elimination orders FGLM wins on zero-dimensional ideals
// (katsura5_lex 1.6 ms against 11 ms), while the small suite cases finish by signatures in 3 to 149
// reduction steps: a budget of 300. A square (or overdetermined) system of shape B·n ≥ 150 under
// such an order skips the probe: cyclic5_lex (600) spent 2 ms in it before the modular route
// answered anyway (4.0 ms in all against 2.0 directly; Singular 1.9 ms), while the cases the probe
// answers are smaller (katsura4_lex 32, cyclic4_lex 96) or have fewer generators than variables
// (the elimination ideals of parametrizations, often positive-dimensional, where the modular route
// has no FGLM). katsura5_lex (80) still probes and goes modular (4.1 ms; Singular 5.5 ms): shape
// does not separate it from cyclic4_lex, nor growth from katsura4_lex (64 bits within 256 elements
// would send katsura4_lex modular, 0.3 → 0.67 ms).
GroebnerResult groebner_automatic(std::span<const Polynomial> generators,
                                  const GroebnerOptions& options, ModularStats* stats,
                                  bool* used_modular) {
    if (used_modular != nullptr) {
        *used_modular = false;
    }
    if (generators.empty()) {
        return signature_groebner_or_buchberger(generators, options);
    }
    const RingPtr& ring = generators.front().ring();
    const bool degree_order = ring->order().is_degree_order();
    constexpr double kOtherOrderModularShape = 150;
    constexpr std::size_t kDegreeOrderBudget = 80000, kOtherOrderBudget = 300;
    // Growth: 32 bits within 128 elements, 64 within 256, … (four elements a bit).
    constexpr std::size_t kGrowthBits = 32, kGrowthBasis = 128, kLargeShapeBudget = 2000000;
    GroebnerResult result;
    const double shape = automatic_shape(generators);
    const bool skip_probe = !degree_order && shape >= kOtherOrderModularShape &&
                            generators.size() >= ring->num_vars() &&
                            options.max_reduction_steps == 0 && options.max_basis_size == 0;
    GroebnerOptions probing = options;
    if (!degree_order) {
        probing.max_reduction_steps = kOtherOrderBudget;
    } else if (shape <= kLargeShape) {
        probing.max_reduction_steps = kDegreeOrderBudget;
    } else {
        probing.max_reduction_steps = kLargeShapeBudget;
        probing.growth_bits = kGrowthBits;
        probing.growth_basis = kGrowthBasis;
    }
    // A caller's own budget of steps stays the limit when it is the smaller.
    if (options.max_reduction_steps != 0) {
        probing.max_reduction_steps =
            std::min(probing.max_reduction_steps, options.max_reduction_steps);
    }
    ModularOptions modular_options;
    modular_options.deadline = options.deadline;
    modular_options.threads = options.threads;
    modular_options.certify = options.certify;
    modular_options.progress = options.progress;
    // The probe runs on every thread given (the signature algorithm attempts the signatures
    // of a degree side by side) and the modular route only once it has handed over. Starting
    // the route beside the probe, as this did when the probe was sequential, saved at most the
    // probe's time (cyclic-8's 0.032 s, every other suite case less) and cost the cases the
    // probe answers a core: eco-10 on two threads took 0.33 s against 0.19 s without it.
    const auto start = std::chrono::steady_clock::now();
    std::string probe = "none: a square system of shape " +
                        std::to_string(static_cast<long>(shape)) + " under a non-degree order";
    if (skip_probe) {
        result.outcome = GroebnerOutcome::stopped_size;  // as if the probe had handed over
    } else {
        result = signature_groebner_or_buchberger(generators, probing);
        probe = "signatures stopped after " + std::to_string(result.stats.reduction_steps) +
                " reduction steps: " + result.reason;
    }
    const double probe_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // Stopped by the probe's budget or growth rule, not by the caller's own limits.
    const bool callers_limit =
        (options.max_basis_size != 0 && result.stats.max_basis_size > options.max_basis_size) ||
        (options.max_reduction_steps != 0 &&
         result.stats.reduction_steps >= options.max_reduction_steps);
    if (result.outcome != GroebnerOutcome::stopped_size || callers_limit) {
        return result;
    }
    if (deadline_passed(options.deadline)) {
        result.outcome = GroebnerOutcome::stopped_timeout;  // the budget was not the limit
        return result;
    }
    if (used_modular != nullptr) {
        *used_modular = true;
    }
    GroebnerResult modular = modular_groebner(generators, modular_options, stats);
    if (stats != nullptr) {
        stats->probe = probe;
        stats->probe_seconds = skip_probe ? 0.0 : probe_seconds;
    }
    if (modular.outcome == GroebnerOutcome::unable) {
        // No stable lift within max_primes (coefficients of tens of thousands of digits): the
        // computation over Q gets there without guessing sizes.
        if (used_modular != nullptr) {
            *used_modular = false;
        }
        return signature_groebner_or_buchberger(generators, options);
    }
    modular.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return modular;
}

std::vector<Polynomial> groebner_modulo(std::span<const Polynomial> generators, std::uint32_t p,
                                        const modular::F4Options& options,
                                        modular::F4Stats* stats) {
    if (p < 2 || p >= (1u << 31) || !n_is_prime(p)) {
        throw InputError("characteristic " + std::to_string(p), "expected a prime below 2^31");
    }
    const PrimeField field{p};
    std::vector<ModularPolynomial> reduced;
    RingPtr ring;
    for (const Polynomial& f : generators) {
        if (ring) {
            require_same_ring(generators.front(), f);
        }
        ring = f.ring();
        std::optional<ModularPolynomial> g = modular::reduce_modulo(f, field);
        if (!g) {
            throw InputError("characteristic " + std::to_string(p),
                             "the prime divides a denominator of the input");
        }
        if (!g->is_zero()) {
            reduced.push_back(std::move(*g));
        }
    }
    std::vector<Polynomial> out;
    if (!ring) {
        return out;
    }
    for (const ModularPolynomial& g : modular::f4(reduced, ring->layout(), field, options, stats)) {
        Polynomial poly(ring);
        for (std::size_t i = 0; i < g.size(); ++i) {
            poly.push_back_term(Rational(static_cast<long>(g.coefficients[i])),
                                g.monomial(i, ring->words()));
        }
        out.push_back(std::move(poly));
    }
    return out;
}

}  // namespace locus::algebra
