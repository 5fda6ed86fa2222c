// `locus bench render`: speed and accuracy of every trace method on the surface suite
// (bench/data/surfaces/SUITE.txt).
#pragma once

#include <string>
#include <vector>

namespace locus::cli {

struct RenderBenchArgs {
    std::string data_dir;              // bench/data
    std::vector<std::string> cases;    // surface names; empty: the whole suite
    std::vector<std::string> methods;  // empty: all
    int size = 128;                    // size×size primary rays per surface
    int threads = 1;                   // the figures are single-core
    double min_seconds = 0.2;          // repeat each method until this much time has passed
    bool csv = false;
    std::string surf = "surf-alggeo-nox";  // same-run reference renderer, or "off"
};

int run_render_bench(const RenderBenchArgs& args);

}  // namespace locus::cli
