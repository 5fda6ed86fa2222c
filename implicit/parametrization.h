// Parametrizations: x, y (and z) as polynomials or quotients of polynomials in parameters, as
// read from `.param` files (DESIGN.md, "Parametrization files"):
//     params: s,t
//     x = s*t
//     y = s
//     z = t^2
// Curves use one parameter and x, y (plane) or x, y, z (space); surfaces use two parameters.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "algebra/rational_function.h"

namespace locus::implicit {

struct Parametrization {
    algebra::RingPtr parameter_ring;       // Q[params], grevlex, params in declared order
    std::vector<std::string> coordinates;  // "x", "y" and possibly "z", in that order
    std::vector<algebra::RationalFunction> components;  // one per coordinate, lowest terms
    // Parameters that appeared inside sin()/cos() and were replaced by the tangent half-angle
    // substitution: parameter u now stands for tan(u/2) (indices into parameter_ring).
    std::vector<std::size_t> half_angle;
};

// Reads a parametrization file. Errors are ParseErrors with line and column: a missing
// `params:` line, an undeclared parameter, a coordinate assigned twice or missing, a coordinate
// other than x, y, z, a denominator that is identically zero, a function other than sin and cos
// of a parameter. sin(u) and cos(u) are turned rational by the tangent half-angle substitution
// (recorded in `half_angle`).
Parametrization parse_parametrization(std::string_view text);

}  // namespace locus::implicit
