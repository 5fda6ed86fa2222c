// Operations on space rather than on values: mirror symmetry and repetition. Both map the
// query point into the child's coordinates with a 1-Lipschitz map.
//
//  * mirror(axes): p → (|x|, |y|, |z|) on the chosen axes; mirror(plane): points on the
//    negative side of the plane (n, c) are reflected to the positive side.
//  * repeat(spacing, counts): copies of the child at every multiple of the spacing (0 on an
//    axis: not repeated); with counts, only cells −n … n on that axis. The child must fit in
//    half a cell. The value is the minimum over the cell of p and its neighbour towards p on
//    each repeated axis, capped by s − e (the child's half extent e): every copy not looked at
//    is at least that far, so the value never exceeds the distance to the repeated set.
#pragma once

#include <array>
#include <optional>

#include "render/sdf/node.h"

namespace locus::render::sdf {

NodePtr make_mirror_axes(NodePtr child, std::array<bool, 3> axes);
NodePtr make_mirror_plane(NodePtr child, const Vec3& normal, const Vec3& point);

// The integer cell of coordinate x for spacing s and optional count n (clamped to −n … n).
long long repetition_cell(double x, double spacing, std::optional<int> count);
NodePtr make_repeat(NodePtr child, const Vec3& spacing, std::array<std::optional<int>, 3> counts);

}  // namespace locus::render::sdf
