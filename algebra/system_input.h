// Ideals as other systems write them, read as ideal files: a Singular session's
//     ring r = 0, (x,y,z), dp;
//     ideal I = x^2+y, y*z-1;
// and a Macaulay2 session's
//     R = QQ[x,y,z, MonomialOrder => Lex];
//     I = ideal(x^2+y, y*z-1)
// pasted as they are (comments, other statements and line breaks included). The ring gives the
// variables, the order and the characteristic; the first ideal gives the generators. The orders
// are those locus prints for these systems (print.h) and their usual spellings: Singular's lp,
// dp, Dp, wp(..), (dp(k),dp(m)), M(..); Macaulay2's Lex, GLex, GRevLex, {GRevLex => {w..}},
// {GRevLex => k, GRevLex => m}, {Weights => {..}, ..}, Eliminate k. Anything else (local
// orders, Wp, quotient rings, parameters) is a ParseError at its line and column.
#pragma once

#include <string_view>

#include "algebra/parse.h"

namespace locus::algebra {

IdealFile parse_singular_input(std::string_view text);
IdealFile parse_macaulay2_input(std::string_view text);

enum class IdealFormat { ideal_file, msolve, singular, macaulay2 };

// By content: a `vars:` line is an ideal file; a `ring` statement Singular; a ring over QQ or
// ZZ/p in brackets Macaulay2; msolve's two header lines msolve; anything else an ideal file
// (whose parser then says what is wrong).
IdealFormat detect_ideal_format(std::string_view text);

// The parser of `format`.
IdealFile parse_ideal_text(std::string_view text, IdealFormat format);

}  // namespace locus::algebra
