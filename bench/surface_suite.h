// The render benchmark suite, bench/data/surfaces/SUITE.txt: one surface a line,
// `name | equation | clip radius | why`, `#` starting a comment line. Read by `locus-bench
// render` and by the render tests, so that both see the same surfaces.
#pragma once

#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "algebra/error.h"

namespace locus::bench {

struct SuiteSurface {
    std::string name, equation;
    double clip_radius = 2.0;
};

// Throws ParseError naming the line of a malformed entry.
inline std::vector<SuiteSurface> parse_surface_suite(std::string_view text) {
    auto trim = [](const std::string& s) {
        const auto b = s.find_first_not_of(" \t");
        const auto e = s.find_last_not_of(" \t\r");
        return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
    };
    std::vector<SuiteSurface> suite;
    std::istringstream in{std::string(text)};
    std::string line;
    std::size_t number = 0;
    while (std::getline(in, line)) {
        ++number;
        if (trim(line).empty() || trim(line)[0] == '#') {
            continue;
        }
        std::stringstream fields(line);
        std::string name, equation, radius;
        std::getline(fields, name, '|');
        std::getline(fields, equation, '|');
        std::getline(fields, radius, '|');
        try {
            suite.push_back({trim(name), trim(equation), std::stod(trim(radius))});
        } catch (const std::exception&) {
            // Built piece by piece: GCC 12 warns (-Wrestrict) on "lit" + string + "lit".
            std::string found = "'";
            found += trim(line);
            found += '\'';
            throw ParseError(number, 1, "name | equation | clip radius", found);
        }
    }
    return suite;
}

}  // namespace locus::bench
