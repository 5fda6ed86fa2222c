// Every order kind: total, compatible with multiplication, 1 smallest, and the packed
// comparison agrees with the matrix definition; exponent overflow is reported, never wrapped.
#include "algebra/monomial_order.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <vector>

#include "algebra/error.h"
#include "algebra/monomial.h"
#include "algebra/monomial_table.h"
#include "tests/support/test_data.h"

namespace locus::algebra {
namespace {

struct OrderCase {
    std::string name;
    std::string text;
    std::vector<std::string> vars;
};

std::vector<OrderCase> order_cases() {
    const std::vector<std::string> v4 = {"x", "y", "z", "w"};
    std::vector<std::string> wide;
    for (char first = 'a'; first < 'f'; ++first) {
        for (char second = 'a'; second < 'i'; ++second) {
            wide.push_back(std::string{first, second});  // 40 names: aa … eh
        }
    }
    return {{"lex", "lex", v4},
            {"grlex", "grlex", v4},
            {"grevlex", "grevlex", v4},
            {"weights", "weights(1,2,3,1)", v4},
            {"elim_first", "elim(x)", v4},
            {"elim_inner", "elim(z,y)", v4},
            {"matrix", "matrix((1,1,1,1),(0,0,0,-1),(0,0,-1,0),(0,-1,0,0))", v4},
            {"matrix_mixed", "matrix((2,1,0,1),(0,-1,1,0),(0,0,0,1),(1,0,0,0))", v4},
            {"grevlex_many", "grevlex", {"a", "b", "c", "d", "e", "f", "g", "h", "i", "j"}},
            // Past 32 variables the divisibility mask has one bit a variable.
            {"grevlex_wide", "grevlex", wide}};
}

class MonomialOrderTest : public ::testing::TestWithParam<OrderCase> {};

std::vector<std::uint32_t> random_exponents(std::mt19937_64& rng, std::size_t n, unsigned max) {
    std::uniform_int_distribution<unsigned> d(0, max);
    std::vector<std::uint32_t> e(n);
    for (auto& x : e) {
        x = d(rng);
    }
    return e;
}

TEST_P(MonomialOrderTest, TotalMultiplicativeAndOneSmallest) {
    const OrderCase& c = GetParam();
    const MonomialOrder order = parse_monomial_order(c.text, c.vars);
    const MonomialLayout layout(order);
    const std::size_t n = c.vars.size();
    const std::size_t w = layout.words();
    std::vector<std::uint32_t> one(n, 0);
    std::vector<std::uint64_t> pa(w), pb(w), pc(w), pac(w), pbc(w), pone(w);
    layout.pack(one, pone.data());
    for (int seed = 0; seed < test::seed_count(300); ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        std::mt19937_64 rng(seed);
        auto a = random_exponents(rng, n, 4), b = random_exponents(rng, n, 4),
             m = random_exponents(rng, n, 3);
        layout.pack(a, pa.data());
        layout.pack(b, pb.data());
        layout.pack(m, pc.data());
        const int ab = layout.compare(pa.data(), pb.data());
        // Packed comparison is the matrix definition.
        EXPECT_EQ(ab, order.compare(a, b));
        // Antisymmetric and total: equal only for equal exponents.
        EXPECT_EQ(ab, -layout.compare(pb.data(), pa.data()));
        EXPECT_EQ(ab == 0, a == b);
        // Multiplicative: a < b implies a·m < b·m.
        layout.multiply(pa.data(), pc.data(), pac.data());
        layout.multiply(pb.data(), pc.data(), pbc.data());
        EXPECT_EQ(layout.compare(pac.data(), pbc.data()), ab);
        // 1 is the smallest monomial.
        if (a != one) {
            EXPECT_GT(layout.compare(pa.data(), pone.data()), 0);
        }
        // Word operations agree with exponent arithmetic.
        std::vector<std::uint32_t> back(n);
        layout.unpack(pac.data(), back);
        for (std::size_t i = 0; i < n; ++i) {
            EXPECT_EQ(back[i], a[i] + m[i]);
        }
        EXPECT_TRUE(layout.divides(pa.data(), pac.data()));
        std::vector<std::uint64_t> lcm(w), gcd(w);
        layout.lcm(pa.data(), pb.data(), lcm.data());
        layout.gcd(pa.data(), pb.data(), gcd.data());
        layout.unpack(lcm.data(), back);
        std::vector<std::uint32_t> gb(n);
        layout.unpack(gcd.data(), gb);
        bool coprime = true;
        bool a_divides_b = true;
        for (std::size_t i = 0; i < n; ++i) {
            EXPECT_EQ(back[i], std::max(a[i], b[i]));
            EXPECT_EQ(gb[i], std::min(a[i], b[i]));
            coprime = coprime && std::min(a[i], b[i]) == 0;
            a_divides_b = a_divides_b && a[i] <= b[i];
        }
        EXPECT_EQ(layout.coprime(pa.data(), pb.data()), coprime);
        EXPECT_EQ(layout.divides(pa.data(), pb.data()), a_divides_b);
        // The divisibility mask: up to 32 variables, min(64/n, 16) bits each holding min(e, that)
        // in unary; past that, bit i mod 64 for each variable that occurs. Either way it never
        // rejects a divisor.
        const unsigned bits = layout.mask_bits_per_variable();
        EXPECT_EQ(bits, n <= 32 ? std::min<unsigned>(16, static_cast<unsigned>(64 / n)) : 1u);
        std::uint64_t expected = 0;
        for (std::size_t i = 0; i < n; ++i) {
            if (bits > 1) {
                const std::uint32_t run = std::min<std::uint32_t>(a[i], bits);
                expected |= ((std::uint64_t{1} << run) - 1) << (i * bits);
            } else {
                expected |= a[i] != 0 ? std::uint64_t{1} << (i % 64) : 0;
            }
        }
        const std::uint64_t mask_a = layout.divisibility_mask(pa.data());
        EXPECT_EQ(mask_a, expected);
        EXPECT_EQ(mask_a & ~layout.divisibility_mask(pac.data()), 0u);  // a divides a·m
        if (a_divides_b) {
            EXPECT_EQ(mask_a & ~layout.divisibility_mask(pb.data()), 0u);
        }
        // The packed lcm must equal packing the exponent-wise max (linear fields recomputed).
        std::vector<std::uint64_t> repacked(w);
        layout.pack(back, repacked.data());
        EXPECT_TRUE(layout.equal(repacked.data(), lcm.data()));
    }
}

INSTANTIATE_TEST_SUITE_P(AllKinds, MonomialOrderTest, ::testing::ValuesIn(order_cases()),
                         [](const auto& param_info) { return param_info.param.name; });

TEST(MonomialOrder, NamedOrdersOnExamples) {
    const std::vector<std::string> xyz = {"x", "y", "z"};
    auto cmp = [&](const char* order, std::vector<std::uint32_t> a, std::vector<std::uint32_t> b) {
        return parse_monomial_order(order, xyz).compare(a, b);
    };
    // CLO ch. 2 §2: x y^5 z^2 vs x^4 y z^2 etc.
    EXPECT_GT(cmp("lex", {1, 2, 0}, {0, 3, 4}), 0);
    EXPECT_LT(cmp("grlex", {1, 2, 0}, {0, 3, 4}), 0);
    EXPECT_GT(cmp("grlex", {1, 2, 4}, {1, 1, 5}), 0);
    EXPECT_GT(cmp("grevlex", {4, 7, 1}, {4, 2, 3}), 0);
    EXPECT_GT(cmp("grevlex", {1, 5, 2}, {4, 1, 3}), 0);
    // weights(1,2,3): y (weight 2) > x (weight 1).
    EXPECT_LT(cmp("weights(1,2,3)", {1, 0, 0}, {0, 1, 0}), 0);
    // elim(z): anything with z beats anything without.
    EXPECT_GT(cmp("elim(z)", {0, 0, 1}, {5, 5, 0}), 0);
}

TEST(MonomialOrder, RejectsBadOrders) {
    const std::vector<std::string> xy = {"x", "y"};
    EXPECT_THROW(parse_monomial_order("revlex", xy), ParseError);
    EXPECT_THROW(parse_monomial_order("weights(1)", xy), ParseError);
    EXPECT_THROW(parse_monomial_order("weights(0,1)", xy), ParseError);
    EXPECT_THROW(parse_monomial_order("elim(q)", xy), ParseError);
    EXPECT_THROW(parse_monomial_order("matrix((1,1),(1,1))", xy), ParseError);   // singular
    EXPECT_THROW(parse_monomial_order("matrix((1,0),(0,-1))", xy), ParseError);  // not global
    EXPECT_THROW(parse_monomial_order("grevlex junk", xy), ParseError);
    try {
        parse_monomial_order("grevlex(", xy, 3, 8);
        FAIL() << "no error";
    } catch (const ParseError& e) {
        EXPECT_EQ(e.line(), 3u);
        EXPECT_EQ(e.column(), 15u);  // the '(' after "grevlex" starting at column 8
    }
}

TEST(MonomialLayout, OverflowIsReportedNotWrapped) {
    const MonomialLayout layout(MonomialOrder::grevlex(2));
    std::vector<std::uint64_t> a(layout.words()), out(layout.words());
    const std::vector<std::uint32_t> big = {20000, 0};
    layout.pack(big, a.data());
    EXPECT_THROW(layout.multiply(a.data(), a.data(), out.data()), ExponentOverflow);
    const std::vector<std::uint32_t> too_big = {40000, 0};
    EXPECT_THROW(layout.pack(too_big, a.data()), ExponentOverflow);
    // The total degree field overflows before any single exponent does.
    const std::vector<std::uint32_t> half = {17000, 17000};
    EXPECT_THROW(layout.pack(half, a.data()), ExponentOverflow);
}

// The monomial table's hash is linear in the packed words, so a product's hash is the sum of
// its factors' (F4 relies on it: the hash of m·t is taken as hash(m) + hash(t)); and the table
// numbers each monomial once, whichever way its hash was obtained. Layouts of one, two and
// several words (3, 8 and 20 variables), 20 000 random products, so that the table grows.
TEST(MonomialTable, HashOfAProductIsTheSumAndEveryMonomialGetsOneIndex) {
    for (const std::size_t n : {3u, 8u, 20u}) {
        const MonomialLayout layout(MonomialOrder::grevlex(n));
        const std::size_t w = layout.words();
        MonomialTable table(w);
        std::map<std::vector<std::uint32_t>, std::uint32_t> seen;
        std::mt19937_64 rng(n);
        std::vector<std::uint64_t> pa(w), pb(w), product(w);
        for (int k = 0; k < 20000; ++k) {
            const auto a = random_exponents(rng, n, 3), b = random_exponents(rng, n, 3);
            layout.pack(a, pa.data());
            layout.pack(b, pb.data());
            layout.multiply(pa.data(), pb.data(), product.data());
            ASSERT_EQ(table.hash(product.data()), table.hash(pa.data()) + table.hash(pb.data()));
            const std::uint32_t index =
                k % 2 == 0 ? table.insert(product.data())
                           : table.insert_hashed(product.data(),
                                                 table.hash(pa.data()) + table.hash(pb.data()));
            std::vector<std::uint32_t> exponents(n);
            for (std::size_t v = 0; v < n; ++v) {
                exponents[v] = a[v] + b[v];
            }
            const auto [it, fresh] = seen.emplace(exponents, index);
            ASSERT_EQ(it->second, index) << "n = " << n;  // the same monomial, the same index
            ASSERT_TRUE(std::equal(product.begin(), product.end(), table.at(index)));
            if (fresh) {
                ASSERT_EQ(index, seen.size() - 1);  // new monomials are numbered in order
            }
        }
        EXPECT_EQ(table.size(), seen.size());
    }
}

}  // namespace
}  // namespace locus::algebra
