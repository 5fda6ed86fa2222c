// Storage for N values of T left uninitialized, for tables and stacks whose every entry is
// written before it is read: T may have default member initializers (DoubleDouble and
// BernsteinBall have), which would otherwise be stored for all N at every
// construction — per ray, in the certified isolation's stack of 53 balls. T must be trivially
// copyable and destructible, so that assigning to an entry creates it.
#pragma once

#include <cstddef>
#include <new>
#include <type_traits>

namespace locus::render::detail {

template <class T, std::size_t N>
class UninitializedArray {
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

  public:
    T* data() { return std::launder(reinterpret_cast<T*>(storage_)); }
    T& operator[](std::size_t i) { return data()[i]; }

  private:
    alignas(T) std::byte storage_[N * sizeof(T)];
};

}  // namespace locus::render::detail
