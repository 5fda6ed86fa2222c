#include "algebra/groebner/detail/pair_criteria.h"

#include <algorithm>

namespace locus::algebra::detail {

void gebauer_moller_update(std::vector<BasisElement>& basis, std::vector<CriticalPair>& pairs,
                           std::size_t new_index, const MonomialLayout& layout,
                           CriteriaCounts& counts) {
    const std::size_t w = layout.words();
    const IntegerPolynomial& h = basis[new_index].poly;
    const std::uint64_t* lm_h = h.monomial(0, w);
    const std::uint32_t deg_h = layout.leading_weight(lm_h);

    // Candidate new pairs (g, h) for every non-redundant g.
    struct Candidate {
        CriticalPair pair;
        bool coprime;
        bool alive = true;
    };
    std::vector<Candidate> candidates;
    for (std::size_t g = 0; g < new_index; ++g) {
        if (basis[g].redundant) {
            continue;
        }
        const std::uint64_t* lm_g = basis[g].poly.monomial(0, w);
        Candidate c;
        c.pair.first = g;
        c.pair.second = new_index;
        c.pair.lcm.resize(w);
        layout.lcm(lm_g, lm_h, c.pair.lcm.data());
        c.pair.lcm_degree = layout.leading_weight(c.pair.lcm.data());
        const std::uint32_t sugar_g =
            basis[g].poly.sugar + c.pair.lcm_degree - layout.leading_weight(lm_g);
        const std::uint32_t sugar_h = h.sugar + c.pair.lcm_degree - deg_h;
        c.pair.sugar = std::max(sugar_g, sugar_h);
        c.coprime = layout.coprime(lm_g, lm_h);
        candidates.push_back(std::move(c));
        ++counts.pairs_created;
    }

    // Chain criterion among the new pairs, in Becker–Weispfenning's order: (g1, h) is dropped
    // when an lcm dividing lcm(g1, h) belongs to a pair not yet examined or to one examined and
    // kept; coprime pairs are kept here (they may still kill others) and removed by the
    // product criterion below. Of pairs with equal lcm the last one survives.
    for (std::size_t a = 0; a < candidates.size(); ++a) {
        if (candidates[a].coprime) {
            continue;
        }
        for (std::size_t b = 0; b < candidates.size(); ++b) {
            if (a == b || !candidates[b].alive) {
                continue;
            }
            if (layout.divides(candidates[b].pair.lcm.data(), candidates[a].pair.lcm.data())) {
                candidates[a].alive = false;
                ++counts.removed_by_chain;
                break;
            }
        }
    }

    // Chain criterion on old pairs ("B" step).
    std::vector<std::uint64_t> lcm_1h(w), lcm_2h(w);
    std::size_t kept = 0;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        CriticalPair& p = pairs[k];
        bool remove = false;
        if (layout.divides(lm_h, p.lcm.data())) {
            layout.lcm(basis[p.first].poly.monomial(0, w), lm_h, lcm_1h.data());
            layout.lcm(basis[p.second].poly.monomial(0, w), lm_h, lcm_2h.data());
            remove = !layout.equal(lcm_1h.data(), p.lcm.data()) &&
                     !layout.equal(lcm_2h.data(), p.lcm.data());
        }
        if (remove) {
            ++counts.removed_by_chain;
        } else {
            if (kept != k) {
                pairs[kept] = std::move(p);
            }
            ++kept;
        }
    }
    pairs.resize(kept);

    // Product criterion, then install the survivors.
    for (auto& c : candidates) {
        if (!c.alive) {
            continue;
        }
        if (c.coprime) {
            ++counts.removed_by_product;
            continue;
        }
        pairs.push_back(std::move(c.pair));
    }

    // Old elements whose leading monomial lm(h) divides get no further pairs.
    for (std::size_t g = 0; g < new_index; ++g) {
        if (!basis[g].redundant && layout.divides(lm_h, basis[g].poly.monomial(0, w))) {
            basis[g].redundant = true;
        }
    }
}

}  // namespace locus::algebra::detail
