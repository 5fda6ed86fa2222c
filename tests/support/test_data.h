// Shared helpers for the test suites: data paths, seeds and small random objects.
#pragma once

#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "algebra/polynomial.h"

namespace locus::test {

// Root of the source tree (tests run with LOCUS_SOURCE_DIR set by CMake).
inline std::string source_dir() {
    const char* dir = std::getenv("LOCUS_SOURCE_DIR");
    return dir ? dir : ".";
}

inline std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// Number of seeds for property tests: base · LOCUS_TEST_MULTIPLIER (default 1).
inline int seed_count(int base) {
    const char* m = std::getenv("LOCUS_TEST_MULTIPLIER");
    const int multiplier = m ? std::max(1, std::atoi(m)) : 1;
    return base * multiplier;
}

// A random sparse polynomial: `terms` terms, each exponent below max_exponent, coefficients
// small integers or halves/thirds (never zero).
inline algebra::Polynomial random_polynomial(const algebra::RingPtr& ring, std::mt19937_64& rng,
                                             int terms, unsigned max_exponent,
                                             bool rational = true) {
    std::uniform_int_distribution<long> coefficient(-9, 9);
    std::uniform_int_distribution<unsigned> exponent(0, max_exponent);
    std::uniform_int_distribution<unsigned long> denominator(1, rational ? 3 : 1);
    std::vector<std::pair<algebra::Rational, std::vector<std::uint32_t>>> t;
    for (int k = 0; k < terms; ++k) {
        long c = 0;
        while (c == 0) {
            c = coefficient(rng);
        }
        std::vector<std::uint32_t> e(ring->num_vars());
        for (auto& x : e) {
            x = exponent(rng);
        }
        t.emplace_back(algebra::Rational(c, denominator(rng)), std::move(e));
    }
    return algebra::Polynomial::from_terms(ring, std::move(t));
}

}  // namespace locus::test
