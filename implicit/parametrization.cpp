#include "implicit/parametrization.h"

#include <algorithm>
#include <cctype>

#include "algebra/error.h"
#include "algebra/parse.h"

namespace locus::implicit {
namespace {

std::size_t first_non_space(std::string_view s, std::size_t from = 0) {
    while (from < s.size() && std::isspace(static_cast<unsigned char>(s[from]))) {
        ++from;
    }
    return from;
}

}  // namespace

Parametrization parse_parametrization(std::string_view text) {
    Parametrization result;
    const std::vector<std::string> allowed = {"x", "y", "z"};
    struct Assignment {
        std::string_view expression;
        std::size_t line, column;
    };
    std::vector<Assignment> assignments(3, Assignment{{}, 0, 0});
    bool have_params = false;
    const std::vector<algebra::SourceLine> lines = algebra::split_lines(text);
    const std::size_t last_line = lines.back().number;
    for (const auto& [raw, line] : lines) {
        const std::size_t start = first_non_space(raw);
        if (start < raw.size() && raw.find_first_not_of(" \t\r", start) != std::string_view::npos) {
            const auto colon = raw.find(':');
            const auto equals = raw.find('=');
            if (colon != std::string_view::npos &&
                (equals == std::string_view::npos || colon < equals)) {
                std::string key(raw.substr(start, colon - start));
                while (!key.empty() && std::isspace(static_cast<unsigned char>(key.back()))) {
                    key.pop_back();
                }
                if (key != "params" || have_params) {
                    throw ParseError(line, start + 1,
                                     have_params ? "one 'params:' line" : "'params:' or 'x = ...'",
                                     "'" + key + ":'");
                }
                const auto names = algebra::parse_name_list(raw.substr(colon + 1), line, colon + 2);
                result.parameter_ring =
                    algebra::PolyRing::make(names, algebra::MonomialOrder::grevlex(names.size()));
                have_params = true;
            } else {
                if (!have_params) {
                    throw ParseError(line, start + 1, "a 'params:' line before the coordinates",
                                     "'" + std::string(raw.substr(start, 12)) + "'");
                }
                if (equals == std::string_view::npos) {
                    throw ParseError(line, raw.size() + 1, "'=' after the coordinate name",
                                     "end of line");
                }
                std::string name(raw.substr(start, equals - start));
                while (!name.empty() && std::isspace(static_cast<unsigned char>(name.back()))) {
                    name.pop_back();
                }
                const auto it = std::find(allowed.begin(), allowed.end(), name);
                if (it == allowed.end()) {
                    throw ParseError(line, start + 1, "a coordinate x, y or z", "'" + name + "'");
                }
                Assignment& a = assignments[static_cast<std::size_t>(it - allowed.begin())];
                if (a.line != 0) {
                    throw ParseError(line, start + 1,
                                     "each coordinate assigned once (" + name +
                                         " was assigned on line " + std::to_string(a.line) + ")",
                                     "'" + name + "' again");
                }
                a = {raw.substr(equals + 1), line, equals + 2};
            }
        }
    }
    if (!have_params) {
        throw ParseError(last_line, 1, "a 'params:' line", "end of input");
    }
    for (std::size_t i = 0; i < 3; ++i) {
        const Assignment& a = assignments[i];
        if (a.line == 0) {
            if (i == 2) {
                break;  // plane curve
            }
            throw ParseError(last_line, 1, "an assignment '" + allowed[i] + " = ...'",
                             "end of input");
        }
        // Name an unsupported function plainly instead of calling it an unknown variable.
        for (const char* f : {"tan", "exp", "log", "sqrt"}) {
            const auto at = a.expression.find(std::string(f) + "(");
            if (at != std::string_view::npos && !result.parameter_ring->variable_index(f)) {
                throw ParseError(a.line, a.column + at,
                                 "a polynomial or a quotient of polynomials (" + std::string(f) +
                                     " is not supported yet)",
                                 "'" + std::string(f) + "'");
            }
        }
        result.coordinates.push_back(allowed[i]);
        result.components.push_back(algebra::parse_rational_function(
            a.expression, result.parameter_ring, a.line, a.column, &result.half_angle));
    }
    return result;
}

}  // namespace locus::implicit
