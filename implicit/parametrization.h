// Parametrizations: x, y (and z) as polynomials or quotients of polynomials in parameters, as
// read from `.param` files (DESIGN.md, "Parametrization files"):
//     params: s,t
//     x = s*t
//     y = s
//     z = t^2
// Curves use one parameter and x, y (plane) or x, y, z (space); surfaces use two parameters.
// An optional line `domain: s in [0, 1], t in [-2, 2]` bounds the parameters for rendering.
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
    // The map as written, when some parameter is an angle: the components over the ring of
    // the parameters and of sin u, cos u for every angle u (named sin_u and cos_u),
    // where circle_relations (sin(u)^2 + cos(u)^2 − 1) hold. Empty for rational maps.
    algebra::RingPtr circle_ring;
    std::vector<algebra::RationalFunction> circle_components;
    std::vector<algebra::Polynomial> circle_relations;
    // `domain: u in [a, b], v in [c, d]`: the box of parameters the user means, one interval
    // per parameter (empty: all of them). Only rendering uses it (the trimmed surface); the
    // implicit equation is that of the whole image. Angles (inside sin/cos) take no interval.
    std::vector<std::pair<algebra::Rational, algebra::Rational>> domain;
};

// Reads a parametrization file. Errors are ParseErrors with line and column: a missing
// `params:` line, an undeclared parameter, a coordinate assigned twice or missing, a coordinate
// other than x, y, z, a denominator that is identically zero, a function other than sin and cos,
// an argument of sin or cos that is not an integer combination of parameters, and a parameter
// used both inside sin/cos and outside them (such a map is not algebraic: the helicoid
// x = u·cos(v), y = u·sin(v), z = v has no implicit equation). sin and cos of multiple angles
// and sums are expanded (e^{iθ} = Π e^{i·k·u}) and turned rational by the tangent half-angle
// substitution (recorded in `half_angle`); the map as written is kept in `circle_components`.
Parametrization parse_parametrization(std::string_view text);

// The map over one common denominator: x_i = numerators[i] / denominator, where the
// denominator is the product of the components' distinct denominators and each numerator is
// multiplied by the denominators of the others. Dixon's matrices, the proof that f vanishes on
// the map and the renderer's trim all work with this polynomial (homogeneous) form.
struct CommonDenominatorForm {
    std::vector<algebra::Polynomial> numerators;  // one per coordinate
    algebra::Polynomial denominator;
};
CommonDenominatorForm over_common_denominator(const Parametrization& map);

}  // namespace locus::implicit
