// The leaves of an SDF scene, each in its own coordinates (centred at the origin, the axis of
// symmetry along y); the scene file places them with transforms (render/sdf/transforms.h).
// Distances are Inigo Quilez's closed forms where an exact one exists; the rest are bounds with
// the Lipschitz constant derived in primitives.cpp.
#pragma once

#include <vector>

#include "render/sdf/node.h"

namespace locus::render::sdf {

// Exact distances.
NodePtr make_sphere(double radius, MaterialPtr material);
// The half-space dot(p, normal) ≤ offset; `normal` need not be unit length.
NodePtr make_plane(const Vec3& normal, double offset, MaterialPtr material);
// A box with half extents `half`, its edges rounded with radius `rounding` (0: sharp).
NodePtr make_box(const Vec3& half, double rounding, MaterialPtr material);
// Major radius in the xz-plane, minor radius of the tube.
NodePtr make_torus(double major, double minor, MaterialPtr material);
NodePtr make_cylinder(double radius, double half_height, MaterialPtr material);
// A capped cone from y = −half_height (radius `bottom`) to +half_height (radius `top`).
NodePtr make_cone(double bottom, double top, double half_height, MaterialPtr material);
NodePtr make_capsule(const Vec3& a, const Vec3& b, double radius, MaterialPtr material);

// Bounds.
// (|p/r| − 1)·min r: exact on the surface, Lipschitz 1, never more than the distance.
NodePtr make_ellipsoid(const Vec3& radii, MaterialPtr material);
// The ball of the exponent-norm, (Σ|pᵢ/rᵢ|^e)^(1/e) = 1 with e ≥ 1 (e = 2: ellipsoid, large e:
// a rounded box).
NodePtr make_superquadric(const Vec3& radii, double exponent, MaterialPtr material);

// Soft objects (Wyvill, McPheeters and Wyvill 1986): F(p) = Σ wᵢ·C(|p − cᵢ|/Rᵢ) with the
// cubic-in-r² falloff C(s) = 1 − 4/9 s⁶ + 17/9 s⁴ − 22/9 s² on s < 1; the surface is F = T.
struct Metaball {
    Vec3 center{0.0, 0.0, 0.0};
    double radius = 1.0;
    double weight = 1.0;
};
NodePtr make_soft_objects(std::vector<Metaball> balls, double threshold, MaterialPtr material);
// max |dC/dr| = kWyvillSlope / R. Hart quotes 3/(2R); the maximum of |C'(s)| on [0, 1] is at
// s = 0.5035 and is 1.5835, about 5.6 % more, so stepping by 3/(2R) could overshoot.
extern const double kWyvillSlope;

}  // namespace locus::render::sdf
