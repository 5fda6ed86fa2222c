// The rewrite-based signature algorithm (signature_groebner.h; Eder–Faugère's survey, JSC 80,
// 2017, Algorithm 3 "RB" with the add-order rewriter).
//
// A signature is held as its index i, its monomial t and its comparison monomial: t·lm(fᵢ) under
// the Schreyer order, t itself under position-over-term. Multiplying a signature by a monomial
// multiplies both monomials, so the regularity test of a reduction step (is m·sig(g) below the
// signature being reduced?) is one packed multiplication and one comparison.
//
// The loop takes the least queued signature T and all the S-pairs that reach it:
//   1. T is skipped when the monomial of a known syzygy signature of the same index divides it
//      (the syzygy criterion: Koszul syzygies of basis elements, and earlier reductions to zero);
//   2. T is skipped unless the newest basis element whose signature divides T is among the
//      elements that reached it (the rewrite criterion; Eder–Roune prove this terminates and
//      leaves a signature Gröbner basis);
//   3. otherwise (T / sig(g))·g for that element g, or the generator itself when T = eᵢ, is
//      reduced by regular reductions only, leading and tail terms alike. Zero makes T a syzygy
//      signature; anything else joins the basis with signature T, and its S-pairs and Koszul
//      syzygies with every older element are formed.
// The S-polynomial is never formed as such: the first regular reduction of (T / sig(g))·g is by
// the pair's other element, which is what the S-polynomial would have been.
#include "algebra/groebner/signature_groebner.h"

#include <algorithm>
#include <chrono>
#include <limits>

#include "algebra/error.h"
#include "algebra/groebner/reduction.h"

namespace locus::algebra {
namespace {

using detail::BasisElement;
using detail::IntegerPolynomial;

// The generator of the signature eᵢ: the input polynomial itself, not a basis element.
constexpr std::uint32_t kInput = std::numeric_limits<std::uint32_t>::max();

// An S-pair waiting in the queue: its signature (index, and `slot` in the run's pool of pair
// monomials: t then the comparison monomial) and the basis element whose multiple reaches it.
struct QueuedPair {
    std::uint32_t index;
    std::uint32_t generator;
    std::uint32_t slot;
};

class SignatureRun final : public detail::ReducerAdmission {
  public:
    SignatureRun(const MonomialLayout& layout, SignatureOrder order,
                 std::vector<IntegerPolynomial> generators)
        : layout_(layout),
          w_(layout.words()),
          order_(order),
          generators_(std::move(generators)),
          elements_of_index_(generators_.size()),
          syzygies_(generators_.size()),
          reducer_(layout),
          product_(w_),
          target_(2 * w_),
          candidate_(2 * w_),
          other_(2 * w_),
          lcm_(w_),
          multiplier_(w_) {}

    // The whole computation; the basis is written in `ring`.
    GroebnerResult run(const GroebnerOptions& options, const RingPtr& ring);

    // Regular reductions only: m·sig(basis[element]) must lie below the signature reduced.
    bool admits(std::size_t element, const std::uint64_t* multiplier) const override {
        layout_.multiply(multiplier, key_of(element), product_.data());
        return compare(index_[element], product_.data(), target_index_, target_.data() + w_) < 0;
    }

  private:
    // Signature monomials of basis element e: t, then the comparison monomial.
    const std::uint64_t* t_of(std::size_t e) const {
        return element_signatures_.data() + 2 * w_ * e;
    }
    const std::uint64_t* key_of(std::size_t e) const { return t_of(e) + w_; }
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
    // The newest element with signature index `index` whose signature monomial divides t.
    std::optional<std::uint32_t> rewriter(std::uint32_t index, const std::uint64_t* t) const;
    // Queues the signature (index, sig = t then key) reached from `generator`.
    void push(std::uint32_t index, const std::uint64_t* sig, std::uint32_t generator);
    QueuedPair pop();
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

    // The queue: a binary heap, least signature first; pair monomials live in slots of a pool.
    std::vector<QueuedPair> heap_;
    std::vector<std::uint64_t> pair_signatures_;
    std::vector<std::uint32_t> free_slots_;

    detail::Reducer reducer_;
    detail::ReductionCounts reduction_;
    GroebnerStats stats_;

    // The signature being reduced (admits() compares against it) and scratch monomials.
    std::uint32_t target_index_ = 0;
    mutable std::vector<std::uint64_t> product_;
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
        if (!layout_.divides(t, s.monomials.data() + k * w_)) {
            std::copy_n(s.monomials.data() + k * w_, w_, s.monomials.data() + kept * w_);
            s.masks[kept] = s.masks[k];
            ++kept;
        }
    }
    s.monomials.resize(kept * w_);
    s.masks.resize(kept);
    s.monomials.insert(s.monomials.end(), t, t + w_);
    s.masks.push_back(layout_.divisibility_mask(t));
}

std::optional<std::uint32_t> SignatureRun::rewriter(std::uint32_t index,
                                                    const std::uint64_t* t) const {
    const std::uint64_t mask = layout_.divisibility_mask(t);
    const std::vector<std::uint32_t>& elements = elements_of_index_[index];
    for (auto e = elements.rbegin(); e != elements.rend(); ++e) {
        if ((element_masks_[*e] & ~mask) == 0 && layout_.divides(t_of(*e), t)) {
            return *e;
        }
    }
    return std::nullopt;
}

void SignatureRun::push(std::uint32_t index, const std::uint64_t* sig, std::uint32_t generator) {
    std::uint32_t slot;
    if (!free_slots_.empty()) {
        slot = free_slots_.back();
        free_slots_.pop_back();
    } else {
        slot = static_cast<std::uint32_t>(pair_signatures_.size() / (2 * w_));
        pair_signatures_.resize(pair_signatures_.size() + 2 * w_);
    }
    std::copy_n(sig, 2 * w_, pair_signatures_.data() + 2 * w_ * slot);
    heap_.push_back({index, generator, slot});
    std::push_heap(heap_.begin(), heap_.end(), [this](const QueuedPair& a, const QueuedPair& b) {
        return compare(a.index, pair_key(a), b.index, pair_key(b)) > 0;
    });
}

QueuedPair SignatureRun::pop() {
    std::pop_heap(heap_.begin(), heap_.end(), [this](const QueuedPair& a, const QueuedPair& b) {
        return compare(a.index, pair_key(a), b.index, pair_key(b)) > 0;
    });
    const QueuedPair p = heap_.back();
    heap_.pop_back();
    free_slots_.push_back(p.slot);
    return p;
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

void SignatureRun::add_element(IntegerPolynomial h) {
    const auto n = static_cast<std::uint32_t>(basis_.size());
    const std::uint64_t* lm_h = h.monomial(0, w_);
    // target_ holds the new element's signature (t, key).
    for (std::uint32_t j = 0; j < n; ++j) {
        const std::uint64_t* lm_j = basis_[j].poly.monomial(0, w_);
        // Koszul syzygy lm(gⱼ)·h − lm(h)·gⱼ: its signature is the larger of lm(gⱼ)·sig(h) and
        // lm(h)·sig(gⱼ).
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
        // The S-pair: the larger of (lcm/lm(h))·sig(h) and (lcm/lm(gⱼ))·sig(gⱼ), reached from its
        // element; equal signatures cancel (a singular pair, not needed).
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
        const bool from_h = c > 0;
        const std::uint32_t index = from_h ? target_index_ : index_[j];
        const std::uint64_t* sig = from_h ? candidate_.data() : other_.data();
        if (is_syzygy(index, sig)) {
            ++stats_.removed_by_syzygy;
            continue;
        }
        push(index, sig, from_h ? n : j);
    }
    h.leading_mask = layout_.divisibility_mask(lm_h);
    basis_.push_back({std::move(h), false});
    index_.push_back(target_index_);
    element_signatures_.insert(element_signatures_.end(), target_.begin(), target_.end());
    element_masks_.push_back(layout_.divisibility_mask(target_.data()));
    elements_of_index_[target_index_].push_back(n);
    stats_.max_basis_size = std::max(stats_.max_basis_size, basis_.size());
}

GroebnerResult SignatureRun::partial(GroebnerResult result, const RingPtr& ring) const {
    // Every element so far and every generator: they generate the ideal, whatever was left.
    for (const BasisElement& e : basis_) {
        result.basis.push_back(detail::to_monic_polynomial(e.poly, ring));
    }
    for (const IntegerPolynomial& f : generators_) {
        result.basis.push_back(detail::to_monic_polynomial(f, ring));
    }
    std::sort(result.basis.begin(), result.basis.end(),
              [&](const Polynomial& a, const Polynomial& b) {
                  return layout_.compare(a.leading_monomial(), b.leading_monomial()) < 0;
              });
    return result;
}

GroebnerResult SignatureRun::run(const GroebnerOptions& options, const RingPtr& ring) {
    GroebnerResult result;
    // The generators' own signatures eᵢ.
    for (std::uint32_t i = 0; i < generators_.size(); ++i) {
        std::fill(target_.begin(), target_.begin() + static_cast<long>(w_), 0);
        comparison_monomial(i, target_.data(), target_.data() + w_);
        push(i, target_.data(), kInput);
    }
    std::vector<std::uint32_t> reached_from;
    std::size_t signatures_done = 0;
    while (!heap_.empty()) {
        if (options.deadline && std::chrono::steady_clock::now() > *options.deadline) {
            result.outcome = GroebnerOutcome::stopped_timeout;
            break;
        }
        if (options.max_basis_size != 0 && basis_.size() > options.max_basis_size) {
            result.outcome = GroebnerOutcome::stopped_size;
            break;
        }
        // The least signature and every element that reaches it.
        const QueuedPair first = pop();
        target_index_ = first.index;
        std::copy_n(pair_t(first), 2 * w_, target_.data());
        reached_from.assign(1, first.generator);
        while (!heap_.empty() && compare(heap_.front().index, pair_key(heap_.front()),
                                         target_index_, target_.data() + w_) == 0) {
            reached_from.push_back(pop().generator);
        }
        ++signatures_done;
        if (options.progress) {
            options.progress({signatures_done, heap_.size(), basis_.size(),
                              layout_.leading_weight(target_.data() + w_)});
        }
        if (is_syzygy(target_index_, target_.data())) {
            stats_.removed_by_syzygy += reached_from.size();
            continue;
        }
        const std::optional<std::uint32_t> g = rewriter(target_index_, target_.data());
        const std::uint32_t wanted = g ? *g : kInput;
        if (std::find(reached_from.begin(), reached_from.end(), wanted) == reached_from.end()) {
            stats_.removed_by_rewriting += reached_from.size();
            continue;
        }
        stats_.removed_by_rewriting += reached_from.size() - 1;
        IntegerPolynomial p;
        if (g) {
            layout_.divide(target_.data(), t_of(*g), multiplier_.data());
            p = multiple(multiplier_.data(), basis_[*g].poly);
        } else {
            p = generators_[target_index_];
        }
        IntegerPolynomial h;
        try {
            h = reducer_.reduce(std::move(p), basis_, reduction_, /*tail=*/true, this);
        } catch (const detail::ReductionInterrupted&) {
            result.outcome = GroebnerOutcome::stopped_timeout;
            break;
        }
        ++stats_.reductions;
        if (h.empty()) {
            ++stats_.zero_reductions;
            add_syzygy(target_index_, target_.data());
            continue;
        }
        if (layout_.is_one(h.monomial(0, w_))) {
            result.basis = {Polynomial::constant(ring, Rational(1))};
            result.stats = stats_;
            result.stats.reduction_steps = reduction_.steps;
            return result;
        }
        add_element(std::move(h));
    }
    if (result.outcome != GroebnerOutcome::complete) {
        result = partial(std::move(result), ring);
    } else {
        for (const IntegerPolynomial& p :
             detail::interreduce(std::move(basis_), layout_, reduction_)) {
            result.basis.push_back(detail::to_monic_polynomial(p, ring));
        }
    }
    result.stats = stats_;
    result.stats.reduction_steps = reduction_.steps;
    return result;
}

}  // namespace

GroebnerResult signature_groebner(std::span<const Polynomial> generators,
                                  const GroebnerOptions& options, SignatureOrder order) {
    const auto start = std::chrono::steady_clock::now();
    GroebnerResult result;
    if (generators.empty()) {
        return result;
    }
    const RingPtr& ring = generators[0].ring();
    for (const auto& g : generators) {
        require_same_ring(generators[0], g);
    }
    const MonomialLayout& layout = ring->layout();
    const std::size_t w = layout.words();
    std::vector<IntegerPolynomial> inputs;
    for (const auto& g : generators) {
        if (g.is_zero()) {
            continue;
        }
        if (layout.is_one(g.leading_monomial())) {
            result.basis = {Polynomial::constant(ring, Rational(1))};
            return result;
        }
        inputs.push_back(detail::to_integer_polynomial(g));
    }
    std::sort(inputs.begin(), inputs.end(),
              [&](const IntegerPolynomial& a, const IntegerPolynomial& b) {
                  return layout.compare(a.monomial(0, w), b.monomial(0, w)) < 0;
              });
    SignatureRun run(layout, order, std::move(inputs));
    result = run.run(options, ring);
    result.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace locus::algebra
