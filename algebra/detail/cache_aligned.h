// Internal to algebra/: vectors whose data starts on a cache line, for the tables the lane
// kernels read and write a whole vector register at a time (residue_lanes.h, the F4 replays on
// lanes). glibc's malloc aligns to 16 bytes, so a 64-byte AVX-512 load or store of such a
// table straddles two cache lines three times in four. `locus-bench lanes` (the certification's
// row kernel, 200 terms a step on random columns of a 4 546-column table, 2026-11-29): 3.99 ns
// a term on 32 lanes with the table 16 bytes past a line, 3.08 ns on lines; 5.69 against 4.41
// on 48.
#pragma once

#include <cstddef>
#include <new>
#include <vector>

namespace locus::algebra::detail {

inline constexpr std::size_t kCacheLine = 64;

template <class T>
struct CacheAlignedAllocator {
    using value_type = T;

    CacheAlignedAllocator() = default;
    template <class U>
    CacheAlignedAllocator(const CacheAlignedAllocator<U>&) noexcept {}

    T* allocate(std::size_t n) {
        if (n > static_cast<std::size_t>(-1) / sizeof(T)) {
            throw std::bad_array_new_length();
        }
        return static_cast<T*>(::operator new (n * sizeof(T), std::align_val_t{kCacheLine}));
    }
    void deallocate(T* memory, std::size_t) noexcept {
        ::operator delete (memory, std::align_val_t{kCacheLine});
    }

    template <class U>
    bool operator==(const CacheAlignedAllocator<U>&) const noexcept {
        return true;
    }
};

template <class T>
using CacheAlignedVector = std::vector<T, CacheAlignedAllocator<T>>;

}  // namespace locus::algebra::detail
