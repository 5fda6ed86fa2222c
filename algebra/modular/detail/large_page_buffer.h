// A grow-only buffer of plain values in transparent huge pages, for F4's split reducers: a
// row's reduction reads a few thousand reducers scattered over tens of megabytes, and in
// 4 KiB pages nearly every one costs a TLB miss (cyclic-8 modulo 65 521: 10 million of them).
// In 2 MiB pages the whole buffer takes a few TLB entries; the page faults of its first use
// also fall from one per 4 KiB to one per 2 MiB. Where huge pages are off, madvise does
// nothing and the buffer is ordinary memory. Internal to algebra/modular/.
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
        const std::size_t bytes = (wanted * sizeof(T) + kLargePage - 1) / kLargePage * kLargePage;
        memory_.reset();
        memory_.reset(static_cast<T*>(::operator new (bytes, std::align_val_t{kLargePage})));
#if defined(__linux__) && defined(MADV_HUGEPAGE)
        ::madvise(memory_.get(), bytes, MADV_HUGEPAGE);  // advice: failing leaves small pages
#endif
        capacity_ = bytes / sizeof(T);
    }

  private:
    static constexpr std::size_t kLargePage = std::size_t{1} << 21;
    struct Release {
        void operator()(T* memory) const noexcept {
            ::operator delete (memory, std::align_val_t{kLargePage});
        }
    };
    std::unique_ptr<T, Release> memory_;
    std::size_t capacity_ = 0;
};

}  // namespace locus::algebra::modular::detail
