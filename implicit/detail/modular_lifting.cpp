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
            std::vector<algebra::modular::LiftedNumber*> companions;
            for (std::size_t u = 0; u < numbers_.size() && companions.size() < 3; ++u) {
                if (u != j && u != pivot_) {
                    companions.push_back(&numbers_[u]);
                }
            }
            return companions;
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
