#include "algebra/poly_ring.h"

#include <algorithm>
#include <cctype>

#include "algebra/error.h"

namespace locus::algebra {
namespace {

bool is_identifier(const std::string& s) {
    if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) {
        return false;
    }
    return std::all_of(s.begin(), s.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    });
}

}  // namespace

PolyRing::PolyRing(std::vector<std::string> names, MonomialOrder order)
    : names_(std::move(names)), layout_(order) {}

RingPtr PolyRing::make(std::vector<std::string> names, MonomialOrder order) {
    if (order.num_vars() != names.size()) {
        throw InputError("ring", "the order is for " + std::to_string(order.num_vars()) +
                                     " variables but " + std::to_string(names.size()) +
                                     " are declared");
    }
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (!is_identifier(names[i])) {
            throw InputError("'" + names[i] + "'", "a variable name must be an identifier");
        }
        for (std::size_t j = 0; j < i; ++j) {
            if (names[i] == names[j]) {
                throw InputError("'" + names[i] + "'", "variable declared twice");
            }
        }
    }
    return RingPtr(new PolyRing(std::move(names), std::move(order)));
}

RingPtr PolyRing::with_order(MonomialOrder order) const {
    return make(names_, std::move(order));
}

std::optional<std::size_t> PolyRing::variable_index(std::string_view name) const {
    for (std::size_t i = 0; i < names_.size(); ++i) {
        if (names_[i] == name) {
            return i;
        }
    }
    return std::nullopt;
}

bool same_ring(const RingPtr& a, const RingPtr& b) {
    return a == b || (a && b && *a == *b);
}

}  // namespace locus::algebra
