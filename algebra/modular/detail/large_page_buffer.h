// A grow-only buffer of plain values in transparent huge pages, for F4's split reducers: a
// row's reduction reads about 1 400 reducers scattered over tens of megabytes (cyclic-8
// modulo 65 521: 10 million reads in all), each to a 4 KiB page of its own. In 2 MiB pages the
// whole buffer takes a few TLB entries, and its first use a few page faults instead of one per
// 4 KiB: cyclic-8's linear algebra went 1.09 → 0.92 s (`locus groebner ... --stats`, old and
// new build interleaved; the VM has no counters to show the TLB misses themselves). Where huge
// pages are off, madvise does nothing and the buffer is ordinary memory. Internal to
// algebra/modular/.
#pragma once

#include <algorithm>
#include <cstddef>
#include <memory>
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
    T* data() { return memory_.get(); }
    const T* data() const { return memory_.get(); }

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
        memory_.reset();
        // A large page is zeroed whole at its first touch, about as long as 30–50 small page
        // faults: below 64 small pages (256 KiB) the ordinary heap is the cheaper, and small
        // matrices (most of the tests' and the suite's) do not pay 2 MiB each.
        const bool large = wanted * sizeof(T) >= kLargePage / 8;
        const std::size_t bytes =
            large ? (wanted * sizeof(T) + kLargePage - 1) / kLargePage * kLargePage
                  : wanted * sizeof(T);
        memory_ = {static_cast<T*>(::operator new(bytes, alignment(large))), Release{large}};
#if defined(__linux__) && defined(MADV_HUGEPAGE)
        if (large) {
            ::madvise(memory_.get(), bytes, MADV_HUGEPAGE);  // advice: failing leaves small pages
        }
#endif
        capacity_ = bytes / sizeof(T);
    }

  private:
    static constexpr std::size_t kLargePage = std::size_t{1} << 21;
    static std::align_val_t alignment(bool large) {
        return std::align_val_t{large ? kLargePage : alignof(T)};
    }
    struct Release {
        bool large = false;
        void operator()(T* memory) const noexcept { ::operator delete(memory, alignment(large)); }
    };
    std::unique_ptr<T, Release> memory_;
    std::size_t capacity_ = 0;
};

}  // namespace locus::algebra::modular::detail
