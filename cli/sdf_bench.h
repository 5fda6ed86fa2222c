// `locus bench sdf`: Hart's speed-ups on SDF scenes (bench/data/sdf/SUITE.txt). Every scene's
// primary rays are traced (no shading) with the speed-ups off, each one alone, and all on;
// the rows give rays per second, primitive evaluations per ray and the share of pixels whose
// first hit differs from the plain march.
#pragma once

#include <string>
#include <vector>

namespace locus::cli {

struct SdfBenchArgs {
    std::string data_dir;            // bench/data
    std::vector<std::string> cases;  // scene names; empty: the whole suite
    int size = 256;                  // image width; the height follows the scene's aspect
    int threads = 1;
    double min_seconds = 0.2;
    bool csv = false;
};

int run_sdf_bench(const SdfBenchArgs& args);

}  // namespace locus::cli
