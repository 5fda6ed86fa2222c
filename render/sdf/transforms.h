// Placing a node in the world: p_world = R·(s·p_local) + c, a rotation R, a uniform scale s > 0
// and a translation c. The value is s·child(p_local), so exact distances stay exact and the
// Lipschitz constant is the child's (Hart: scaling by s scales distances by s).
// Rays map to the child's coordinates with the same parameter t, so a child that traces
// exactly (an algebraic surface) still does.
#pragma once

#include <glm/mat3x3.hpp>

#include "render/sdf/node.h"

namespace locus::render::sdf {

// Rotation by `degrees` about `axis` (right-handed); the axis must be non-zero.
glm::dmat3 rotation_about(const Vec3& axis, double degrees);
// Rotation by Euler angles in degrees, applied about x, then y, then z (R = Rz·Ry·Rx).
glm::dmat3 rotation_euler(const Vec3& degrees);

NodePtr make_placement(NodePtr child, const glm::dmat3& rotation, double scale,
                       const Vec3& translation);

}  // namespace locus::render::sdf
