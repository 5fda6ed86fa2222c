// Giac (Debian's xcas package: the `giac` command) as the second same-run reference of the
// Gröbner suite, beside Singular: `gbasis` under the ideal's order, over Q or modulo the ideal's
// characteristic, timed inside Giac by its own time() (start-up not counted), on the given
// number of threads. Giac's modular algorithm is probabilistic: its bases are not certified.
#pragma once

#include <string>

#include "algebra/parse.h"
#include "bench/singular.h"

namespace locus::bench {

// Mean seconds of Giac's gbasis on the ideal, as Giac's time() gives it (it repeats the call
// until 0.1 s have passed); {-1, 0} when Giac failed, ran past `limit_seconds` (when > 0), or
// has no such order (Giac knows lex, grlex and grevlex: plex, tdeg, revlex).
Timing time_giac_gbasis(const std::string& giac, const algebra::IdealFile& ideal, int threads,
                        double limit_seconds = 0);

}  // namespace locus::bench
