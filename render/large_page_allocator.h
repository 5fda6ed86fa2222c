// An allocator for a frame's large buffers (its colours, their 8-bit codes) that asks the kernel
// for transparent huge pages. A 512² frame's colours are 3 MB: in 4 KiB pages that is 768 page
// faults the first time they are written, and on this project's machines a fault costs 5–10 µs
// (about a tenth of a whole `locus render` of a sphere). In 2 MiB pages it is two. Small buffers,
// and systems where huge pages are off (madvise then does nothing), take the ordinary path.
#pragma once

#include <cstddef>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace locus::render {

inline constexpr std::size_t kLargePage = std::size_t{1} << 21;
// From here on a buffer is rounded up to whole large pages. The kernel zeroes a large page in
// about the time of 30–50 small faults, so from 64 small pages (256 KiB) on it is the cheaper.
inline constexpr std::size_t kLargePageThreshold = kLargePage / 8;

template <class T>
struct LargePageAllocator {
    using value_type = T;

    LargePageAllocator() = default;
    template <class U>
    LargePageAllocator(const LargePageAllocator<U>&) noexcept {}

    T* allocate(std::size_t n) {
        if (n > static_cast<std::size_t>(-1) / sizeof(T) - kLargePage) {
            throw std::bad_array_new_length();
        }
        const std::size_t bytes = n * sizeof(T);
        if (bytes < kLargePageThreshold) {
            return static_cast<T*>(::operator new (bytes, std::align_val_t{alignof(T)}));
        }
        const std::size_t rounded = (bytes + kLargePage - 1) / kLargePage * kLargePage;
        void* memory = ::operator new (rounded, std::align_val_t{kLargePage});
#if defined(__linux__) && defined(MADV_HUGEPAGE)
        ::madvise(memory, rounded, MADV_HUGEPAGE);  // advice: failing leaves ordinary pages
#endif
        return static_cast<T*>(memory);
    }

    void deallocate(T* memory, std::size_t n) noexcept {
        const std::size_t bytes = n * sizeof(T);
        if (bytes < kLargePageThreshold) {
            ::operator delete (memory, std::align_val_t{alignof(T)});
        } else {
            ::operator delete (memory, std::align_val_t{kLargePage});
        }
    }

    template <class U>
    bool operator==(const LargePageAllocator<U>&) const noexcept {
        return true;
    }
};

// A frame-sized array of pixel values.
template <class T>
using PixelBuffer = std::vector<T, LargePageAllocator<T>>;

}  // namespace locus::render
