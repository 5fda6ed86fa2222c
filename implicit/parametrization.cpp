#include "implicit/parametrization.h"

#include <algorithm>
#include <cctype>

#include "algebra/error.h"
#include "algebra/parse.h"
#include "implicit/bezier_patch.h"

namespace locus::implicit {
namespace {

std::size_t first_non_space(std::string_view s, std::size_t from = 0) {
    while (from < s.size() && std::isspace(static_cast<unsigned char>(s[from]))) {
        ++from;
    }
    return from;
}

// `u in [a, b], v in [c, d]`: one interval per parameter, exact bounds a < b.
std::vector<std::pair<algebra::Rational, algebra::Rational>> parse_domain(
    std::string_view text, std::size_t line, std::size_t first_column, const Parametrization& map) {
    const std::size_t k = map.parameter_ring->num_vars();
    std::vector<std::pair<algebra::Rational, algebra::Rational>> domain(k);
    std::vector<bool> given(k, false);
    std::size_t i = 0;
    auto column = [&] { return first_column + i; };
    auto skip_spaces = [&] {
        while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) {
            ++i;
        }
    };
    auto found = [&] {
        return i < text.size() ? "'" + std::string(text.substr(i, 12)) + "'"
                               : std::string("the end of the line");
    };
    auto expect_char = [&](char c, const char* what) {
        skip_spaces();
        if (i >= text.size() || text[i] != c) {
            throw ParseError(line, column(), what, found());
        }
        ++i;
    };
    auto number = [&] {
        skip_spaces();
        const std::size_t begin = i;
        while (i < text.size() &&
               (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '.' ||
                text[i] == '/' || text[i] == '-' || text[i] == '+')) {
            ++i;
        }
        std::string_view literal = text.substr(begin, i - begin);
        const bool negative = literal.starts_with('-');
        if (negative || literal.starts_with('+')) {
            literal.remove_prefix(1);
        }
        algebra::Rational value;
        if (!algebra::Rational::from_literal(literal, value)) {
            i = begin;
            throw ParseError(line, column(), "a bound such as -2, 1.5 or 3/4", found());
        }
        return negative ? -value : value;
    };
    while (true) {
        skip_spaces();
        const std::size_t begin = i;
        while (i < text.size() &&
               (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '_')) {
            ++i;
        }
        const std::string name(text.substr(begin, i - begin));
        const auto v = map.parameter_ring->variable_index(name);
        if (!v) {
            i = begin;
            throw ParseError(line, column(), "a parameter name", found());
        }
        if (given[*v]) {
            i = begin;
            throw ParseError(line, column(), "each parameter once", "'" + name + "' again");
        }
        if (std::find(map.half_angle.begin(), map.half_angle.end(), *v) != map.half_angle.end()) {
            i = begin;
            throw ParseError(line, column(),
                             "a parameter outside sin and cos (an angle's range is the circle)",
                             "'" + name + "'");
        }
        skip_spaces();
        if (text.substr(i, 2) != "in") {
            throw ParseError(line, column(), "'in'", found());
        }
        i += 2;
        expect_char('[', "'['");
        const algebra::Rational lo = number();
        expect_char(',', "','");
        const std::size_t hi_column = column();
        const algebra::Rational hi = number();
        if (!(lo < hi)) {
            throw ParseError(line, hi_column + 1, "an upper bound above the lower one",
                             hi.to_string());
        }
        expect_char(']', "']'");
        domain[*v] = {lo, hi};
        given[*v] = true;
        skip_spaces();
        if (i >= text.size()) {
            break;
        }
        expect_char(',', "',' or the end of the line");
    }
    for (std::size_t v = 0; v < k; ++v) {
        if (!given[v]) {
            throw ParseError(
                line, column(),
                "an interval for every parameter (" + map.parameter_ring->variable_name(v) + ")",
                "the end of the line");
        }
    }
    return domain;
}

}  // namespace

Parametrization parse_parametrization(std::string_view text) {
    // A `bezier:` line makes the file a patch given by control points (implicit/bezier_patch.h).
    for (const auto& [raw, line] : algebra::split_lines(text)) {
        const std::size_t start = first_non_space(raw);
        std::string_view rest = raw.substr(start);
        if (rest.starts_with("bezier")) {
            rest.remove_prefix(6);
            rest.remove_prefix(std::min(rest.size(), first_non_space(rest)));
            if (rest.starts_with(":")) {
                std::vector<std::string> names;
                const BezierPatch patch = parse_bezier_param(text, &names);
                return to_parametrization(patch, names);
            }
        }
    }
    Parametrization result;
    const std::vector<std::string> allowed = {"x", "y", "z"};
    struct Assignment {
        std::string_view expression;
        std::size_t line, column;
    };
    std::vector<Assignment> assignments(3, Assignment{{}, 0, 0});
    bool have_params = false;
    std::string_view domain_text;  // after 'domain:', read once the parameters are known
    std::size_t domain_line = 0, domain_column = 0;
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
                if (key == "domain") {
                    if (domain_line != 0) {
                        throw ParseError(line, start + 1, "one 'domain:' line", "'domain:'");
                    }
                    domain_text = raw.substr(colon + 1);
                    domain_line = line;
                    domain_column = colon + 2;
                    continue;
                }
                if (key != "params" || have_params) {
                    throw ParseError(line, start + 1,
                                     have_params ? "one 'params:' line" : "'params:' or 'x = ...'",
                                     "'" + key + ":'");
                }
                const auto names = algebra::parse_name_list(raw.substr(colon + 1), line, colon + 2);
                for (const std::string& name : names) {
                    if (std::find(allowed.begin(), allowed.end(), name) != allowed.end()) {
                        const std::size_t at = raw.find(name, colon + 1);
                        throw ParseError(line, at + 1,
                                         "parameter names other than the coordinates x, y, z",
                                         "'" + name + "'");
                    }
                }
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
    algebra::Trigonometry trigonometry;
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
            a.expression, result.parameter_ring, a.line, a.column, &trigonometry));
    }
    // A parameter inside sin/cos must appear nowhere else: the substitution u -> tan(u/2) holds
    // only where u stands for the angle alone, and a map such as (u·cos v, u·sin v, v) is not
    // algebraic at all.
    const std::size_t k = result.parameter_ring->num_vars();
    for (std::size_t v = 0; v < k; ++v) {
        const algebra::Trigonometry::Use inside = trigonometry.inside[v];
        const algebra::Trigonometry::Use outside = trigonometry.outside[v];
        if (inside.line != 0) {
            result.half_angle.push_back(v);
        }
        if (inside.line != 0 && outside.line != 0) {
            const std::string& name = result.parameter_ring->variable_name(v);
            throw ParseError(outside.line, outside.column,
                             "the angle " + name + " only inside sin and cos (it is used in " +
                                 "sin/cos at line " + std::to_string(inside.line) + ", column " +
                                 std::to_string(inside.column) +
                                 "; a map that mixes an angle with its sine or cosine is not "
                                 "algebraic)",
                             "'" + name + "' outside sin and cos");
        }
    }
    if (!result.half_angle.empty()) {
        // The map as written: the parameters, then sin and cos of each angle (sin declared
        // first, so that sin(u)^2 leads sin(u)^2 + cos(u)^2 − 1 under grevlex).
        std::vector<std::string> names = result.parameter_ring->variable_names();
        algebra::Trigonometry circle;
        circle.form = algebra::Trigonometry::Form::circle;
        circle.cos_of.assign(k, 0);
        circle.sin_of.assign(k, 0);
        // Named sin_u, cos_u (with '_' appended while a name is taken).
        const auto fresh = [&](std::string name) {
            while (std::find(names.begin(), names.end(), name) != names.end()) {
                name += '_';
            }
            return name;
        };
        for (const std::size_t v : result.half_angle) {
            const std::string& u = result.parameter_ring->variable_name(v);
            circle.sin_of[v] = names.size();
            names.push_back(fresh("sin_" + u));
            circle.cos_of[v] = names.size();
            names.push_back(fresh("cos_" + u));
        }
        result.circle_ring =
            algebra::PolyRing::make(names, algebra::MonomialOrder::grevlex(names.size()));
        for (std::size_t i = 0; i < result.coordinates.size(); ++i) {
            const Assignment& a = assignments[i];
            result.circle_components.push_back(algebra::parse_rational_function(
                a.expression, result.circle_ring, a.line, a.column, &circle));
        }
        const algebra::Polynomial one =
            algebra::Polynomial::constant(result.circle_ring, algebra::Rational(1));
        for (const std::size_t v : result.half_angle) {
            const auto s = algebra::Polynomial::variable(result.circle_ring, circle.sin_of[v]);
            const auto c = algebra::Polynomial::variable(result.circle_ring, circle.cos_of[v]);
            result.circle_relations.push_back(s * s + c * c - one);
        }
    }
    if (domain_line != 0) {
        result.domain = parse_domain(domain_text, domain_line, domain_column, result);
    }
    return result;
}

CommonDenominatorForm over_common_denominator(const Parametrization& map) {
    std::vector<algebra::Polynomial> distinct;
    for (const auto& c : map.components) {
        if (std::find(distinct.begin(), distinct.end(), c.denominator()) == distinct.end()) {
            distinct.push_back(c.denominator());
        }
    }
    CommonDenominatorForm form{
        {}, algebra::Polynomial::constant(map.parameter_ring, algebra::Rational(1))};
    for (const auto& d : distinct) {
        form.denominator *= d;
    }
    for (const auto& c : map.components) {
        algebra::Polynomial numerator = c.numerator();
        for (const auto& d : distinct) {
            if (!(d == c.denominator())) {
                numerator *= d;
            }
        }
        form.numerators.push_back(std::move(numerator));
    }
    return form;
}

}  // namespace locus::implicit
