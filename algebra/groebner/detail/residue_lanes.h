// Internal to the Gröbner code: vectors of residues of one integer modulo K primes below 2^31
// ("lanes"), with the few operations the certification's reducer (zero_reducer.h) needs, each
// done on all K lanes at once. K is a multiple of 8; the kernels use AVX-512 or AVX2 when the
// processor has them (chosen once, at start-up) and plain C++ otherwise.
//
// Single products are Montgomery's with R = 2^32: multiply(x, y) = x·y·R⁻¹ mod p, with a
// constant (an inverse, a factor) stored in Montgomery form y·R mod p so that multiply(x, y·R)
// = x·y and the other operand stays plain. The row kernel, which multiplies a whole row of
// basis coefficients by one multiplier, uses Shoup's method with that multiplier's quotients
// computed once: the coefficients stay plain and need no second table (a table of quotients
// for them, the other way to use Shoup's method, was slower: 10.7 against 7.4 ns a term with
// 32 lanes over 100 000 terms of coefficients, the tables being what the kernel reads).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace locus::algebra::detail {

class LanePrimes {
  public:
    // The `lanes` largest primes below 2^31 for which `usable` holds, in descending order;
    // `lanes` is a positive multiple of 8.
    LanePrimes(std::size_t lanes, const std::function<bool(std::uint32_t)>& usable);
    // These odd primes below 2^31, in this order, the last repeated up to a multiple of 8.
    explicit LanePrimes(std::span<const std::uint32_t> primes);

    std::size_t size() const { return primes_.size(); }
    const std::uint32_t* primes() const { return primes_.data(); }
    const std::uint32_t* neg_inverses() const { return neg_inverses_.data(); }
    const double* reciprocals() const { return reciprocals_.data(); }  // 2^32/p
    std::uint32_t prime(std::size_t lane) const { return primes_[lane]; }

    // Scalar forms of the lane operations, for set-up and rare paths.
    std::uint32_t multiply(std::size_t lane, std::uint32_t x, std::uint32_t y) const;
    // x·R mod p.
    std::uint32_t to_montgomery(std::size_t lane, std::uint32_t x) const;

  private:
    void add(std::uint32_t p);

    std::vector<std::uint32_t> primes_, neg_inverses_;  // −p⁻¹ mod 2^32
    std::vector<double> reciprocals_;
};

namespace lanes {

// out = x·y·R⁻¹ on every lane (x plain and y in Montgomery form give x·y plain).
void multiply(std::uint32_t* out, const std::uint32_t* x, const std::uint32_t* y,
              const LanePrimes& primes);
// x = −x on every lane.
void negate(std::uint32_t* x, const LanePrimes& primes);
bool is_zero(const std::uint32_t* x, std::size_t lanes);
// out = ⌊b·2^32/p⌋ on every lane: the precomputed quotients of Shoup's multiplication by b.
void shoup_quotients(std::uint32_t* out, const std::uint32_t* b, const LanePrimes& primes);
// For t < n: table[columns[t]·K …] += b·rows[t·K …], K = primes.size(): adds b times a
// polynomial whose coefficients (plain residues, one row of K each) land on the given columns
// of a table of K residues a column. The columns must be distinct. `b_quotients` is
// shoup_quotients(b): with the multiplier fixed for the whole row, Shoup's multiplication
// takes four multiplies a block of lanes where Montgomery's takes five (15–30 % faster).
void add_scaled_rows(std::uint32_t* table, const std::uint32_t* columns, std::size_t n,
                     const std::uint32_t* rows, const std::uint32_t* b,
                     const std::uint32_t* b_quotients, const LanePrimes& primes);
// The certification's reductions done together (ResidueZeroReducer::reduce_together): up to
// kSlots reductions share one table, whose column c holds for slot s its K residues from
// table[(c·kSlots + s)·K] (a column's slots side by side), with a rigorous bound per slot
// (log_bound.h units) and a pending byte per slot at [c·kSlots + s]. (Slots padded to whole
// cache lines, 24 lanes to 32, were slower on katsura-10: its table no longer fit the cache.)
inline constexpr std::size_t kSlots = 8;
struct SlotBounds {
    std::int64_t* bound;         // kSlots a column
    const std::int64_t* term;    // a term: added to each slot's offset
    const std::int64_t* offset;  // kSlots
    std::uint8_t* pending;       // kSlots a column
    std::uint32_t* fresh;        // room for n a slot: slot s's from fresh + s·n
    std::size_t* fresh_count;    // kSlots
    std::int64_t* highest;       // kSlots
};
// For every slot s in `slots` (bit s set) and every term t < n, at column c = columns[t]:
// the residues table[(c·kSlots + s)·K + l] += b[s·K + l]·rows[t·K + l] for l < K
// (b_quotients[s·K …] = shoup_quotients of b's slot s); the bound [c·kSlots + s] raised to
// of_sum(bound, offset[s] + term[t]) and highest[s] to the max of itself and that; and when
// the pending byte is 0, it becomes 1 and c is appended to slot s's fresh columns. The rows
// come from memory once for all the slots (the point of reducing together: katsura-11's rows
// are 49 MB on 32 lanes); the AVX-512 kernel raises a column's slots' bounds together, then
// makes a pass per slot over the rows, by then in the first-level cache.
void add_scaled_rows_together(std::uint32_t* table, const std::uint32_t* columns, std::size_t n,
                              const std::uint32_t* rows, unsigned slots, const std::uint32_t* b,
                              const std::uint32_t* b_quotients, const LanePrimes& primes,
                              SlotBounds& bounds);
// out = Σ_i halves[i]·powers[i·K …]·R⁻¹ for i < count: the residues of the integer whose
// 32-bit digits are `halves` (least significant first) when powers[i] holds 2^(32·i) in
// Montgomery form, or its Montgomery form when powers[i] holds 2^(32·(i+1)).
void combine_digits(std::uint32_t* out, const std::uint32_t* halves, std::size_t count,
                    const std::uint32_t* powers, const LanePrimes& primes);

// Which kernels run: "avx512", "avx2" or "portable" (the best the processor supports).
const char* kernel_name();
// The kernels this processor can run, and a way to pick one, so that the tests can check each
// against the others.
std::vector<std::string> supported_kernels();
void select_kernels(const std::string& name);  // throws std::invalid_argument if unsupported

}  // namespace lanes

}  // namespace locus::algebra::detail
