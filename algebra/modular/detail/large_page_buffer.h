// A grow-only buffer of plain values in transparent huge pages, for F4's split reducers: a
// row's reduction reads about 1 400 reducers scattered over tens of megabytes (cyclic-8
// modulo 65 521: 10 million reads in all), each to a 4 KiB page of its own. In 2 MiB pages the
// whole buffer takes a few TLB entries, and its first use a few page faults instead of one per
// 4 KiB: cyclic-8's linear algebra went 1.09 → 0.92 s (`locus groebner ... --stats`, old and
// new build interleaved; the VM has no counters to show the TLB misses themselves). Where huge
// pages are off, madvise does nothing and the buffer is ordinary memory.
//
// Large buffers are a mapping of their own that grows in place or moves with mremap, which
// carries the pages already touched along instead of taking fresh ones: growing by halves from
// 2 to 24 MiB in fresh blocks touched 62 MiB for cyclic-8 modulo 65 521 (its peak resident
// memory 95 → 79 MB with the mapping). A first touch is what costs here (a fresh 2 MiB page
// took 2–5 ms on this VM, a reused one 0.1 ms). Internal to algebra/modular/.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <new>
#include <type_traits>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace locus::algebra::modular::detail {

template <class T>
class LargePageBuffer {
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

  public:
    LargePageBuffer() = default;
    LargePageBuffer(const LargePageBuffer&) = delete;
    LargePageBuffer& operator=(const LargePageBuffer&) = delete;
    ~LargePageBuffer() { release(); }

    T* data() { return memory_; }
    const T* data() const { return memory_; }

    // Room for n values. What the buffer held is not kept when it grows; new memory is not
    // initialised.
    void make_room(std::size_t n) {
        if (n <= capacity_) {
            return;
        }
        const std::size_t wanted = std::max(n, capacity_ + capacity_ / 2);
        if (wanted > static_cast<std::size_t>(-1) / sizeof(T) - kLargePage) {
            throw std::bad_array_new_length();
        }
        // A large page is zeroed whole at its first touch, about as long as 30–50 small page
        // faults: below 64 small pages (256 KiB) the ordinary heap is the cheaper, and small
        // matrices (most of the tests' and the suite's) do not pay 2 MiB each.
        if (wanted * sizeof(T) < kLargePage / 8) {
            release();
            memory_ = static_cast<T*>(::operator new(wanted * sizeof(T)));
            capacity_ = wanted;
            return;
        }
        const std::size_t bytes = (wanted * sizeof(T) + kLargePage - 1) / kLargePage * kLargePage;
        grow_mapping(bytes);
        capacity_ = bytes / sizeof(T);
    }

  private:
    static constexpr std::size_t kLargePage = std::size_t{1} << 21;

#if defined(__linux__)
    // `bytes` (whole large pages) of fresh mapping aligned to a large page, so that every one
    // of them can be a huge page; nullptr when the address space is exhausted.
    static void* map_aligned(std::size_t bytes) {
        void* const region = ::mmap(nullptr, bytes + kLargePage, PROT_READ | PROT_WRITE,
                                    MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (region == MAP_FAILED) {
            return nullptr;
        }
        const auto begin = reinterpret_cast<std::uintptr_t>(region);
        const std::uintptr_t aligned = (begin + kLargePage - 1) & ~(kLargePage - 1);
        if (aligned > begin) {
            ::munmap(region, aligned - begin);
        }
        if (const std::uintptr_t tail = begin + kLargePage - aligned; tail > 0) {
            ::munmap(reinterpret_cast<void*>(aligned + bytes), tail);
        }
        return reinterpret_cast<void*>(aligned);
    }
    void grow_mapping(std::size_t bytes) {
        void* memory = map_aligned(bytes);
        if (memory == nullptr) {
            throw std::bad_alloc();
        }
        if (mapped_bytes_ > 0) {
            // Onto the new region: the pages already touched move with their contents.
            if (::mremap(memory_, mapped_bytes_, bytes, MREMAP_MAYMOVE | MREMAP_FIXED, memory) ==
                MAP_FAILED) {
                ::munmap(memory, bytes);
                throw std::bad_alloc();
            }
        } else {
            release();
        }
        memory_ = static_cast<T*>(memory);
        mapped_bytes_ = bytes;
#if defined(MADV_HUGEPAGE)
        ::madvise(memory, bytes, MADV_HUGEPAGE);  // advice: failing leaves small pages
#endif
    }
    void release() noexcept {
        if (mapped_bytes_ > 0) {
            ::munmap(memory_, mapped_bytes_);
        } else {
            ::operator delete(memory_);
        }
        memory_ = nullptr;
        mapped_bytes_ = 0;
        capacity_ = 0;
    }
#else
    void grow_mapping(std::size_t bytes) {
        release();
        memory_ = static_cast<T*>(::operator new(bytes));
    }
    void release() noexcept {
        ::operator delete(memory_);
        memory_ = nullptr;
        capacity_ = 0;
    }
#endif

    T* memory_ = nullptr;
    std::size_t capacity_ = 0;
    std::size_t mapped_bytes_ = 0;  // a mapping of its own when not 0, else the heap's
};

}  // namespace locus::algebra::modular::detail
