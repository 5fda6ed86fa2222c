// Writing polynomials and bases: the normalized form of DESIGN.md, and input for Singular,
// Macaulay2 and LaTeX.
//
// Normalized form: terms in the polynomial's stored (descending) order, coefficients `a/b` in
// lowest terms, `*` between factors, `^k` for k > 1, variables in declared order, a coefficient
// ±1 omitted before a non-constant monomial: `x^2*y-1/2*z+3`. A normalized *basis* is monic and
// sorted by leading monomial ascending (normalize_basis), so two systems' outputs compare line
// by line.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "algebra/polynomial.h"

namespace locus::algebra {

enum class OutputFormat {
    normalized,
    singular,
    macaulay2,
    latex,
    msolve,
    sympy,
    maple,
    mathematica
};

// Throws InputError for a name other than normalized, singular, macaulay2, latex, msolve, sympy,
// maple, mathematica (m2 and locus are accepted as synonyms).
OutputFormat parse_output_format(std::string_view name);

std::string to_string(const Polynomial& f);
// f with its variables called `names` (one a variable of f's ring), e.g. for another system.
std::string to_string(const Polynomial& f, const std::vector<std::string>& names);
std::string to_latex(const Polynomial& f);

// Monic, sorted by leading monomial ascending, zeros dropped.
std::vector<Polynomial> normalize_basis(std::vector<Polynomial> basis);

// A basis (or any list of polynomials) in `format`: normalized and latex print one polynomial a
// line; singular and macaulay2 print a ring declaration and an ideal that can be pasted into
// those systems as they are; msolve prints msolve's input format (variables, characteristic,
// the polynomials separated by commas; msolve reads it as grevlex in the variables' order,
// the same ideal whatever order the basis was computed for); sympy prints Python (symbols, then
// the list, fractions as Rational(p, q)), maple and mathematica their list syntax, each with a
// comment naming the order's call there. `characteristic` p ≠ 0: the coefficients are residues
// modulo p (printed in [0, p)), and the rings say so (`ring r = p`, `ZZ/p`, a comment).
// Variables a system reserves (Singular's `ring`, `std`, the ring's and ideal's own names `r`,
// `G`; Python's keywords; Mathematica's one-letter built-ins and any name with `_`) are renamed
// to fresh ones and the output says so in a comment first; Maple quotes them in backquotes.
std::string format_polynomials(std::span<const Polynomial> polys, const PolyRing& ring,
                               OutputFormat format, std::string_view ideal_name = "G",
                               std::uint32_t characteristic = 0);

// One polynomial in the syntax of `format` (no ring, no renaming): for answers printed beside
// other text, such as the cofactors of `locus ideal member`.
std::string format_polynomial(const Polynomial& f, OutputFormat format);

// The ring declaration in Singular's language (`ring r = 0, (x,y,z), dp;`), with variables
// reordered into blocks where the order needs it (elim of non-leading variables).
std::string singular_ring(const PolyRing& ring, std::string_view ring_name = "r",
                          std::uint32_t characteristic = 0);

// An ideal file that parse_ideal_file reads back to the same ring, generators and
// characteristic.
std::string to_ideal_file(std::span<const Polynomial> generators, const PolyRing& ring,
                          std::uint32_t characteristic = 0);

}  // namespace locus::algebra
