// F4's pair update (Gebauer–Möller's criteria as Becker–Weispfenning's UPDATE) and the
// selection of each step's pairs by sugar.
#include "algebra/modular/detail/f4_engine.h"

#include <algorithm>

namespace locus::algebra::modular::detail {

// An element without pairs (a replay repeats the recorded steps instead).
// In a replay, also notes whether its support is the recorded one.
void F4Engine::append_element(ModularPolynomial poly) {
    const std::size_t h = basis_.size();
    fits_trace_.push_back(replaying_ != nullptr && h < replaying_->supports.size() &&
                          poly.monomials == replaying_->supports[h]);
    basis_.push_back({std::move(poly), 0, false, false, 0, {}});
    basis_[h].mask = layout_.divisibility_mask(lead(h));
    live_.add(h, basis_[h].mask, lead(h), words_);
}

// Gebauer–Möller (Becker–Weispfenning's UPDATE) for the element just appended.
void F4Engine::add_element(ModularPolynomial poly, std::uint32_t sugar) {
    check_deadline();  // each call is quadratic in the basis size
    const std::size_t h = basis_.size();
    if (record_ != nullptr) {
        record_->supports.push_back(poly.monomials);
    }
    basis_.push_back({std::move(poly), 0, false, false, sugar, {}});
    basis_[h].mask = layout_.divisibility_mask(lead(h));
    // The new pairs (g, h), g live, with their lcms in one block (a vector per pair cost an
    // allocation for every pair created, most of which the chain criterion drops at once).
    const std::size_t count = live_.index.size();
    stats_.pairs_created += count;
    std::vector<std::uint64_t> lcms(count * words_);
    std::vector<std::uint64_t> lcm_mask(count);
    std::vector<std::uint32_t> by_lcm(count);
    for (std::size_t a = 0; a < count; ++a) {
        layout_.lcm(live_.lead.data() + a * words_, lead(h), lcms.data() + a * words_);
        lcm_mask[a] = layout_.divisibility_mask(lcms.data() + a * words_);
        by_lcm[a] = static_cast<std::uint32_t>(a);
    }
    // Chain criterion among the new pairs (M and F): of the pairs whose lcms divide one
    // another, only the first of those with the least lcm stays, that is, a pair stays when no
    // other pair's lcm properly divides its lcm and no earlier pair has the same lcm. A proper
    // divisor is smaller under any (global) monomial order, so in the order of the lcms, ties
    // by position, a pair need only be compared with the pairs kept before it: a dropped pair's
    // divisor is kept and divides as well. Comparing every pair with every other was quadratic
    // in the basis size (4 % of cyclic-8 modulo a prime); this is linear in it times the
    // survivors, a few dozen. The divisibility mask rejects most non-divisors first.
    std::sort(by_lcm.begin(), by_lcm.end(), [&](std::uint32_t a, std::uint32_t b) {
        const int order = layout_.compare(lcms.data() + a * words_, lcms.data() + b * words_);
        return order != 0 ? order < 0 : a < b;
    });
    std::vector<char> keep(count, 0);
    std::vector<std::uint32_t> survivors;
    for (const std::uint32_t a : by_lcm) {
        const std::uint64_t* lcm_a = lcms.data() + a * words_;
        const bool divided = std::any_of(survivors.begin(), survivors.end(), [&](std::uint32_t b) {
            return (lcm_mask[b] & ~lcm_mask[a]) == 0 &&
                   layout_.divides(lcms.data() + b * words_, lcm_a);
        });
        if (divided) {
            ++stats_.removed_by_chain;
        } else {
            keep[a] = 1;
            survivors.push_back(a);
        }
    }
    // Old pairs (B): drop (g1, g2) when lm(h) divides their lcm and both lcm(gi, h) differ.
    std::vector<std::uint64_t> scratch(words_);
    std::erase_if(pairs_, [&](const Pair& pair) {
        if (!layout_.divides(lead(h), pair.lcm.data())) {
            return false;
        }
        layout_.lcm(lead(pair.first), lead(h), scratch.data());
        if (layout_.equal(scratch.data(), pair.lcm.data())) {
            return false;
        }
        layout_.lcm(lead(pair.second), lead(h), scratch.data());
        if (layout_.equal(scratch.data(), pair.lcm.data())) {
            return false;
        }
        ++stats_.removed_by_chain;
        return true;
    });
    // Product criterion on the survivors, which join the pairs in the order of the live
    // elements (the order select_pairs breaks ties by).
    for (std::size_t a = 0; a < count; ++a) {
        if (!keep[a]) {
            continue;
        }
        const std::uint32_t g = live_.index[a];
        if (layout_.coprime(lead(g), lead(h))) {
            ++stats_.removed_by_product;
            continue;
        }
        const std::uint64_t* lcm = lcms.data() + a * words_;
        const std::uint32_t lcm_degree = layout_.leading_weight(lcm);
        const std::uint32_t degree =
            std::max(basis_[g].sugar + lcm_degree - layout_.leading_weight(lead(g)),
                     sugar + lcm_degree - layout_.leading_weight(lead(h)));
        pairs_.push_back({g, h, std::vector<std::uint64_t>(lcm, lcm + words_), degree});
    }
    // The elements h makes redundant leave the live ones, and h joins them.
    live_.erase_if(
        [&](std::uint32_t g) {
            basis_[g].redundant = layout_.divides(lead(h), lead(g));
            return basis_[g].redundant;
        },
        words_);
    live_.add(h, basis_[h].mask, lead(h), words_);
}

// The pairs of this step: all of the least sugar degree (batch_, degree orders), or the one
// best pair; `degree` receives the sugar of what the step makes.
std::vector<Pair> F4Engine::select_pairs(std::uint32_t& degree) {
    degree = pairs_.front().degree;
    for (const Pair& pair : pairs_) {
        degree = std::min(degree, pair.degree);
    }
    std::vector<Pair> chosen;
    if (!batch_) {
        std::size_t best = pairs_.size();
        for (std::size_t i = 0; i < pairs_.size(); ++i) {
            const bool better =
                best == pairs_.size() ||
                (!by_lcm_only_ && pairs_[i].degree != pairs_[best].degree
                     ? pairs_[i].degree < pairs_[best].degree
                     : layout_.compare(pairs_[i].lcm.data(), pairs_[best].lcm.data()) < 0);
            if (better) {
                best = i;
            }
        }
        degree = pairs_[best].degree;  // the sugar of what this step makes
        chosen.push_back(std::move(pairs_[best]));
        pairs_.erase(pairs_.begin() + static_cast<long>(best));
    } else {
        std::erase_if(pairs_, [&](Pair& pair) {
            if (pair.degree != degree) {
                return false;
            }
            chosen.push_back(std::move(pair));
            return true;
        });
    }
    stats_.pairs_reduced += chosen.size();
    return chosen;
}

void F4Engine::release_finished() {
    std::vector<char> paired(basis_.size(), 0);
    for (const Pair& pair : pairs_) {
        paired[pair.first] = 1;
        paired[pair.second] = 1;
    }
    for (std::size_t g = 0; g < basis_.size(); ++g) {
        Element& e = basis_[g];
        if (!e.redundant || e.released || paired[g]) {
            continue;
        }
        e.poly.monomials.resize(words_);
        e.poly.monomials.shrink_to_fit();
        e.poly.coefficients.resize(1);
        e.poly.coefficients.shrink_to_fit();
        e.term_hashes = {};
        e.released = true;
        ++stats_.released_elements;
    }
}

}  // namespace locus::algebra::modular::detail
