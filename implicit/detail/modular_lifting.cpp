#include "implicit/detail/modular_lifting.h"

#include "algebra/modular/modular_polynomial.h"

namespace locus::implicit::detail {

NormalizedLifting::NormalizedLifting(std::size_t size, std::size_t pivot)
    : pivot_(pivot), numbers_(size), current_(size) {}

bool NormalizedLifting::add(const std::vector<ulong>& image, ulong p) {
    const algebra::modular::PrimeField field(p);
    const ulong scale = field.inverse(image[pivot_]);
    for (std::size_t j = 0; j < numbers_.size(); ++j) {
        numbers_[j].residues.push_back(field.multiply(image[j], scale));
    }
    lift_.add_prime(p);
    if (!lift_.attempt_due()) {
        return false;
    }
    algebra::modular::RationalLift::Attempt attempt(lift_);
    bool confirmed = true;
    for (std::size_t j = 0; j < numbers_.size(); ++j) {
        // The entries share the pivot's denominator (they are a primitive integer vector
        // divided by its pivot entry): as integers over it they need about half the primes.
        const bool found = attempt.reconstruct_sharing(numbers_[j], denominator_, hint_, [&] {
            return algebra::modular::companions_near(
                j, numbers_.size(), 7, pivot_,
                [&](std::size_t u) -> algebra::modular::LiftedNumber& { return numbers_[u]; });
        });
        if (!found) {
            return false;
        }
        confirmed = confirmed && numbers_[j].confirmed();
    }
    if (!confirmed) {
        return false;
    }
    for (std::size_t j = 0; j < numbers_.size(); ++j) {
        current_[j] = numbers_[j].value;
    }
    return true;
}

}  // namespace locus::implicit::detail
