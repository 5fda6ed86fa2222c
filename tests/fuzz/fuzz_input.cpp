#include "tests/fuzz/fuzz_input.h"

#include <cstdio>
#include <cstdlib>

namespace locus::fuzz {

void property_failed(const char* what, std::string_view input) {
    std::fprintf(stderr, "property failed: %s\ninput (%zu bytes):\n%.*s\n", what, input.size(),
                 static_cast<int>(input.size()), input.data());
    std::abort();
}

}  // namespace locus::fuzz
