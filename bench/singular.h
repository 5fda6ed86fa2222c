// Singular (Debian's `singular`) as the same-run reference of the Gröbner and implicitization
// suites: scripts are written to a temporary file and run by `Singular -q --no-rc`; times are
// measured inside Singular with `rtimer` in microseconds, so its start-up is not counted.
#pragma once

#include <string>
#include <vector>

#include "algebra/parse.h"
#include "algebra/poly_ring.h"
#include "algebra/polynomial.h"
#include "implicit/parametrization.h"

namespace locus::bench {

// Repetitions per case and side at most: enough for sub-millisecond cases to run for the
// whole --min-seconds, where single runs moved their ratios by 30 % on a shared machine.
inline constexpr int kMaxRuns = 1000;

struct Timing {
    double seconds = 0;  // mean seconds per run; negative when the run failed or timed out
    int runs = 0;
};

// Mean seconds of Singular's std (reduced basis: redSB, redTail) on the ideal, repeated until
// `min_seconds` have passed or kMaxRuns runs.
Timing time_singular_std(const std::string& singular, const algebra::IdealFile& ideal,
                         double min_seconds);

// Seconds of Singular's `eliminate` on the elimination ideal of `map`, or -1 when Singular
// failed or took longer than `limit_seconds` (killed by timeout(1)).
double time_singular_eliminate(const std::string& singular, const implicit::Parametrization& map,
                               double limit_seconds);

}  // namespace locus::bench
