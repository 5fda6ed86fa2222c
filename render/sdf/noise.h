// Band-limited noise for displacements: Perlin's improved gradient noise (2002) summed over
// octaves (fractional Brownian motion). Octave i has frequency f·2^i and amplitude a·2^(−i);
// each is scaled so that its gradient never exceeds 3·amplitude·frequency, the "3 per octave"
// Lipschitz constant Hart uses for noise (checked by tests/render/sdf_lipschitz_test.cpp).
#pragma once

#include <array>
#include <cstdint>

#include "render/vec3.h"

namespace locus::render::sdf {

class Noise {
  public:
    Noise(double amplitude, double frequency, int octaves, std::uint64_t seed);

    double value(const Vec3& p) const;
    // Σ 3·aᵢ·fᵢ over the octaves: a Lipschitz constant of value().
    double lipschitz() const { return lipschitz_; }
    // Σ aᵢ: |value| never exceeds it (the bounds of a displaced node grow by this much).
    double max_amplitude() const { return max_amplitude_; }

  private:
    double octave(const Vec3& p) const;  // one octave, |value| ≤ 1, |gradient| ≤ 3

    std::array<std::uint8_t, 512> permutation_{};
    double amplitude_, frequency_;
    int octaves_;
    double lipschitz_ = 0.0, max_amplitude_ = 0.0;
};

}  // namespace locus::render::sdf
