// Bézier patches as Computer-Aided Design writes them: tensor-product patches of degree (m, n)
// and triangular patches of degree n, given by control points, polynomial or rational (a weight
// per control point). Read from the common `.bpt` layout (the Utah teapot's file) and from the
// `bezier:` form of `.param` files; turned into a Parametrization whose components are the
// Bernstein sums, exact over Q (decimals are read as the rationals they denote).
//
// `.bpt`:  line 1 the number of patches; per patch a line "m n" and then (m+1)(n+1) lines
//          "x y z" (or "x y z w" for a weight w), control point P_ij at line i·(n+1) + j.
// `.param` with a `bezier:` line instead of the assignments:
//          bezier: 3 3            tensor-product patch of degrees 3 (in s) and 3 (in t)
//          bezier: triangle 3     triangular patch of degree 3
//          params: u,v            optional, default s,t
//          then the control points, one "x y z [w]" a line: (m+1)(n+1) of them for a tensor
//          patch (P_ij, i the index in s), (n+1)(n+2)/2 for a triangle (P_ijk with
//          i + j + k = n in the order i = n…0, j = n−i…0; weight of s^i t^j (1−s−t)^k).
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "algebra/polynomial.h"
#include "algebra/rational.h"
#include "implicit/parametrization.h"

namespace locus::implicit {

struct BezierPatch {
    enum class Kind { tensor, triangle };
    Kind kind = Kind::tensor;
    unsigned degree_s = 0;  // m for tensor patches, n for triangles
    unsigned degree_t = 0;  // n for tensor patches, equal to degree_s for triangles
    // x, y, z, weight (1 unless given).
    std::vector<std::array<algebra::Rational, 4>> points;
    bool rational = false;  // some weight differs from the others
    std::size_t first_line = 0;
};

// Every patch of a `.bpt` file, in order. ParseErrors name the line and column: a count that
// is not a positive integer or disagrees with the patches present, a degree line that is not two
// integers in 1..16, a control point that is not three or four exact decimals, a weight ≤ 0.
std::vector<BezierPatch> parse_bpt(std::string_view text);

// Does the text look like a `.bpt` file (its first non-blank line is a lone integer)?
bool looks_like_bpt(std::string_view text);

// The `.param` form (see above); called by parse_parametrization when the file has a
// `bezier:` line.
BezierPatch parse_bezier_param(std::string_view text, std::vector<std::string>* parameter_names);

// (Σ w·P·B, Σ w·B) over Q[params]: the numerators of x, y, z and their common denominator, as
// sums over the Bernstein basis B (before any cancellation; the denominator is a constant w
// for polynomial patches with equal weights).
std::array<algebra::Polynomial, 4> homogeneous_map(const BezierPatch& patch,
                                                   const algebra::RingPtr& ring);

// x = Σ w·P·B / Σ w·B with the Bernstein basis B (the denominator is 1 for polynomial patches),
// over Q[params] (default s, t).
Parametrization to_parametrization(const BezierPatch& patch,
                                   const std::vector<std::string>& parameter_names = {"s", "t"});

}  // namespace locus::implicit
