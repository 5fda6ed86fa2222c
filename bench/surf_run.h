// surf (Debian's surf-alggeo) as the same-run reference of `locus-bench render`, and the
// median-and-fastest summary of repeated timings that its comparisons use.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "bench/surface_suite.h"

namespace locus::bench {

// The median and the fastest of repeated runs. The median shrugs off runs slowed several-fold
// by other work on a shared machine; the fastest is the run least disturbed (noise only ever
// adds time), and moves less from one benchmark run to the next.
struct RunTimes {
    double median = -1.0;
    double best = -1.0;
};

// The median and the fastest of `times` (not empty).
RunTimes summary_of(std::vector<double> times);

// One run of surf on the surface at size×size, as a whole process: drawing it (and saving the
// picture), or, for the start-up that the frame comparison subtracts, only reading the same
// script. Seconds, or negative when surf fails or leaves no picture.
class SurfRun {
  public:
    SurfRun(std::string surf, const SuiteSurface& s, int size);
    ~SurfRun();
    SurfRun(const SurfRun&) = delete;
    SurfRun& operator=(const SurfRun&) = delete;

    double operator()(bool draw) const;

  private:
    std::string surf_;
    const SuiteSurface& surface_;
    int size_;
    std::filesystem::path script_, image_;
};

// Seconds of wall-clock time for `command` run through the shell, or negative when it exits
// with a failure.
double time_command(const std::string& command);

}  // namespace locus::bench
