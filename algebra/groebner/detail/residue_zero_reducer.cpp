#include "algebra/groebner/detail/residue_zero_reducer.h"
#include "algebra/deadline.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>

#include <flint/ulong_extras.h>

namespace locus::algebra::detail {

namespace lb = log_bound;

namespace {

constexpr std::size_t kLaneBits = 31;

// A fresh rebuild of the pending values every few steps is a sign that the lanes are too
// narrow: more lanes cost less than rebuilding.
constexpr std::size_t kRebuildsBeforeMoreLanes = 8;

// A GMP integer that clears itself, for the paths an exception can leave.
struct OwnedInteger {
    mpz_t value;
    OwnedInteger() { mpz_init(value); }
    ~OwnedInteger() { mpz_clear(value); }
    OwnedInteger(const OwnedInteger&) = delete;
    OwnedInteger& operator=(const OwnedInteger&) = delete;
};

// Eight lanes more (248 bits) while they are few, a quarter more past 64.
std::size_t next_lanes(std::size_t lanes) {
    return lanes < 64 ? lanes + 8 : (lanes + lanes / 4 + 7) / 8 * 8;
}

}  // namespace

std::size_t ResidueZeroReducer::initial_lanes(const std::vector<BasisElement>& basis) {
    std::size_t bits = 0;
    for (const BasisElement& e : basis) {
        for (const Integer& c : e.poly.coefficients) {
            bits = std::max<std::size_t>(bits, fmpz_bits(c.get()));
        }
    }
    const std::size_t digits = (bits + 64 + 2) / kLaneBits + 1;
    return (digits + 1 + 7) / 8 * 8;  // and the redundant lane
}

ResidueZeroReducer::ResidueZeroReducer(const MonomialLayout& layout,
                                       const std::vector<BasisElement>& basis, std::size_t lanes,
                                       bool learn)
    : layout_(layout), basis_(basis), elements_(basis.size()), table_(layout.words()) {
    search_.gather(basis, layout);
    for (std::size_t k = 0; k < basis.size(); ++k) {
        Element& e = elements_[k];
        mpz_init_set_ui(e.leading, 1);
        const IntegerPolynomial& g = basis[k].poly;
        if (!g.empty()) {
            fmpz_get_mpz(e.leading, g.coefficients[0].get());  // positive
            e.leading_lower = lb::lower(e.leading);
        }
        for (std::size_t j = 1; j < g.size(); ++j) {
            e.term_bounds.push_back(lb::upper(g.coefficients[j].get()));
            e.largest_term_bound = std::max(e.largest_term_bound, e.term_bounds.back());
        }
    }
    mpz_inits(gcd_, cofactor_, scratch_, nullptr);
    product_.resize(layout.words());
    multiplier_.resize(layout.words());
    for (std::size_t slot = 0; slot < lanes::kSlots; ++slot) {
        reductions_[slot].slot = slot;
    }
    first_lanes_ = lanes != 0 ? lanes : initial_lanes(basis);
    learn_ = learn;
    activate(first_lanes_);
}

ResidueZeroReducer::~ResidueZeroReducer() {
    for (Element& e : elements_) {
        mpz_clear(e.leading);
    }
    mpz_clears(gcd_, cofactor_, scratch_, nullptr);
}

std::unique_ptr<ResidueZeroReducer::Level> ResidueZeroReducer::make_level(std::size_t lanes) const {
    // Primes that divide a leading coefficient are skipped: every L must be invertible.
    const auto usable = [this](std::uint32_t p) {
        return std::none_of(elements_.begin(), elements_.end(),
                            [p](const Element& e) { return mpz_fdiv_ui(e.leading, p) == 0; });
    };
    auto level = std::make_unique<Level>();
    level->system = std::make_unique<ResidueSystem>(LanePrimes(lanes, usable));
    ResidueSystem& system = *level->system;
    const LanePrimes& primes = system.primes();
    level->elements.resize(basis_.size());
    for (std::size_t k = 0; k < basis_.size(); ++k) {
        ElementLanes& el = level->elements[k];
        const Element& e = elements_[k];
        el.minus_leading_inverse.resize(lanes);
        for (std::size_t l = 0; l < lanes; ++l) {
            const std::uint32_t p = primes.prime(l);
            const auto inverse = static_cast<std::uint32_t>(n_invmod(mpz_fdiv_ui(e.leading, p), p));
            el.minus_leading_inverse[l] = primes.to_montgomery(l, p - inverse);  // L⁻¹ ≠ 0
        }
        const IntegerPolynomial& g = basis_[k].poly;
        el.rows.resize(g.size() > 1 ? (g.size() - 1) * lanes : 0);
        for (std::size_t j = 1; j < g.size(); ++j) {
            system.residues(g.coefficients[j].get(), el.rows.data() + (j - 1) * lanes, false);
        }
        if (mpz_cmp_ui(e.leading, 1) != 0) {
            el.divisor = system.divisor(e.leading);
        }
    }
    level->one.resize(lanes);
    for (std::size_t l = 0; l < lanes; ++l) {
        level->one[l] = primes.to_montgomery(l, 1);
    }
    return level;
}

void ResidueZeroReducer::activate(std::size_t lanes) {
    std::unique_ptr<Level>& slot = levels_[lanes];
    if (!slot) {
        slot = make_level(lanes);
    }
    active_ = slot.get();
    // Columns numbered while another level was active; every value is zero between groups.
    level().values.resize(table_.size() * lanes::kSlots * lanes, 0);
    multipliers_.resize(lanes::kSlots * lanes);
    quotients_.resize(lanes::kSlots * lanes);
    digits_.resize(lanes);
    load_multiplier_.resize(lanes);
    load_quotients_.resize(lanes);
    statistics_.lanes = std::max(statistics_.lanes, lanes);
}

void ResidueZeroReducer::reset_lambda(Reduction& r) {
    r.lambda = level().one;
    r.lambda_digits.resize(lanes());
    lanes::multiply(r.lambda_digits.data(), r.lambda.data(), level().system->digit_factors(),
                    level().system->primes());
}

void ResidueZeroReducer::schedule(std::uint32_t c) {
    if (in_heap_[c] == 0) {
        in_heap_[c] = 1;
        heap_.push_back(c);
        std::push_heap(heap_.begin(), heap_.end(), by_rank());
    }
}

void ResidueZeroReducer::scale_lambda(Reduction& r, const std::uint32_t* factor) {
    const LanePrimes& primes = level().system->primes();
    lanes::multiply(r.lambda.data(), r.lambda.data(), factor, primes);
    lanes::multiply(r.lambda_digits.data(), r.lambda.data(), level().system->digit_factors(),
                    primes);
}

std::uint32_t ResidueZeroReducer::column(const std::uint64_t* m) {
    const std::uint32_t c = table_.insert(m);
    if (c == in_heap_.size()) {
        in_heap_.push_back(0);
        bound_.resize(bound_.size() + lanes::kSlots, lb::kZero);
        pending_.resize(pending_.size() + lanes::kSlots, 0);
        level().values.resize(level().values.size() + lanes::kSlots * lanes(), 0);
        reducer_rows_.add_column();
        rank_.push_back(0);
        const auto at = ordered_.insert(c).first;
        const std::uint64_t below = at == ordered_.begin() ? 0 : rank_[*std::prev(at)];
        const std::uint64_t above =
            std::next(at) == ordered_.end() ? UINT64_MAX : rank_[*std::next(at)];
        if (above - below >= 2) {
            rank_[c] = below + (above - below) / 2;
        } else {
            const std::uint64_t step = UINT64_MAX / (ordered_.size() + 1);
            std::uint64_t rank = 0;
            for (const std::uint32_t column : ordered_) {
                rank_[column] = rank += step;
            }
        }
    }
    return c;
}

std::int32_t ResidueZeroReducer::row_of(std::uint32_t c) {
    return reducer_rows_.row_of(c, table_, search_, layout_, basis_, multiplier_.data(),
                                product_.data(),
                                [this](const std::uint64_t* m) { return column(m); });
}

void ResidueZeroReducer::push(Reduction& r, std::uint32_t c) {
    if (pending(r, c) == 0) {
        pending(r, c) = 1;
        r.pending_columns.push_back(c);
        ++r.pending_count;
    }
    schedule(c);
}

void ResidueZeroReducer::compact_pending(Reduction& r) {
    // A column popped and made pending again is listed twice: marked 2 when first kept.
    std::size_t kept = 0;
    for (const std::uint32_t c : r.pending_columns) {
        if (pending(r, c) == 1) {
            pending(r, c) = 2;
            r.pending_columns[kept++] = c;
        }
    }
    r.pending_columns.resize(kept);
    for (const std::uint32_t c : r.pending_columns) {
        pending(r, c) = 1;
    }
}

bool ResidueZeroReducer::add_multiple(Reduction& r, const std::uint32_t* multiplier,
                                      lb::Units multiplier_bound, const std::uint64_t* m,
                                      const IntegerPolynomial& p, std::size_t from,
                                      const std::uint32_t* rows, const lb::Units* bounds) {
    const std::size_t w = layout_.words();
    touched_.clear();
    touched_bounds_.clear();
    for (std::size_t j = from; j < p.size(); ++j) {
        layout_.multiply(p.monomial(j, w), m, product_.data());
        const std::uint32_t c = column(product_.data());
        const lb::Units sum =
            lb::of_sum(true_bound(r, c), lb::of_product(multiplier_bound, bounds[j - from]));
        if (sum > level().system->capacity()) {
            r.needed = sum;
            return false;
        }
        touched_.push_back(c);
        touched_bounds_.push_back(sum);
    }
    const LanePrimes& primes = level().system->primes();
    lanes::shoup_quotients(load_quotients_.data(), multiplier, primes);
    const std::uint32_t first = 0;
    for (std::size_t t = 0; t < touched_.size(); ++t) {
        const std::uint32_t c = touched_[t];
        // One term at a time: the value's place is the slot's, not a plain table's.
        lanes::add_scaled_rows(value(r, c), &first, 1, rows + t * lanes(), multiplier,
                               load_quotients_.data(), primes);
        bound(r, c) = touched_bounds_[t] - r.offset;
        r.highest_bound = std::max(r.highest_bound, bound(r, c));
        push(r, c);
    }
    return true;
}

void ResidueZeroReducer::load(Reduction& r, const Job& job) {
    const std::size_t width = lanes();
    reset_lambda(r);
    r.factor.resize(width);
    r.offset = 0;
    r.highest_bound = lb::kZero;
    r.rebuilds = 0;
    r.just_rebuilt = false;
    r.steps = 0;
    r.state = Reduction::State::running;
    bool loaded = true;
    if (job.polynomial != nullptr) {
        const IntegerPolynomial& p = *job.polynomial;
        load_rows_.resize(p.size() * width);
        load_bounds_.resize(p.size());
        for (std::size_t j = 0; j < p.size(); ++j) {
            level().system->residues(p.coefficients[j].get(), load_rows_.data() + j * width, false);
            load_bounds_[j] = lb::upper(p.coefficients[j].get());
        }
        std::fill(load_multiplier_.begin(), load_multiplier_.end(), 1);
        std::fill(multiplier_.begin(), multiplier_.end(), 0);  // the monomial 1
        loaded = add_multiple(r, load_multiplier_.data(), 0, multiplier_.data(), p, 0,
                              load_rows_.data(), load_bounds_.data());
    } else {
        const std::size_t w = layout_.words();
        const IntegerPolynomial& f = basis_[job.first].poly;
        const IntegerPolynomial& g = basis_[job.second].poly;
        // s = a·mf·f − b·mg·g with a = lc(g)/d, b = lc(f)/d: the leading terms cancel.
        std::vector<std::uint64_t> mf(w), mg(w);
        layout_.divide(job.lcm, f.monomial(0, w), mf.data());
        layout_.divide(job.lcm, g.monomial(0, w), mg.data());
        OwnedInteger owned_a, owned_minus_b;
        mpz_ptr a = owned_a.value, minus_b = owned_minus_b.value;
        mpz_gcd(a, elements_[job.first].leading, elements_[job.second].leading);
        mpz_divexact(minus_b, elements_[job.first].leading, a);
        mpz_neg(minus_b, minus_b);
        mpz_divexact(a, elements_[job.second].leading, a);
        level().system->residues(a, load_multiplier_.data(), false);
        loaded = add_multiple(r, load_multiplier_.data(), lb::upper(a), mf.data(), f, 1,
                              level().elements[job.first].rows.data(),
                              elements_[job.first].term_bounds.data());
        if (loaded) {
            level().system->residues(minus_b, load_multiplier_.data(), false);
            loaded = add_multiple(r, load_multiplier_.data(), lb::upper(minus_b), mg.data(), g, 1,
                                  level().elements[job.second].rows.data(),
                                  elements_[job.second].term_bounds.data());
        }
    }
    if (!loaded) {
        finish(r, Reduction::State::exhausted);
    }
}

void ResidueZeroReducer::finish(Reduction& r, Reduction::State state) {
    for (const std::uint32_t c : r.pending_columns) {
        if (pending(r, c) != 0) {
            std::fill_n(value(r, c), lanes(), 0);
            bound(r, c) = lb::kZero;
            pending(r, c) = 0;
        }
    }
    r.pending_columns.clear();
    r.pending_count = 0;
    r.state = state;
}

void ResidueZeroReducer::abandon_group(std::size_t members) {
    for (std::size_t k = 0; k < members; ++k) {
        finish(reductions_[k], Reduction::State::not_zero);
    }
    for (const std::uint32_t c : heap_) {
        in_heap_[c] = 0;
    }
    heap_.clear();
}

void ResidueZeroReducer::rebuild_pending(Reduction& r, std::uint32_t lc) {
    ++statistics_.rebuilds;
    const LanePrimes& primes = level().system->primes();
    compact_pending(r);
    std::vector<std::uint32_t> columns(r.pending_columns);
    columns.push_back(lc);
    std::vector<OwnedInteger> values(columns.size());
    OwnedInteger owned_content;
    mpz_ptr content = owned_content.value;
    for (std::size_t h = 0; h < columns.size(); ++h) {
        lanes::multiply(digits_.data(), value(r, columns[h]), r.lambda_digits.data(), primes);
        level().system->reconstruct(digits_.data(), values[h].value);
        mpz_gcd(content, content, values[h].value);
    }
    if (mpz_cmp_ui(content, 1) > 0) {
        bool invertible = true;
        for (std::size_t l = 0; l < lanes(); ++l) {
            const std::uint32_t p = primes.prime(l);
            const ulong residue = mpz_fdiv_ui(content, p);
            invertible = invertible && residue != 0;
            r.factor[l] = residue == 0 ? 0
                                       : primes.to_montgomery(
                                             l, static_cast<std::uint32_t>(n_invmod(residue, p)));
        }
        for (OwnedInteger& v : values) {
            mpz_divexact(v.value, v.value, content);
        }
        if (invertible) {
            scale_lambda(r, r.factor.data());  // V/content = (Λ/content)·s
        } else {
            for (std::size_t h = 0; h < columns.size(); ++h) {
                level().system->residues(values[h].value, value(r, columns[h]), false);
            }
            reset_lambda(r);  // the residues are the values themselves now
        }
    }
    r.offset = 0;
    r.highest_bound = lb::kZero;
    for (std::size_t h = 0; h < columns.size(); ++h) {
        bound(r, columns[h]) = lb::upper(values[h].value);
        r.highest_bound = std::max(r.highest_bound, bound(r, columns[h]));
    }
}

bool ResidueZeroReducer::prepare_step(Reduction& r, std::uint32_t c, const ReducerRows::Row& row) {
    const LanePrimes& primes = level().system->primes();
    const Element& e = elements_[row.element];
    const ElementLanes& el = level().elements[row.element];
    const std::size_t length = basis_[row.element].poly.size() - 1;
    const std::uint32_t* columns = reducer_rows_.columns_of(row);
    const lb::Units capacity = level().system->capacity();
    for (;;) {
        const std::uint32_t* s = value(r, c);
        // g = gcd(V, L) for the fraction-free value V = Λ·s of the leading coefficient, from
        // V mod L; a = L/g multiplies p (and Λ) when g ≠ L.
        lb::Units gcd_lower = 0;
        bool scaled = false;
        if (el.divisor) {
            lanes::multiply(digits_.data(), s, r.lambda_digits.data(), primes);
            remainder_.resize(el.divisor->limbs.size());
            level().system->remainder(digits_.data(), *el.divisor, remainder_.data());
            if (std::all_of(remainder_.begin(), remainder_.end(),
                            [](mp_limb_t x) { return x == 0; })) {
                gcd_lower = e.leading_lower;
            } else {
                mpz_set_ui(scratch_, 0);
                std::copy(remainder_.begin(), remainder_.end(),
                          mpz_limbs_write(scratch_, static_cast<mp_size_t>(remainder_.size())));
                mpz_limbs_finish(scratch_, static_cast<mp_size_t>(remainder_.size()));
                mpz_gcd(gcd_, scratch_, e.leading);
                mpz_divexact(cofactor_, e.leading, gcd_);
                gcd_lower = mpz_cmp_ui(gcd_, 1) == 0 ? 0 : lb::lower(gcd_);
                scaled = true;
            }
        }
        // The bounds after a·p − b·m·g, b = V/g, checked before anything changes.
        const lb::Units b_bound = true_bound(r, c) - gcd_lower;
        const lb::Units offset = scaled ? r.offset + lb::upper(cofactor_) : r.offset;
        // Bounds relative to the new offset (those of bound_ are: multiplying by a moves only
        // the offset). Every new bound is at most the sum of the highest pending one and the
        // largest product; when that fits, the step goes ahead and the bounds are computed
        // with the pushes, in one pass after the kernel. Otherwise each is computed first.
        const lb::Units relative_b = b_bound - offset, limit = capacity - offset;
        const bool surely_fits =
            lb::of_sum(r.highest_bound, relative_b + e.largest_term_bound) <= limit;
        if (!surely_fits) {
            bool fits = !scaled || r.highest_bound <= limit;
            lb::Units highest = lb::kZero;
            for (std::size_t t = 0; t < length; ++t) {
                highest = std::max(highest,
                                   lb::of_sum(bound(r, columns[t]), relative_b + e.term_bounds[t]));
            }
            fits = fits && highest <= limit;
            if (!fits) {
                if (r.just_rebuilt || r.rebuilds == kRebuildsBeforeMoreLanes) {
                    std::fill_n(value(r, c), lanes(), 0);
                    bound(r, c) = lb::kZero;
                    r.needed = std::max(scaled ? r.highest_bound : lb::kZero, highest) + r.offset;
                    finish(r, Reduction::State::exhausted);
                    return false;
                }
                rebuild_pending(r, c);
                ++r.rebuilds;
                r.just_rebuilt = true;
                continue;  // the same step on the rebuilt values
            }
        }
        r.just_rebuilt = false;
        // In residues: s ← s − (s_c/L)·m·g.
        std::uint32_t* multiplier = multipliers_.data() + r.slot * lanes();
        lanes::multiply(multiplier, s, el.minus_leading_inverse.data(), primes);
        lanes::shoup_quotients(quotients_.data() + r.slot * lanes(), multiplier, primes);
        r.scaled = scaled;
        if (scaled) {
            level().system->residues(cofactor_, r.factor.data(), true);
        }
        r.step_offset = offset;
        r.relative_b = relative_b;
        return true;
    }
}

void ResidueZeroReducer::make_steps(std::span<Reduction* const> taking, std::uint32_t c,
                                    const ReducerRows::Row& row) {
    const Element& e = elements_[row.element];
    const ElementLanes& el = level().elements[row.element];
    const std::size_t length = basis_[row.element].poly.size() - 1;
    unsigned slots = 0;
    for (Reduction* r : taking) {
        std::fill_n(value(*r, c), lanes(), 0);
        bound(*r, c) = lb::kZero;
        if (r->scaled) {
            r->offset = r->step_offset;
            scale_lambda(*r, r->factor.data());
        }
        slots |= 1u << r->slot;
        slot_offsets_[r->slot] = r->relative_b;
        slot_highest_[r->slot] = r->highest_bound;
        fresh_counts_[r->slot] = 0;
    }
    if (fresh_.size() < lanes::kSlots * length) {
        fresh_.resize(lanes::kSlots * length);  // grown only
    }
    // The residues and the bounds of every slot in one pass over the terms.
    lanes::SlotBounds bounds{bound_.data(),       e.term_bounds.data(), slot_offsets_.data(),
                             pending_.data(),     fresh_.data(),        fresh_counts_.data(),
                             slot_highest_.data()};
    lanes::add_scaled_rows_together(level().values.data(), reducer_rows_.columns_of(row), length,
                                    el.rows.data(), slots, multipliers_.data(), quotients_.data(),
                                    level().system->primes(), bounds);
    for (Reduction* r : taking) {
        r->highest_bound = slot_highest_[r->slot];
        const std::uint32_t* fresh = fresh_.data() + r->slot * length;
        for (std::size_t k = 0; k < fresh_counts_[r->slot]; ++k) {
            r->pending_columns.push_back(fresh[k]);
            schedule(fresh[k]);
        }
        r->pending_count += fresh_counts_[r->slot];
        ++r->steps;
    }
    statistics_.reducer_terms += length * taking.size();
    statistics_.lane_terms += length * taking.size() * lanes();
    statistics_.row_terms += length;
}

void ResidueZeroReducer::run_group(std::span<const Job> jobs, std::span<const std::size_t> members,
                                   std::size_t lanes) {
    activate(lanes);
    for (std::size_t k = 0; k < members.size(); ++k) {
        load(reductions_[k], jobs[members[k]]);
    }
    std::size_t rounds = 0;
    try {
        while (!heap_.empty()) {
            std::pop_heap(heap_.begin(), heap_.end(), by_rank());
            const std::uint32_t c = heap_.back();
            heap_.pop_back();
            in_heap_[c] = 0;
            taking_.clear();
            for (std::size_t k = 0; k < members.size(); ++k) {
                Reduction& r = reductions_[k];
                if (r.state != Reduction::State::running || pending(r, c) == 0) {
                    continue;
                }
                pending(r, c) = 0;
                --r.pending_count;
                if (lanes::is_zero(value(r, c), lanes)) {
                    bound(r, c) = lb::kZero;
                } else {
                    taking_.push_back(&r);
                }
                if (r.pending_columns.size() > 2 * r.pending_count + 64) {
                    compact_pending(r);
                }
            }
            if (taking_.empty()) {
                continue;
            }
            const std::int32_t index = row_of(c);  // may number new columns: values may move
            if (index == ReducerRows::kIrreducible) {
                for (Reduction* r : taking_) {
                    std::fill_n(value(*r, c), lanes, 0);
                    bound(*r, c) = lb::kZero;
                    finish(*r, Reduction::State::not_zero);
                }
                continue;
            }
            const ReducerRows::Row row = reducer_rows_.row(index);
            // Those whose step does not fit even after a rebuild leave the group.
            std::size_t ready = 0;
            for (Reduction* r : taking_) {
                if (prepare_step(*r, c, row)) {
                    taking_[ready++] = r;
                }
            }
            taking_.resize(ready);
            if (!taking_.empty()) {
                make_steps(taking_, c, row);
            }
            if (++rounds % 16 == 0 && deadline_passed(deadline_)) {
                throw ReductionInterrupted{};
            }
        }
    } catch (...) {
        abandon_group(members.size());
        throw;
    }
    for (std::size_t k = 0; k < members.size(); ++k) {
        Reduction& r = reductions_[k];
        if (r.state == Reduction::State::running) {
            r.pending_columns.clear();  // every one was popped: none is pending
            r.pending_count = 0;
            r.state = Reduction::State::zero;
        }
    }
}

ResidueZeroReducer::Start& ResidueZeroReducer::start_of(std::uint32_t degree) {
    // A degree not seen yet starts where the degree below it does (values grow with degree).
    Start& start = starts_[degree];
    if (start.lanes == 0) {
        const auto below = starts_.find(degree);
        start.lanes = below == starts_.begin() ? first_lanes_ : std::prev(below)->second.lanes;
    }
    return start;
}

std::uint32_t ResidueZeroReducer::degree_of(const Job& job) const {
    if (job.polynomial != nullptr) {
        return job.polynomial->empty()
                   ? 0
                   : layout_.total_degree(job.polynomial->monomial(0, layout_.words()));
    }
    return layout_.total_degree(job.lcm);
}

void ResidueZeroReducer::reduce_together(std::span<const Job> jobs, std::span<Verdict> verdicts,
                                         std::span<ReductionCounts> counts) {
    // Reductions begin on the fewest lanes that most of those of their degree fit: narrower
    // lanes are read faster, and a reduction that outgrows them starts again on more. When a
    // quarter of those begun on a degree's lanes have had to, the degree's start moves up. A
    // group begins on the widest start of its jobs' degrees.
    if (jobs.size() > lanes::kSlots || verdicts.size() != jobs.size() ||
        counts.size() != jobs.size()) {
        throw std::invalid_argument(
            "ResidueZeroReducer::reduce_together: at most kSlots jobs, "
            "a verdict and a count for each");
    }
    std::vector<std::size_t> members;
    std::size_t lanes = 0;
    for (std::size_t k = 0; k < jobs.size(); ++k) {
        if (jobs[k].polynomial != nullptr && jobs[k].polynomial->empty()) {
            verdicts[k] = Verdict::zero;
            continue;
        }
        members.push_back(k);
        lanes = std::max(lanes, start_of(degree_of(jobs[k])).lanes);
    }
    if (members.empty()) {
        return;
    }
    run_group(jobs, members, lanes);
    // Outcomes in order, each exhausted one begun again alone on more lanes.
    std::vector<Reduction::State> states(members.size());
    std::vector<log_bound::Units> needed(members.size());
    std::vector<std::size_t> steps(members.size());
    for (std::size_t m = 0; m < members.size(); ++m) {
        states[m] = reductions_[m].state;
        needed[m] = reductions_[m].needed;
        steps[m] = reductions_[m].steps;
    }
    for (std::size_t m = 0; m < members.size(); ++m) {
        const std::size_t k = members[m];
        std::size_t at = lanes;
        bool restarted = false;
        while (states[m] == Reduction::State::exhausted) {
            ++statistics_.restarts;
            restarted = true;
            // Room for half as much again as the bound that did not fit: values that outgrew
            // one level tend to keep growing, and every start again repeats the work.
            const auto bits =
                static_cast<std::size_t>(std::max<lb::Units>(0, needed[m]) / lb::kPerBit);
            std::size_t wanted = next_lanes(at);
            while ((wanted - 1) * kLaneBits < bits + bits / 2 + 3) {
                wanted = next_lanes(wanted);
            }
            if (wanted > kMostLanes) {
                break;
            }
            const auto existing = levels_.lower_bound(wanted);
            at = existing != levels_.end() ? existing->first : wanted;
            const std::size_t alone[] = {k};
            run_group(jobs, alone, at);
            states[m] = reductions_[0].state;
            needed[m] = reductions_[0].needed;
            steps[m] = reductions_[0].steps;
        }
        if (states[m] == Reduction::State::exhausted) {
            verdicts[k] = Verdict::too_wide;
            continue;
        }
        verdicts[k] = states[m] == Reduction::State::zero ? Verdict::zero : Verdict::not_zero;
        counts[k].steps += steps[m];
        Start& start = start_of(degree_of(jobs[k]));
        ++start.begun;
        start.outgrown += restarted ? 1 : 0;
        if (learn_ && start.begun >= 4 && 4 * start.outgrown > start.begun) {
            const auto above = levels_.upper_bound(start.lanes);
            start = {above != levels_.end() ? above->first : next_lanes(start.lanes), 0, 0};
        }
    }
}

}  // namespace locus::algebra::detail
