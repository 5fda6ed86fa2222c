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
        el.leading_inverse.resize(lanes);
        for (std::size_t l = 0; l < lanes; ++l) {
            const std::uint32_t p = primes.prime(l);
            const auto inverse = static_cast<std::uint32_t>(n_invmod(mpz_fdiv_ui(e.leading, p), p));
            el.leading_inverse[l] = primes.to_montgomery(l, inverse);
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
    return level;
}

void ResidueZeroReducer::activate(std::size_t lanes) {
    std::unique_ptr<Level>& slot = levels_[lanes];
    if (!slot) {
        slot = make_level(lanes);
    }
    active_ = slot.get();
    // Columns numbered while another level was active; every column is zero between reductions.
    level().values.resize(table_.size() * lanes, 0);
    lambda_.resize(lanes);
    lambda_digits_.resize(lanes);
    multiplier_lanes_.resize(lanes);
    digits_.resize(lanes);
    factor_.resize(lanes);
    quotients_.resize(lanes);
    statistics_.lanes = std::max(statistics_.lanes, lanes);
}

void ResidueZeroReducer::begin() {
    const LanePrimes& primes = level().system->primes();
    for (std::size_t l = 0; l < lanes(); ++l) {
        lambda_[l] = primes.to_montgomery(l, 1);
    }
    lanes::multiply(lambda_digits_.data(), lambda_.data(), level().system->digit_factors(), primes);
    offset_ = 0;
    highest_bound_ = lb::kZero;
}

void ResidueZeroReducer::scale_lambda(const std::uint32_t* factor) {
    const LanePrimes& primes = level().system->primes();
    lanes::multiply(lambda_.data(), lambda_.data(), factor, primes);
    lanes::multiply(lambda_digits_.data(), lambda_.data(), level().system->digit_factors(), primes);
}

lb::Units ResidueZeroReducer::true_bound(std::uint32_t c) const {
    return bound_[c] + offset_;
}

void ResidueZeroReducer::set_true_bound(std::uint32_t c, lb::Units bound) {
    bound_[c] = bound - offset_;
    highest_bound_ = std::max(highest_bound_, bound_[c]);
}

std::uint32_t ResidueZeroReducer::column(const std::uint64_t* m) {
    const std::uint32_t c = table_.insert(m);
    if (c == bound_.size()) {
        level().values.resize(level().values.size() + lanes(), 0);
        bound_.push_back(lb::kZero);
        pending_.push_back(0);
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

void ResidueZeroReducer::push(std::uint32_t c) {
    if (pending_[c] == 0) {
        pending_[c] = 1;
        heap_.push_back(c);
        std::push_heap(heap_.begin(), heap_.end(),
                       [this](std::uint32_t x, std::uint32_t y) { return rank_[x] < rank_[y]; });
    }
}

void ResidueZeroReducer::add_multiple(const std::uint32_t* multiplier, lb::Units multiplier_bound,
                                      const std::uint64_t* m, const IntegerPolynomial& p,
                                      std::size_t from, const std::uint32_t* rows,
                                      const lb::Units* bounds) {
    const std::size_t w = layout_.words();
    touched_.clear();
    touched_bounds_.clear();
    for (std::size_t j = from; j < p.size(); ++j) {
        layout_.multiply(p.monomial(j, w), m, product_.data());
        const std::uint32_t c = column(product_.data());
        const lb::Units bound =
            lb::of_sum(true_bound(c), lb::of_product(multiplier_bound, bounds[j - from]));
        if (bound > level().system->capacity()) {
            throw LanesExhausted{bound};
        }
        touched_.push_back(c);
        touched_bounds_.push_back(bound);
    }
    lanes::shoup_quotients(quotients_.data(), multiplier, level().system->primes());
    lanes::add_scaled_rows(level().values.data(), touched_.data(), touched_.size(), rows,
                           multiplier, quotients_.data(), level().system->primes());
    for (std::size_t t = 0; t < touched_.size(); ++t) {
        set_true_bound(touched_[t], touched_bounds_[t]);
        push(touched_[t]);
    }
}

void ResidueZeroReducer::clear_pending() {
    for (const std::uint32_t c : heap_) {
        std::fill_n(value(c), lanes(), 0);
        bound_[c] = lb::kZero;
        pending_[c] = 0;
    }
    heap_.clear();
}

void ResidueZeroReducer::rebuild_pending(std::uint32_t lc) {
    ++statistics_.rebuilds;
    const LanePrimes& primes = level().system->primes();
    std::vector<std::uint32_t> columns(heap_);
    columns.push_back(lc);
    std::vector<OwnedInteger> values(columns.size());
    OwnedInteger owned_content;
    mpz_ptr content = owned_content.value;
    for (std::size_t h = 0; h < columns.size(); ++h) {
        lanes::multiply(digits_.data(), value(columns[h]), lambda_digits_.data(), primes);
        level().system->reconstruct(digits_.data(), values[h].value);
        mpz_gcd(content, content, values[h].value);
    }
    if (mpz_cmp_ui(content, 1) > 0) {
        bool invertible = true;
        for (std::size_t l = 0; l < lanes(); ++l) {
            const std::uint32_t p = primes.prime(l);
            const ulong residue = mpz_fdiv_ui(content, p);
            invertible = invertible && residue != 0;
            factor_[l] = residue == 0 ? 0
                                      : primes.to_montgomery(
                                            l, static_cast<std::uint32_t>(n_invmod(residue, p)));
        }
        for (OwnedInteger& v : values) {
            mpz_divexact(v.value, v.value, content);
        }
        if (invertible) {
            scale_lambda(factor_.data());  // V/content = (Λ/content)·s
        } else {
            for (std::size_t h = 0; h < columns.size(); ++h) {
                level().system->residues(values[h].value, value(columns[h]), false);
            }
            begin();  // Λ = 1: the residues are the values themselves now
        }
    }
    offset_ = 0;
    highest_bound_ = lb::kZero;
    for (std::size_t h = 0; h < columns.size(); ++h) {
        bound_[columns[h]] = lb::upper(values[h].value);
        highest_bound_ = std::max(highest_bound_, bound_[columns[h]]);
    }
}

bool ResidueZeroReducer::reduce_loaded(ReductionCounts& counts) {
    const auto descending = [this](std::uint32_t x, std::uint32_t y) {
        return rank_[x] < rank_[y];
    };
    const LanePrimes& primes = level().system->primes();
    const std::size_t width = lanes();
    std::size_t rebuilds = 0;
    bool just_rebuilt = false;
    while (!heap_.empty()) {
        std::pop_heap(heap_.begin(), heap_.end(), descending);
        const std::uint32_t c = heap_.back();
        heap_.pop_back();
        pending_[c] = 0;
        if (lanes::is_zero(value(c), width)) {
            bound_[c] = lb::kZero;
            continue;
        }
        const std::int32_t r = row_of(c);  // may number new columns: values_ may move
        if (r == ReducerRows::kIrreducible) {
            std::fill_n(value(c), width, 0);
            bound_[c] = lb::kZero;
            clear_pending();
            return false;
        }
        const ReducerRows::Row row = reducer_rows_.row(r);
        const Element& e = elements_[row.element];
        const ElementLanes& el = level().elements[row.element];
        const std::uint32_t* s = value(c);

        // g = gcd(V, L) for the fraction-free value V = Λ·s of the leading coefficient, from
        // V mod L; a = L/g multiplies p (and Λ) when g ≠ L.
        lb::Units gcd_lower = 0;
        bool scaled = false;
        if (el.divisor) {
            lanes::multiply(digits_.data(), s, lambda_digits_.data(), primes);
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
        const lb::Units b_bound = true_bound(c) - gcd_lower;
        const lb::Units offset = scaled ? offset_ + lb::upper(cofactor_) : offset_;
        const std::size_t length = basis_[row.element].poly.size() - 1;
        const std::uint32_t* columns = reducer_rows_.columns_of(row);
        const lb::Units capacity = level().system->capacity();
        // Bounds relative to the new offset (those of bound_ are: multiplying by a moves only
        // the offset). Every new bound is at most the sum of the highest pending one and the
        // largest product; when that fits, the step goes ahead and the bounds are computed
        // with the pushes, in one pass after the kernel. Otherwise each is computed first.
        const lb::Units relative_b = b_bound - offset, limit = capacity - offset;
        const bool surely_fits =
            lb::of_sum(highest_bound_, relative_b + e.largest_term_bound) <= limit;
        if (!surely_fits) {
            bool fits = !scaled || highest_bound_ <= limit;
            lb::Units highest = lb::kZero;
            for (std::size_t t = 0; t < length; ++t) {
                highest = std::max(highest,
                                   lb::of_sum(bound_[columns[t]], relative_b + e.term_bounds[t]));
            }
            fits = fits && highest <= limit;
            if (!fits) {
                if (just_rebuilt || rebuilds == kRebuildsBeforeMoreLanes) {
                    std::fill_n(value(c), width, 0);
                    bound_[c] = lb::kZero;
                    throw LanesExhausted{std::max(scaled ? highest_bound_ : lb::kZero, highest) +
                                         offset};
                }
                rebuild_pending(c);
                ++rebuilds;
                just_rebuilt = true;
                push(c);
                continue;
            }
        }
        just_rebuilt = false;

        // In residues: s ← s − (s_c/L)·m·g.
        lanes::multiply(multiplier_lanes_.data(), s, el.leading_inverse.data(), primes);
        lanes::negate(multiplier_lanes_.data(), primes);
        std::fill_n(value(c), width, 0);
        bound_[c] = lb::kZero;
        if (scaled) {
            offset_ = offset;
            level().system->residues(cofactor_, factor_.data(), true);
            scale_lambda(factor_.data());
        }
        lanes::shoup_quotients(quotients_.data(), multiplier_lanes_.data(), primes);
        // The residues and the bounds in one pass over the terms.
        if (fresh_.size() < length) {
            fresh_.resize(length);  // grown only: a resize per step zero-filled what it regrew
        }
        lanes::ColumnBounds raise{bound_.data(),   e.term_bounds.data(), relative_b,
                                  pending_.data(), fresh_.data(),        0,
                                  highest_bound_};
        lanes::add_scaled_rows_bounded(level().values.data(), columns, length, el.rows.data(),
                                       multiplier_lanes_.data(), quotients_.data(), primes, raise);
        statistics_.reducer_terms += length;
        statistics_.lane_terms += length * width;
        highest_bound_ = raise.highest;
        for (std::size_t k = 0; k < raise.fresh_count; ++k) {
            heap_.push_back(fresh_[k]);
            std::push_heap(heap_.begin(), heap_.end(), descending);
        }
        ++counts.steps;
        if (counts.steps % 16 == 0 && deadline_passed(deadline_)) {
            clear_pending();
            throw ReductionInterrupted{};
        }
    }
    return true;
}

template <typename Load>
bool ResidueZeroReducer::reduce_with_retries(std::uint32_t degree, Load load,
                                             ReductionCounts& counts) {
    // Reductions begin on the fewest lanes that most of those of their degree fit: narrower
    // lanes are read faster, and a reduction that outgrows them starts again on more. When a
    // quarter of those begun on a degree's lanes have had to, the degree's start moves up. A
    // degree not seen yet starts where the degree below it does (values grow with degree).
    Start& start = starts_[degree];
    if (start.lanes == 0) {
        const auto below = starts_.find(degree);
        start.lanes = below == starts_.begin() ? first_lanes_ : std::prev(below)->second.lanes;
    }
    for (std::size_t lanes = start.lanes;;) {
        activate(lanes);
        ReductionCounts attempt;
        try {
            begin();
            load();
            const bool zero = reduce_loaded(attempt);
            counts.steps += attempt.steps;
            ++start.begun;
            start.outgrown += lanes > start.lanes ? 1 : 0;
            if (learn_ && start.begun >= 4 && 4 * start.outgrown > start.begun) {
                const auto above = levels_.upper_bound(start.lanes);
                start = {above != levels_.end() ? above->first : next_lanes(start.lanes), 0, 0};
            }
            return zero;
        } catch (const LanesExhausted& exhausted) {
            clear_pending();
            ++statistics_.restarts;
            // Room for half as much again as the bound that did not fit: values that outgrew
            // one level tend to keep growing, and every start again repeats the work.
            const auto bits =
                static_cast<std::size_t>(std::max<lb::Units>(0, exhausted.needed) / lb::kPerBit);
            std::size_t wanted = next_lanes(lanes);
            while ((wanted - 1) * kLaneBits < bits + bits / 2 + 3) {
                wanted = next_lanes(wanted);
            }
            if (wanted > kMostLanes) {
                throw TooWide{};
            }
            const auto existing = levels_.lower_bound(wanted);
            lanes = existing != levels_.end() ? existing->first : wanted;
        }
    }
}

bool ResidueZeroReducer::reduces_to_zero(const IntegerPolynomial& p, ReductionCounts& counts) {
    if (p.empty()) {
        return true;
    }
    return reduce_with_retries(
        layout_.total_degree(p.monomial(0, layout_.words())),
        [&] {
            const std::size_t width = lanes();
            load_rows_.resize(p.size() * width);
            load_bounds_.resize(p.size());
            for (std::size_t j = 0; j < p.size(); ++j) {
                level().system->residues(p.coefficients[j].get(), load_rows_.data() + j * width,
                                         false);
                load_bounds_[j] = lb::upper(p.coefficients[j].get());
            }
            std::fill(multiplier_lanes_.begin(), multiplier_lanes_.end(), 1);
            std::fill(multiplier_.begin(), multiplier_.end(), 0);  // the monomial 1
            add_multiple(multiplier_lanes_.data(), 0, multiplier_.data(), p, 0, load_rows_.data(),
                         load_bounds_.data());
        },
        counts);
}

bool ResidueZeroReducer::s_polynomial_reduces_to_zero(std::size_t i, std::size_t j,
                                                      const std::uint64_t* lcm,
                                                      ReductionCounts& counts) {
    const std::size_t w = layout_.words();
    const IntegerPolynomial& f = basis_[i].poly;
    const IntegerPolynomial& g = basis_[j].poly;
    // s = a·mf·f − b·mg·g with a = lc(g)/d, b = lc(f)/d: the leading terms cancel.
    std::vector<std::uint64_t> mf(w), mg(w);
    layout_.divide(lcm, f.monomial(0, w), mf.data());
    layout_.divide(lcm, g.monomial(0, w), mg.data());
    OwnedInteger owned_a, owned_minus_b;
    mpz_ptr a = owned_a.value, minus_b = owned_minus_b.value;
    mpz_gcd(a, elements_[i].leading, elements_[j].leading);
    mpz_divexact(minus_b, elements_[i].leading, a);
    mpz_neg(minus_b, minus_b);
    mpz_divexact(a, elements_[j].leading, a);
    return reduce_with_retries(
        layout_.total_degree(lcm),
        [&] {
            level().system->residues(a, multiplier_lanes_.data(), false);
            add_multiple(multiplier_lanes_.data(), lb::upper(a), mf.data(), f, 1,
                         level().elements[i].rows.data(), elements_[i].term_bounds.data());
            level().system->residues(minus_b, multiplier_lanes_.data(), false);
            add_multiple(multiplier_lanes_.data(), lb::upper(minus_b), mg.data(), g, 1,
                         level().elements[j].rows.data(), elements_[j].term_bounds.data());
        },
        counts);
}

}  // namespace locus::algebra::detail
