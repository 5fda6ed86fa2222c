#include "algebra/modular/detail/fglm.h"

#include <algorithm>
#include <map>
#include <set>
#include <string>

#include "algebra/deadline.h"
#include "algebra/error.h"

namespace locus::algebra::modular {

namespace {

using Exponents = std::vector<std::uint32_t>;
using Vector = std::vector<std::uint32_t>;  // coordinates on the standard monomials

bool divides(const Exponents& a, const Exponents& b) {
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i] > b[i]) {
            return false;
        }
    }
    return true;
}

// Normal forms modulo a zero-dimensional reduced basis, as vectors over its standard monomials.
class NormalForms {
  public:
    NormalForms(const std::vector<ModularPolynomial>& basis, const MonomialLayout& layout,
                const PrimeField& field)
        : layout_(layout), field_(field), n_(layout.num_vars()) {
        for (const ModularPolynomial& g : basis) {
            leads_.push_back(unpack(g.monomials.data()));
        }
        basis_ = &basis;
    }

    // Enumerates the standard monomials; false when there are infinitely many (some variable
    // has no pure power among the leading monomials) or more than `limit`.
    bool enumerate(std::size_t limit) {
        for (std::size_t v = 0; v < n_; ++v) {
            const bool has_power =
                std::any_of(leads_.begin(), leads_.end(), [&](const Exponents& e) {
                    for (std::size_t w = 0; w < n_; ++w) {
                        if (w != v && e[w] != 0) {
                            return false;
                        }
                    }
                    return e[v] > 0;
                });
            if (!has_power) {
                return false;
            }
        }
        std::vector<Exponents> queue{Exponents(n_, 0)};
        if (is_reducible(queue.front())) {
            return false;  // the unit ideal: nothing to convert
        }
        index_[queue.front()] = 0;
        standard_.push_back(queue.front());
        for (std::size_t next = 0; next < standard_.size(); ++next) {
            for (std::size_t v = 0; v < n_; ++v) {
                Exponents m = standard_[next];
                ++m[v];
                if (index_.count(m) != 0 || is_reducible(m)) {
                    continue;
                }
                if (standard_.size() >= limit) {
                    return false;
                }
                index_[m] = standard_.size();
                standard_.push_back(m);
            }
        }
        return true;
    }

    std::size_t dimension() const { return standard_.size(); }
    std::size_t index_of_one() const { return 0; }

    // NF(x_v · (the polynomial with coordinates u)).
    Vector times_variable(const Vector& u, std::size_t v) {
        Vector out(dimension(), 0);
        for (std::size_t k = 0; k < u.size(); ++k) {
            if (u[k] == 0) {
                continue;
            }
            Exponents m = standard_[k];
            ++m[v];
            add_scaled(out, m, u[k]);
        }
        return out;
    }

  private:
    Exponents unpack(const std::uint64_t* m) const {
        Exponents e(n_);
        layout_.unpack(m, e);
        return e;
    }
    bool is_reducible(const Exponents& m) const {
        return std::any_of(leads_.begin(), leads_.end(),
                           [&](const Exponents& l) { return divides(l, m); });
    }

    // out += c · NF(m).
    void add_scaled(Vector& out, const Exponents& m, std::uint64_t c) {
        if (const auto found = index_.find(m); found != index_.end()) {
            out[found->second] = static_cast<std::uint32_t>(field_.add(out[found->second], c));
            return;
        }
        const Vector& nf = normal_form(m);
        for (std::size_t k = 0; k < nf.size(); ++k) {
            if (nf[k] != 0) {
                out[k] = static_cast<std::uint32_t>(field_.add(out[k], field_.multiply(c, nf[k])));
            }
        }
    }

    // NF of a monomial that is not standard (memoised).
    const Vector& normal_form(const Exponents& m) {
        if (const auto found = memo_.find(m); found != memo_.end()) {
            return found->second;
        }
        Vector nf(dimension(), 0);
        const ModularPolynomial* lead_of = nullptr;
        std::size_t divisor = leads_.size();
        for (std::size_t g = 0; g < leads_.size(); ++g) {
            if (leads_[g] == m) {
                lead_of = &(*basis_)[g];
                break;
            }
            if (divisor == leads_.size() && divides(leads_[g], m)) {
                divisor = g;
            }
        }
        if (lead_of != nullptr) {
            // m = −tail (the tail of a reduced basis element is standard).
            for (std::size_t i = 1; i < lead_of->size(); ++i) {
                const Exponents t = unpack(lead_of->monomial(i, layout_.words()));
                nf[index_.at(t)] =
                    static_cast<std::uint32_t>(field_.negate(lead_of->coefficients[i]));
            }
        } else {
            // m = x_v · q with q still divisible by a leading monomial: NF(m) = x_v · NF(q).
            std::size_t v = 0;
            while (m[v] <= leads_[divisor][v]) {
                ++v;
            }
            Exponents q = m;
            --q[v];
            const Vector inner = normal_form(q);
            nf = times_variable(inner, v);
        }
        return memo_.emplace(m, std::move(nf)).first->second;
    }

    const MonomialLayout& layout_;
    PrimeField field_;
    std::size_t n_;
    const std::vector<ModularPolynomial>* basis_ = nullptr;
    std::vector<Exponents> leads_;
    std::vector<Exponents> standard_;
    std::map<Exponents, std::size_t> index_;
    std::map<Exponents, Vector> memo_;
};

}  // namespace

std::optional<std::vector<ModularPolynomial>> fglm(
    const std::vector<ModularPolynomial>& basis, const MonomialLayout& from,
    const MonomialLayout& to, const PrimeField& field, std::size_t max_dimension,
    std::optional<std::chrono::steady_clock::time_point> deadline) {
    NormalForms forms(basis, from, field);
    if (basis.empty() || !forms.enumerate(max_dimension)) {
        return std::nullopt;
    }
    const std::size_t n = to.num_vars();
    const std::size_t words = to.words();
    const std::size_t dimension = forms.dimension();
    auto pack = [&](const Exponents& e) {
        std::vector<std::uint64_t> m(words);
        to.pack(e, m.data());
        return m;
    };
    // Candidates in ascending target order, each known as x_v · (staircase entry).
    struct Candidate {
        std::vector<std::uint64_t> packed;
        Exponents exponents;
        std::size_t parent;  // index in the new staircase, or npos for 1
        std::size_t variable;
    };
    auto less = [&](const Candidate& a, const Candidate& b) {
        return to.compare(a.packed.data(), b.packed.data()) < 0;
    };
    std::set<Candidate, decltype(less)> candidates(less);
    constexpr std::size_t npos = static_cast<std::size_t>(-1);
    candidates.insert({pack(Exponents(n, 0)), Exponents(n, 0), npos, 0});

    std::vector<Exponents> staircase;     // the new standard monomials
    std::vector<Vector> staircase_forms;  // their normal forms (unreduced)
    std::vector<Vector> rows;             // echelon rows, pivot coordinate normalised to 1
    std::vector<std::size_t> pivots;      // pivot coordinate of each row
    std::vector<Vector> combinations;     // row = Σ combination[t] · NF(staircase[t])
    std::vector<Exponents> new_leads;
    std::vector<ModularPolynomial> out;
    while (!candidates.empty()) {
        if (deadline_passed(deadline)) {
            throw Timeout("FGLM modulo " + std::to_string(field.p));
        }
        const Candidate c = *candidates.begin();
        candidates.erase(candidates.begin());
        if (std::any_of(new_leads.begin(), new_leads.end(),
                        [&](const Exponents& l) { return divides(l, c.exponents); })) {
            continue;
        }
        Vector v(dimension, 0);
        if (c.parent == npos) {
            v[forms.index_of_one()] = 1;
        } else {
            v = forms.times_variable(staircase_forms[c.parent], c.variable);
        }
        const Vector form = v;
        Vector combination(staircase.size() + 1, 0);
        for (std::size_t r = 0; r < rows.size(); ++r) {
            const std::uint64_t factor = v[pivots[r]];
            if (factor == 0) {
                continue;
            }
            const std::uint64_t minus = field.negate(factor);
            for (std::size_t k = 0; k < dimension; ++k) {
                if (rows[r][k] != 0) {
                    v[k] = static_cast<std::uint32_t>(
                        field.add(v[k], field.multiply(minus, rows[r][k])));
                }
            }
            for (std::size_t t = 0; t < combinations[r].size(); ++t) {
                if (combinations[r][t] != 0) {
                    combination[t] = static_cast<std::uint32_t>(
                        field.add(combination[t], field.multiply(minus, combinations[r][t])));
                }
            }
        }
        // Now v = NF(m) + Σ combination[t]·NF(staircase[t]).
        const auto pivot = std::find_if(v.begin(), v.end(), [](std::uint32_t x) { return x != 0; });
        if (pivot == v.end()) {
            // m + Σ combination[t]·staircase[t] lies in the ideal: a basis element.
            std::vector<std::pair<std::vector<std::uint64_t>, std::uint32_t>> terms;
            terms.emplace_back(c.packed, 1);
            for (std::size_t t = 0; t < staircase.size(); ++t) {
                if (combination[t] != 0) {
                    terms.emplace_back(pack(staircase[t]), combination[t]);
                }
            }
            std::sort(terms.begin(), terms.end(), [&](const auto& a, const auto& b) {
                return to.compare(a.first.data(), b.first.data()) > 0;
            });
            ModularPolynomial g;
            for (const auto& [monomial, coefficient] : terms) {
                g.monomials.insert(g.monomials.end(), monomial.begin(), monomial.end());
                g.coefficients.push_back(coefficient);
            }
            out.push_back(std::move(g));
            new_leads.push_back(c.exponents);
            continue;
        }
        // A new standard monomial; its row is v with combination + e_new, normalised.
        const std::size_t index = staircase.size();
        combination[index] = 1;
        const std::uint64_t inverse = field.inverse(*pivot);
        for (std::uint32_t& x : v) {
            x = static_cast<std::uint32_t>(field.multiply(x, inverse));
        }
        for (std::uint32_t& x : combination) {
            x = static_cast<std::uint32_t>(field.multiply(x, inverse));
        }
        pivots.push_back(static_cast<std::size_t>(pivot - v.begin()));
        rows.push_back(std::move(v));
        combinations.push_back(std::move(combination));
        staircase.push_back(c.exponents);
        staircase_forms.push_back(form);
        for (std::size_t var = 0; var < n; ++var) {
            Exponents next = c.exponents;
            ++next[var];
            candidates.insert({pack(next), next, index, var});
        }
    }
    return out;  // found in ascending order of leading monomials
}

}  // namespace locus::algebra::modular
