// f4_replay_lanes (f4.h): a recorded F4 run repeated modulo several primes at once.
//
// The matrices of a replay are the same for every lucky prime; only the residues differ. So
// every entry holds one residue a prime ("lane", groebner/detail/residue_lanes.h), and subtracting
// a pivot row is one vector multiply-add per term for all the primes together, where a replay one
// prime at a time pays the scan, the indexing and the loop per prime. A prime whose computation
// leaves the recording (a row reducing to another leading column, an element with another support,
// a generator vanishing) drops out of the batch; the others go on.
#include <algorithm>
#include <chrono>
#include <numeric>
#include <string>

#include <flint/ulong_extras.h>

#include "algebra/deadline.h"
#include "algebra/error.h"
#include "algebra/groebner/detail/residue_lanes.h"
#include "algebra/modular/f4.h"

namespace locus::algebra::modular {

// Fills a LaneBases (f4.h) element by element.
class LaneBasesBuilder {
  public:
    LaneBasesBuilder(std::size_t primes, std::size_t words, std::size_t width) {
        bases_.words_ = words;
        bases_.width_ = width;
        bases_.alive_.assign(primes, 0);
        bases_.first_.push_back(0);
    }
    static LaneBases none(std::size_t primes) {
        LaneBases bases;
        bases.alive_.assign(primes, 0);
        return bases;
    }
    // An element: its leading monomial (column `leading` of `column_monomials`, coefficient 1)
    // and its tail, `residues` holding width residues a column.
    void element(const std::uint64_t* column_monomials, std::uint32_t leading,
                 const std::vector<std::uint32_t>& tail_columns, const std::uint32_t* residues) {
        const std::size_t words = bases_.words_, width = bases_.width_;
        const std::uint64_t* m = column_monomials + static_cast<std::size_t>(leading) * words;
        bases_.monomials_.insert(bases_.monomials_.end(), m, m + words);
        bases_.residues_.insert(bases_.residues_.end(), width, 1);
        for (std::size_t t = 0; t < tail_columns.size(); ++t) {
            m = column_monomials + static_cast<std::size_t>(tail_columns[t]) * words;
            bases_.monomials_.insert(bases_.monomials_.end(), m, m + words);
        }
        bases_.residues_.insert(bases_.residues_.end(), residues,
                                residues + tail_columns.size() * width);
        bases_.first_.push_back(bases_.first_.back() + 1 + tail_columns.size());
    }
    LaneBases finish(const std::vector<char>& alive) {
        std::copy_n(alive.begin(), bases_.alive_.size(), bases_.alive_.begin());
        return std::move(bases_);
    }

  private:
    LaneBases bases_;
};

std::optional<std::vector<ModularPolynomial>> LaneBases::basis(std::size_t i) const {
    if (!has(i)) {
        return std::nullopt;
    }
    std::vector<ModularPolynomial> out(first_.size() - 1);
    for (std::size_t e = 0; e + 1 < first_.size(); ++e) {
        // Sized once: grown term by term, the copies and allocations were a third of
        // katsura-10's replays.
        std::size_t terms = 0;
        for (std::size_t t = first_[e]; t < first_[e + 1]; ++t) {
            terms += residues_[t * width_ + i] != 0 ? 1 : 0;
        }
        ModularPolynomial& poly = out[e];
        poly.coefficients.reserve(terms);
        poly.monomials.reserve(terms * words_);
        for (std::size_t t = first_[e]; t < first_[e + 1]; ++t) {
            const std::uint32_t residue = residues_[t * width_ + i];
            if (residue != 0) {
                poly.coefficients.push_back(residue);
                const std::uint64_t* m = monomials_.data() + t * words_;
                poly.monomials.insert(poly.monomials.end(), m, m + words_);
            }
        }
    }
    return out;
}

namespace {

using detail::LanePrimes;
namespace lanes = detail::lanes;

// A row of the matrix: its columns and, per column, one residue a lane.
struct LaneRow {
    std::vector<std::uint32_t> columns;
    std::vector<std::uint32_t> residues;  // columns.size() × lanes
};

// A pivot: a recorded row (an element's residues on the recorded columns) or a fresh one.
struct Pivot {
    const std::uint32_t* columns;
    std::size_t size;
    const std::uint32_t* residues;
};

class LaneReplay {
  public:
    LaneReplay(const F4Trace& trace, std::span<const std::uint32_t> primes,
               const MonomialLayout& layout, const F4Options& options)
        : trace_(trace),
          lanes_(primes),
          count_(primes.size()),
          layout_(layout),
          words_(layout.words()),
          options_(options),
          alive_(primes.size(), 1),
          factor_(lanes_.size()),
          quotients_(lanes_.size()) {}

    LaneBases run(std::span<const std::vector<ModularPolynomial>> generators) {
        if (trace_.final_elements.empty() || !load_generators(generators)) {
            return LaneBasesBuilder::none(count_);
        }
        for (const F4Trace::Step& step : trace_.steps) {
            if (!replay_step(step)) {
                return LaneBasesBuilder::none(count_);
            }
        }
        return reduced_bases();
    }

  private:
    std::size_t width() const { return lanes_.size(); }
    bool any_alive() const { return std::find(alive_.begin(), alive_.end(), 1) != alive_.end(); }

    void check_deadline() const {
        if (deadline_passed(options_.deadline)) {
            throw Timeout("F4 replay modulo " + std::to_string(count_) + " primes");
        }
    }

    // The lanes of `value` that are alive and non-zero (or zero) die.
    void kill_where(const std::uint32_t* value, bool zero) {
        for (std::size_t l = 0; l < count_; ++l) {
            if (alive_[l] && (value[l] == 0) == zero) {
                alive_[l] = 0;
            }
        }
    }

    // The generators, monic, each lane's from its own prime; a lane whose non-zero generators
    // are not the recorded ones, with the recorded supports, dies.
    bool load_generators(std::span<const std::vector<ModularPolynomial>> generators) {
        const std::size_t k = width();
        elements_.assign(trace_.generators, {});
        for (std::size_t l = 0; l < count_; ++l) {
            std::vector<const ModularPolynomial*> nonzero;
            for (const ModularPolynomial& g : generators[l]) {
                if (!g.is_zero()) {
                    nonzero.push_back(&g);
                }
            }
            if (nonzero.size() != trace_.generators) {
                alive_[l] = 0;
                continue;
            }
            for (std::size_t i = 0; i < nonzero.size() && alive_[l]; ++i) {
                alive_[l] = nonzero[i]->monomials == trace_.supports[i] ? 1 : 0;
            }
            if (!alive_[l]) {
                continue;
            }
            const std::uint64_t p = lanes_.prime(l);
            for (std::size_t i = 0; i < nonzero.size(); ++i) {
                const ModularPolynomial& g = *nonzero[i];
                LaneRow& e = elements_[i];
                e.residues.resize(g.size() * k, 0);
                const std::uint64_t inverse = n_invmod(g.coefficients.front(), p);
                for (std::size_t t = 0; t < g.size(); ++t) {
                    e.residues[t * k + l] =
                        static_cast<std::uint32_t>(g.coefficients[t] * inverse % p);
                }
            }
        }
        return any_alive();
    }

    // Reduces acc (lanes per column) from column `from` on by the pivots: the columns left,
    // with their residues, in `out`; acc is zero afterwards.
    void reduce(std::size_t from, const std::vector<std::int64_t>& pivot_of_column,
                const std::vector<Pivot>& pivots, LaneRow& out) {
        const std::size_t k = width();
        out.columns.clear();
        out.residues.clear();
        for (std::size_t c = from; c < pivot_of_column.size(); ++c) {
            std::uint32_t* v = acc_.data() + c * k;
            if (lanes::is_zero(v, k)) {
                continue;
            }
            const std::int64_t pivot = pivot_of_column[c];
            if (pivot < 0) {
                out.columns.push_back(static_cast<std::uint32_t>(c));
                out.residues.insert(out.residues.end(), v, v + k);
                std::fill_n(v, k, 0);
                continue;
            }
            // acc −= v·(pivot row), the pivot being monic on every lane.
            std::copy_n(v, k, factor_.data());
            lanes::negate(factor_.data(), lanes_);
            std::fill_n(v, k, 0);
            lanes::shoup_quotients(quotients_.data(), factor_.data(), lanes_);
            const Pivot& row = pivots[static_cast<std::size_t>(pivot)];
            lanes::add_scaled_rows(acc_.data(), row.columns + 1, row.size - 1, row.residues + k,
                                   factor_.data(), quotients_.data(), lanes_);
        }
    }

    void load(const Pivot& row, std::size_t first) {
        const std::size_t k = width();
        for (std::size_t t = first; t < row.size; ++t) {
            std::copy_n(row.residues + t * k, k, acc_.data() + row.columns[t] * k);
        }
    }

    // Multiplies every lane of `row` by the inverse of its residue in the first column.
    void make_monic(LaneRow& row) {
        const std::size_t k = width();
        for (std::size_t l = 0; l < k; ++l) {
            const std::uint32_t lead = row.residues[l];
            const std::uint32_t inverse =
                lead == 0 ? 0 : static_cast<std::uint32_t>(n_invmod(lead, lanes_.prime(l)));
            factor_[l] = lanes_.to_montgomery(l, inverse);
        }
        for (std::size_t t = 0; t < row.columns.size(); ++t) {
            std::uint32_t* r = row.residues.data() + t * k;
            lanes::multiply(r, r, factor_.data(), lanes_);
        }
    }

    // A row of the recorded matrix: the element's residues on the recorded columns.
    Pivot row_of(const F4Trace::Row& r) const {
        return {r.columns.data(), r.columns.size(), elements_[r.element].residues.data()};
    }
    static Pivot pivot_of(const LaneRow& row) {
        return {row.columns.data(), row.columns.size(), row.residues.data()};
    }

    bool replay_step(const F4Trace::Step& step) {
        const std::size_t k = width();
        const std::size_t columns = step.column_monomials.size() / words_;
        std::vector<Pivot> pivots;
        pivots.reserve(step.reducers.size() + step.rows.size());
        std::vector<std::int64_t> pivot_of_column(columns, -1);
        for (const F4Trace::Row& r : step.reducers) {
            if (r.element >= elements_.size()) {
                return false;
            }
            pivot_of_column[r.columns.front()] = static_cast<std::int64_t>(pivots.size());
            pivots.push_back(row_of(r));
        }
        acc_.assign(columns * k, 0);
        // Fresh rows are pivots for the rows after them: reserved, so that they do not move.
        std::vector<LaneRow> fresh;
        fresh.reserve(step.rows.size());
        LaneRow reduced;
        for (std::size_t i = 0; i < step.rows.size(); ++i) {
            check_deadline();
            const F4Trace::Row& r = step.rows[i];
            if (r.element >= elements_.size()) {
                return false;
            }
            load(row_of(r), 0);
            reduce(r.columns.front(), pivot_of_column, pivots, reduced);
            // Every lane must reduce to the recorded leading column: lanes non-zero before it,
            // or zero on it, leave the recording.
            const std::uint32_t leading = step.leading[i];
            std::size_t at = 0;
            while (at < reduced.columns.size() && reduced.columns[at] < leading) {
                kill_where(reduced.residues.data() + at * k, false);
                ++at;
            }
            if (at == reduced.columns.size() || reduced.columns[at] != leading) {
                return false;  // zero on the leading column in every lane
            }
            kill_where(reduced.residues.data() + at * k, true);
            if (!any_alive()) {
                return false;
            }
            LaneRow row;
            row.columns.assign(reduced.columns.begin() + static_cast<long>(at),
                               reduced.columns.end());
            row.residues.assign(reduced.residues.begin() + static_cast<long>(at * k),
                                reduced.residues.end());
            make_monic(row);
            fresh.push_back(std::move(row));
            pivot_of_column[leading] = static_cast<std::int64_t>(pivots.size());
            pivots.push_back(pivot_of(fresh.back()));
        }
        // New elements, smallest leading monomial first (as F4 appends them), on the supports
        // recorded for them.
        std::sort(fresh.begin(), fresh.end(), [](const LaneRow& a, const LaneRow& b) {
            return a.columns.front() > b.columns.front();
        });
        for (LaneRow& row : fresh) {
            if (elements_.size() >= trace_.supports.size() ||
                !fit_support(row, step, trace_.supports[elements_.size()])) {
                return false;
            }
            elements_.push_back(std::move(row));
        }
        return any_alive();
    }

    // Aligns the row with the recorded support of its element (monomials descending): lanes
    // non-zero off it, or zero on it, die. False when no lane is left.
    bool fit_support(LaneRow& row, const F4Trace::Step& step,
                     const std::vector<std::uint64_t>& support) {
        const std::size_t k = width();
        const std::size_t terms = support.size() / words_;
        LaneRow fitted;
        fitted.residues.assign(terms * k, 0);
        std::size_t c = 0;
        for (std::size_t t = 0; t < terms; ++t) {
            const std::uint64_t* m = support.data() + t * words_;
            // Columns descend with the monomials: those before m are off the support.
            while (c < row.columns.size() &&
                   layout_.compare(step.column_monomials.data() + row.columns[c] * words_, m) > 0) {
                kill_where(row.residues.data() + c * k, false);
                ++c;
            }
            if (c < row.columns.size() &&
                layout_.equal(step.column_monomials.data() + row.columns[c] * words_, m)) {
                std::copy_n(row.residues.data() + c * k, k, fitted.residues.data() + t * k);
                kill_where(fitted.residues.data() + t * k, true);
                ++c;
            } else {
                std::fill(alive_.begin(), alive_.end(), 0);  // zero there in every lane
            }
        }
        for (; c < row.columns.size(); ++c) {
            kill_where(row.residues.data() + c * k, false);
        }
        row.residues = std::move(fitted.residues);
        row.columns.clear();  // an element's columns come from the rows that use it
        return any_alive();
    }

    // The last recorded matrix reduces the minimal elements' tails: the reduced bases of the
    // live lanes, elements by ascending leading monomial (LaneBases).
    LaneBases reduced_bases() {
        const std::size_t k = width();
        const F4Trace::Step& step = trace_.final_step;
        const std::size_t columns = step.column_monomials.size() / words_;
        std::vector<Pivot> pivots;
        std::vector<std::int64_t> pivot_of_column(columns, -1);
        for (const F4Trace::Row& r : step.reducers) {
            if (r.element >= elements_.size()) {
                return LaneBasesBuilder::none(count_);
            }
            pivot_of_column[r.columns.front()] = static_cast<std::int64_t>(pivots.size());
            pivots.push_back(row_of(r));
        }
        // Columns descend with the monomials: ascending leading monomials are descending
        // leading columns. The pivots are the recorded rows, which no tail reduction changes,
        // so the elements can be reduced in that order.
        std::vector<std::size_t> order(trace_.final_elements.size());
        std::iota(order.begin(), order.end(), std::size_t{0});
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return pivots[a].columns[0] > pivots[b].columns[0];
        });
        acc_.assign(columns * k, 0);
        LaneBasesBuilder out(count_, words_, k);
        LaneRow tail;
        for (const std::size_t e : order) {
            check_deadline();
            const Pivot& row = pivots[e];
            if (row.size > 1) {
                load(row, 1);
                reduce(row.columns[1], pivot_of_column, pivots, tail);
            } else {
                tail = {};
            }
            out.element(step.column_monomials.data(), row.columns[0], tail.columns,
                        tail.residues.data());
        }
        return out.finish(alive_);
    }

    const F4Trace& trace_;
    LanePrimes lanes_;
    std::size_t count_;  // the primes asked for; lanes past them repeat the last
    const MonomialLayout& layout_;
    std::size_t words_;
    const F4Options& options_;
    std::vector<char> alive_;
    std::vector<LaneRow> elements_;  // residues only: their columns are per matrix
    std::vector<std::uint32_t> acc_, factor_, quotients_;
};

}  // namespace

LaneBases f4_replay_lanes(const F4Trace& trace,
                          std::span<const std::vector<ModularPolynomial>> generators,
                          std::span<const std::uint32_t> primes, const MonomialLayout& layout,
                          const F4Options& options) {
    if (generators.size() != primes.size()) {
        throw std::invalid_argument("f4_replay_lanes: one list of generators a prime");
    }
    LaneReplay replay(trace, primes, layout, options);
    return replay.run(generators);
}

}  // namespace locus::algebra::modular
