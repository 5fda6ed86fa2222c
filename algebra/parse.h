// Reading polynomials and ideal files (formats in DESIGN.md, "Polynomials" and "Ideal files").
//
// Polynomials are infix text over the ring's variables: integers, rationals `3/4`, decimals
// read exactly (`0.1` = 1/10), `+ - * / ^`, parentheses, free whitespace. `^` takes a
// non-negative integer literal; `/` only a constant divisor. Every error is a ParseError whose
// line and column (1-based) point at the offending character and which says what was expected.
#pragma once

#include <string_view>
#include <vector>

#include "algebra/polynomial.h"
#include "algebra/rational_function.h"

namespace locus::algebra {

// Parses `text` as one polynomial of `ring`. Positions are reported relative to (line,
// first_column), so that a caller parsing a fragment of a file reports file positions.
Polynomial parse_polynomial(std::string_view text, const RingPtr& ring, std::size_t line = 1,
                            std::size_t first_column = 1);

// The same grammar, but `/` divides by any non-zero expression: a quotient of polynomials such
// as `(1-t^2)/(1+t^2)`, returned in lowest terms. A divisor that is identically zero is a
// ParseError at the divisor. With `half_angle`, sin(v) and cos(v) of a variable v are accepted
// and replaced by the tangent half-angle forms 2v/(1+v^2) and (1-v^2)/(1+v^2) (v now standing
// for tan(v/2)); the indices of such variables are appended to *half_angle.
RationalFunction parse_rational_function(std::string_view text, const RingPtr& ring,
                                         std::size_t line = 1, std::size_t first_column = 1,
                                         std::vector<std::size_t>* half_angle = nullptr);

// The contents of an ideal file: its ring (variables and order) and its generators in file
// order (zero generators are dropped), with the line each generator came from.
struct IdealFile {
    RingPtr ring;
    std::vector<Polynomial> generators;
    std::vector<std::size_t> generator_lines;
};

// `vars:` is required before the first generator; `order:` is optional (default grevlex);
// `#` starts a comment. Example:
//     vars: x,y,z
//     order: lex
//     x^2+y^2+z^2-1
IdealFile parse_ideal_file(std::string_view text);

// One line of a line-oriented file (ideal and parametrization files): its text with any `#`
// comment removed, and its 1-based number. Every line is returned, blank ones included, so the
// last number is the line where the input ends.
struct SourceLine {
    std::string_view text;
    std::size_t number;
};
std::vector<SourceLine> split_lines(std::string_view text);

// Splits a comma-separated identifier list such as "x, y,z" (for `vars:` and `params:`),
// reporting bad names and repeats at their column.
std::vector<std::string> parse_name_list(std::string_view text, std::size_t line,
                                         std::size_t first_column);

}  // namespace locus::algebra
