// Deformations of a node, with the Lipschitz constants that keep sphere tracing safe.
//
//  * twist(k): rotate each horizontal slice by k·y radians about the y axis. The Jacobian of
//    the map has norm ≤ 1 + |k|·r at distance r from the axis, so inside the child's bounding
//    cylinder (radius R) the value is child/(L·(1 + |k|R)); outside it, the distance to that
//    cylinder takes over (a twist keeps r). Hart's "twist restricted to a radius".
//  * bend(k): the same in the xy-plane, rotating by k·x about the z axis.
//  * round(r): child/L − r, the child grown by r (edges rounded).
//  * elongate(h): the child stretched by 2h along each axis, p → p − clamp(p, −h, h).
//  * displace(noise): child/L + noise(p), Lipschitz 1 + Σ 3·aᵢ·fᵢ (render/sdf/noise.h).
#pragma once

#include "render/sdf/node.h"
#include "render/sdf/noise.h"

namespace locus::render::sdf {

NodePtr make_twist(NodePtr child, double radians_per_unit);
NodePtr make_bend(NodePtr child, double radians_per_unit);
NodePtr make_round(NodePtr child, double radius);
NodePtr make_elongate(NodePtr child, const Vec3& half_lengths);
NodePtr make_displace(NodePtr child, const Noise& noise);

}  // namespace locus::render::sdf
