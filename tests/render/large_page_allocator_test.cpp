// The frame buffers' allocator: large buffers start on a large-page boundary (where the kernel
// can back them with huge pages), small ones are ordinary, and both hold what is written.
#include "render/large_page_allocator.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>

namespace locus::render {
namespace {

TEST(LargePageAllocator, LargeBuffersStartOnALargePageBoundary) {
    for (const std::size_t floats :
         {std::size_t{1} << 16, std::size_t{786432}, std::size_t{3} << 20}) {
        PixelBuffer<float> buffer(floats, 0.5f);
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(buffer.data()) % kLargePage, 0u) << floats;
        std::iota(buffer.begin(), buffer.end(), 0.0f);
        EXPECT_EQ(buffer[floats - 1], static_cast<float>(floats - 1));
    }
}

TEST(LargePageAllocator, SmallBuffersAndGrowthKeepTheirContents) {
    PixelBuffer<std::uint8_t> bytes;
    for (int i = 0; i < 600000; ++i) {  // grows through both paths of the allocator
        bytes.push_back(static_cast<std::uint8_t>(i * 7));
    }
    for (int i = 0; i < 600000; i += 9973) {
        ASSERT_EQ(bytes[static_cast<std::size_t>(i)], static_cast<std::uint8_t>(i * 7)) << i;
    }
    PixelBuffer<double> small(3, 1.25);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(small.data()) % alignof(double), 0u);
    EXPECT_EQ(small[2], 1.25);
    EXPECT_TRUE(LargePageAllocator<float>() == LargePageAllocator<double>());
}

TEST(LargePageAllocator, AnImpossibleSizeIsBadAlloc) {
    LargePageAllocator<double> allocator;
    EXPECT_THROW(static_cast<void>(allocator.allocate(static_cast<std::size_t>(-1) / 4)),
                 std::bad_alloc);
}

}  // namespace
}  // namespace locus::render
