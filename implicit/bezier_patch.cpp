#include "implicit/bezier_patch.h"

#include <flint/fmpz.h>

#include <cctype>
#include <optional>

#include "algebra/error.h"
#include "algebra/parse.h"

namespace locus::implicit {

using algebra::Integer;
using algebra::Polynomial;
using algebra::Rational;

namespace {

constexpr unsigned kMaxDegree = 16;  // 17² control points; implicit degree up to 512

struct Token {
    std::string_view text;
    std::size_t column;  // 1-based
};

std::vector<Token> tokens_of(std::string_view line) {
    std::vector<Token> result;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) {
            ++i;
        }
        if (i >= line.size() || line[i] == '#') {
            break;
        }
        const std::size_t start = i;
        while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i])) &&
               line[i] != '#') {
            ++i;
        }
        result.push_back({line.substr(start, i - start), start + 1});
    }
    return result;
}

std::string shown(std::string_view token) {
    return token.empty() ? "the end of the line" : "'" + std::string(token.substr(0, 40)) + "'";
}

Rational exact_number(const Token& token, std::size_t line) {
    std::string_view text = token.text;
    bool negative = false;
    if (!text.empty() && (text[0] == '-' || text[0] == '+')) {
        negative = text[0] == '-';
        text.remove_prefix(1);
    }
    Rational value;
    if (text.size() > 4096 || !Rational::from_literal(text, value)) {
        throw ParseError(line, token.column, "a decimal number such as 1.3375 or 3/4",
                         shown(token.text));
    }
    return negative ? -value : value;
}

unsigned small_integer(const Token& token, std::size_t line, unsigned low, unsigned high,
                       const std::string& what) {
    unsigned value = 0;
    bool ok = !token.text.empty() && token.text.size() <= 4;
    for (const char c : token.text) {
        ok = ok && std::isdigit(static_cast<unsigned char>(c));
        value = value * 10 + static_cast<unsigned>(c - '0');
    }
    if (!ok || value < low || value > high) {
        throw ParseError(
            line, token.column,
            what + " (an integer from " + std::to_string(low) + " to " + std::to_string(high) + ")",
            shown(token.text));
    }
    return value;
}

// The meaningful lines (comments and blank lines skipped), with their numbers.
std::vector<std::pair<std::vector<Token>, std::size_t>> meaningful_lines(std::string_view text) {
    std::vector<std::pair<std::vector<Token>, std::size_t>> result;
    for (const auto& [line, number] : algebra::split_lines(text)) {
        auto tokens = tokens_of(line);
        if (!tokens.empty()) {
            result.emplace_back(std::move(tokens), number);
        }
    }
    return result;
}

std::array<Rational, 4> control_point(const std::vector<Token>& tokens, std::size_t line) {
    if (tokens.size() < 3 || tokens.size() > 4) {
        const Token& at = tokens.size() > 4 ? tokens[4] : tokens.back();
        throw ParseError(line, tokens.size() > 4 ? at.column : at.column + at.text.size(),
                         "a control point 'x y z' or 'x y z weight'",
                         tokens.size() > 4 ? shown(at.text) : shown(""));
    }
    std::array<Rational, 4> point{exact_number(tokens[0], line), exact_number(tokens[1], line),
                                  exact_number(tokens[2], line), Rational(1)};
    if (tokens.size() == 4) {
        point[3] = exact_number(tokens[3], line);
        if (point[3].sign() <= 0) {
            throw ParseError(line, tokens[3].column, "a positive weight", shown(tokens[3].text));
        }
    }
    return point;
}

std::size_t point_count(const BezierPatch& patch) {
    return patch.kind == BezierPatch::Kind::tensor
               ? (patch.degree_s + 1) * (patch.degree_t + 1)
               : (patch.degree_s + 1) * (patch.degree_s + 2) / 2;
}

void mark_rational(BezierPatch& patch) {
    patch.rational = false;
    for (const auto& p : patch.points) {
        patch.rational = patch.rational || !(p[3] == patch.points.front()[3]);
    }
}

Integer binomial(unsigned n, unsigned k) {
    Integer b;
    fmpz_bin_uiui(b.get(), n, k);
    return b;
}

// (base)^e by repeated multiplication (e ≤ 16).
Polynomial power(const Polynomial& base, unsigned e) {
    Polynomial result = Polynomial::constant(base.ring(), Rational(1));
    for (unsigned i = 0; i < e; ++i) {
        result *= base;
    }
    return result;
}

}  // namespace

bool looks_like_bpt(std::string_view text) {
    const auto lines = meaningful_lines(text.substr(0, std::min<std::size_t>(text.size(), 4096)));
    if (lines.empty() || lines.front().first.size() != 1) {
        return false;
    }
    for (const char c : lines.front().first.front().text) {
        if (!std::isdigit(static_cast<unsigned char>(c))) {
            return false;
        }
    }
    return true;
}

std::vector<BezierPatch> parse_bpt(std::string_view text) {
    const auto lines = meaningful_lines(text);
    if (lines.empty()) {
        throw ParseError(1, 1, "the number of patches", "an empty file");
    }
    const auto& [head, head_line] = lines.front();
    if (head.size() != 1) {
        throw ParseError(head_line, head[1].column, "the number of patches alone on the line",
                         shown(head[1].text));
    }
    const unsigned count = small_integer(head[0], head_line, 1, 4096, "the number of patches");
    std::vector<BezierPatch> patches;
    std::size_t at = 1;
    for (unsigned k = 0; k < count; ++k) {
        if (at >= lines.size()) {
            const std::size_t last = lines.back().second;
            throw ParseError(last + 1, 1,
                             "patch " + std::to_string(k + 1) + " of " + std::to_string(count) +
                                 " (a line 'm n')",
                             "the end of the file");
        }
        const auto& [degrees, degree_line] = lines[at++];
        if (degrees.size() != 2) {
            const Token& bad = degrees.size() > 2 ? degrees[2] : degrees[0];
            throw ParseError(degree_line,
                             degrees.size() > 2 ? bad.column : bad.column + bad.text.size(),
                             "the degrees of patch " + std::to_string(k + 1) + " as 'm n'",
                             degrees.size() > 2 ? shown(bad.text) : shown(""));
        }
        BezierPatch patch;
        patch.first_line = degree_line;
        patch.degree_s = small_integer(degrees[0], degree_line, 1, kMaxDegree, "a degree");
        patch.degree_t = small_integer(degrees[1], degree_line, 1, kMaxDegree, "a degree");
        const std::size_t needed = point_count(patch);
        for (std::size_t i = 0; i < needed; ++i) {
            if (at >= lines.size()) {
                throw ParseError(lines.back().second + 1, 1,
                                 "control point " + std::to_string(i + 1) + " of " +
                                     std::to_string(needed) + " of patch " + std::to_string(k + 1),
                                 "the end of the file");
            }
            const auto& [tokens, line] = lines[at++];
            if (tokens.size() == 2 && i == 0) {
                throw ParseError(line, tokens[0].column, "a control point 'x y z'",
                                 "a degree line (too few control points before it?)");
            }
            patch.points.push_back(control_point(tokens, line));
        }
        mark_rational(patch);
        patches.push_back(std::move(patch));
    }
    if (at < lines.size()) {
        throw ParseError(lines[at].second, lines[at].first.front().column,
                         "the end of the file after " + std::to_string(count) + " patches",
                         shown(lines[at].first.front().text));
    }
    return patches;
}

BezierPatch parse_bezier_param(std::string_view text, std::vector<std::string>* parameter_names) {
    BezierPatch patch;
    bool have_kind = false, have_params = false;
    std::vector<std::string> names = {"s", "t"};
    std::size_t last_line = 1;
    for (const auto& [line_text, line] : algebra::split_lines(text)) {
        last_line = line;
        const auto tokens = tokens_of(line_text);
        if (tokens.empty()) {
            continue;
        }
        const std::string_view first = tokens[0].text;
        if (first.starts_with("bezier:") || first == "bezier") {
            if (have_kind) {
                throw ParseError(line, tokens[0].column, "one 'bezier:' line", shown(first));
            }
            // Re-tokenize after the colon: "bezier: 3 3", "bezier:triangle 3".
            const std::size_t colon = line_text.find(':');
            if (colon == std::string_view::npos) {
                throw ParseError(line, tokens[0].column + first.size(), "':'", shown(""));
            }
            std::vector<Token> rest = tokens_of(line_text.substr(colon + 1));
            for (auto& t : rest) {
                t.column += colon + 1;
            }
            if (!rest.empty() && rest[0].text == "triangle") {
                patch.kind = BezierPatch::Kind::triangle;
                if (rest.size() != 2) {
                    throw ParseError(line, rest.size() > 2 ? rest[2].column : line_text.size() + 1,
                                     "'bezier: triangle N'",
                                     rest.size() > 2 ? shown(rest[2].text) : shown(""));
                }
                patch.degree_s = patch.degree_t =
                    small_integer(rest[1], line, 1, kMaxDegree, "a degree");
            } else {
                if (rest.size() != 2) {
                    throw ParseError(
                        line, rest.size() > 2 ? rest[2].column : line_text.size() + 1,
                        "'bezier: M N' (tensor-product degrees) or 'bezier: triangle N'",
                        rest.size() > 2 ? shown(rest[2].text) : shown(""));
                }
                patch.degree_s = small_integer(rest[0], line, 1, kMaxDegree, "a degree");
                patch.degree_t = small_integer(rest[1], line, 1, kMaxDegree, "a degree");
            }
            patch.first_line = line;
            have_kind = true;
        } else if (first.starts_with("params:") || first == "params") {
            if (have_params) {
                throw ParseError(line, tokens[0].column, "one 'params:' line", shown(first));
            }
            const std::size_t colon = line_text.find(':');
            if (colon == std::string_view::npos) {
                throw ParseError(line, tokens[0].column + first.size(), "':'", shown(""));
            }
            names = algebra::parse_name_list(line_text.substr(colon + 1), line, colon + 2);
            if (names.size() != 2) {
                throw ParseError(line, colon + 2, "two parameters for a patch",
                                 std::to_string(names.size()));
            }
            for (const auto& name : names) {
                if (name == "x" || name == "y" || name == "z") {
                    throw ParseError(line, line_text.find(name, colon) + 1,
                                     "parameter names other than the coordinates x, y, z",
                                     "'" + name + "'");
                }
            }
            have_params = true;
        } else {
            if (!have_kind) {
                throw ParseError(line, tokens[0].column, "'bezier: M N' before the control points",
                                 shown(first));
            }
            if (patch.points.size() == point_count(patch)) {
                throw ParseError(line, tokens[0].column,
                                 "the end of the file after " + std::to_string(point_count(patch)) +
                                     " control points",
                                 shown(first));
            }
            patch.points.push_back(control_point(tokens, line));
        }
    }
    if (!have_kind) {
        throw ParseError(last_line, 1, "a 'bezier:' line", "the end of the file");
    }
    if (patch.points.size() != point_count(patch)) {
        throw ParseError(last_line + 1, 1, std::to_string(point_count(patch)) + " control points",
                         std::to_string(patch.points.size()));
    }
    mark_rational(patch);
    if (parameter_names != nullptr) {
        *parameter_names = names;
    }
    return patch;
}

std::array<Polynomial, 4> homogeneous_map(const BezierPatch& patch, const algebra::RingPtr& ring) {
    const Polynomial one = Polynomial::constant(ring, Rational(1));
    const Polynomial s = Polynomial::variable(ring, 0);
    const Polynomial t = Polynomial::variable(ring, 1);
    // Bernstein basis, in the order of the control points.
    std::vector<Polynomial> basis;
    if (patch.kind == BezierPatch::Kind::tensor) {
        const unsigned m = patch.degree_s, n = patch.degree_t;
        for (unsigned i = 0; i <= m; ++i) {
            const Polynomial bs = Polynomial::constant(ring, Rational(binomial(m, i))) *
                                  power(s, i) * power(one - s, m - i);
            for (unsigned j = 0; j <= n; ++j) {
                basis.push_back(bs * Polynomial::constant(ring, Rational(binomial(n, j))) *
                                power(t, j) * power(one - t, n - j));
            }
        }
    } else {
        const unsigned n = patch.degree_s;
        const Polynomial r = one - s - t;
        for (unsigned i = n + 1; i-- > 0;) {
            for (unsigned j = n - i + 1; j-- > 0;) {
                const unsigned k = n - i - j;
                // n! / (i! j! k!) = C(n, i) · C(n − i, j)
                const Rational c(binomial(n, i) * binomial(n - i, j));
                basis.push_back(Polynomial::constant(ring, c) * power(s, i) * power(t, j) *
                                power(r, k));
            }
        }
    }
    std::array<Polynomial, 4> map{Polynomial(ring), Polynomial(ring), Polynomial(ring),
                                  Polynomial(ring)};
    for (std::size_t p = 0; p < basis.size(); ++p) {
        const auto& point = patch.points[p];
        const Polynomial weighted = Polynomial::constant(ring, point[3]) * basis[p];
        for (std::size_t c = 0; c < 3; ++c) {
            map[c] += Polynomial::constant(ring, point[c]) * weighted;
        }
        map[3] += weighted;
    }
    return map;
}

Parametrization to_parametrization(const BezierPatch& patch,
                                   const std::vector<std::string>& parameter_names) {
    Parametrization map;
    map.parameter_ring =
        algebra::PolyRing::make(parameter_names, algebra::MonomialOrder::grevlex(2));
    map.coordinates = {"x", "y", "z"};
    const auto& ring = map.parameter_ring;
    std::array<Polynomial, 4> sums = homogeneous_map(patch, ring);
    if (!patch.rational) {
        // Equal weights cancel: Σ w B = w.
        const Polynomial inverse =
            Polynomial::constant(ring, Rational(1) / patch.points.front()[3]);
        for (std::size_t c = 0; c < 3; ++c) {
            sums[c] = sums[c] * inverse;
        }
        sums[3] = Polynomial::constant(ring, Rational(1));
    }
    for (std::size_t c = 0; c < 3; ++c) {
        map.components.emplace_back(sums[c], sums[3]);
    }
    return map;
}

}  // namespace locus::implicit
