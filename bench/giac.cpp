#include "bench/giac.h"

#include <unistd.h>  // for getpid

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "algebra/print.h"

namespace locus::bench {

Timing time_giac_gbasis(const std::string& giac, const algebra::IdealFile& ideal,
                        double min_seconds, int threads, double limit_seconds) {
    const algebra::PolyRing& ring = *ideal.ring;
    const char* order = nullptr;
    switch (ring.order().kind()) {
    case algebra::MonomialOrder::Kind::lex:
        order = "plex";
        break;
    case algebra::MonomialOrder::Kind::grlex:
        order = "tdeg";
        break;
    case algebra::MonomialOrder::Kind::grevlex:
        order = "revlex";
        break;
    default:
        return {-1, 0};
    }
    std::string generators, variables;
    for (const algebra::Polynomial& f : ideal.generators) {
        if (!generators.empty()) {
            generators += ',';
        }
        // Over GF(p) Giac takes the residues itself: `(f) % p` is f with coefficients mod p.
        if (ideal.characteristic == 0) {
            generators += algebra::to_string(f);
        } else {
            generators += '(';
            generators += algebra::to_string(f);
            generators += ")%";
            generators += std::to_string(ideal.characteristic);
        }
    }
    for (std::size_t v = 0; v < ring.num_vars(); ++v) {
        if (v != 0) {
            variables += ',';
        }
        variables += ring.variable_name(v);
    }
    const std::string call = "gbasis([" + generators + "],[" + variables + "]," + order + ")";
    // One statement a line: Giac reads its input line by line. time() gives [cpu, real].
    std::string script = "threads:=" + std::to_string(threads) + ";\n";
    script += "t:=time(" + call + ");s:=t[1];n:=1;\n";  // at least one run
    script += "while (s < " + std::to_string(min_seconds) + " and n < " + std::to_string(kMaxRuns) +
              ") { t:=time(" + call + "); s:=s+t[1]; n:=n+1; };\n";
    script += "print(\"LOCUSBENCH\", s, n);\n";
    const auto path = std::filesystem::temp_directory_path() /
                      ("locus-bench-" + std::to_string(::getpid()) + ".giac");
    {
        std::ofstream out(path);
        out << script;
    }
    std::string command;
    if (limit_seconds > 0) {
        command = "timeout " + std::to_string(std::lround(limit_seconds)) + " ";
    }
    command += giac + " < " + path.string() + " 2>&1";
    Timing t{-1, 0};
    if (FILE* pipe = popen(command.c_str(), "r")) {
        char line[4096];
        while (std::fgets(line, sizeof line, pipe)) {
            double seconds = 0;
            int runs = 0;
            if (std::sscanf(line, "LOCUSBENCH,%lf,%d", &seconds, &runs) == 2 && runs > 0) {
                t = {seconds / runs, runs};
            }
        }
        pclose(pipe);
    }
    std::filesystem::remove(path);
    return t;
}

}  // namespace locus::bench
