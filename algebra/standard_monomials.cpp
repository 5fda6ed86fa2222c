#include "algebra/standard_monomials.h"

#include <algorithm>

#include "algebra/deadline.h"
#include "algebra/error.h"

namespace locus::algebra {
namespace {

bool divides(const ExponentVector& a, const ExponentVector& b) {
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

Support support_of(const ExponentVector& g) {
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
void minimalize(std::vector<ExponentVector>& generators) {
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

class Counter {
  public:
    Counter(std::size_t n, std::optional<std::chrono::steady_clock::time_point> deadline)
        : n_(n), deadline_(deadline) {}

    Integer count(std::vector<ExponentVector> generators) {
        if ((++calls_ & 0xff) == 0 && deadline_passed(deadline_)) {
            throw Timeout("counting the standard monomials was not complete at the deadline");
        }
        minimalize(generators);
        std::vector<std::uint32_t> pure(n_, 0);
        std::vector<std::size_t> mixed_uses(n_, 0);
        bool any_mixed = false;
        for (const ExponentVector& g : generators) {
            const Support support = support_of(g);
            if (support.size == 0) {
                return Integer(0);  // the unit ideal: nothing is standard
            }
            if (support.size == 1) {
                // Minimal: one pure power per variable, and every variable keeps one (both
                // M + ⟨x⟩ and M : x keep the others' and give x its own).
                pure[support.variable] = g[support.variable];
                continue;
            }
            any_mixed = true;
            for (std::size_t v = 0; v < n_; ++v) {
                mixed_uses[v] += g[v] != 0 ? 1 : 0;
            }
        }
        if (!any_mixed) {
            Integer product(1);
            for (std::uint32_t d : pure) {
                fmpz_mul_ui(product.get(), product.get(), d);
            }
            return product;
        }
        // The pivot: the variable in most mixed generators, which shrinks both branches most.
        const auto x = static_cast<std::size_t>(
            std::max_element(mixed_uses.begin(), mixed_uses.end()) - mixed_uses.begin());
        std::vector<ExponentVector> plus_x;                // M + ⟨x⟩
        std::vector<ExponentVector> colon_x = generators;  // M : x
        for (const ExponentVector& g : generators) {
            if (g[x] == 0) {
                plus_x.push_back(g);
            }
        }
        ExponentVector x_itself(n_, 0);
        x_itself[x] = 1;
        plus_x.push_back(std::move(x_itself));
        for (ExponentVector& g : colon_x) {
            g[x] = g[x] > 0 ? g[x] - 1 : 0;
        }
        Integer total = count(std::move(plus_x));
        const Integer with_x = count(std::move(colon_x));
        fmpz_add(total.get(), total.get(), with_x.get());
        return total;
    }

  private:
    std::size_t n_;
    std::optional<std::chrono::steady_clock::time_point> deadline_;
    std::uint64_t calls_ = 0;
};

}  // namespace

bool has_finitely_many_standard_monomials(const std::vector<ExponentVector>& generators,
                                          std::size_t n) {
    std::vector<bool> has_pure_power(n, false);
    for (const ExponentVector& g : generators) {
        const Support support = support_of(g);
        if (support.size == 0) {
            return true;
        }
        if (support.size == 1) {
            has_pure_power[support.variable] = true;
        }
    }
    return std::all_of(has_pure_power.begin(), has_pure_power.end(), [](bool b) { return b; });
}

Integer count_standard_monomials(std::vector<ExponentVector> generators, std::size_t n,
                                 std::optional<std::chrono::steady_clock::time_point> deadline) {
    for (const ExponentVector& g : generators) {
        if (g.size() != n) {
            throw InputError("standard monomials", "an exponent vector of the wrong length");
        }
    }
    if (!has_finitely_many_standard_monomials(generators, n)) {
        throw InputError("standard monomials", "the monomial ideal is not zero-dimensional");
    }
    return Counter(n, deadline).count(std::move(generators));
}

}  // namespace locus::algebra
