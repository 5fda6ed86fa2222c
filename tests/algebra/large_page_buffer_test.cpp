// F4's grow-only buffer (algebra/modular/detail/large_page_buffer.h): small sizes from the
// ordinary heap, from 256 KiB whole 2 MiB-aligned large pages of a mapping of its own that
// grows by mremap; every value it promises room for can be written and read back (past the
// end of a mapping is a fault; AddressSanitizer, in the debug preset, checks the heap's).
#include <gtest/gtest.h>

#include <cstdint>

#include "algebra/modular/detail/large_page_buffer.h"

namespace locus::algebra::modular::detail {
namespace {

void fill_and_check(LargePageBuffer<std::uint32_t>& buffer, std::size_t n) {
    buffer.make_room(n);
    std::uint32_t* data = buffer.data();
    for (std::size_t i = 0; i < n; ++i) {
        data[i] = static_cast<std::uint32_t>(i * 2654435761u);
    }
    for (std::size_t i = 0; i < n; ++i) {
        ASSERT_EQ(data[i], static_cast<std::uint32_t>(i * 2654435761u)) << i;
    }
}

TEST(LargePageBuffer, GrowsFromTheHeapToLargePages) {
    LargePageBuffer<std::uint32_t> buffer;
    buffer.make_room(0);
    fill_and_check(buffer, 1);
    fill_and_check(buffer, 1000);  // 4 KB: the ordinary heap
    const std::uint32_t* small = buffer.data();
    fill_and_check(buffer, 500);  // no growth: the same memory
    EXPECT_EQ(buffer.data(), small);
    fill_and_check(buffer, 3'000'000);  // 12 MB: large pages, aligned to them
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(buffer.data()) % (std::uintptr_t{1} << 21), 0u);
    const std::uint32_t* large = buffer.data();
    fill_and_check(buffer, 3'000'001);  // within the rounding to whole pages: no growth
    EXPECT_EQ(buffer.data(), large);
    // Growing a large buffer moves its mapping (mremap) to a region that is aligned again.
    for (std::size_t n : {5'000'000u, 9'000'000u, 14'000'000u}) {
        fill_and_check(buffer, n);
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(buffer.data()) % (std::uintptr_t{1} << 21), 0u)
            << n;
    }
}

TEST(LargePageBuffer, StartsLarge) {
    LargePageBuffer<std::uint64_t> buffer;
    buffer.make_room(1'000'000);  // 8 MB at once: a mapping from the start
    std::uint64_t* data = buffer.data();
    data[0] = 1;
    data[999'999] = 2;
    EXPECT_EQ(data[0] + data[999'999], 3u);
}

}  // namespace
}  // namespace locus::algebra::modular::detail
