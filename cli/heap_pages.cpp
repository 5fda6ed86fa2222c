#include "cli/heap_pages.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <climits>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <thread>

#include <malloc.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>

#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

namespace locus::cli {

namespace {

constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
// Address space the main thread's heap is grown by at once: no memory until touched, and
// enough for every benchmark but katsura-12 (whose heap outgrows it; the rest of that heap is
// in ordinary pages).
constexpr std::size_t kReservation = std::size_t{1} << 30;
// glibc's heaps of threads other than the main one: HEAP_MAX_SIZE, 2 · DEFAULT_MMAP_THRESHOLD_MAX
// = 64 MiB on 64-bit systems, each aligned to its size (malloc/arena.c). A wrong guess only
// advises some other mapping.
constexpr std::uintptr_t kThreadHeap = std::uintptr_t{64} << 20;
// Blocks below this come from the heap: glibc's largest allowed threshold (its own starts at
// 128 KiB and rises only as mapped blocks are freed, each of them faulted in page by page).
constexpr int kMmapThreshold = 32 << 20;
// glibc's default padding of each growth of the main heap, restored after the reservation.
constexpr int kDefaultTopPad = 128 << 10;
// A thread's heap is made writable at once by two blocks of this size.
constexpr std::size_t kThreadHeapGrowth = std::size_t{30} << 20;
static_assert(2 * kThreadHeapGrowth < kThreadHeap && kThreadHeapGrowth < kMmapThreshold);
// How long the threads' advice waits for every thread of its arena to come (with 20 ms, under a
// load of two busy processes on two cores, the worker often had not).
constexpr std::chrono::milliseconds kWorkerWait{500};

void advise(std::uintptr_t begin, std::uintptr_t end) {
    begin = (begin + kHugePage - 1) & ~(kHugePage - 1);
    if (end > begin) {
        ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);  // advice only
    }
}

bool address_space_limited() {
    rlimit limit{};
    return ::getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur != RLIM_INFINITY;
}

// Whether the heap could be set up (a glibc that refuses these settings, as under
// GLIBC_TUNABLES with other heap sizes, gets nothing more: not the threads' part either).
bool advise_main_heap() {
    // Serve blocks below kMmapThreshold from the heap, and keep what is freed (a trimmed heap is
    // faulted in again): the threshold first, so that a refusal leaves glibc as it was.
    if (::mallopt(M_MMAP_THRESHOLD, kMmapThreshold) == 0 ||
        ::mallopt(M_TRIM_THRESHOLD, INT_MAX) == 0) {
        return false;
    }
    ::mallopt(M_TOP_PAD, static_cast<int>(kReservation));
    void* const before = ::sbrk(0);
    // More than the top of the heap holds, so that the heap grows: by this and the pad.
    void* const probe = std::malloc(::mallinfo2().keepcost + kHugePage);
    // Not untouched in the compiler's eyes: an allocation nothing uses may be left out.
    __asm__ volatile("" : : "r"(probe) : "memory");
    void* const after = ::sbrk(0);
    // Past the reservation the heap grows as glibc's default has it (in ordinary pages).
    ::mallopt(M_TOP_PAD, kDefaultTopPad);
    std::free(probe);
    if (before == reinterpret_cast<void*>(-1) || after == reinterpret_cast<void*>(-1)) {
        return false;
    }
    advise(reinterpret_cast<std::uintptr_t>(before), reinterpret_cast<std::uintptr_t>(after));
    return true;
}

// The heap of the calling thread (not the main one), found from a block malloc gives it, then
// grown at once: glibc makes such a heap writable only as far as each allocation needs, and a
// huge page needs its 2 MiB writable when first touched (growing by small steps, katsura-10's
// worker kept 63 of its 65 MB in small pages).
void advise_this_thread_heap() {
    void* const probe = std::malloc(64);
    __asm__ volatile("" : : "r"(probe) : "memory");  // kept (see advise_main_heap)
    const auto address = reinterpret_cast<std::uintptr_t>(probe);
    if (probe == nullptr) {
        return;
    }
    const std::uintptr_t heap = address & ~(kThreadHeap - 1);
    ::madvise(reinterpret_cast<void*>(heap), kThreadHeap, MADV_HUGEPAGE);  // advice only
    // Two blocks below the mmap threshold, so both in the heap: most of its 64 MiB.
    void* const growth[2] = {std::malloc(kThreadHeapGrowth), std::malloc(kThreadHeapGrowth)};
    __asm__ volatile("" : : "r"(growth[0]), "r"(growth[1]) : "memory");
    std::free(growth[1]);
    std::free(growth[0]);
    std::free(probe);
}

// Each oneTBB thread of an arena of `threads` (at most the threads oneTBB has) other than this
// one advises its heap. glibc keeps a thread's heap (its arena's) for the life of the thread and
// oneTBB keeps its threads, whatever arena runs them later. The tasks wait for each other
// (kWorkerWait at most), so that every thread takes one; a thread busy elsewhere by then is
// left as it is.
void advise_worker_heaps(int threads) {
    threads = std::min(threads, tbb::info::default_concurrency());
    const std::thread::id caller = std::this_thread::get_id();
    std::atomic<int> arrived{0};
    tbb::task_arena arena(threads);
    arena.execute([&] {
        tbb::parallel_for(
            0, threads,
            [&](int) {
                ++arrived;
                // Sleeping, not spinning: on a loaded machine a thread may take long to come,
                // and the wait must not take a core from the computation meanwhile.
                const auto until = std::chrono::steady_clock::now() + kWorkerWait;
                while (arrived.load() < threads && std::chrono::steady_clock::now() < until) {
                    std::this_thread::sleep_for(std::chrono::microseconds(100));
                }
                if (std::this_thread::get_id() != caller) {
                    advise_this_thread_heap();
                }
            },
            tbb::static_partitioner{});
    });
}

}  // namespace

void use_large_pages_for_heap(int threads) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
    (void)threads;  // the sanitizers' allocators have heaps of their own
#else
    static bool done = false;
    if (done || address_space_limited()) {
        return;
    }
    done = true;
    if (advise_main_heap() && threads > 1) {
        // On a thread of its own, not waited for: it starts oneTBB's threads (about 3 ms of a
        // core), which the computation needs anyway. Joined at exit (locus itself ends with
        // _Exit; locus-bench returns from main).
        static std::jthread helper;
        helper = std::jthread([threads] { advise_worker_heaps(threads); });
    }
#endif
}

}  // namespace locus::cli
