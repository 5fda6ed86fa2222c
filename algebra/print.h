// Writing polynomials and bases: the normalized form of DESIGN.md, and input for Singular,
// Macaulay2 and LaTeX.
//
// Normalized form: terms in the polynomial's stored (descending) order, coefficients `a/b` in
// lowest terms, `*` between factors, `^k` for k > 1, variables in declared order, a coefficient
// ±1 omitted before a non-constant monomial: `x^2*y-1/2*z+3`. A normalized *basis* is monic and
// sorted by leading monomial ascending (normalize_basis), so two systems' outputs compare line
// by line.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "algebra/polynomial.h"

namespace locus::algebra {

enum class OutputFormat { normalized, singular, macaulay2, latex };

// Throws InputError for a name other than normalized, singular, macaulay2, latex.
OutputFormat parse_output_format(std::string_view name);

std::string to_string(const Polynomial& f);
std::string to_latex(const Polynomial& f);

// Monic, sorted by leading monomial ascending, zeros dropped.
std::vector<Polynomial> normalize_basis(std::vector<Polynomial> basis);

// A basis (or any list of polynomials) in `format`: normalized and latex print one polynomial a
// line; singular and macaulay2 print a ring declaration and an ideal that can be pasted into
// those systems as they are.
std::string format_polynomials(std::span<const Polynomial> polys, const PolyRing& ring,
                               OutputFormat format, std::string_view ideal_name = "G");

// The ring declaration in Singular's language (`ring r = 0, (x,y,z), dp;`), with variables
// reordered into blocks where the order needs it (elim of non-leading variables).
std::string singular_ring(const PolyRing& ring, std::string_view ring_name = "r");

// An ideal file that parse_ideal_file reads back to the same ring and generators.
std::string to_ideal_file(std::span<const Polynomial> generators, const PolyRing& ring);

}  // namespace locus::algebra
