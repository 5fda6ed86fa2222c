// Lifting a vector of rationals known only up to a scalar from its images modulo primes, for the
// interpolation and Dixon routes: every image is normalised first (the coefficient at `pivot`
// becomes 1), then lifted by the library's one lifting machinery (algebra/modular/
// rational_lift.h: product-tree Chinese remaindering, Wang's reconstruction, values checked
// against later primes). The lift is accepted when every value is confirmed by a prime it was
// not reconstructed from, and the caller then proves the result exactly (a lift is only a
// candidate).
#pragma once

#include <flint/flint.h>

#include <vector>

#include "algebra/modular/rational_lift.h"
#include "algebra/rational.h"

namespace locus::implicit::detail {

class NormalizedLifting {
  public:
    NormalizedLifting(std::size_t size, std::size_t pivot);

    // Adds an image modulo the prime p (its `pivot` entry must be non-zero: the caller skips
    // primes where it is not; primes must be distinct). Returns true when the reconstruction
    // is stable.
    bool add(const std::vector<ulong>& image, ulong p);

    // The current reconstruction (meaningful after add returned true).
    const std::vector<algebra::Rational>& values() const { return current_; }
    std::size_t primes() const { return lift_.primes(); }

  private:
    std::size_t pivot_;
    algebra::modular::RationalLift lift_;
    std::vector<algebra::modular::LiftedNumber> numbers_;
    std::vector<algebra::Rational> current_;
    algebra::Integer denominator_{1}, hint_{1};  // rational_lift.h's reconstruct_sharing
};

}  // namespace locus::implicit::detail
