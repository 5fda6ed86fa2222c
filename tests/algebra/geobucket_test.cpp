// The geobucket (algebra/groebner/detail/geobucket.h) against a naive polynomial: a map from packed
// monomial to coefficient, updated term by term. Random multiples are subtracted, undone
// (every term cancels back), scaled and popped, in rings of one to six words a monomial (the
// merges are compiled for one to four words and run generically past that), with coefficients
// from a word to a few hundred bits (FLINT's immediates and GMP integers). A product whose
// exponents overflow throws and leaves the bucket usable. (Whether the products made before
// the throw are freed no sanitizer can tell: FLINT's pages keep every integer reachable.)
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <vector>

#include <flint/fmpz.h>

#include "algebra/error.h"
#include "algebra/groebner/detail/geobucket.h"
#include "algebra/monomial.h"
#include "algebra/monomial_order.h"
#include "tests/support/test_data.h"

namespace locus::algebra::detail {
namespace {

using Monomial = std::vector<std::uint64_t>;

class Naive {
  public:
    explicit Naive(const MonomialLayout& layout) : layout_(layout) {}

    void assign(const IntegerPolynomial& p) {
        terms_.clear();
        for (std::size_t k = 0; k < p.size(); ++k) {
            add(monomial_of(p, k), p.coefficients[k]);
        }
    }
    // −b·m·g[from..]
    void subtract_multiple(const Integer& b, const std::uint64_t* m, const IntegerPolynomial& g,
                           std::size_t from) {
        const std::size_t w = layout_.words();
        Monomial product(w);
        for (std::size_t k = from; k < g.size(); ++k) {
            layout_.multiply(g.monomial(k, w), m, product.data());
            Integer c;
            fmpz_mul(c.get(), g.coefficients[k].get(), b.get());
            fmpz_neg(c.get(), c.get());
            add(product, c);
        }
    }
    void scale(const Integer& a) {
        for (auto& [m, c] : terms_) {
            fmpz_mul(c.get(), c.get(), a.get());
        }
    }
    // The terms, descending under the order.
    std::vector<std::pair<Monomial, Integer>> descending() const {
        std::vector<std::pair<Monomial, Integer>> out(terms_.begin(), terms_.end());
        std::sort(out.begin(), out.end(), [&](const auto& x, const auto& y) {
            return layout_.compare(x.first.data(), y.first.data()) > 0;
        });
        return out;
    }
    void erase(const Monomial& m) { terms_.erase(m); }

  private:
    Monomial monomial_of(const IntegerPolynomial& p, std::size_t k) const {
        const std::uint64_t* m = p.monomial(k, layout_.words());
        return Monomial(m, m + layout_.words());
    }
    void add(const Monomial& m, const Integer& c) {
        Integer& slot = terms_[m];
        fmpz_add(slot.get(), slot.get(), c.get());
        if (slot.is_zero()) {
            terms_.erase(m);
        }
    }

    const MonomialLayout& layout_;
    std::map<Monomial, Integer> terms_;  // any order of the keys: descending() sorts
};

Integer random_coefficient(std::mt19937_64& rng) {
    Integer c;
    // A third of them past a word: 70 to 320 bits.
    if (rng() % 3 == 0) {
        fmpz_set_ui(c.get(), rng() | 1);
        fmpz_mul_2exp(c.get(), c.get(), 6 + rng() % 256);
        fmpz_add_ui(c.get(), c.get(), rng() % 1000);
    } else {
        fmpz_set_si(c.get(), static_cast<slong>(rng() % 2000) - 1000);
        if (c.is_zero()) {
            fmpz_one(c.get());
        }
    }
    if (rng() % 2 == 0) {
        fmpz_neg(c.get(), c.get());
    }
    return c;
}

// `terms` distinct random monomials (exponents below 4), descending, with non-zero coefficients.
IntegerPolynomial random_polynomial(const MonomialLayout& layout, std::size_t vars,
                                    std::mt19937_64& rng, std::size_t terms) {
    const std::size_t w = layout.words();
    std::vector<Monomial> monomials;
    std::vector<std::uint32_t> exponents(vars);
    for (std::size_t t = 0; t < terms; ++t) {
        for (auto& e : exponents) {
            e = static_cast<std::uint32_t>(rng() % 4);
        }
        Monomial m(w);
        layout.pack(exponents, m.data());
        monomials.push_back(std::move(m));
    }
    std::sort(monomials.begin(), monomials.end(), [&](const Monomial& x, const Monomial& y) {
        return layout.compare(x.data(), y.data()) > 0;
    });
    monomials.erase(std::unique(monomials.begin(), monomials.end()), monomials.end());
    IntegerPolynomial p;
    for (const Monomial& m : monomials) {
        p.monomials.insert(p.monomials.end(), m.begin(), m.end());
        p.coefficients.push_back(random_coefficient(rng));
    }
    return p;
}

// Pops every term of the bucket and compares with the naive polynomial.
void expect_same(GeoBucket& bucket, const Naive& naive, const MonomialLayout& layout) {
    const std::vector<std::pair<Monomial, Integer>> expected = naive.descending();
    Monomial m(layout.words());
    Integer c;
    std::size_t k = 0;
    while (bucket.pop_leading(m.data(), c)) {
        ASSERT_LT(k, expected.size()) << "more terms than expected";
        EXPECT_EQ(m, expected[k].first) << "term " << k;
        EXPECT_TRUE(fmpz_equal(c.get(), expected[k].second.get())) << "term " << k;
        ++k;
    }
    EXPECT_EQ(k, expected.size()) << "fewer terms than expected";
}

TEST(GeoBucket, AgreesWithANaivePolynomialInEveryWordCount) {
    // 2, 6, 11, 14 and 20 variables under grevlex: 1, 2, 3, 4 and 6 words a monomial.
    for (const std::size_t vars : {2u, 6u, 11u, 14u, 20u}) {
        const MonomialLayout layout(MonomialOrder::grevlex(vars));
        const std::size_t w = layout.words();
        for (int seed = 0; seed < test::seed_count(6); ++seed) {
            SCOPED_TRACE("variables " + std::to_string(vars) + ", seed " + std::to_string(seed));
            std::mt19937_64 rng(static_cast<std::uint64_t>(seed) * 7919 + vars);
            GeoBucket bucket(layout);
            Naive naive(layout);
            const IntegerPolynomial start = random_polynomial(layout, vars, rng, 1 + rng() % 60);
            bucket.assign(start);
            naive.assign(start);
            for (int step = 0; step < 40; ++step) {
                // Reducers from 1 to 300 terms reach the buckets of levels 0 to 2 and carry.
                const IntegerPolynomial g = random_polynomial(layout, vars, rng, 1 + rng() % 300);
                const Integer b = random_coefficient(rng);
                std::vector<std::uint32_t> exponents(vars);
                for (auto& e : exponents) {
                    e = static_cast<std::uint32_t>(rng() % 3);
                }
                Monomial m(w);
                layout.pack(exponents, m.data());
                const std::size_t from = rng() % 2;
                bucket.subtract_multiple(b, m.data(), g, from);
                naive.subtract_multiple(b, m.data(), g, from);
                if (rng() % 3 == 0) {
                    // Undone: every term of the multiple cancels, to zero or to what was there.
                    Integer minus_b;
                    fmpz_neg(minus_b.get(), b.get());
                    bucket.subtract_multiple(minus_b, m.data(), g, from);
                    naive.subtract_multiple(minus_b, m.data(), g, from);
                }
                if (rng() % 8 == 0) {
                    const Integer a = random_coefficient(rng);
                    bucket.scale(a);
                    naive.scale(a);
                }
                if (rng() % 4 == 0) {
                    // The leading term leaves both.
                    Monomial lead(w);
                    Integer c;
                    if (bucket.pop_leading(lead.data(), c)) {
                        const auto expected = naive.descending();
                        ASSERT_FALSE(expected.empty());
                        EXPECT_EQ(lead, expected.front().first);
                        EXPECT_TRUE(fmpz_equal(c.get(), expected.front().second.get()));
                        naive.erase(lead);
                    } else {
                        EXPECT_TRUE(naive.descending().empty());
                    }
                }
            }
            expect_same(bucket, naive, layout);
        }
    }
}

TEST(GeoBucket, AnOverflowingProductThrowsAndLeavesTheBucketUsable) {
    // Under lex, x^2 leads x^2 + B·x·y^3 + B·y^32000; times y^1000 the last term would be
    // y^33000, past the 15-bit field. The products before it (one of them a GMP integer that
    // no term of the bucket holds) are made first.
    const MonomialLayout layout(MonomialOrder::lex(2));
    const std::size_t w = layout.words();
    auto monomial = [&](std::uint32_t x, std::uint32_t y) {
        Monomial m(w);
        const std::vector<std::uint32_t> e = {x, y};
        layout.pack(e, m.data());
        return m;
    };
    Integer big;
    fmpz_set_ui(big.get(), 12345);
    fmpz_mul_2exp(big.get(), big.get(), 200);
    IntegerPolynomial g;
    for (const auto& [m, c] : std::vector<std::pair<Monomial, Integer>>{
             {monomial(2, 0), Integer(1)}, {monomial(1, 3), big}, {monomial(0, 32000), big}}) {
        g.monomials.insert(g.monomials.end(), m.begin(), m.end());
        g.coefficients.push_back(c);
    }
    IntegerPolynomial p;
    for (const auto& [m, c] : std::vector<std::pair<Monomial, Integer>>{
             {monomial(2, 1000), big}, {monomial(1, 0), big}, {monomial(0, 5), Integer(7)}}) {
        p.monomials.insert(p.monomials.end(), m.begin(), m.end());
        p.coefficients.push_back(c);
    }
    GeoBucket bucket(layout);
    bucket.assign(p);
    const Monomial m = monomial(0, 1000);
    EXPECT_THROW(bucket.subtract_multiple(big, m.data(), g, 0), ExponentOverflow);
    // Assigned afresh, the bucket works as before.
    Naive naive(layout);
    bucket.assign(p);
    naive.assign(p);
    expect_same(bucket, naive, layout);
}

}  // namespace
}  // namespace locus::algebra::detail
