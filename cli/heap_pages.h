// The heap in transparent huge pages, for the commands whose work is large algebra (groebner,
// ideal, implicitize): their allocations (a basis a prime from every F4 replay, the residues
// of the lift, the certification's tables) are touched once and freed, and every 4 KiB page of
// them cost a page fault of 5–12 µs on the machines measured. Katsura-10 on one thread made
// 35 000 of them; with its heap in huge pages, about 1 100.
//
// Why here and not in glibc: Debian's kernels give huge pages only where madvise asks for them,
// and glibc's malloc asks only under GLIBC_TUNABLES=glibc.malloc.hugetlb=1, read at the start of
// the process, which a program cannot set for itself. So the main thread's heap is grown once
// by a reservation of address space (no memory until touched) and advised, and each worker
// thread's heap is advised from that thread. Everything is advice: where it fails (no huge
// pages, an address-space limit, another allocator under a sanitizer) the heap is the ordinary
// one and only the speed differs.
#pragma once

namespace locus::cli {

// Call before the heavy work, after apply_process_limits (an --max-memory limit turns the
// reservation off: reserved address space would count against it). `threads` > 1 also advises
// the heaps of the other threads of a oneTBB arena of that many, on a thread started for it
// (only each thread's first heap of 64 MiB: past it, glibc's next heaps are in ordinary
// pages); pass 1 where the work is
// small, since a second thread costs a whole process about 0.6 ms here (its start and the
// exit's teardown), a twentieth of a small `locus groebner`. Idempotent.
void use_large_pages_for_heap(int threads);

}  // namespace locus::cli
