#include "algebra/standard_monomials.h"

#include <algorithm>

#include "algebra/deadline.h"
#include "algebra/detail/monomial_ideal.h"
#include "algebra/error.h"

namespace locus::algebra {
namespace {

using detail::minimalize;
using detail::Support;
using detail::support_of;

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
        for (const ExponentVector& g : generators) {
            const Support support = support_of(g);
            if (support.size == 0) {
                return Integer(0);  // the unit ideal: nothing is standard
            }
            if (support.size == 1) {
                // Minimal: one pure power per variable, and every variable keeps one (both
                // M + ⟨x⟩ and M : x keep the others' and give x its own).
                pure[support.variable] = g[support.variable];
            }
        }
        const std::optional<std::size_t> pivot = detail::pivot_variable(generators, n_);
        if (!pivot) {
            Integer product(1);
            for (std::uint32_t d : pure) {
                fmpz_mul_ui(product.get(), product.get(), d);
            }
            return product;
        }
        const std::size_t x = *pivot;
        std::vector<ExponentVector> plus_x = detail::plus_variable(generators, x, n_);
        std::vector<ExponentVector> colon_x = detail::colon_variable(std::move(generators), x);
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
