#include "algebra/modular/detail/dense_update.h"

#include <immintrin.h>

#include "algebra/detail/kernel_choice.h"

// GCC 12 sees the _mm512_undefined_epi32() inside AVX-512 intrinsics as uninitialized reads
// (GCC bug 105593); the intrinsics are correct.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#pragma GCC diagnostic ignored "-Wuninitialized"

namespace locus::algebra::modular::detail {

namespace {

inline std::uint64_t bounded_sum(std::uint64_t sum, std::uint64_t limit) {
    return sum >= limit ? sum - limit : sum;
}

void lazy_portable(std::uint64_t* acc, const std::uint32_t* coefficients, std::size_t n,
                   std::uint32_t factor) {
    for (std::size_t j = 0; j < n; ++j) {
        acc[j] += std::uint64_t{factor} * coefficients[j];
    }
}

void bounded_portable(std::uint64_t* acc, const std::uint32_t* coefficients, std::size_t n,
                      std::uint32_t factor, std::uint64_t limit) {
    for (std::size_t j = 0; j < n; ++j) {
        acc[j] = bounded_sum(acc[j] + std::uint64_t{factor} * coefficients[j], limit);
    }
}

#define LOCUS_AVX2 __attribute__((target("avx2")))

// Four lanes a vector: four 32-bit coefficients widened, multiplied by the factor as 32×32 →
// 64 bits (vpmuludq), added. AVX2 has no unsigned 64-bit minimum, so the bounded form compares
// with the sign bit flipped.
LOCUS_AVX2 void lazy_avx2(std::uint64_t* acc, const std::uint32_t* coefficients, std::size_t n,
                          std::uint32_t factor) {
    const __m256i f = _mm256_set1_epi64x(factor);
    std::size_t j = 0;
    for (; j + 4 <= n; j += 4) {
        const __m256i c = _mm256_cvtepu32_epi64(
            _mm_loadu_si128(reinterpret_cast<const __m128i*>(coefficients + j)));
        __m256i* target = reinterpret_cast<__m256i*>(acc + j);
        _mm256_storeu_si256(target,
                            _mm256_add_epi64(_mm256_loadu_si256(target), _mm256_mul_epu32(c, f)));
    }
    lazy_portable(acc + j, coefficients + j, n - j, factor);
}

LOCUS_AVX2 void bounded_avx2(std::uint64_t* acc, const std::uint32_t* coefficients, std::size_t n,
                             std::uint32_t factor, std::uint64_t limit) {
    const __m256i f = _mm256_set1_epi64x(factor);
    const __m256i l = _mm256_set1_epi64x(static_cast<long long>(limit));
    const __m256i flip = _mm256_set1_epi64x(static_cast<long long>(std::uint64_t{1} << 63));
    const __m256i below = _mm256_xor_si256(l, flip);
    std::size_t j = 0;
    for (; j + 4 <= n; j += 4) {
        const __m256i c = _mm256_cvtepu32_epi64(
            _mm_loadu_si128(reinterpret_cast<const __m128i*>(coefficients + j)));
        __m256i* target = reinterpret_cast<__m256i*>(acc + j);
        const __m256i sum = _mm256_add_epi64(_mm256_loadu_si256(target), _mm256_mul_epu32(c, f));
        // sum < limit (unsigned) ⇔ limit ^ 2⁶³ > sum ^ 2⁶³ (signed).
        const __m256i keep = _mm256_cmpgt_epi64(below, _mm256_xor_si256(sum, flip));
        _mm256_storeu_si256(target, _mm256_blendv_epi8(_mm256_sub_epi64(sum, l), sum, keep));
    }
    bounded_portable(acc + j, coefficients + j, n - j, factor, limit);
}

#define LOCUS_AVX512 __attribute__((target("avx512f")))

// Eight lanes a vector, two vectors an iteration.
LOCUS_AVX512 void lazy_avx512(std::uint64_t* acc, const std::uint32_t* coefficients, std::size_t n,
                              std::uint32_t factor) {
    const __m512i f = _mm512_set1_epi64(factor);
    std::size_t j = 0;
    for (; j + 16 <= n; j += 16) {
        const __m512i c0 = _mm512_cvtepu32_epi64(
            _mm256_loadu_si256(reinterpret_cast<const __m256i*>(coefficients + j)));
        const __m512i c1 = _mm512_cvtepu32_epi64(
            _mm256_loadu_si256(reinterpret_cast<const __m256i*>(coefficients + j + 8)));
        const __m512i a0 = _mm512_loadu_si512(acc + j);
        const __m512i a1 = _mm512_loadu_si512(acc + j + 8);
        _mm512_storeu_si512(acc + j, _mm512_add_epi64(a0, _mm512_mul_epu32(c0, f)));
        _mm512_storeu_si512(acc + j + 8, _mm512_add_epi64(a1, _mm512_mul_epu32(c1, f)));
    }
    if (j + 8 <= n) {
        const __m512i c = _mm512_cvtepu32_epi64(
            _mm256_loadu_si256(reinterpret_cast<const __m256i*>(coefficients + j)));
        _mm512_storeu_si512(acc + j,
                            _mm512_add_epi64(_mm512_loadu_si512(acc + j), _mm512_mul_epu32(c, f)));
        j += 8;
    }
    lazy_portable(acc + j, coefficients + j, n - j, factor);
}

LOCUS_AVX512 void bounded_avx512(std::uint64_t* acc, const std::uint32_t* coefficients,
                                 std::size_t n, std::uint32_t factor, std::uint64_t limit) {
    const __m512i f = _mm512_set1_epi64(factor);
    const __m512i l = _mm512_set1_epi64(static_cast<long long>(limit));
    std::size_t j = 0;
    for (; j + 8 <= n; j += 8) {
        const __m512i c = _mm512_cvtepu32_epi64(
            _mm256_loadu_si256(reinterpret_cast<const __m256i*>(coefficients + j)));
        const __m512i sum = _mm512_add_epi64(_mm512_loadu_si512(acc + j), _mm512_mul_epu32(c, f));
        // Below the limit the subtraction wraps past it, so the minimum is the sum.
        _mm512_storeu_si512(acc + j, _mm512_min_epu64(sum, _mm512_sub_epi64(sum, l)));
    }
    bounded_portable(acc + j, coefficients + j, n - j, factor, limit);
}

struct Kernels {
    const char* name;
    void (*lazy)(std::uint64_t*, const std::uint32_t*, std::size_t, std::uint32_t);
    void (*bounded)(std::uint64_t*, const std::uint32_t*, std::size_t, std::uint32_t,
                    std::uint64_t);
};

constexpr Kernels kPortable{"portable", lazy_portable, bounded_portable};
constexpr Kernels kAvx2{"avx2", lazy_avx2, bounded_avx2};
constexpr Kernels kAvx512{"avx512", lazy_avx512, bounded_avx512};

algebra::detail::KernelChoice<Kernels>& choice() {
    static algebra::detail::KernelChoice<Kernels> kernels(kPortable, kAvx2, kAvx512);
    return kernels;
}

const Kernels& kernels() {
    return choice().get();
}

}  // namespace

void add_dense_lazy(std::uint64_t* acc, const std::uint32_t* coefficients, std::size_t n,
                    std::uint32_t factor) {
    kernels().lazy(acc, coefficients, n, factor);
}

void add_dense_bounded(std::uint64_t* acc, const std::uint32_t* coefficients, std::size_t n,
                       std::uint32_t factor, std::uint64_t limit) {
    kernels().bounded(acc, coefficients, n, factor, limit);
}

const char* dense_update_kernels() {
    return kernels().name;
}

std::vector<std::string> supported_dense_update_kernels() {
    return choice().supported();
}

void select_dense_update_kernels(const std::string& name) {
    choice().select(name);
}

}  // namespace locus::algebra::modular::detail
