#include "algebra/assert.h"

#include <cstdio>
#include <cstdlib>

namespace locus::detail {

void assertion_failed(const char* condition, const char* file, int line) {
    std::fprintf(stderr,
                 "locus: internal invariant violated (a bug; please report it): %s at %s:%d\n",
                 condition, file, line);
    std::abort();
}

}  // namespace locus::detail
