// Where a surface f(x, y, z) = 0 lies, for framing a picture when the user gave no clip region
// or camera (`locus render EQUATION`, `--fit`).
//
// The answer is an estimate for framing, not a certificate, and says so in its kind:
//  * A surface is `bounded` when the top-degree form f_d keeps one sign, away from zero, on
//    every sampled direction (f_d definite: f ≠ 0 far out), or certainly keeps one sign by its
//    terms' form (even powers with coefficients of one sign, each variable's pure power among
//    them: x⁴⁰ + y⁴⁰ + z⁴⁰, whose least value on the sphere is too small for the sampled
//    test). An odd degree, a sign change of
//    f_d (then f changes sign on every large sphere) or a near-zero of f_d gives `unbounded`;
//    so does a bounded surface whose f_d merely vanishes somewhere (x⁴ + y² + z² − 1), which
//    keeps the documented default frame.
//  * The box is that of the outermost points found along lines through a centre, one line per
//    direction of a 1024-point lattice, traced inwards from beyond the roots' Fujiwara bound by
//    the certified tracer; when the box found is off the origin, a second round starts from its
//    centre (the lines then meet the whole surface, not its far side). Each face of the box is
//    then pushed out by a pattern search over directions near the best one. Every point found
//    lies on the surface, so the box is an inner approximation: a part thinner than the
//    lattice spacing (about 0.11 rad seen from the centre) can be missed, and
//    fitted_clip_sphere pads it.
//    When no line through the origin meets the surface, the lines are drawn through the point
//    Newton's steps along f's gradient reach from the origin (or from a corner of the unit
//    cube): a unit sphere 10⁵ away, or one of radius 10⁻⁴ beside the origin, is met that way.
//  * `none_found` is a bounded surface with no point on any of those lines: it may have no real
//    point (x² + y² + z² + 1) or be smaller than the spacing seen from every centre tried.
#pragma once

#include <chrono>
#include <optional>

#include "algebra/compiled.h"
#include "render/clip_region.h"
#include "render/vec3.h"

namespace locus::render {

struct SurfaceExtent {
    enum class Kind { bounded, unbounded, none_found } kind = Kind::unbounded;
    Vec3 low{0.0}, high{0.0};  // bounded: the box of the points found
    int lines = 0;             // lines traced
    int newton_points = 0;     // centres other than the origin that Newton's steps reached
};

// Throws Timeout when `deadline` passes (checked every few lines).
SurfaceExtent estimate_extent(const algebra::CompiledPolynomial& f, int directions = 1024,
                              std::optional<std::chrono::steady_clock::time_point> deadline = {});

// The box of the surface's points inside `region` that lie outermost on lines through the
// centre of the region's bounding sphere, traced by the certified tracer; nothing when none is
// found (then the surface probably does not meet the region). An inner approximation, as above.
std::optional<ClipBox> box_in_region(
    const algebra::CompiledPolynomial& f, const ClipRegion& region, int directions = 1024,
    std::optional<std::chrono::steady_clock::time_point> deadline = {});

// The point of the surface nearest `centre` on the rays from it along `directions` lattice
// directions (spread over the whole sphere), traced by the certified tracer; nothing when none
// meets it.
// For saying where a surface is that its clip region missed: an estimate, like the extents.
std::optional<Vec3> nearest_point_on_lines(
    const algebra::CompiledPolynomial& f, const Vec3& centre, int directions = 1024,
    std::optional<std::chrono::steady_clock::time_point> deadline = {});

// The clip sphere about a bounded extent: centred on its box, with 1.05 times the box's
// half-diagonal as radius (1e-3 for a surface that is a point); nothing unless the extent is
// bounded.
std::optional<ClipSphere> fitted_clip_sphere(const SurfaceExtent& extent);

}  // namespace locus::render
