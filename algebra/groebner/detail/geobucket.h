// Internal to the Gröbner code: an integer polynomial kept as a few sorted buckets of
// geometrically growing length (Yan, "The geobucket data structure for polynomials", J.
// Symbolic Computation 25 (1998) 285–293), so that subtracting a multiple of a short
// polynomial from a long one costs about the short one's length, not the long one's.
//
// A reduction replaces p by a·p − b·m·g again and again; merging every step into p's single
// sorted list copied all of p each time, over half of Buchberger's time on eco-7 (perf: 53 %
// in that merge), where the reducers are much shorter than p.
#pragma once

#include <utility>
#include <vector>

#include <flint/fmpz.h>

#include "algebra/groebner/detail/integer_polynomial.h"

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
    // Terms [head, count): their monomials (`words` words per term) and their coefficients,
    // which the bucket owns. A fmpz is one word, so a term moves by copying that word: the slot
    // it leaves is dead and is never cleared (a std::vector<Integer> paid a move constructor,
    // a call out of line, and a destructor per term and merge: 10 % of eco-11's time).
    // Storage keeps its size across merges (no zero-fill, no reallocation).
    struct Bucket {
        Bucket() = default;
        Bucket(Bucket&& other) noexcept { swap(other); }
        Bucket& operator=(Bucket&& other) noexcept {
            swap(other);
            return *this;
        }
        Bucket(const Bucket&) = delete;
        Bucket& operator=(const Bucket&) = delete;
        ~Bucket() { release(); }

        std::size_t size() const { return count - head; }
        // Clears the live coefficients.
        void release() {
            for (std::size_t k = head; k < count; ++k) {
                fmpz_clear(&coefficients[k]);
            }
            forget();
        }
        // Empties a bucket whose live terms have all been moved out or cleared.
        void forget() { head = count = 0; }
        // Room for `terms` terms of `words` words from the start; the bucket must be empty.
        void make_room(std::size_t terms, std::size_t words) {
            if (coefficients.size() < terms) {
                coefficients.resize(terms);
            }
            if (monomials.size() < terms * words) {
                monomials.resize(terms * words);
            }
        }
        void swap(Bucket& other) noexcept {
            monomials.swap(other.monomials);
            coefficients.swap(other.coefficients);
            std::swap(head, other.head);
            std::swap(count, other.count);
        }

        std::vector<std::uint64_t> monomials;
        std::vector<fmpz> coefficients;
        std::size_t head = 0, count = 0;
    };
    static std::size_t capacity(std::size_t level) { return std::size_t{16} << (2 * level); }
    static std::size_t level_for(std::size_t length);
    // target := target + source (both from their heads); source is left empty.
    void merge(Bucket& target, Bucket& source);
    // The merges with the monomials' word count fixed at compile time (W > 0), or not (W = 0):
    // comparisons, products and copies of one to four words are then a few register moves.
    template <std::size_t W>
    void merge_words(Bucket& target, Bucket& source);
    template <std::size_t W>
    void subtract_multiple_words(const Integer& b, const std::uint64_t* m,
                                 const IntegerPolynomial& g, std::size_t from);
    // Moves buckets over their capacity up, from `level` on.
    void carry(std::size_t level);

    const MonomialLayout& layout_;
    std::vector<Bucket> buckets_;
    Bucket scratch_;
    std::vector<std::uint64_t> product_;
    Integer negated_;  // −b of subtract_multiple
};

}  // namespace locus::algebra::detail
