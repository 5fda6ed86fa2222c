// Internal to the Gröbner code: an integer polynomial kept as a few sorted buckets of
// geometrically growing length (Yan, "The geobucket data structure for polynomials", J.
// Symbolic Computation 25 (1998) 285–293), so that subtracting a multiple of a short
// polynomial from a long one costs about the short one's length, not the long one's.
//
// A reduction replaces p by a·p − b·m·g again and again; merging every step into p's single
// sorted list copied all of p each time, over half of Buchberger's time on eco-7 (perf: 53 %
// in that merge), where the reducers are much shorter than p.
#pragma once

#include <vector>

#include "algebra/groebner/integer_polynomial.h"

namespace locus::algebra::detail {

class GeoBucket {
  public:
    explicit GeoBucket(const MonomialLayout& layout) : layout_(layout) {}

    // Replaces the content by p (terms descending, no zero coefficients).
    void assign(IntegerPolynomial p);
    // Subtracts b·m·g[from..]: the products are formed while merging (fmpz_submul into the
    // terms already there), not as a polynomial of their own.
    void subtract_multiple(const Integer& b, const std::uint64_t* m, const IntegerPolynomial& g,
                           std::size_t from);
    // Removes the leading term and writes it to `monomial` (layout.words() words) and
    // `coefficient`; false when the polynomial is zero.
    bool pop_leading(std::uint64_t* monomial, Integer& coefficient);
    // Multiplies every coefficient by a.
    void scale(const Integer& a);
    // The gcd of all coefficients, folded into g.
    void fold_content(Integer& g) const;
    // Divides every coefficient by g, which divides them all.
    void divide_exactly(const Integer& g);
    // The terms left, descending, appended to `out`; the bucket is left empty.
    void drain_into(IntegerPolynomial& out);

  private:
    // Terms from `head` on; the ones before it are gone.
    // The coefficients count the terms; `monomials` is storage for at least that many (words
    // per term), kept at its size across clears so that a merge does not zero-fill it again
    // (memset was 2 % of eco-7's instructions).
    struct Bucket {
        std::vector<std::uint64_t> monomials;
        std::vector<Integer> coefficients;
        std::size_t head = 0;
        std::size_t size() const { return coefficients.size() - head; }
        void clear() {
            coefficients.clear();
            head = 0;
        }
        // Storage for `words` words of monomials from the start.
        std::uint64_t* monomial_storage(std::size_t words) {
            if (monomials.size() < words) {
                monomials.resize(words);
            }
            return monomials.data();
        }
    };
    static std::size_t capacity(std::size_t level) { return std::size_t{16} << (2 * level); }
    static std::size_t level_for(std::size_t length);
    // target := target + source (both from their heads); source is left empty.
    void merge(Bucket& target, Bucket& source);
    // Moves buckets over their capacity up, from `level` on.
    void carry(std::size_t level);

    const MonomialLayout& layout_;
    std::vector<Bucket> buckets_;
    Bucket scratch_;
    std::vector<std::uint64_t> product_;
    Integer negated_;  // −b of subtract_multiple
};

}  // namespace locus::algebra::detail
