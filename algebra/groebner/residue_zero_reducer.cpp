#include "algebra/groebner/residue_zero_reducer.h"

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

}  // namespace

std::size_t ResidueZeroReducer::initial_lanes(const std::vector<BasisElement>& basis) {
    std::size_t bits = 0;
    for (const BasisElement& e : basis) {
        for (const Integer& c : e.poly.coefficients) {
            bits = std::max<std::size_t>(bits, fmpz_bits(c.get()));
        }
    }
    const std::size_t digits = (2 * bits + 64 + 2) / kLaneBits + 1;
    return (digits + 1 + 7) / 8 * 8;  // and the redundant lane
}

ResidueZeroReducer::ResidueZeroReducer(const MonomialLayout& layout,
                                       const std::vector<BasisElement>& basis, std::size_t lanes)
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
        }
    }
    mpz_inits(gcd_, cofactor_, scratch_, nullptr);
    product_.resize(layout.words());
    multiplier_.resize(layout.words());
    use_lanes(lanes != 0 ? lanes : initial_lanes(basis));
}

ResidueZeroReducer::~ResidueZeroReducer() {
    for (Element& e : elements_) {
        mpz_clear(e.leading);
    }
    mpz_clears(gcd_, cofactor_, scratch_, nullptr);
}

void ResidueZeroReducer::use_lanes(std::size_t lanes) {
    // Primes that divide a leading coefficient are skipped: every L must be invertible.
    const auto usable = [this](std::uint32_t p) {
        return std::none_of(elements_.begin(), elements_.end(),
                            [p](const Element& e) { return mpz_fdiv_ui(e.leading, p) == 0; });
    };
    system_ = std::make_unique<ResidueSystem>(LanePrimes(lanes, usable));
    const LanePrimes& primes = system_->primes();
    element_lanes_.assign(basis_.size(), ElementLanes{});
    for (std::size_t k = 0; k < basis_.size(); ++k) {
        ElementLanes& el = element_lanes_[k];
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
            system_->residues(g.coefficients[j].get(), el.rows.data() + (j - 1) * lanes, true);
        }
        if (mpz_cmp_ui(e.leading, 1) != 0) {
            el.divisor = system_->divisor(e.leading);
        }
    }
    values_.assign(table_.size() * lanes, 0);
    std::fill(bound_.begin(), bound_.end(), lb::kZero);
    lambda_.resize(lanes);
    lambda_digits_.resize(lanes);
    multiplier_lanes_.resize(lanes);
    digits_.resize(lanes);
    factor_.resize(lanes);
    statistics_.lanes = lanes;
    begin();
}

void ResidueZeroReducer::begin() {
    const LanePrimes& primes = system_->primes();
    for (std::size_t l = 0; l < lanes(); ++l) {
        lambda_[l] = primes.to_montgomery(l, 1);
    }
    lanes::multiply(lambda_digits_.data(), lambda_.data(), system_->digit_factors(), primes);
    offset_ = 0;
    highest_bound_ = lb::kZero;
}

void ResidueZeroReducer::scale_lambda(const std::uint32_t* factor) {
    const LanePrimes& primes = system_->primes();
    lanes::multiply(lambda_.data(), lambda_.data(), factor, primes);
    lanes::multiply(lambda_digits_.data(), lambda_.data(), system_->digit_factors(), primes);
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
        values_.resize(values_.size() + lanes(), 0);
        bound_.push_back(lb::kZero);
        pending_.push_back(0);
        row_of_column_.push_back(kNotLookedUp);
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
    if (row_of_column_[c] != kNotLookedUp) {
        return row_of_column_[c];
    }
    const std::size_t w = layout_.words();
    // Copied: numbering new columns below may move the table's storage.
    std::vector<std::uint64_t> monomial(table_.at(c), table_.at(c) + w);
    const long k = search_.find(monomial.data(), layout_);
    if (k < 0) {
        row_of_column_[c] = kIrreducible;
        return kIrreducible;
    }
    const IntegerPolynomial& g = basis_[static_cast<std::size_t>(k)].poly;
    layout_.divide(monomial.data(), g.monomial(0, w), multiplier_.data());
    const Row row{static_cast<std::size_t>(k), row_columns_.size()};
    for (std::size_t j = 1; j < g.size(); ++j) {
        layout_.multiply(g.monomial(j, w), multiplier_.data(), product_.data());
        row_columns_.push_back(column(product_.data()));
    }
    rows_.push_back(row);
    row_of_column_[c] = static_cast<std::int32_t>(rows_.size() - 1);
    return row_of_column_[c];
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
        if (bound > system_->capacity()) {
            throw LanesExhausted{};
        }
        touched_.push_back(c);
        touched_bounds_.push_back(bound);
    }
    lanes::add_scaled_rows(values_.data(), touched_.data(), touched_.size(), rows, multiplier,
                           system_->primes());
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
    const LanePrimes& primes = system_->primes();
    std::vector<std::uint32_t> columns(heap_);
    columns.push_back(lc);
    std::vector<OwnedInteger> values(columns.size());
    OwnedInteger owned_content;
    mpz_ptr content = owned_content.value;
    for (std::size_t h = 0; h < columns.size(); ++h) {
        lanes::multiply(digits_.data(), value(columns[h]), lambda_digits_.data(), primes);
        system_->reconstruct(digits_.data(), values[h].value);
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
                system_->residues(values[h].value, value(columns[h]), false);
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
    const LanePrimes& primes = system_->primes();
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
        if (r == kIrreducible) {
            std::fill_n(value(c), width, 0);
            bound_[c] = lb::kZero;
            clear_pending();
            return false;
        }
        const Row row = rows_[static_cast<std::size_t>(r)];
        const Element& e = elements_[row.element];
        const ElementLanes& el = element_lanes_[row.element];
        const std::uint32_t* s = value(c);

        // g = gcd(V, L) for the fraction-free value V = Λ·s of the leading coefficient, from
        // V mod L; a = L/g multiplies p (and Λ) when g ≠ L.
        lb::Units gcd_lower = 0;
        bool scaled = false;
        if (el.divisor) {
            lanes::multiply(digits_.data(), s, lambda_digits_.data(), primes);
            remainder_.resize(el.divisor->limbs.size());
            system_->remainder(digits_.data(), *el.divisor, remainder_.data());
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
        const std::uint32_t* columns = row_columns_.data() + row.offset;
        const lb::Units capacity = system_->capacity();
        bool fits = !scaled || highest_bound_ + offset <= capacity;
        // The new bounds, relative to the new offset: b's bound plus the coefficient's, summed
        // with the column's (locals throughout: bound_ and the members alias as int64s).
        touched_bounds_.resize(length);
        {
            const lb::Units* old = bound_.data();
            const lb::Units* term = e.term_bounds.data();
            lb::Units* fresh = touched_bounds_.data();
            const lb::Units relative_b = b_bound - offset, limit = capacity - offset;
            lb::Units highest = lb::kZero;
            for (std::size_t t = 0; t < length; ++t) {
                fresh[t] = lb::of_sum(old[columns[t]], relative_b + term[t]);
                highest = std::max(highest, fresh[t]);
            }
            fits = fits && highest <= limit;
        }
        if (!fits) {
            if (just_rebuilt || rebuilds == kRebuildsBeforeMoreLanes) {
                std::fill_n(value(c), width, 0);
                bound_[c] = lb::kZero;
                throw LanesExhausted{};
            }
            rebuild_pending(c);
            ++rebuilds;
            just_rebuilt = true;
            push(c);
            continue;
        }
        just_rebuilt = false;

        // In residues: s ← s − (s_c/L)·m·g.
        lanes::multiply(multiplier_lanes_.data(), s, el.leading_inverse.data(), primes);
        lanes::negate(multiplier_lanes_.data(), primes);
        std::fill_n(value(c), width, 0);
        bound_[c] = lb::kZero;
        if (scaled) {
            offset_ = offset;
            system_->residues(cofactor_, factor_.data(), true);
            scale_lambda(factor_.data());
        }
        lanes::add_scaled_rows(values_.data(), columns, length, el.rows.data(),
                               multiplier_lanes_.data(), primes);
        {
            lb::Units* bound = bound_.data();
            lb::Units highest = highest_bound_;
            for (std::size_t t = 0; t < length; ++t) {
                const std::uint32_t column = columns[t];
                bound[column] = touched_bounds_[t];
                highest = std::max(highest, touched_bounds_[t]);
                if (pending_[column] == 0) {
                    pending_[column] = 1;
                    heap_.push_back(column);
                    std::push_heap(heap_.begin(), heap_.end(), descending);
                }
            }
            highest_bound_ = highest;
        }
        ++counts.steps;
        if (deadline_ && counts.steps % 16 == 0 && std::chrono::steady_clock::now() > *deadline_) {
            clear_pending();
            throw ReductionInterrupted{};
        }
    }
    return true;
}

template <typename Load>
bool ResidueZeroReducer::reduce_with_retries(Load load, ReductionCounts& counts) {
    for (;;) {
        ReductionCounts attempt;
        try {
            begin();
            load();
            const bool zero = reduce_loaded(attempt);
            counts.steps += attempt.steps;
            return zero;
        } catch (const LanesExhausted&) {
            clear_pending();
            ++statistics_.restarts;
            const std::size_t more = lanes() + std::max<std::size_t>(8, lanes() / 4 / 8 * 8);
            if (more > kMostLanes) {
                throw TooWide{};
            }
            use_lanes(more);
        }
    }
}

bool ResidueZeroReducer::reduces_to_zero(const IntegerPolynomial& p, ReductionCounts& counts) {
    if (p.empty()) {
        return true;
    }
    return reduce_with_retries(
        [&] {
            const std::size_t width = lanes();
            load_rows_.resize(p.size() * width);
            load_bounds_.resize(p.size());
            for (std::size_t j = 0; j < p.size(); ++j) {
                system_->residues(p.coefficients[j].get(), load_rows_.data() + j * width, true);
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
        [&] {
            system_->residues(a, multiplier_lanes_.data(), false);
            add_multiple(multiplier_lanes_.data(), lb::upper(a), mf.data(), f, 1,
                         element_lanes_[i].rows.data(), elements_[i].term_bounds.data());
            system_->residues(minus_b, multiplier_lanes_.data(), false);
            add_multiple(multiplier_lanes_.data(), lb::upper(minus_b), mg.data(), g, 1,
                         element_lanes_[j].rows.data(), elements_[j].term_bounds.data());
        },
        counts);
}

}  // namespace locus::algebra::detail
