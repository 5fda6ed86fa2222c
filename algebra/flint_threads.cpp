#include "algebra/flint_threads.h"

#include <flint/flint.h>

namespace locus::algebra {

namespace {

// Destroyed when its thread ends, after the thread's last use of FLINT (a thread_local's
// destructor runs before the thread's static TLS, where FLINT keeps its caches, goes away).
struct FlintCachesOfThisThread {
    ~FlintCachesOfThisThread() { flint_cleanup(); }
};

}  // namespace

void release_flint_caches_at_thread_exit() {
    thread_local FlintCachesOfThisThread caches;
    static_cast<void>(caches);
}

}  // namespace locus::algebra
