// Lifting a vector of rationals from its images modulo primes: Chinese remaindering and
// rational reconstruction (Wang), shared by the interpolation and Dixon routes. The vector is
// known only up to a scalar, so every image is normalised first (the coefficient at `pivot`
// becomes 1); the lift is accepted when reconstruction succeeds and agrees with the lift of one
// prime fewer, and the caller then proves the result exactly (a lift is only a candidate).
#pragma once

#include <flint/flint.h>

#include <vector>

#include "algebra/rational.h"

namespace locus::implicit::detail {

class NormalizedLifting {
  public:
    NormalizedLifting(std::size_t size, std::size_t pivot);

    // Adds an image modulo the prime p (its `pivot` entry must be non-zero: the caller skips
    // primes where it is not). Returns true when the reconstruction is stable.
    bool add(const std::vector<ulong>& image, ulong p);

    // The current reconstruction (meaningful after add returned true).
    const std::vector<algebra::Rational>& values() const { return current_; }
    std::size_t primes() const { return primes_; }

  private:
    std::size_t pivot_;
    std::size_t primes_ = 0;
    std::vector<algebra::Integer> residues_;
    algebra::Integer modulus_{1};
    std::vector<algebra::Rational> previous_, current_;
};

}  // namespace locus::implicit::detail
