// The signature-based algorithm (signature_groebner.h): Roune and Stillman's SB ("Practical
// Gröbner basis computation", ISSAC 2012), which is Eder and Roune's RB with the rewrite order of
// least leading monomial, in the formulation of Eder and Faugère's survey (JSC 80, 2017).
//
// A signature is held as its index i, its monomial t and its comparison monomial: t·lm(fᵢ) under
// the Schreyer order, t itself under position-over-term. Multiplying a signature by a monomial
// multiplies both monomials, so the regularity test of a reduction step (is m·sig(g) below the
// signature being reduced?) is one packed multiplication and one comparison.
//
// The loop takes the least queued signature T (all the S-pairs that reach it at once):
//   1. T is skipped when the monomial of a known syzygy signature of the same index divides it
//      (the syzygy criterion: Koszul syzygies of basis elements, and earlier reductions to zero);
//   2. of the elements g whose signature divides T, the one whose multiple (T / sig(g))·g has the
//      least leading monomial is taken (ties: fewer terms, then the larger signature; mathicgb's
//      choice); no element means T = eᵢ, and the generator itself is taken;
//   3. T is skipped when that multiple's leading monomial has no regular reducer (the singular
//      criterion: the multiple is as reduced as anything of signature T can be, and an element
//      of smaller ratio already stands for it);
//   4. otherwise the multiple is reduced by regular reductions only, leading and tail terms alike.
//      Zero makes T a syzygy signature; anything else joins the basis with signature T, and its
//      S-pairs and Koszul syzygies with every older element are formed.
// The S-polynomial is never formed as such: the first regular reduction of the multiple cancels
// its leading term against an element of smaller signature, which is what the S-polynomial of
// the pair would have done.
//
// Why SB's choice and not the newest element (RB's add order): both were prototyped in Python
// over GF(32003) on the suite and made the same work to within 12 % either way (eco-7 31 094 and
// 27 490 term operations, noon-5 11 980 and 12 067); SB's singular criterion is what the
// termination proof of the GVW framework rests on, and mathicgb runs it in production. Discarding
// singular top-reducible *results* after reducing the newest element's multiple, tried first,
// lost basis elements (noon-4): the criterion belongs with the least-lead choice.
#include "algebra/groebner/signature_groebner.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <memory>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "algebra/error.h"
#include "algebra/flint_threads.h"
#include "algebra/groebner/detail/reduction.h"

namespace locus::algebra {
namespace {

using detail::BasisElement;
using detail::IntegerPolynomial;

// An S-pair waiting in the queue: its signature's index, and the `slot` of its monomials (t, then
// the comparison monomial) in the run's pool. (32-bit, like the element numbers: four billion
// queued pairs or elements would have exhausted memory long before.)
struct QueuedPair {
    std::uint32_t index;
    std::uint32_t slot;
};

// What one signature T came to, from the criteria and the reduction of its multiple: skipped
// by the syzygy criterion, skipped by the singular criterion, or reduced (to `h`, maybe zero),
// having seen the first `basis_size` elements and `syzygies` syzygy signatures.
struct Attempt {
    enum class Kind { syzygy, singular, reduced };
    Kind kind = Kind::reduced;
    std::optional<std::uint32_t> element;  // whose multiple was taken; none: the generator
    IntegerPolynomial h;
    std::size_t basis_size = 0, syzygies = 0;
};

// A signature taken from the queue with every S-pair that reaches it, and, in a batch, what
// its attempt on the batch's basis came to.
struct Taken {
    std::uint32_t index = 0;
    std::vector<std::uint64_t> sig;  // t, then the comparison monomial
    std::size_t reaching = 1;
    std::optional<Attempt> ahead;
};

class SignatureRun {
  public:
    SignatureRun(const MonomialLayout& layout, SignatureOrder order,
                 std::vector<IntegerPolynomial> generators)
        : layout_(layout),
          w_(layout.words()),
          order_(order),
          generators_(std::move(generators)),
          elements_of_index_(generators_.size()),
          syzygies_(generators_.size()),
          target_(2 * w_),
          candidate_(2 * w_),
          other_(2 * w_),
          lcm_(w_),
          multiplier_(w_) {}

    // The whole computation; the basis is written in `ring`.
    GroebnerResult run(const GroebnerOptions& options, const RingPtr& ring,
                       std::size_t steps_before_batches);

  private:
    // Regular reductions only: a multiple m·g may reduce a polynomial of signature T when
    // m·sig(g) < T. One admission a reduction, each with its own scratch, so that reductions
    // of a batch run side by side.
    class Admission final : public detail::ReducerAdmission {
      public:
        Admission(const SignatureRun& run, std::uint32_t index, const std::uint64_t* key)
            : run_(run), index_(index), key_(key), product_(run.w_) {}
        bool admits(std::size_t element, const std::uint64_t* multiplier) const override {
            run_.layout_.multiply(multiplier, run_.key_of(element), product_.data());
            return run_.compare(run_.index_[element], product_.data(), index_, key_) < 0;
        }

      private:
        const SignatureRun& run_;
        std::uint32_t index_;
        const std::uint64_t* key_;
        mutable std::vector<std::uint64_t> product_;
    };

    // A reducer and scratch monomials: the main loop's, or a batch worker's.
    struct Workspace {
        explicit Workspace(const MonomialLayout& layout)
            : reducer(layout),
              first(layout.words()),
              second(layout.words()),
              multiplier(layout.words()),
              lead(layout.words()) {}
        detail::Reducer reducer;
        detail::ReductionCounts counts;
        std::vector<std::uint64_t> first, second, multiplier, lead;
    };

    // Signature monomials of basis element e: t, then the comparison monomial.
    const std::uint64_t* t_of(std::size_t e) const {
        return element_signatures_.data() + 2 * w_ * e;
    }
    const std::uint64_t* key_of(std::size_t e) const { return t_of(e) + w_; }
    const std::uint64_t* lm_of(std::size_t e) const { return basis_[e].poly.monomial(0, w_); }
    const std::uint64_t* pair_t(const QueuedPair& p) const {
        return pair_signatures_.data() + 2 * w_ * p.slot;
    }
    const std::uint64_t* pair_key(const QueuedPair& p) const { return pair_t(p) + w_; }

    // Signature order on (index, comparison monomial).
    int compare(std::uint32_t index_a, const std::uint64_t* key_a, std::uint32_t index_b,
                const std::uint64_t* key_b) const {
        if (order_ == SignatureOrder::position_over_term && index_a != index_b) {
            return index_a < index_b ? -1 : 1;
        }
        const int c = layout_.compare(key_a, key_b);
        if (c != 0) {
            return c;
        }
        return index_a == index_b ? 0 : (index_a < index_b ? -1 : 1);
    }

    // The comparison monomial of t·eᵢ, into `out`.
    void comparison_monomial(std::uint32_t index, const std::uint64_t* t,
                             std::uint64_t* out) const {
        if (order_ == SignatureOrder::schreyer) {
            layout_.multiply(t, generators_[index].monomial(0, w_), out);
        } else {
            std::copy_n(t, w_, out);
        }
    }

    bool is_syzygy(std::uint32_t index, const std::uint64_t* t) const;
    void add_syzygy(std::uint32_t index, const std::uint64_t* t);
    // Of the elements with signature index `index` whose signature monomial divides t, the one
    // whose multiple into t·e_index has the least leading monomial (ties: fewer terms, then the
    // larger signature); none when there is no such element.
    std::optional<std::uint32_t> least_lead_element(std::uint32_t index, const std::uint64_t* t,
                                                    Workspace& ws) const;
    // Whether some multiple of an element that `admission` admits has leading monomial m.
    bool has_regular_reducer(const std::uint64_t* m, const Admission& admission,
                             Workspace& ws) const;
    // The singular criterion for the multiple of `element` into signature `sig`: no element
    // that `admission` admits has a multiple with its leading monomial. Leaves the multiplier
    // in ws.multiplier (and the leading monomial in ws.lead).
    bool singular(std::uint32_t element, const std::uint64_t* sig, const Admission& admission,
                  Workspace& ws) const;
    // The criteria and the reduction for signature (index, sig) on the basis as it is.
    Attempt attempt(std::uint32_t index, const std::uint64_t* sig, Workspace& ws) const;
    // Whether an element from `from` on reduces a term of h by a multiple `admission` admits.
    bool reducible_by_newer(const IntegerPolynomial& h, std::size_t from,
                            const Admission& admission, Workspace& ws) const;
    // What `ahead`, attempted on an earlier basis, comes to on the basis as it is now: the same
    // decisions checked again (they are cheap), and the reduction continued by the elements
    // added since; attempted afresh when the element chosen or the singular criterion changed.
    Attempt bring_up_to_date(Attempt ahead, std::uint32_t index, const std::uint64_t* sig,
                             Workspace& ws) const;
    // The heap's order: a before b when a's signature is the larger, so the least is on top.
    auto later_than() const {
        return [this](const QueuedPair& a, const QueuedPair& b) {
            return compare(a.index, pair_key(a), b.index, pair_key(b)) > 0;
        };
    }
    void push(std::uint32_t index, const std::uint64_t* sig);
    QueuedPair pop();
    // The least queued signature and every pair that reaches it.
    Taken take();
    // Takes the queued pairs of `taken`'s signature off the queue, counting them as reaching it.
    void take_equal(Taken& taken);
    // The next signatures of the least degree (at most `most`), each attempted on the basis
    // as it is, side by side on `threads` threads.
    std::vector<Taken> take_batch(std::size_t most, int threads, const GroebnerOptions& options);
    void add_element(IntegerPolynomial h);
    IntegerPolynomial multiple(const std::uint64_t* m, const IntegerPolynomial& g) const;
    GroebnerResult partial(GroebnerResult result, const RingPtr& ring) const;

    const MonomialLayout& layout_;
    const std::size_t w_;
    const SignatureOrder order_;
    std::vector<IntegerPolynomial> generators_;  // leading monomials ascending

    // The basis and each element's signature.
    std::vector<BasisElement> basis_;
    std::vector<std::uint32_t> index_;
    std::vector<std::uint64_t> element_signatures_;  // 2w words an element
    std::vector<std::uint64_t> element_masks_;       // divisibility masks of the t's
    std::vector<std::vector<std::uint32_t>> elements_of_index_;

    // Known syzygy signatures per index, kept minimal: monomials (w words each) and masks.
    struct Syzygies {
        std::vector<std::uint64_t> monomials, masks;
    };
    std::vector<Syzygies> syzygies_;
    std::size_t syzygies_added_ = 0;

    // The queue: a binary heap, least signature first; pair monomials live in slots of a pool.
    std::vector<QueuedPair> heap_;
    std::vector<std::uint64_t> pair_signatures_;
    std::vector<std::uint32_t> free_slots_;

    GroebnerStats stats_;

    // The threads of the batches and their workspaces, made at the first batch worth them.
    // Smaller batches are attempted in turn: an arena's start and a parallel loop cost more
    // than a few small reductions (cyclic4 under lex took 0.9 ms against 0.06).
    static constexpr std::size_t kLeastInParallel = 8;
    struct Workers {
        template <typename Make>
        Workers(int threads, Make make) : arena(threads), workspaces(make) {}
        tbb::task_arena arena;
        tbb::enumerable_thread_specific<std::unique_ptr<Workspace>> workspaces;
    };
    std::unique_ptr<Workers> workers_;

    // The signature of the element being added (add_element reads it) and scratch monomials.
    std::uint32_t target_index_ = 0;
    std::vector<std::uint64_t> target_, candidate_, other_, lcm_, multiplier_;
};

bool SignatureRun::is_syzygy(std::uint32_t index, const std::uint64_t* t) const {
    const Syzygies& s = syzygies_[index];
    const std::uint64_t mask = layout_.divisibility_mask(t);
    for (std::size_t k = 0; k < s.masks.size(); ++k) {
        if ((s.masks[k] & ~mask) == 0 && layout_.divides(s.monomials.data() + k * w_, t)) {
            return true;
        }
    }
    return false;
}

void SignatureRun::add_syzygy(std::uint32_t index, const std::uint64_t* t) {
    if (is_syzygy(index, t)) {
        return;
    }
    // Drop the ones t divides: the list stays the minimal generators of what is known.
    Syzygies& s = syzygies_[index];
    std::size_t kept = 0;
    for (std::size_t k = 0; k < s.masks.size(); ++k) {
        if (layout_.divides(t, s.monomials.data() + k * w_)) {
            continue;
        }
        if (kept != k) {
            std::copy_n(s.monomials.data() + k * w_, w_, s.monomials.data() + kept * w_);
            s.masks[kept] = s.masks[k];
        }
        ++kept;
    }
    s.monomials.resize(kept * w_);
    s.masks.resize(kept);
    s.monomials.insert(s.monomials.end(), t, t + w_);
    s.masks.push_back(layout_.divisibility_mask(t));
    ++syzygies_added_;
}

std::optional<std::uint32_t> SignatureRun::least_lead_element(std::uint32_t index,
                                                              const std::uint64_t* t,
                                                              Workspace& ws) const {
    const std::uint64_t mask = layout_.divisibility_mask(t);
    std::optional<std::uint32_t> best;
    for (const std::uint32_t e : elements_of_index_[index]) {
        if ((element_masks_[e] & ~mask) != 0 || !layout_.divides(t_of(e), t)) {
            continue;
        }
        if (best) {
            // (t / t_e)·lm(e) against (t / t_b)·lm(b): multiplied by t_e·t_b / t, lm(e)·t_b
            // against lm(b)·t_e.
            layout_.multiply(lm_of(e), t_of(*best), ws.first.data());
            layout_.multiply(lm_of(*best), t_of(e), ws.second.data());
            const int c = layout_.compare(ws.first.data(), ws.second.data());
            if (c > 0) {
                continue;
            }
            if (c == 0) {
                const std::size_t terms = basis_[e].poly.size(),
                                  best_terms = basis_[*best].poly.size();
                if (terms > best_terms ||
                    (terms == best_terms && layout_.compare(t_of(e), t_of(*best)) < 0)) {
                    continue;
                }
            }
        }
        best = e;
    }
    return best;
}

bool SignatureRun::has_regular_reducer(const std::uint64_t* m, const Admission& admission,
                                       Workspace& ws) const {
    const std::uint64_t mask = layout_.divisibility_mask(m);
    for (std::size_t e = 0; e < basis_.size(); ++e) {
        if ((basis_[e].poly.leading_mask & ~mask) == 0 && layout_.divides(lm_of(e), m)) {
            layout_.divide(m, lm_of(e), ws.first.data());
            if (admission.admits(e, ws.first.data())) {
                return true;
            }
        }
    }
    return false;
}

bool SignatureRun::singular(std::uint32_t element, const std::uint64_t* sig,
                            const Admission& admission, Workspace& ws) const {
    layout_.divide(sig, t_of(element), ws.multiplier.data());
    layout_.multiply(ws.multiplier.data(), lm_of(element), ws.lead.data());
    return !has_regular_reducer(ws.lead.data(), admission, ws);
}

Attempt SignatureRun::attempt(std::uint32_t index, const std::uint64_t* sig, Workspace& ws) const {
    Attempt a;
    a.basis_size = basis_.size();
    a.syzygies = syzygies_added_;
    if (is_syzygy(index, sig)) {
        a.kind = Attempt::Kind::syzygy;
        return a;
    }
    a.element = least_lead_element(index, sig, ws);
    const Admission admission(*this, index, sig + w_);
    IntegerPolynomial p;
    if (a.element) {
        if (singular(*a.element, sig, admission, ws)) {
            a.kind = Attempt::Kind::singular;
            return a;
        }
        p = multiple(ws.multiplier.data(), basis_[*a.element].poly);
    } else {
        // No element of this index yet: T is the generator's own eᵢ.
        p = generators_[index];
    }
    a.h = ws.reducer.reduce(std::move(p), basis_, ws.counts, /*tail=*/true, &admission);
    return a;
}

bool SignatureRun::reducible_by_newer(const IntegerPolynomial& h, std::size_t from,
                                      const Admission& admission, Workspace& ws) const {
    for (std::size_t j = 0; j < h.size(); ++j) {
        const std::uint64_t* m = h.monomial(j, w_);
        const std::uint64_t mask = layout_.divisibility_mask(m);
        for (std::size_t e = from; e < basis_.size(); ++e) {
            if ((basis_[e].poly.leading_mask & ~mask) == 0 && layout_.divides(lm_of(e), m)) {
                layout_.divide(m, lm_of(e), ws.first.data());
                if (admission.admits(e, ws.first.data())) {
                    return true;
                }
            }
        }
    }
    return false;
}

Attempt SignatureRun::bring_up_to_date(Attempt ahead, std::uint32_t index, const std::uint64_t* sig,
                                       Workspace& ws) const {
    const bool grew = ahead.basis_size != basis_.size();
    if (!grew && ahead.syzygies == syzygies_added_) {
        return ahead;  // nothing it depends on has changed
    }
    // Syzygies and elements are only added: a signature skipped stays skipped, a regular
    // reducer stays one, and a reduction by the elements then is one by the elements now.
    if (ahead.kind == Attempt::Kind::syzygy) {
        return ahead;
    }
    if (is_syzygy(index, sig)) {
        Attempt skipped;
        skipped.kind = Attempt::Kind::syzygy;
        return skipped;
    }
    if (!grew) {
        return ahead;
    }
    if (least_lead_element(index, sig, ws) != ahead.element) {
        return attempt(index, sig, ws);
    }
    if (ahead.kind == Attempt::Kind::singular) {
        const Admission admission(*this, index, sig + w_);
        return singular(*ahead.element, sig, admission, ws) ? ahead : attempt(index, sig, ws);
    }
    if (!ahead.h.empty()) {
        // h is reduced by the elements it saw; only a term that a newer one reduces needs the
        // reduction continued (most do not: a whole reduction would search every term again).
        const Admission admission(*this, index, sig + w_);
        if (reducible_by_newer(ahead.h, ahead.basis_size, admission, ws)) {
            ahead.h =
                ws.reducer.reduce(std::move(ahead.h), basis_, ws.counts, /*tail=*/true, &admission);
        }
    }
    return ahead;
}

void SignatureRun::push(std::uint32_t index, const std::uint64_t* sig) {
    std::uint32_t slot;
    if (!free_slots_.empty()) {
        slot = free_slots_.back();
        free_slots_.pop_back();
    } else {
        slot = static_cast<std::uint32_t>(pair_signatures_.size() / (2 * w_));
        pair_signatures_.resize(pair_signatures_.size() + 2 * w_);
    }
    std::copy_n(sig, 2 * w_, pair_signatures_.data() + 2 * w_ * slot);
    heap_.push_back({index, slot});
    std::push_heap(heap_.begin(), heap_.end(), later_than());
}

QueuedPair SignatureRun::pop() {
    std::pop_heap(heap_.begin(), heap_.end(), later_than());
    const QueuedPair p = heap_.back();
    heap_.pop_back();
    free_slots_.push_back(p.slot);
    return p;
}

Taken SignatureRun::take() {
    Taken taken;
    const QueuedPair first = pop();
    taken.index = first.index;
    taken.sig.assign(pair_t(first), pair_t(first) + 2 * w_);
    take_equal(taken);
    return taken;
}

void SignatureRun::take_equal(Taken& taken) {
    while (!heap_.empty() && compare(heap_.front().index, pair_key(heap_.front()), taken.index,
                                     taken.sig.data() + w_) == 0) {
        pop();
        ++taken.reaching;
    }
}

std::vector<Taken> SignatureRun::take_batch(std::size_t most, int threads,
                                            const GroebnerOptions& options) {
    std::vector<Taken> batch;
    const std::uint32_t degree = layout_.leading_weight(pair_key(heap_.front()));
    while (!heap_.empty() && batch.size() < most &&
           layout_.leading_weight(pair_key(heap_.front())) == degree) {
        batch.push_back(take());
    }
    if (batch.size() < kLeastInParallel) {
        return batch;  // attempted in turn, as on one thread
    }
    if (!workers_) {
        workers_ = std::make_unique<Workers>(threads, [this, &options] {
            release_flint_caches_at_thread_exit();  // made on the worker that uses it
            auto ws = std::make_unique<Workspace>(layout_);
            ws->reducer.set_deadline(options.deadline);
            return ws;
        });
    }
    stats_.batched_signatures += batch.size();
    workers_->arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, batch.size(), 1),
                          [&](const tbb::blocked_range<std::size_t>& range) {
                              Workspace& ws = *workers_->workspaces.local();
                              for (std::size_t i = range.begin(); i != range.end(); ++i) {
                                  batch[i].ahead = attempt(batch[i].index, batch[i].sig.data(), ws);
                              }
                          });
    });
    for (const std::unique_ptr<Workspace>& ws : workers_->workspaces) {
        stats_.reduction_steps += ws->counts.steps;
        ws->counts.steps = 0;
    }
    return batch;
}

IntegerPolynomial SignatureRun::multiple(const std::uint64_t* m, const IntegerPolynomial& g) const {
    IntegerPolynomial p;
    p.monomials.resize(g.monomials.size());
    for (std::size_t i = 0; i < g.size(); ++i) {
        layout_.multiply(g.monomial(i, w_), m, p.monomials.data() + i * w_);
    }
    p.coefficients = g.coefficients;
    p.sugar = g.sugar + layout_.leading_weight(m);
    return p;
}

std::size_t largest_coefficient_bits(const IntegerPolynomial& h) {
    std::size_t bits = 0;
    for (const Integer& c : h.coefficients) {
        bits = std::max<std::size_t>(bits, fmpz_bits(c.get()));
    }
    return bits;
}

void SignatureRun::add_element(IntegerPolynomial h) {
    const auto n = static_cast<std::uint32_t>(basis_.size());
    const std::uint64_t* lm_h = h.monomial(0, w_);
    // target_ holds the new element's signature (t, key).
    for (std::uint32_t j = 0; j < n; ++j) {
        const std::uint64_t* lm_j = lm_of(j);
        // Koszul syzygy lm(gⱼ)·h − lm(h)·gⱼ: its signature is the larger of lm(gⱼ)·sig(h) and
        // lm(h)·sig(gⱼ). Only a shortcut: one whose signature leaves the packed range is left out.
        try {
            layout_.multiply(lm_j, target_.data(), candidate_.data());
            layout_.multiply(lm_j, target_.data() + w_, candidate_.data() + w_);
            layout_.multiply(lm_h, t_of(j), other_.data());
            layout_.multiply(lm_h, key_of(j), other_.data() + w_);
            const int koszul =
                compare(target_index_, candidate_.data() + w_, index_[j], other_.data() + w_);
            if (koszul > 0) {
                add_syzygy(target_index_, candidate_.data());
            } else if (koszul < 0) {
                add_syzygy(index_[j], other_.data());
            }
        } catch (const ExponentOverflow&) {
        }
        // The S-pair: the larger of (lcm/lm(h))·sig(h) and (lcm/lm(gⱼ))·sig(gⱼ); equal signatures
        // cancel (a singular pair, not needed).
        layout_.lcm(lm_j, lm_h, lcm_.data());
        layout_.divide(lcm_.data(), lm_h, multiplier_.data());
        layout_.multiply(multiplier_.data(), target_.data(), candidate_.data());
        layout_.multiply(multiplier_.data(), target_.data() + w_, candidate_.data() + w_);
        layout_.divide(lcm_.data(), lm_j, multiplier_.data());
        layout_.multiply(multiplier_.data(), t_of(j), other_.data());
        layout_.multiply(multiplier_.data(), key_of(j), other_.data() + w_);
        const int c = compare(target_index_, candidate_.data() + w_, index_[j], other_.data() + w_);
        if (c == 0) {
            continue;
        }
        ++stats_.pairs_created;
        const std::uint32_t index = c > 0 ? target_index_ : index_[j];
        const std::uint64_t* sig = c > 0 ? candidate_.data() : other_.data();
        if (is_syzygy(index, sig)) {
            ++stats_.removed_by_syzygy;
            continue;
        }
        push(index, sig);
    }
    basis_.push_back({std::move(h), false});
    index_.push_back(target_index_);
    element_signatures_.insert(element_signatures_.end(), target_.begin(), target_.end());
    element_masks_.push_back(layout_.divisibility_mask(target_.data()));
    elements_of_index_[target_index_].push_back(n);
    stats_.max_basis_size = std::max(stats_.max_basis_size, basis_.size());
}

GroebnerResult SignatureRun::partial(GroebnerResult result, const RingPtr& ring) const {
    // Every element so far and every generator: they generate the ideal, whatever was left.
    // Primitive over Z, not monic: the deadline has passed (to_primitive_polynomial says why).
    for (const BasisElement& e : basis_) {
        result.basis.push_back(detail::to_primitive_polynomial(e.poly, ring));
    }
    for (const IntegerPolynomial& f : generators_) {
        result.basis.push_back(detail::to_primitive_polynomial(f, ring));
    }
    std::sort(result.basis.begin(), result.basis.end(),
              [&](const Polynomial& a, const Polynomial& b) {
                  return layout_.compare(a.leading_monomial(), b.leading_monomial()) < 0;
              });
    return result;
}

GroebnerResult SignatureRun::run(const GroebnerOptions& options, const RingPtr& ring,
                                 std::size_t steps_before_batches) {
    GroebnerResult result;
    Workspace main(layout_);
    // Reductions are interruptible from the start: the partial result keeps every generator.
    main.reducer.set_deadline(options.deadline);
    // The generators' own signatures eᵢ.
    for (std::uint32_t i = 0; i < generators_.size(); ++i) {
        std::fill(target_.begin(), target_.begin() + static_cast<long>(w_), 0);
        comparison_monomial(i, target_.data(), target_.data() + w_);
        push(i, target_.data());
    }
    // With more than one thread, once `steps_before_batches` reduction steps are made (a
    // smaller run is over in milliseconds, less than starting the threads costs: eco7 on two
    // threads took 1.9 ms against 1.1 without this), the signatures of one degree are
    // attempted side by side on the
    // basis as it was before them, then taken in order as one thread would, each brought up to
    // date: the same decisions checked again and its reduction continued by the elements the
    // batch added before it. Signatures queued meanwhile below a batch's next one come first.
    // Every reduction is then one the sequential loop could have made, and the batches do not
    // depend on timing: the result is the same on every run and equals the sequential one
    // once interreduced (a reduced basis is unique).
    const int threads = std::max(1, options.threads);
    constexpr std::size_t kMostInBatch = 256;
    std::vector<Taken> batch;
    std::size_t next_in_batch = 0;
    std::size_t signatures_done = 0;
    stats_.reduction_steps = 0;
    const auto steps = [&] { return stats_.reduction_steps + main.counts.steps; };
    while (!heap_.empty() || next_in_batch < batch.size()) {
        if (const auto stop = requested_stop(options, basis_.size(), steps())) {
            result.outcome = *stop;
            break;
        }
        Taken taken;
        try {
            if (threads > 1 && next_in_batch == batch.size() && steps() >= steps_before_batches) {
                batch = take_batch(kMostInBatch, threads, options);
                next_in_batch = 0;
            }
            if (next_in_batch < batch.size() &&
                (heap_.empty() ||
                 compare(batch[next_in_batch].index, batch[next_in_batch].sig.data() + w_,
                         heap_.front().index, pair_key(heap_.front())) <= 0)) {
                taken = std::move(batch[next_in_batch++]);
                take_equal(taken);  // S-pairs the batch's elements queued with its signature
            } else {
                taken = take();
            }
        } catch (const detail::ReductionInterrupted&) {
            result.outcome = GroebnerOutcome::stopped_timeout;
            break;
        }
        target_index_ = taken.index;
        std::copy_n(taken.sig.data(), 2 * w_, target_.data());
        ++signatures_done;
        if (options.progress) {
            // Queued: the heap and what is left of the batch.
            options.progress({signatures_done, heap_.size() + (batch.size() - next_in_batch),
                              basis_.size(), layout_.leading_weight(target_.data() + w_)});
        }
        Attempt a;
        try {
            a = taken.ahead
                    ? bring_up_to_date(std::move(*taken.ahead), taken.index, taken.sig.data(), main)
                    : attempt(taken.index, taken.sig.data(), main);
        } catch (const detail::ReductionInterrupted&) {
            result.outcome = GroebnerOutcome::stopped_timeout;
            break;
        }
        if (a.kind == Attempt::Kind::syzygy) {
            stats_.removed_by_syzygy += taken.reaching;
            continue;
        }
        stats_.removed_by_rewriting += taken.reaching - 1;
        if (a.kind == Attempt::Kind::singular) {
            ++stats_.removed_by_rewriting;  // the singular criterion
            continue;
        }
        IntegerPolynomial h = std::move(a.h);
        ++stats_.reductions;
        if (h.empty()) {
            ++stats_.zero_reductions;
            add_syzygy(target_index_, target_.data());
            continue;
        }
        if (layout_.is_one(h.monomial(0, w_))) {
            result.basis = {Polynomial::constant(ring, Rational(1))};
            result.stats = stats_;
            result.stats.reduction_steps = steps();
            return result;
        }
        const std::size_t bits = options.growth_bits != 0 ? largest_coefficient_bits(h) : 0;
        const bool grew_early = options.growth_bits != 0 && bits >= options.growth_bits &&
                                basis_.size() * options.growth_bits < options.growth_basis * bits;
        add_element(std::move(h));
        if (grew_early) {
            result.outcome = GroebnerOutcome::stopped_size;
            result.reason = "coefficients of " + std::to_string(bits) + " bits in a basis of " +
                            std::to_string(basis_.size()) + " elements";
            break;
        }
    }
    if (result.outcome != GroebnerOutcome::complete) {
        result = partial(std::move(result), ring);
    } else {
        for (const IntegerPolynomial& p :
             detail::interreduce(std::move(basis_), layout_, main.counts,
                                 steps() >= steps_before_batches ? threads : 1)) {
            result.basis.push_back(detail::to_monic_polynomial(p, ring));
        }
    }
    result.stats = stats_;
    result.stats.reduction_steps = steps();
    return result;
}

}  // namespace

GroebnerResult signature_groebner(std::span<const Polynomial> generators,
                                  const GroebnerOptions& options, SignatureOrder order,
                                  std::size_t steps_before_batches) {
    const auto start = std::chrono::steady_clock::now();
    GroebnerResult result;
    std::vector<IntegerPolynomial> inputs = detail::sorted_integer_generators(generators);
    if (!inputs.empty()) {
        const RingPtr& ring = generators[0].ring();
        const MonomialLayout& layout = ring->layout();
        if (layout.is_one(inputs.front().monomial(0, layout.words()))) {
            // A non-zero constant, the least monomial: the unit ideal.
            result.basis = {Polynomial::constant(ring, Rational(1))};
        } else {
            SignatureRun run(layout, order, std::move(inputs));
            result = run.run(options, ring, steps_before_batches);
        }
    }
    result.stats.algorithm = GroebnerAlgorithm::signature;
    result.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

GroebnerResult signature_groebner_or_buchberger(std::span<const Polynomial> generators,
                                                const GroebnerOptions& options) {
    try {
        return signature_groebner(generators, options);
    } catch (const ExponentOverflow&) {
        // A signature left the packed range (they can exceed the polynomials' degrees); Buchberger
        // needs only lcms of leading monomials.
        return buchberger(generators, options);
    }
}

}  // namespace locus::algebra
