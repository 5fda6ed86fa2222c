// Small pieces of monomial-ideal arithmetic shared by the standard-monomial count and the
// Hilbert series (exponent vectors of one length).
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <vector>

#include "algebra/standard_monomials.h"

namespace locus::algebra::detail {

inline bool divides(const ExponentVector& a, const ExponentVector& b) {
    for (std::size_t v = 0; v < a.size(); ++v) {
        if (a[v] > b[v]) {
            return false;
        }
    }
    return true;
}

// How many variables g involves, and the last of them.
struct Support {
    std::size_t size = 0;
    std::size_t variable = 0;
};

inline Support support_of(const ExponentVector& g) {
    Support support;
    for (std::size_t v = 0; v < g.size(); ++v) {
        if (g[v] != 0) {
            ++support.size;
            support.variable = v;
        }
    }
    return support;
}

// Drops generators that another one divides (and duplicates).
inline void minimalize(std::vector<ExponentVector>& generators) {
    std::sort(generators.begin(), generators.end());
    generators.erase(std::unique(generators.begin(), generators.end()), generators.end());
    std::vector<ExponentVector> kept;
    for (std::size_t i = 0; i < generators.size(); ++i) {
        bool redundant = false;
        for (std::size_t j = 0; j < generators.size() && !redundant; ++j) {
            redundant = j != i && divides(generators[j], generators[i]);
        }
        if (!redundant) {
            kept.push_back(generators[i]);  // a copy: later rounds still divide by it
        }
    }
    generators = std::move(kept);
}

// The pivot variable of the splitting recursions: the one in most generators that are not pure
// powers (which shrinks both branches most), or none when every generator is a pure power.
inline std::optional<std::size_t> pivot_variable(const std::vector<ExponentVector>& generators,
                                                 std::size_t n) {
    std::vector<std::size_t> mixed_uses(n, 0);
    bool any_mixed = false;
    for (const ExponentVector& g : generators) {
        if (support_of(g).size < 2) {
            continue;
        }
        any_mixed = true;
        for (std::size_t v = 0; v < n; ++v) {
            mixed_uses[v] += g[v] != 0 ? 1 : 0;
        }
    }
    if (!any_mixed) {
        return std::nullopt;
    }
    return static_cast<std::size_t>(std::max_element(mixed_uses.begin(), mixed_uses.end()) -
                                    mixed_uses.begin());
}

// M + ⟨x⟩ and M : x.
inline std::vector<ExponentVector> plus_variable(const std::vector<ExponentVector>& generators,
                                                 std::size_t x, std::size_t n) {
    std::vector<ExponentVector> out;
    for (const ExponentVector& g : generators) {
        if (g[x] == 0) {
            out.push_back(g);
        }
    }
    ExponentVector x_itself(n, 0);
    x_itself[x] = 1;
    out.push_back(std::move(x_itself));
    return out;
}
inline std::vector<ExponentVector> colon_variable(std::vector<ExponentVector> generators,
                                                  std::size_t x) {
    for (ExponentVector& g : generators) {
        g[x] = g[x] > 0 ? g[x] - 1 : 0;
    }
    return generators;
}

}  // namespace locus::algebra::detail
