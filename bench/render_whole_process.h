// `locus-bench render --whole-process`: the command a user types, timed as a whole process
// beside surf's whole process on every suite surface — start-up, parsing, compiling, the frame
// and writing the picture included on both sides (issue 21: users judge the command).
#pragma once

#include <string>
#include <vector>

#include "bench/surface_suite.h"

namespace locus::bench {

struct WholeProcessArgs {
    int size = 512;
    std::string locus;   // the locus executable
    std::string surf;    // the surf executable, or empty for locus alone
    std::string method;  // `--method` for locus render, or empty for its default
    double min_seconds = 1.0;
    bool csv = false;
};

// For each surface, `locus render EQUATION -o F.png --size N×N --clip-radius R --shadows off`
// (and `--method M` when given)
// and surf drawing the same surface at the same size into a PPM, each through the shell, in
// alternating rounds (at least five, until min_seconds of locus runs, at most 15); prints the
// medians and the fastest runs and their ratios. Returns the exit code.
int run_whole_process_comparison(const std::vector<SuiteSurface>& suite,
                                 const WholeProcessArgs& args);

}  // namespace locus::bench
