// Shared data of the Gröbner test suites (Buchberger, signature-based, multi-modular): the
// registered literature cases, the Singular oracle ideals, and small random ideals.
#pragma once

#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "algebra/parse.h"
#include "tests/support/test_data.h"

namespace locus::test {

// The names listed in tests/data/known/CASES.txt; each has NAME.ideal and NAME.expected (the
// normalized reduced basis) beside it.
inline std::vector<std::string> known_case_names() {
    std::vector<std::string> names;
    std::istringstream in(read_text(source_dir() + "/tests/data/known/CASES.txt"));
    for (std::string line; std::getline(in, line);) {
        if (!line.empty() && line[0] != '#') {
            names.push_back(line);
        }
    }
    return names;
}

// One ideal of tests/data/oracle/random.txt: its number, its ideal file and the normalized reduced
// basis Singular computed (scripts/capture-singular-oracle).
struct OracleCase {
    std::string number, ideal, expected;
};

inline std::vector<OracleCase> oracle_cases() {
    std::istringstream in(read_text(source_dir() + "/tests/data/oracle/random.txt"));
    std::vector<OracleCase> cases;
    OracleCase current;
    enum { outside, reading_ideal, reading_expected } state = outside;
    for (std::string line; std::getline(in, line);) {
        if (state == outside && line.rfind("case ", 0) == 0) {
            current = {line.substr(5), "", ""};
            state = reading_ideal;
        } else if (state == reading_ideal && line == "expected:") {
            state = reading_expected;
        } else if (state == reading_ideal) {
            current.ideal += line + "\n";
        } else if (state == reading_expected && line == "end") {
            cases.push_back(current);
            state = outside;
        } else if (state == reading_expected) {
            current.expected += line + "\n";
        }
    }
    return cases;
}

// A random small ideal: 2–4 variables, 2–4 sparse generators of degree ≤ 4, under one of lex,
// grlex, grevlex, weights, elim(y) and elim(x,z), chosen by the seed.
inline algebra::IdealFile random_ideal(std::mt19937_64& rng, int seed) {
    const char* orders[] = {"lex", "grlex", "grevlex", "weights(1,2,1,3)", "elim(y)", "elim(x,z)"};
    const std::vector<std::string> all = {"x", "y", "z", "w"};
    const std::size_t n = 2 + static_cast<std::size_t>(seed) % 3;
    std::vector<std::string> names(all.begin(), all.begin() + static_cast<long>(n));
    std::string order = orders[seed % 6];
    if (order.rfind("weights", 0) == 0) {
        order = n == 2 ? "weights(1,2)" : n == 3 ? "weights(1,2,1)" : order;
    }
    if (order == "elim(x,z)" && n == 2) {
        order = "elim(x)";
    }
    algebra::IdealFile f;
    f.ring = algebra::PolyRing::make(names, algebra::parse_monomial_order(order, names));
    const int count = 2 + seed % 3;
    for (int k = 0; k < count; ++k) {
        // Exponents up to 2 in 2–3 variables, up to 1 in 4 (degree ≤ 4 either way).
        f.generators.push_back(random_polynomial(f.ring, rng, 2 + (seed + k) % 3, n == 4 ? 1 : 2));
    }
    return f;
}

}  // namespace locus::test
