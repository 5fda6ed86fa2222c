// A polynomial ring Q[x1..xn] with a fixed monomial order, as an immutable shared value.
//
// The ring owns the variable names (declared order = the order's tie-break, x > y > z), the
// MonomialOrder and the packed MonomialLayout derived from it. Polynomials hold a
// shared_ptr<const PolyRing>; operations on polynomials of different rings throw MixedRings
// unless the rings are equal as values (same names, same order). CoCoALib's "specify the ring
// first" rule: there is no global current ring.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "algebra/monomial.h"
#include "algebra/monomial_order.h"

namespace locus::algebra {

class PolyRing;
using RingPtr = std::shared_ptr<const PolyRing>;

class PolyRing {
  public:
    // Throws InputError when a name is repeated or is not an identifier.
    static RingPtr make(std::vector<std::string> variable_names, MonomialOrder order);
    // Same variables, another order (for elimination and order changes).
    RingPtr with_order(MonomialOrder order) const;

    const std::vector<std::string>& variable_names() const { return names_; }
    const std::string& variable_name(std::size_t i) const { return names_[i]; }
    std::size_t num_vars() const { return names_.size(); }
    const MonomialOrder& order() const { return layout_.order(); }
    const MonomialLayout& layout() const { return layout_; }
    std::size_t words() const { return layout_.words(); }
    std::optional<std::size_t> variable_index(std::string_view name) const;

    friend bool operator==(const PolyRing& a, const PolyRing& b) {
        return a.names_ == b.names_ && a.order() == b.order();
    }

  private:
    PolyRing(std::vector<std::string> names, MonomialOrder order);

    std::vector<std::string> names_;
    MonomialLayout layout_;
};

// True when both pointers denote equal rings (cheap when they are the same object).
bool same_ring(const RingPtr& a, const RingPtr& b);

}  // namespace locus::algebra
