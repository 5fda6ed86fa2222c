// FLINT keeps caches for each thread — its pool of GMP integers, tens to hundreds of kilobytes
// once the thread has met big integers — and frees them only when that same thread calls
// flint_cleanup(). A thread that ends without it leaves them behind for good. Threads end under
// locus all the time: the Python module runs every call on a thread of its own, and oneTBB ends
// its worker threads whenever the last thread using it lets go (after each such call), so a loop
// of `locus.groebner(..., threads=2)` grew by about 190 kB a call.
#pragma once

namespace locus::algebra {

// This thread frees FLINT's caches when it ends. Cheap after the first call in a thread (a
// thread_local's guard). Called by the library's entry points that compute with big integers
// (groebner) for the calling thread, and by every parallel body that does (the modular lift
// and replays, the signature algorithm's and the certification's workers, the tail reduction,
// the exact tier of the renderer, implicitization by Dixon and the implicit equation's check)
// for oneTBB's workers — whose observers cannot do it: an observer sees one arena only. New
// parallel code that meets big integers calls it too; locus view calls it on its HTTP threads.
void release_flint_caches_at_thread_exit();

}  // namespace locus::algebra
