// Boolean operations on SDF nodes, plain and smooth, n-ary and folded left to right:
// union(a, b, c) = union(union(a, b), c), difference(a, b, c) = a minus b minus c.
//
// Children are divided by their Lipschitz constants first, so every operation here has
// Lipschitz constant 1 (min, max and the three smooth minima below are all 1-Lipschitz in
// their arguments: their gradients are convex combinations of the children's).
#pragma once

#include <vector>

#include "render/sdf/node.h"

namespace locus::render::sdf {

NodePtr make_union(std::vector<NodePtr> children);
NodePtr make_intersection(std::vector<NodePtr> children);
NodePtr make_difference(std::vector<NodePtr> children);

// The smooth minimum of the seed thesis and Quilez, with a blend radius k (world units):
//  * polynomial, order n ≥ 2: h = max(k − |a − b|, 0)/k, min(a, b) − hⁿ·k/(2n); it equals
//    min(a, b) wherever |a − b| ≥ k (n = 2: quadratic, n = 3: cubic, C^(n−1));
//  * exponential: −k·ln(e^(−a/k) + e^(−b/k)); it is below min everywhere (by k·ln 2 at most);
//  * root: (a + b − √((a − b)² + k²))/2.
enum class BlendKind { polynomial, exponential, root };
struct Blend {
    BlendKind kind = BlendKind::polynomial;
    double k = 0.25;
    int order = 2;  // polynomial only
    // How far below min(a, b) the blend can go: the bounds of a smooth union grow by this.
    double max_lowering() const;
};
struct Blended {
    double value;
    double weight_of_b;  // the material mix: 0 where a alone shapes the surface, 1 for b alone
};
Blended smooth_min(double a, double b, const Blend& blend);

NodePtr make_smooth_union(std::vector<NodePtr> children, const Blend& blend);
NodePtr make_smooth_intersection(std::vector<NodePtr> children, const Blend& blend);
NodePtr make_smooth_difference(std::vector<NodePtr> children, const Blend& blend);

}  // namespace locus::render::sdf
