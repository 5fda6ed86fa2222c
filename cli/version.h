// What `locus --version` prints: locus's version and those of the libraries it was built with.
#pragma once

#include <string>

namespace locus::cli {

// "locus 0.1.0\nFLINT 2.9.0, GMP 6.2.1, OpenImageIO 2.4.7.1, zlib 1.2.13" (one library per
// item; GMP's is the one loaded at run time, the others those compiled against).
std::string version_text();

}  // namespace locus::cli
