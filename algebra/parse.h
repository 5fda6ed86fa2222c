// Reading polynomials and ideal files (formats in DESIGN.md, "Polynomials" and "Ideal files").
//
// Polynomials are infix text over the ring's variables: integers, rationals `3/4`, decimals
// read exactly (`0.1` = 1/10, `1.5e-3` = 3/2000), `+ - * / ^`, parentheses, free whitespace. `^`
// takes a non-negative integer literal; `/` only a constant divisor. Every error is a ParseError
// whose line and column (1-based) point at the offending character and which says what was
// expected.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "algebra/polynomial.h"
#include "algebra/rational_function.h"

namespace locus::algebra {

// Parentheses may nest this deep (each level is a few stack frames of the recursive-descent
// parser; deeper input is a ParseError at the parenthesis, not a stack overflow). The margin is
// for the sanitizers' larger frames: under AddressSanitizer 1000 levels of a .param expression
// overflowed the 8 MiB stack, 900 did not.
inline constexpr int kMaxNesting = 256;

// Parses `text` as one polynomial of `ring`. Positions are reported relative to (line,
// first_column), so that a caller parsing a fragment of a file reports file positions.
Polynomial parse_polynomial(std::string_view text, const RingPtr& ring, std::size_t line = 1,
                            std::size_t first_column = 1);

// How parse_rational_function reads sin(θ) and cos(θ), where θ is an integer combination of
// the ring's variables such as u, 2*u, -v or u - 3*v (anything else inside sin or cos is a
// ParseError). Multiple angles and sums come from e^{iθ} = Π e^{i·k·v}.
struct Trigonometry {
    enum class Form {
        // Each angle v stands for tan(v/2) (the tangent half-angle substitution):
        // e^{iv} = (1 + iv)²/(1 + v²), so cos v = (1 − v²)/(1 + v²), sin v = 2v/(1 + v²).
        half_angle,
        // cos v and sin v are variables of the ring, cos_of[v] and sin_of[v]; cos(θ) and sin(θ)
        // are the real and imaginary parts of Π (cos v + i·sin v)^k, polynomials in them.
        circle,
    };
    Form form = Form::half_angle;
    std::vector<std::size_t> cos_of, sin_of;  // Form::circle: indexed by the angle's variable
    // Filled by the parser (sized to the ring's variables): where each variable was first used
    // inside sin or cos, and where as itself (line 0: not at all).
    struct Use {
        std::size_t line = 0, column = 0;
    };
    std::vector<Use> inside, outside;
};

// The same grammar, but `/` divides by any non-zero expression: a quotient of polynomials such
// as `(1-t^2)/(1+t^2)`, returned in lowest terms. A divisor that is identically zero is a
// ParseError at the divisor. With `trigonometry`, sin(θ) and cos(θ) are accepted and read as it
// says; without, they are a ParseError.
RationalFunction parse_rational_function(std::string_view text, const RingPtr& ring,
                                         std::size_t line = 1, std::size_t first_column = 1,
                                         Trigonometry* trigonometry = nullptr);

// The contents of an ideal file: its ring (variables and order) and its generators in file
// order (zero generators are dropped), with the line each generator came from.
struct IdealFile {
    RingPtr ring;
    std::vector<Polynomial> generators;
    std::vector<std::size_t> generator_lines;
    // 0: the ideal is over Q. A prime p < 2³¹: over GF(p); the generators are still stored
    // over Q (their coefficients stand for their residues: no denominator is divisible by p),
    // and only modular code may compute with them.
    std::uint32_t characteristic = 0;
};

// `vars:` is required before the first generator; `order:` is optional (default grevlex);
// `characteristic:` is optional (default 0: over Q; a prime below 2³¹: over GF(p)); `#` starts
// a comment. Example:
//     vars: x,y,z
//     order: lex
//     characteristic: 32003
//     x^2+y^2+z^2-1
IdealFile parse_ideal_file(std::string_view text);

// msolve's input format (`.ms`): the variables on the first line (comma-separated), the
// characteristic on the second (0 or a prime below 2³¹), then the polynomials separated by
// commas over any number of lines. The ring is grevlex in the variables' order. Example:
//     x,y,z
//     0
//     x^2+y^2+z^2-1,
//     x*y-z
IdealFile parse_msolve_file(std::string_view text);

// Does the text look like msolve's format rather than an ideal file (its first non-blank line
// has no ':' and its second non-blank line is a number)?
bool looks_like_msolve(std::string_view text);

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
