// Krull dimension, degree and Hilbert series: the 240 random oracle ideals against Singular's
// dim, mult, vdim and hilb (tests/data/oracle/dimension.txt, scripts/capture-singular-dimension),
// literature values, and on random monomial ideals against a brute-force count of standard
// monomials per degree and a brute-force search of independent sets (oracles that share no code
// with the recursion).
#include "algebra/hilbert_series.h"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <sstream>

#include "algebra/ideal_ops.h"
#include "algebra/parse.h"
#include "tests/support/ideal_cases.h"

namespace locus::algebra {
namespace {

struct SingularDimension {
    long dim = 0;
    std::string mult, vdim;
    std::vector<std::string> second_series;  // Singular's hilb(S, 2), its trailing 0 dropped
};

std::map<std::string, SingularDimension> singular_dimensions() {
    std::istringstream in(test::read_text(test::source_dir() + "/tests/data/oracle/dimension.txt"));
    std::map<std::string, SingularDimension> out;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("case ", 0) != 0) {
            continue;
        }
        std::istringstream fields(line.substr(5));
        std::string number, hilb_word, series;
        SingularDimension d;
        fields >> number >> d.dim >> d.mult >> d.vdim >> hilb_word >> series;
        std::istringstream entries(series);
        for (std::string c; std::getline(entries, c, ',');) {
            d.second_series.push_back(c);
        }
        d.second_series.pop_back();
        while (!d.second_series.empty() && d.second_series.back() == "0") {
            d.second_series.pop_back();
        }
        out[number] = d;
    }
    return out;
}

TEST(HilbertSeries, OracleIdealsAgreeWithSingular) {
    const auto expected = singular_dimensions();
    ASSERT_EQ(expected.size(), 240u);
    std::size_t positive = 0;
    for (const test::OracleCase& c : test::oracle_cases()) {
        const IdealFile ideal = parse_ideal_file(c.ideal);
        const HilbertData h = ideal_hilbert_data(ideal.ring, ideal.generators);
        const SingularDimension& s = expected.at(c.number);
        if (s.dim < 0) {
            EXPECT_TRUE(h.unit) << "case " << c.number;
            continue;
        }
        ASSERT_FALSE(h.unit) << "case " << c.number;
        EXPECT_EQ(static_cast<long>(h.dimension), s.dim) << "case " << c.number;
        EXPECT_EQ(h.degree.to_string(), s.mult) << "case " << c.number;
        std::vector<std::string> series;
        for (const Integer& q : h.reduced_numerator) {
            series.push_back(q.to_string());
        }
        EXPECT_EQ(series, s.second_series) << "case " << c.number;
        if (s.dim == 0) {
            EXPECT_EQ(h.degree.to_string(), s.vdim) << "case " << c.number;
        } else {
            ++positive;
        }
        EXPECT_EQ(h.independent_set.size(), h.dimension);
    }
    EXPECT_GE(positive, 100u);
}

TEST(HilbertSeries, KnownValues) {
    const RingPtr r = PolyRing::make({"x", "y", "z", "w"}, MonomialOrder::grevlex(4));
    const auto data = [&](std::vector<std::string> gens) {
        std::vector<Polynomial> polys;
        for (const std::string& g : gens) {
            polys.push_back(parse_polynomial(g, r));
        }
        return ideal_hilbert_data(r, polys);
    };
    // The twisted cubic's cone (homogeneous): a surface of degree 3 in P^3, HP = 3s + 1.
    const HilbertData cubic = data({"x*z-y^2", "y*w-z^2", "x*w-y*z"});
    EXPECT_EQ(cubic.dimension, 2u);
    EXPECT_EQ(cubic.degree.to_string(), "3");
    ASSERT_EQ(cubic.hilbert_polynomial.size(), 2u);
    EXPECT_EQ(cubic.hilbert_polynomial[1].to_string(), "3");
    EXPECT_EQ(cubic.hilbert_polynomial[0].to_string(), "1");
    // A complete intersection of degrees 2, 3 and 4: degree 24, zero-dimensional.
    const HilbertData ci = data({"x^2-y*w", "y^3-z*x^2", "z^4-w^4+x", "w^5"});
    EXPECT_EQ(ci.dimension, 0u);
    // The zero ideal: Q[x,y,z,w], HS = 1/(1−t)^4, HP = C(s+3, 3).
    const HilbertData zero = data({});
    EXPECT_EQ(zero.dimension, 4u);
    EXPECT_EQ(zero.degree.to_string(), "1");
    EXPECT_EQ(zero.hilbert_polynomial.back().to_string(), "1/6");
    EXPECT_EQ(hilbert_function(zero, 5).to_string(), "56");
    EXPECT_TRUE(data({"x*y-1", "x"}).unit);
}

// Random monomial ideals: the series' coefficients are the number of standard monomials of
// each degree, counted one by one; the dimension is the largest independent set, found by trying
// every subset; HF = HP from the regularity on.
TEST(HilbertSeries, RandomMonomialIdealsAgainstBruteForce) {
    std::mt19937 rng(20261126);
    for (int round = 0; round < 150; ++round) {
        const std::size_t n = 1 + rng() % 4;
        std::vector<ExponentVector> gens(rng() % 5);
        for (ExponentVector& g : gens) {
            g.resize(n);
            for (std::uint32_t& e : g) {
                e = rng() % 4 == 0 ? 0 : rng() % 3;
            }
        }
        const HilbertData h = hilbert_data(gens, n);
        const auto standard = [&](const ExponentVector& m) {
            for (const ExponentVector& g : gens) {
                bool divides = true;
                for (std::size_t v = 0; v < n; ++v) {
                    divides = divides && g[v] <= m[v];
                }
                if (divides) {
                    return false;
                }
            }
            return true;
        };
        for (std::size_t s = 0; s <= 7; ++s) {
            // Every monomial of degree s in n variables.
            long count = 0;
            ExponentVector m(n, 0);
            const std::function<void(std::size_t, std::size_t)> walk = [&](std::size_t v,
                                                                           std::size_t left) {
                if (v + 1 == n) {
                    m[v] = static_cast<std::uint32_t>(left);
                    count += standard(m) ? 1 : 0;
                    return;
                }
                for (std::size_t e = 0; e <= left; ++e) {
                    m[v] = static_cast<std::uint32_t>(e);
                    walk(v + 1, left - e);
                }
            };
            walk(0, s);
            ASSERT_EQ(hilbert_function(h, s).to_string(), std::to_string(count))
                << "round " << round << " degree " << s;
            if (!h.unit && h.dimension > 0 && s >= h.regularity) {
                Rational hp(0), power(1);
                for (const Rational& c : h.hilbert_polynomial) {
                    hp += c * power;
                    power *= Rational(static_cast<long>(s));
                }
                EXPECT_EQ(hp.to_string(), std::to_string(count)) << "round " << round;
            }
        }
        if (h.unit) {
            continue;
        }
        std::size_t largest = 0;
        for (std::size_t subset = 0; subset < (std::size_t{1} << n); ++subset) {
            const bool independent = std::none_of(gens.begin(), gens.end(), [&](const auto& g) {
                for (std::size_t v = 0; v < n; ++v) {
                    if (g[v] != 0 && !(subset >> v & 1)) {
                        return false;
                    }
                }
                return true;
            });
            if (independent) {
                largest = std::max<std::size_t>(largest, std::popcount(subset));
            }
        }
        EXPECT_EQ(h.dimension, largest) << "round " << round;
    }
}

}  // namespace
}  // namespace locus::algebra
