#include "bench/giac.h"

#include <cmath>
#include <cstdio>
#include <vector>

#include "algebra/print.h"
#include "bench/script_run.h"

namespace locus::bench {

Timing time_giac_gbasis(const std::string& giac, const algebra::IdealFile& ideal, int threads,
                        double limit_seconds) {
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
    // The ring's variables are renamed v0, v1, …: a name of the input could be one of Giac's
    // constants (i, e, pi, D) or a name of the script (henrion5 has a variable t).
    std::vector<std::string> names;
    std::string variables;
    for (std::size_t v = 0; v < ring.num_vars(); ++v) {
        std::string name = "v";
        name += std::to_string(v);
        names.push_back(std::move(name));
        if (v != 0) {
            variables += ',';
        }
        variables += names.back();
    }
    std::string generators;
    for (const algebra::Polynomial& f : ideal.generators) {
        if (!generators.empty()) {
            generators += ',';
        }
        // Over GF(p) Giac takes the residues itself: `(f) % p` is f with coefficients mod p.
        if (ideal.characteristic == 0) {
            generators += algebra::to_string(f, names);
        } else {
            generators += '(';
            generators += algebra::to_string(f, names);
            generators += ")%";
            generators += std::to_string(ideal.characteristic);
        }
    }
    const std::string call = "gbasis([" + generators + "],[" + variables + "]," + order + ")";
    // Giac's time() repeats the call itself (1, 10, 100, … times, until 0.1 s have passed)
    // and gives the mean [cpu, real] of one call: one time() is the measurement. One statement
    // a line: Giac reads line by line.
    std::string script = "threads:=" + std::to_string(threads) + ";\n";
    script += "locusbench_t:=time(" + call + ");\n";
    script += "print(\"LOCUSBENCH\", locusbench_t[1]);\n";
    Timing t{-1, 0};
    run_script({giac, "", true, ".giac", limit_seconds}, script, [&](const char* line) {
        double seconds = 0;
        if (std::sscanf(line, "LOCUSBENCH,%lf", &seconds) == 1) {
            t = {seconds, 1};
        }
    });
    return t;
}

}  // namespace locus::bench
