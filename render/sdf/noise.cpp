#include "render/sdf/noise.h"

#include <cmath>
#include <numeric>

namespace locus::render::sdf {

namespace {

double fade(double t) {
    return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

double lerp(double t, double a, double b) {
    return a + t * (b - a);
}

// The twelve edge directions of the cube (Perlin 2002), picked by the low four bits.
double grad(int hash, double x, double y, double z) {
    const int h = hash & 15;
    const double u = h < 8 ? x : y;
    const double v = h < 4 ? y : (h == 12 || h == 14 ? x : z);
    return ((h & 1) == 0 ? u : -u) + ((h & 2) == 0 ? v : -v);
}

// Improved noise has values in about [−1.04, 1.04] and gradients up to about 2.9 (measured by
// dense sampling, tests/render/sdf_lipschitz_test.cpp); this factor makes both safe: values
// within ±0.95 and gradients within 2.7 < 3.
constexpr double kOctaveScale = 0.92;

}  // namespace

Noise::Noise(double amplitude, double frequency, int octaves, std::uint64_t seed)
    : amplitude_(amplitude), frequency_(frequency), octaves_(octaves) {
    std::array<std::uint8_t, 256> p{};
    std::iota(p.begin(), p.end(), 0);
    // Fisher–Yates with SplitMix64, so that a seed always gives the same field.
    std::uint64_t state = seed;
    for (int i = 255; i > 0; --i) {
        state += 0x9e3779b97f4a7c15ULL;
        std::uint64_t z = state;
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        z ^= z >> 31;
        std::swap(p[static_cast<std::size_t>(i)], p[z % static_cast<std::uint64_t>(i + 1)]);
    }
    for (std::size_t i = 0; i < 512; ++i) {
        permutation_[i] = p[i & 255];
    }
    double a = amplitude, f = frequency;
    for (int i = 0; i < octaves; ++i) {
        lipschitz_ += 3.0 * a * f;
        max_amplitude_ += a;
        a *= 0.5;
        f *= 2.0;
    }
}

double Noise::octave(const Vec3& point) const {
    const Vec3 cell = glm::floor(point);
    const int X = static_cast<int>(static_cast<long long>(cell.x) & 255);
    const int Y = static_cast<int>(static_cast<long long>(cell.y) & 255);
    const int Z = static_cast<int>(static_cast<long long>(cell.z) & 255);
    const double x = point.x - cell.x, y = point.y - cell.y, z = point.z - cell.z;
    const double u = fade(x), v = fade(y), w = fade(z);
    const auto& P = permutation_;
    const int A = P[X] + Y, AA = P[A] + Z, AB = P[A + 1] + Z;
    const int B = P[X + 1] + Y, BA = P[B] + Z, BB = P[B + 1] + Z;
    const double n =
        lerp(w,
             lerp(v, lerp(u, grad(P[AA], x, y, z), grad(P[BA], x - 1, y, z)),
                  lerp(u, grad(P[AB], x, y - 1, z), grad(P[BB], x - 1, y - 1, z))),
             lerp(v, lerp(u, grad(P[AA + 1], x, y, z - 1), grad(P[BA + 1], x - 1, y, z - 1)),
                  lerp(u, grad(P[AB + 1], x, y - 1, z - 1), grad(P[BB + 1], x - 1, y - 1, z - 1))));
    return kOctaveScale * n;
}

double Noise::value(const Vec3& p) const {
    double sum = 0.0, a = amplitude_, f = frequency_;
    for (int i = 0; i < octaves_; ++i) {
        sum += a * octave(p * f);
        a *= 0.5;
        f *= 2.0;
    }
    return sum;
}

}  // namespace locus::render::sdf
