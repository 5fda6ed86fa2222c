// use_large_pages_for_heap (cli/heap_pages.h): blocks malloc gives after it, on the main thread
// and on oneTBB's threads, lie in mappings the kernel may back with huge pages, and an
// address-space limit turns it off. Each case runs in a child process (the function acts once
// per process). Read from /proc/self/smaps, where the advice shows only in the kernel's
// "madvise" mode (Debian's default); in the others those cases are skipped.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>

#include <sys/resource.h>
#include <unistd.h>

#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "cli/heap_pages.h"

namespace {

// Whether the function acts in this build (under the sanitizers, whose allocators keep heaps of
// their own, it does nothing).
bool acts_here() {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
    return false;
#else
    return true;
#endif
}

// Whether the kernel gives huge pages where madvise asks, and only there (the mode "always"
// makes every block eligible, advised or not; "never", none): the only mode in which the advice
// shows in /proc/self/smaps.
bool advice_is_visible() {
    std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string modes;
    std::getline(in, modes);
    return acts_here() && modes.find("[madvise]") != std::string::npos;
}

// The THPeligible field of the mapping holding `address` (-1: no such mapping or field).
int huge_page_eligible(const void* address) {
    const auto a = reinterpret_cast<std::uintptr_t>(address);
    std::ifstream in("/proc/self/smaps");
    std::string line;
    bool inside = false;
    while (std::getline(in, line)) {
        unsigned long begin = 0, end = 0;
        if (std::sscanf(line.c_str(), "%lx-%lx ", &begin, &end) == 2) {  // a mapping's line
            inside = a >= begin && a < end;
            continue;
        }
        if (inside && line.rfind("THPeligible:", 0) == 0) {
            return std::atoi(line.c_str() + 12);
        }
    }
    return -1;
}

// A block of several huge pages, as the algebra's allocations are (kept from the optimizer).
void* block() {
    void* p = std::malloc(std::size_t{8} << 20);
    __asm__ volatile("" : : "r"(p) : "memory");
    return p;
}

// An address 4 MiB into such a block.
const void* inside(const void* p) {
    return static_cast<const char*>(p) + (std::size_t{4} << 20);
}

TEST(HeapPages, MainThreadBlocksAreInAdvisedMemory) {
    if (!advice_is_visible()) {
        GTEST_SKIP() << "huge pages not in the madvise mode here (or a sanitizer's allocator)";
    }
    EXPECT_EXIT(
        {
            void* const before = block();
            const int eligible_before = huge_page_eligible(inside(before));
            locus::cli::use_large_pages_for_heap(1);
            void* const after = block();
            // Before: an ordinary block (not eligible); after: eligible past its first huge page
            // (it may begin in the part of the heap that was there before, left as it was).
            std::_Exit(eligible_before == 0 && huge_page_eligible(inside(after)) == 1 ? 0 : 1);
        },
        ::testing::ExitedWithCode(0), "");
}

TEST(HeapPages, WorkerThreadBlocksAreInAdvisedMemory) {
    if (!advice_is_visible()) {
        GTEST_SKIP() << "huge pages not in the madvise mode here (or a sanitizer's allocator)";
    }
    if (tbb::info::default_concurrency() < 2) {
        GTEST_SKIP() << "one core for this process: oneTBB has no worker thread";
    }
    EXPECT_EXIT(
        {
            const std::thread::id main = std::this_thread::get_id();
            // oneTBB's worker started and idle first, as in a computation long under way, so
            // that the advice finds it within its wait even on a loaded machine.
            tbb::parallel_for(0, 2, [](int) {});
            locus::cli::use_large_pages_for_heap(2);
            // The advice is given on a thread of its own, not waited for, which takes the
            // worker if it finds it free: leave it that time, then poll for a block allocated on
            // a worker thread in advised memory.
            std::this_thread::sleep_for(std::chrono::milliseconds(200));
            bool seen = false;
            const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
            while (!seen && std::chrono::steady_clock::now() < until) {
                tbb::task_arena arena(2);
                arena.execute([&] {
                    tbb::parallel_for(0, 64, [&](int) {
                        if (std::this_thread::get_id() != main) {
                            void* const p = block();
                            if (huge_page_eligible(inside(p)) == 1) {
                                seen = true;
                            }
                            std::free(p);
                        }
                        std::this_thread::sleep_for(std::chrono::milliseconds(1));
                    });
                });
            }
            std::_Exit(seen ? 0 : 1);
        },
        ::testing::ExitedWithCode(0), "");
}

TEST(HeapPages, AnAddressSpaceLimitTurnsItOff) {
    if (!acts_here()) {
        GTEST_SKIP() << "a sanitizer's allocator: the function does nothing in this build";
    }
    EXPECT_EXIT(
        {
            rlimit limit{};
            limit.rlim_cur = limit.rlim_max = rlim_t{8} << 30;
            if (setrlimit(RLIMIT_AS, &limit) != 0) {
                std::_Exit(2);
            }
            void* const before = ::sbrk(0);
            locus::cli::use_large_pages_for_heap(1);
            // Nothing reserved: the heap has not grown by the gigabyte of address space.
            const auto grown = static_cast<char*>(::sbrk(0)) - static_cast<char*>(before);
            std::_Exit(grown < (std::ptrdiff_t{1} << 29) ? 0 : 1);
        },
        ::testing::ExitedWithCode(0), "");
}

}  // namespace
