#include "algebra/groebner/detail/residue_lanes.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

#include <immintrin.h>

#include <flint/ulong_extras.h>

#include "algebra/detail/kernel_choice.h"
#include "algebra/groebner/detail/log_bound.h"

// GCC 12 sees the _mm512_undefined_epi32() inside AVX-512 intrinsics as uninitialized reads
// (GCC bug 105593); the intrinsics are correct.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#pragma GCC diagnostic ignored "-Wuninitialized"

namespace locus::algebra::detail {

namespace {

using lanes::kSlots;
using lanes::SlotBounds;

// x·y·2^-32 mod p for x·y < 2^32·p (one operand below p suffices).
inline std::uint32_t montgomery(std::uint32_t x, std::uint32_t y, std::uint32_t p,
                                std::uint32_t neg_inverse) {
    const std::uint64_t t = static_cast<std::uint64_t>(x) * y;
    const std::uint32_t m = static_cast<std::uint32_t>(t) * neg_inverse;
    // t + m·p < 2^32·p + 2^32·p: fits in 64 bits because p < 2^31.
    const auto u = static_cast<std::uint32_t>((t + static_cast<std::uint64_t>(m) * p) >> 32);
    return u >= p ? u - p : u;
}

inline std::uint32_t add_mod(std::uint32_t x, std::uint32_t y, std::uint32_t p) {
    const std::uint32_t s = x + y;  // < 2p < 2^32
    return s >= p ? s - p : s;
}

// SlotBounds's update of one slot for one term, on the caller's locals.
inline void raise_slot(const lanes::SlotBounds& bounds, std::size_t slot, std::uint32_t column,
                       std::int64_t term, std::size_t n) {
    const std::size_t at = static_cast<std::size_t>(column) * lanes::kSlots + slot;
    const std::int64_t raised = log_bound::of_sum(bounds.bound[at], bounds.offset[slot] + term);
    bounds.bound[at] = raised;
    bounds.highest[slot] = std::max(bounds.highest[slot], raised);
    if (bounds.pending[at] == 0) {
        bounds.pending[at] = 1;
        bounds.fresh[slot * n + bounds.fresh_count[slot]++] = column;
    }
}

// --- portable ------------------------------------------------------------------------------

void multiply_portable(std::uint32_t* out, const std::uint32_t* x, const std::uint32_t* y,
                       const std::uint32_t* p, const std::uint32_t* ninv, std::size_t lanes) {
    for (std::size_t l = 0; l < lanes; ++l) {
        out[l] = montgomery(x[l], y[l], p[l], ninv[l]);
    }
}

// x·b mod p by Shoup's method, for b < p and b_quotient = ⌊b·2^32/p⌋: the quotient estimate
// ⌊x·b_quotient/2^32⌋ is at most one short, so the remainder, taken modulo 2^32, is below 2p.
inline std::uint32_t shoup(std::uint32_t x, std::uint32_t b, std::uint32_t b_quotient,
                           std::uint32_t p) {
    const auto q = static_cast<std::uint32_t>((static_cast<std::uint64_t>(x) * b_quotient) >> 32);
    const std::uint32_t r = x * b - q * p;
    return r >= p ? r - p : r;
}

void add_scaled_rows_portable(std::uint32_t* table, const std::uint32_t* columns, std::size_t n,
                              const std::uint32_t* rows, const std::uint32_t* b,
                              const std::uint32_t* b_quotients, const std::uint32_t* p,
                              std::size_t lanes) {
    for (std::size_t t = 0; t < n; ++t) {
        std::uint32_t* v = table + static_cast<std::size_t>(columns[t]) * lanes;
        const std::uint32_t* row = rows + t * lanes;
        for (std::size_t l = 0; l < lanes; ++l) {
            v[l] = add_mod(v[l], shoup(row[l], b[l], b_quotients[l], p[l]), p[l]);
        }
    }
}

// The estimate from 2^32/p in floating point is off by at most one either way; the remainder
// tells which.
void shoup_quotients_portable(std::uint32_t* out, const std::uint32_t* b, const std::uint32_t* p,
                              const double* reciprocal, std::size_t lanes) {
    for (std::size_t l = 0; l < lanes; ++l) {
        const std::uint64_t numerator = static_cast<std::uint64_t>(b[l]) << 32;
        auto q = static_cast<std::uint64_t>(static_cast<double>(b[l]) * reciprocal[l]);
        const auto r = static_cast<std::int64_t>(numerator - q * p[l]);
        q = r < 0 ? q - 1 : (r >= static_cast<std::int64_t>(p[l]) ? q + 1 : q);
        out[l] = static_cast<std::uint32_t>(q);
    }
}

void combine_digits_portable(std::uint32_t* out, const std::uint32_t* halves, std::size_t count,
                             const std::uint32_t* powers, const std::uint32_t* p,
                             const std::uint32_t* ninv, std::size_t lanes) {
    for (std::size_t l = 0; l < lanes; ++l) {
        std::uint32_t acc = 0;
        for (std::size_t i = 0; i < count; ++i) {
            acc = add_mod(acc, montgomery(halves[i], powers[i * lanes + l], p[l], ninv[l]), p[l]);
        }
        out[l] = acc;
    }
}

// --- AVX2: blocks of 8 lanes ---------------------------------------------------------------

#define LOCUS_AVX2 __attribute__((target("avx2")))

LOCUS_AVX2 inline __m256i montgomery8(__m256i x, __m256i y, __m256i p, __m256i p_odd,
                                      __m256i ninv) {
    const __m256i te = _mm256_mul_epu32(x, y);
    const __m256i to = _mm256_mul_epu32(_mm256_srli_epi64(x, 32), _mm256_srli_epi64(y, 32));
    const __m256i t_low = _mm256_blend_epi32(te, _mm256_slli_epi64(to, 32), 0xAA);
    const __m256i m = _mm256_mullo_epi32(t_low, ninv);
    const __m256i ue = _mm256_add_epi64(te, _mm256_mul_epu32(m, p));
    const __m256i uo = _mm256_add_epi64(to, _mm256_mul_epu32(_mm256_srli_epi64(m, 32), p_odd));
    const __m256i u = _mm256_blend_epi32(_mm256_srli_epi64(ue, 32), uo, 0xAA);
    return _mm256_min_epu32(u, _mm256_sub_epi32(u, p));
}

LOCUS_AVX2 inline __m256i add_mod8(__m256i x, __m256i y, __m256i p) {
    const __m256i s = _mm256_add_epi32(x, y);
    return _mm256_min_epu32(s, _mm256_sub_epi32(s, p));
}

LOCUS_AVX2 inline __m256i load8(const std::uint32_t* a) {
    return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(a));
}

LOCUS_AVX2 inline void store8(std::uint32_t* a, __m256i v) {
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(a), v);
}

LOCUS_AVX2 void multiply_avx2(std::uint32_t* out, const std::uint32_t* x, const std::uint32_t* y,
                              const std::uint32_t* p, const std::uint32_t* ninv,
                              std::size_t lanes) {
    for (std::size_t l = 0; l < lanes; l += 8) {
        const __m256i pv = load8(p + l);
        store8(out + l, montgomery8(load8(x + l), load8(y + l), pv, _mm256_srli_epi64(pv, 32),
                                    load8(ninv + l)));
    }
}

LOCUS_AVX2 inline __m256i shoup8(__m256i x, __m256i b, __m256i b_quotient, __m256i b_quotient_odd,
                                 __m256i p) {
    const __m256i qe = _mm256_srli_epi64(_mm256_mul_epu32(x, b_quotient), 32);
    const __m256i qo = _mm256_mul_epu32(_mm256_srli_epi64(x, 32), b_quotient_odd);
    const __m256i q = _mm256_blend_epi32(qe, qo, 0xAA);
    const __m256i r = _mm256_sub_epi32(_mm256_mullo_epi32(x, b), _mm256_mullo_epi32(q, p));
    return _mm256_min_epu32(r, _mm256_sub_epi32(r, p));
}

LOCUS_AVX2 void add_scaled_rows_avx2(std::uint32_t* table, const std::uint32_t* columns,
                                     std::size_t n, const std::uint32_t* rows,
                                     const std::uint32_t* b, const std::uint32_t* b_quotients,
                                     const std::uint32_t* p, std::size_t lanes) {
    for (std::size_t t = 0; t < n; ++t) {
        std::uint32_t* v = table + static_cast<std::size_t>(columns[t]) * lanes;
        const std::uint32_t* row = rows + t * lanes;
        for (std::size_t l = 0; l < lanes; l += 8) {
            const __m256i pv = load8(p + l), bq = load8(b_quotients + l);
            const __m256i product =
                shoup8(load8(row + l), load8(b + l), bq, _mm256_srli_epi64(bq, 32), pv);
            store8(v + l, add_mod8(load8(v + l), product, pv));
        }
    }
}

LOCUS_AVX2 void combine_digits_avx2(std::uint32_t* out, const std::uint32_t* halves,
                                    std::size_t count, const std::uint32_t* powers,
                                    const std::uint32_t* p, const std::uint32_t* ninv,
                                    std::size_t lanes) {
    for (std::size_t l = 0; l < lanes; l += 8) {
        const __m256i pv = load8(p + l), p_odd = _mm256_srli_epi64(pv, 32), nv = load8(ninv + l);
        __m256i acc = _mm256_setzero_si256();
        for (std::size_t i = 0; i < count; ++i) {
            const __m256i h = _mm256_set1_epi32(static_cast<int>(halves[i]));
            acc = add_mod8(acc, montgomery8(h, load8(powers + i * lanes + l), pv, p_odd, nv), pv);
        }
        store8(out + l, acc);
    }
}

// --- AVX-512: blocks of 16 lanes, the last one masked to 8 when K is not a multiple of 16 ---

#define LOCUS_AVX512 __attribute__((target("avx512f")))

LOCUS_AVX512 inline __m512i montgomery16(__m512i x, __m512i y, __m512i p, __m512i p_odd,
                                         __m512i ninv) {
    const __m512i te = _mm512_mul_epu32(x, y);
    const __m512i to = _mm512_mul_epu32(_mm512_srli_epi64(x, 32), _mm512_srli_epi64(y, 32));
    const __m512i t_low = _mm512_mask_blend_epi32(0xAAAA, te, _mm512_slli_epi64(to, 32));
    const __m512i m = _mm512_mullo_epi32(t_low, ninv);
    const __m512i ue = _mm512_add_epi64(te, _mm512_mul_epu32(m, p));
    const __m512i uo = _mm512_add_epi64(to, _mm512_mul_epu32(_mm512_srli_epi64(m, 32), p_odd));
    const __m512i u = _mm512_mask_blend_epi32(0xAAAA, _mm512_srli_epi64(ue, 32), uo);
    return _mm512_min_epu32(u, _mm512_sub_epi32(u, p));
}

LOCUS_AVX512 inline __m512i add_mod16(__m512i x, __m512i y, __m512i p) {
    const __m512i s = _mm512_add_epi32(x, y);
    return _mm512_min_epu32(s, _mm512_sub_epi32(s, p));
}

// Lanes [l, l + 16) or, for the last block of a K ≡ 8 (mod 16), [l, l + 8).
LOCUS_AVX512 inline __mmask16 block_mask(std::size_t l, std::size_t lanes) {
    return l + 16 <= lanes ? __mmask16{0xFFFF} : __mmask16{0x00FF};
}

LOCUS_AVX512 inline __m512i load16(const std::uint32_t* a, __mmask16 mask) {
    return _mm512_maskz_loadu_epi32(mask, a);
}

LOCUS_AVX512 void multiply_avx512(std::uint32_t* out, const std::uint32_t* x,
                                  const std::uint32_t* y, const std::uint32_t* p,
                                  const std::uint32_t* ninv, std::size_t lanes) {
    for (std::size_t l = 0; l < lanes; l += 16) {
        const __mmask16 mask = block_mask(l, lanes);
        const __m512i pv = load16(p + l, mask);
        const __m512i r = montgomery16(load16(x + l, mask), load16(y + l, mask), pv,
                                       _mm512_srli_epi64(pv, 32), load16(ninv + l, mask));
        _mm512_mask_storeu_epi32(out + l, mask, r);
    }
}

LOCUS_AVX512 inline __m512i shoup16(__m512i x, __m512i b, __m512i b_quotient,
                                    __m512i b_quotient_odd, __m512i p) {
    const __m512i qe = _mm512_srli_epi64(_mm512_mul_epu32(x, b_quotient), 32);
    const __m512i qo = _mm512_mul_epu32(_mm512_srli_epi64(x, 32), b_quotient_odd);
    const __m512i q = _mm512_mask_blend_epi32(0xAAAA, qe, qo);
    const __m512i r = _mm512_sub_epi32(_mm512_mullo_epi32(x, b), _mm512_mullo_epi32(q, p));
    return _mm512_min_epu32(r, _mm512_sub_epi32(r, p));
}

// The lane count as a template parameter for the common widths: the loop over blocks unrolls
// and the primes and the multiplier stay in registers across the terms. `row_stride` and
// `table_stride` are the lanes a term and a column hold (more than kLanes when a wider row is
// done in chunks of at most 64 lanes, or when the table holds several slots a column).
// kPrefetch asks for the column kPrefetchAhead terms on: a certification's shared table
// (katsura-11: 12–18 MB) is read from the last-level cache, where 8 terms ahead took
// katsura-11's certification from 17.5 to 16.0 s (katsura-10, whose table is 3.5 MB:
// unchanged). The slots' bounds are prefetched as far ahead (16.4 -> 15.6 s; katsura-10
// 1.50 -> 1.37 s).
constexpr std::size_t kPrefetchAhead = 8;
template <std::size_t kLanes, bool kPrefetch>
LOCUS_AVX512 void add_scaled_rows_avx512_fixed(std::uint32_t* table, const std::uint32_t* columns,
                                               std::size_t n, const std::uint32_t* rows,
                                               const std::uint32_t* b,
                                               const std::uint32_t* b_quotients,
                                               const std::uint32_t* p, std::size_t row_stride,
                                               std::size_t table_stride) {
    constexpr std::size_t kBlocks = kLanes / 16;
    constexpr bool kTail = kLanes % 16 != 0;
    __m512i bv[kBlocks + 1], bq[kBlocks + 1], bq_odd[kBlocks + 1], pv[kBlocks + 1];
    for (std::size_t k = 0; k < kBlocks; ++k) {
        bv[k] = _mm512_loadu_si512(b + 16 * k);
        bq[k] = _mm512_loadu_si512(b_quotients + 16 * k);
        bq_odd[k] = _mm512_srli_epi64(bq[k], 32);
        pv[k] = _mm512_loadu_si512(p + 16 * k);
    }
    __m256i b_tail{}, bq_tail{}, bq_odd_tail{}, p_tail{};
    if constexpr (kTail) {
        b_tail = load8(b + 16 * kBlocks);
        bq_tail = load8(b_quotients + 16 * kBlocks);
        bq_odd_tail = _mm256_srli_epi64(bq_tail, 32);
        p_tail = load8(p + 16 * kBlocks);
    }
    for (std::size_t t = 0; t < n; ++t) {
        std::uint32_t* v = table + static_cast<std::size_t>(columns[t]) * table_stride;
        const std::uint32_t* row = rows + t * row_stride;
        if (kPrefetch && t + kPrefetchAhead < n) {
            const char* ahead = reinterpret_cast<const char*>(
                table + static_cast<std::size_t>(columns[t + kPrefetchAhead]) * table_stride);
            for (std::size_t line = 0; line < kLanes * sizeof(std::uint32_t); line += 64) {
                _mm_prefetch(ahead + line, _MM_HINT_T0);
            }
        }
        for (std::size_t k = 0; k < kBlocks; ++k) {
            const __m512i product =
                shoup16(_mm512_loadu_si512(row + 16 * k), bv[k], bq[k], bq_odd[k], pv[k]);
            _mm512_storeu_si512(v + 16 * k,
                                add_mod16(_mm512_loadu_si512(v + 16 * k), product, pv[k]));
        }
        if constexpr (kTail) {
            const __m256i product =
                shoup8(load8(row + 16 * kBlocks), b_tail, bq_tail, bq_odd_tail, p_tail);
            store8(v + 16 * kBlocks, add_mod8(load8(v + 16 * kBlocks), product, p_tail));
        }
    }
}

// add_scaled_rows_avx512_fixed over any number of lanes: chunks of at most 64, each with its
// primes and multiplier in registers across the terms (one masked block loop over all the
// lanes reloaded them for every term and block: the certification's 104 lanes of cyclic-8
// spent a third of the run there).
LOCUS_AVX512 void add_scaled_rows_avx512_strided(std::uint32_t* table, const std::uint32_t* columns,
                                                 std::size_t n, const std::uint32_t* rows,
                                                 const std::uint32_t* b,
                                                 const std::uint32_t* b_quotients,
                                                 const std::uint32_t* p, std::size_t lanes,
                                                 std::size_t table_stride, bool prefetch) {
    for (std::size_t l = 0; l < lanes; l += 64) {
        const std::size_t chunk = std::min<std::size_t>(64, lanes - l);
        const auto run = [&](auto plain, auto prefetching) {
            (prefetch ? prefetching : plain)(table + l, columns, n, rows + l, b + l,
                                             b_quotients + l, p + l, lanes, table_stride);
        };
#define LOCUS_CHUNK(K) \
    run(add_scaled_rows_avx512_fixed<K, false>, add_scaled_rows_avx512_fixed<K, true>)
        switch (chunk) {
        case 8:
            LOCUS_CHUNK(8);
            break;
        case 16:
            LOCUS_CHUNK(16);
            break;
        case 24:
            LOCUS_CHUNK(24);
            break;
        case 32:
            LOCUS_CHUNK(32);
            break;
        case 40:
            LOCUS_CHUNK(40);
            break;
        case 48:
            LOCUS_CHUNK(48);
            break;
        case 56:
            LOCUS_CHUNK(56);
            break;
        default:
            LOCUS_CHUNK(64);
            break;  // lanes are a multiple of 8
        }
#undef LOCUS_CHUNK
    }
}

LOCUS_AVX512 void add_scaled_rows_avx512(std::uint32_t* table, const std::uint32_t* columns,
                                         std::size_t n, const std::uint32_t* rows,
                                         const std::uint32_t* b, const std::uint32_t* b_quotients,
                                         const std::uint32_t* p, std::size_t lanes) {
    add_scaled_rows_avx512_strided(table, columns, n, rows, b, b_quotients, p, lanes, lanes, false);
}

// The bounds of every slot for every term, then each slot's residues in a pass of its own:
// with its multiplier in registers, the row (25 KB for 200 terms on 32 lanes) read again from
// the first-level cache. One pass over the terms for all the slots, each reading its
// multiplier from memory, was a third slower per slot and term (2026-11-29, a throwaway
// harness like `locus-bench lanes`; that variant was not committed).
LOCUS_AVX512 void add_scaled_rows_together_avx512(
    std::uint32_t* table, const std::uint32_t* columns, std::size_t n, const std::uint32_t* rows,
    unsigned slots, const std::uint32_t* b, const std::uint32_t* b_quotients,
    const std::uint32_t* p, std::size_t lanes, SlotBounds& bounds) {
    const __mmask8 slot_mask = static_cast<__mmask8>(slots);
    const __m512i offset = _mm512_loadu_si512(bounds.offset);
    const __m512i last = _mm512_set1_epi64(static_cast<long long>(log_bound::kSumTableSize - 1));
    // log_bound's chord nodes, 32 and the 32 after them, for two-register permutes.
    const std::int32_t* nodes = log_bound::kSumNodes.data();
    const __m512i node_low = _mm512_loadu_si512(nodes), node_high = _mm512_loadu_si512(nodes + 16);
    const __m512i next_low = _mm512_loadu_si512(nodes + 1);
    const __m512i next_high = _mm512_loadu_si512(nodes + 17);
    constexpr int kStepBits = 5;
    static_assert(log_bound::kSumNodeStep == 1u << kStepBits &&
                  log_bound::kSumTableSize / log_bound::kSumNodeStep == 32);
    const __m512i step_less_one = _mm512_set1_epi32((1 << kStepBits) - 1);
    __m512i highest = _mm512_loadu_si512(bounds.highest);
    for (std::size_t t = 0; t < n; ++t) {
        const std::uint32_t c = columns[t];
        if (t + kPrefetchAhead < n) {
            const std::size_t ahead =
                static_cast<std::size_t>(columns[t + kPrefetchAhead]) * kSlots;
            _mm_prefetch(reinterpret_cast<const char*>(bounds.bound + ahead), _MM_HINT_T0);
            _mm_prefetch(reinterpret_cast<const char*>(bounds.pending + ahead), _MM_HINT_T0);
        }
        // The slots' bounds: of_sum for all of them at once, the sum table's entry computed
        // from its chord (log_bound.h) on 32-bit lanes instead of gathered from the table.
        std::int64_t* bound = bounds.bound + static_cast<std::size_t>(c) * kSlots;
        const __m512i x = _mm512_loadu_si512(bound);
        const __m512i y = _mm512_add_epi64(offset, _mm512_set1_epi64(bounds.term[t]));
        const __m512i high = _mm512_max_epi64(x, y), low = _mm512_min_epi64(x, y);
        const __m512i gap = _mm512_zextsi256_si512(
            _mm512_cvtepi64_epi32(_mm512_min_epi64(_mm512_sub_epi64(high, low), last)));
        const __m512i node = _mm512_srli_epi32(gap, kStepBits);
        const __m512i from = _mm512_permutex2var_epi32(node_low, node, node_high);
        const __m512i to = _mm512_permutex2var_epi32(next_low, node, next_high);
        const __m512i chord = _mm512_add_epi32(
            _mm512_slli_epi32(from, kStepBits),
            _mm512_mullo_epi32(_mm512_sub_epi32(to, from), _mm512_and_si512(gap, step_less_one)));
        const __m512i raise = _mm512_cvtepi32_epi64(_mm512_castsi512_si256(
            _mm512_srli_epi32(_mm512_add_epi32(chord, step_less_one), kStepBits)));
        const __m512i raised = _mm512_add_epi64(high, raise);
        _mm512_mask_storeu_epi64(bound, slot_mask, raised);
        highest = _mm512_mask_max_epi64(highest, slot_mask, highest, raised);
        // Slots for which the column was not pending: now it is, and listed.
        std::uint8_t* pending = bounds.pending + static_cast<std::size_t>(c) * kSlots;
        unsigned fresh =
            static_cast<unsigned>(_mm_movemask_epi8(_mm_cmpeq_epi8(
                _mm_loadl_epi64(reinterpret_cast<const __m128i*>(pending)), _mm_setzero_si128()))) &
            slots;
        while (fresh != 0) {
            const unsigned s = static_cast<unsigned>(__builtin_ctz(fresh));
            pending[s] = 1;
            bounds.fresh[s * n + bounds.fresh_count[s]++] = c;
            fresh &= fresh - 1;
        }
    }
    _mm512_storeu_si512(bounds.highest, highest);
    for (unsigned s = 0; s < kSlots; ++s) {
        if ((slots >> s & 1u) != 0) {
            add_scaled_rows_avx512_strided(table + s * lanes, columns, n, rows, b + s * lanes,
                                           b_quotients + s * lanes, p, lanes, kSlots * lanes, true);
        }
    }
}

// shoup_quotients_portable on 8 lanes at a time. The estimate is below 2^32 (b < p < 2^31
// puts the exact quotient below 2^32 − 2), so it converts to 32 bits unsaturated.
LOCUS_AVX512 void shoup_quotients_avx512(std::uint32_t* out, const std::uint32_t* b,
                                         const std::uint32_t* p, const double* reciprocal,
                                         std::size_t lanes) {
    for (std::size_t l = 0; l < lanes; l += 8) {
        const __m256i b8 = load8(b + l);
        const __m512i p64 = _mm512_cvtepu32_epi64(load8(p + l));
        const __m512d estimate =
            _mm512_mul_pd(_mm512_cvtepu32_pd(b8), _mm512_loadu_pd(reciprocal + l));
        __m512i q = _mm512_cvtepu32_epi64(_mm512_cvttpd_epu32(estimate));
        const __m512i numerator = _mm512_slli_epi64(_mm512_cvtepu32_epi64(b8), 32);
        const __m512i r = _mm512_sub_epi64(numerator, _mm512_mul_epu32(q, p64));
        const __m512i one = _mm512_set1_epi64(1);
        q = _mm512_mask_sub_epi64(q, _mm512_cmplt_epi64_mask(r, _mm512_setzero_si512()), q, one);
        q = _mm512_mask_add_epi64(q, _mm512_cmpge_epi64_mask(r, p64), q, one);
        store8(out + l, _mm512_cvtepi64_epi32(q));
    }
}

LOCUS_AVX512 void combine_digits_avx512(std::uint32_t* out, const std::uint32_t* halves,
                                        std::size_t count, const std::uint32_t* powers,
                                        const std::uint32_t* p, const std::uint32_t* ninv,
                                        std::size_t lanes) {
    for (std::size_t l = 0; l < lanes; l += 16) {
        const __mmask16 mask = block_mask(l, lanes);
        const __m512i pv = load16(p + l, mask), p_odd = _mm512_srli_epi64(pv, 32);
        const __m512i nv = load16(ninv + l, mask);
        __m512i acc = _mm512_setzero_si512();
        for (std::size_t i = 0; i < count; ++i) {
            const __m512i h = _mm512_set1_epi32(static_cast<int>(halves[i]));
            acc = add_mod16(
                acc, montgomery16(h, load16(powers + i * lanes + l, mask), pv, p_odd, nv), pv);
        }
        _mm512_mask_storeu_epi32(out + l, mask, acc);
    }
}

// add_scaled_rows_together of an instruction set without the AVX-512 slot kernel: per term and
// slot, the bounds (raise_slot) and the kernel's multiply-add on that one term (at column 0 of
// the slot's place).
template <void (*Kernel)(std::uint32_t*, const std::uint32_t*, std::size_t, const std::uint32_t*,
                         const std::uint32_t*, const std::uint32_t*, const std::uint32_t*,
                         std::size_t)>
void add_scaled_rows_together_by_slot(std::uint32_t* table, const std::uint32_t* columns,
                                      std::size_t n, const std::uint32_t* rows, unsigned slots,
                                      const std::uint32_t* b, const std::uint32_t* b_quotients,
                                      const std::uint32_t* p, std::size_t lanes,
                                      SlotBounds& bounds) {
    const std::uint32_t first = 0;
    for (std::size_t t = 0; t < n; ++t) {
        const std::uint32_t c = columns[t];
        for (std::size_t s = 0; s < kSlots; ++s) {
            if ((slots >> s & 1u) == 0) {
                continue;
            }
            raise_slot(bounds, s, c, bounds.term[t], n);
            Kernel(table + (static_cast<std::size_t>(c) * kSlots + s) * lanes, &first, 1,
                   rows + t * lanes, b + s * lanes, b_quotients + s * lanes, p, lanes);
        }
    }
}

struct Kernels {
    const char* name;
    void (*multiply)(std::uint32_t*, const std::uint32_t*, const std::uint32_t*,
                     const std::uint32_t*, const std::uint32_t*, std::size_t);
    void (*add_scaled_rows)(std::uint32_t*, const std::uint32_t*, std::size_t, const std::uint32_t*,
                            const std::uint32_t*, const std::uint32_t*, const std::uint32_t*,
                            std::size_t);
    void (*combine_digits)(std::uint32_t*, const std::uint32_t*, std::size_t, const std::uint32_t*,
                           const std::uint32_t*, const std::uint32_t*, std::size_t);
    void (*add_scaled_rows_together)(std::uint32_t*, const std::uint32_t*, std::size_t,
                                     const std::uint32_t*, unsigned, const std::uint32_t*,
                                     const std::uint32_t*, const std::uint32_t*, std::size_t,
                                     SlotBounds&);
    void (*shoup_quotients)(std::uint32_t*, const std::uint32_t*, const std::uint32_t*,
                            const double*, std::size_t);
};

constexpr Kernels kPortable{"portable",
                            multiply_portable,
                            add_scaled_rows_portable,
                            combine_digits_portable,
                            add_scaled_rows_together_by_slot<add_scaled_rows_portable>,
                            shoup_quotients_portable};
constexpr Kernels kAvx2{"avx2",
                        multiply_avx2,
                        add_scaled_rows_avx2,
                        combine_digits_avx2,
                        add_scaled_rows_together_by_slot<add_scaled_rows_avx2>,
                        shoup_quotients_portable};
constexpr Kernels kAvx512{"avx512",
                          multiply_avx512,
                          add_scaled_rows_avx512,
                          combine_digits_avx512,
                          add_scaled_rows_together_avx512,
                          shoup_quotients_avx512};

KernelChoice<Kernels>& choice() {
    static KernelChoice<Kernels> kernels(kPortable, kAvx2, kAvx512);
    return kernels;
}

const Kernels& kernels() {
    return choice().get();
}

}  // namespace

LanePrimes::LanePrimes(std::size_t lanes, const std::function<bool(std::uint32_t)>& usable) {
    if (lanes == 0 || lanes % 8 != 0) {
        throw std::invalid_argument("LanePrimes: the number of lanes must be a multiple of 8");
    }
    for (std::uint32_t n = (1u << 31) - 1; primes_.size() < lanes; n -= 2) {
        if (n_is_prime(n) != 0 && usable(n)) {
            add(n);
        }
    }
}

LanePrimes::LanePrimes(std::span<const std::uint32_t> primes) {
    if (primes.empty()) {
        throw std::invalid_argument("LanePrimes: no primes");
    }
    for (const std::uint32_t p : primes) {
        if (p < 3 || p >= (1u << 31) || n_is_prime(p) == 0) {
            throw std::invalid_argument("LanePrimes: not an odd prime below 2^31");
        }
        add(p);
    }
    while (primes_.size() % 8 != 0) {
        add(primes.back());
    }
}

void LanePrimes::add(std::uint32_t p) {
    primes_.push_back(p);
    // Newton's iteration doubles the correct low bits of p⁻¹ mod 2^32: 1 → 32 in 5 steps.
    std::uint32_t inverse = 1;
    for (int i = 0; i < 5; ++i) {
        inverse *= 2 - p * inverse;
    }
    neg_inverses_.push_back(0u - inverse);
    reciprocals_.push_back(4294967296.0 / p);
}

std::uint32_t LanePrimes::multiply(std::size_t lane, std::uint32_t x, std::uint32_t y) const {
    return montgomery(x, y, primes_[lane], neg_inverses_[lane]);
}

std::uint32_t LanePrimes::to_montgomery(std::size_t lane, std::uint32_t x) const {
    return static_cast<std::uint32_t>((static_cast<std::uint64_t>(x) << 32) % primes_[lane]);
}

namespace lanes {

void multiply(std::uint32_t* out, const std::uint32_t* x, const std::uint32_t* y,
              const LanePrimes& primes) {
    kernels().multiply(out, x, y, primes.primes(), primes.neg_inverses(), primes.size());
}

void negate(std::uint32_t* x, const LanePrimes& primes) {
    const std::uint32_t* p = primes.primes();
    for (std::size_t l = 0; l < primes.size(); ++l) {
        x[l] = x[l] == 0 ? 0 : p[l] - x[l];
    }
}

bool is_zero(const std::uint32_t* x, std::size_t lanes) {
    std::uint32_t any = 0;
    for (std::size_t l = 0; l < lanes; ++l) {
        any |= x[l];
    }
    return any == 0;
}

void shoup_quotients(std::uint32_t* out, const std::uint32_t* b, const LanePrimes& primes) {
    kernels().shoup_quotients(out, b, primes.primes(), primes.reciprocals(), primes.size());
}

void add_scaled_rows(std::uint32_t* table, const std::uint32_t* columns, std::size_t n,
                     const std::uint32_t* rows, const std::uint32_t* b,
                     const std::uint32_t* b_quotients, const LanePrimes& primes) {
    // A reducer with no tail has no rows (a null pointer, which the kernels offset per block
    // of lanes: undefined, found by the differential fuzzer): nothing to add.
    if (n == 0) {
        return;
    }
    kernels().add_scaled_rows(table, columns, n, rows, b, b_quotients, primes.primes(),
                              primes.size());
}

void add_scaled_rows_together(std::uint32_t* table, const std::uint32_t* columns, std::size_t n,
                              const std::uint32_t* rows, unsigned slots, const std::uint32_t* b,
                              const std::uint32_t* b_quotients, const LanePrimes& primes,
                              SlotBounds& bounds) {
    if (n == 0 || slots == 0) {
        return;  // as add_scaled_rows
    }
    kernels().add_scaled_rows_together(table, columns, n, rows, slots, b, b_quotients,
                                       primes.primes(), primes.size(), bounds);
}

void combine_digits(std::uint32_t* out, const std::uint32_t* halves, std::size_t count,
                    const std::uint32_t* powers, const LanePrimes& primes) {
    kernels().combine_digits(out, halves, count, powers, primes.primes(), primes.neg_inverses(),
                             primes.size());
}

const char* kernel_name() {
    return kernels().name;
}

std::vector<std::string> supported_kernels() {
    return choice().supported();
}

void select_kernels(const std::string& name) {
    choice().select(name);
}

}  // namespace lanes

}  // namespace locus::algebra::detail
