// The primary rays of one frame, restricted to a surface all at once (the row-coherent
// substitution of SURFER/jsurf, recentred for accuracy).
//
// Every primary ray starts at the eye e with direction d(x, y) = base + x·U + y·V
// (render/camera.h), and d·w = 1 for the viewing direction w. So the ray meets the plane
// through the clip centre c perpendicular to w at the same parameter D = (c − e)·w for every
// pixel, at q(x, y) = e + D·d(x, y), which is affine in (x, y) too. The family is expanded about
// that plane, t = D + s:
//     F(t) = f(q + s·d) = Σ_k H_k(x, y) s^k,
// where along one image row H_k is a polynomial in x of degree ≤ n = deg f. Expanding about
// the eye instead (F = Σ g_k(d) t^k with g = f(e + ·)) costs fewer operations but cancels
// catastrophically: at degree 12 with the eye 4 clip radii away the terms reach 1e13 around
// roots of size 1, and half of the rays came out wrong. About the plane, the terms have the
// size of f inside the clip region.
//
// Per row, F is restricted along n + 1 rays at Chebyshev nodes of the row, and each H_k is
// interpolated there (exact for degree ≤ n) and stored in powers of u = (x − centre)/half-width
// ∈ [−1, 1]. A pixel then costs (n + 1)² multiply-adds (169 at degree 12), no expansion.
#pragma once

#include <vector>

#include "render/camera.h"
#include "render/detail/chebyshev_interpolation.h"
#include "render/ray_restriction.h"

namespace locus::render {

// H_k coefficients for one image row: row[k][j] is the coefficient of u^j in H_k.
struct RowExpansion {
    int degree = -1;
    double center_x = 0.0;
    double inverse_half_width = 1.0;
    std::array<std::array<double, kMaxDegree + 1>, kMaxDegree + 1> row;
};

// Above this degree primary rays are restricted one by one (LineRestrictor about the middle of
// each ray's interval) instead of from the family: the per-row interpolation of H_k lost about
// 5e-6 in depth on the degree-20 Chmutov surface (stability atlas, chmutov_20), above the
// 1e-6 × clip radius that counts as wrong, while every ray traced alone was within it.
inline constexpr int kMaxFamilyDegree = 16;

class RayFamily {
  public:
    // `center`: a point the restriction is expanded about (the clip region's centre); `width`
    // and `height`: the image size in pixels.
    RayFamily(const algebra::CompiledPolynomial& f, const Camera& camera, const Vec3& center,
              int width, int height);

    // F(t) = restriction(t − origin_t()).
    double origin_t() const { return plane_t_; }
    // Expands the row at continuous image coordinate y: from the frame's interpolant in y
    // ((n + 1)³ multiply-adds), not by restricting f along n + 1 rays of the row.
    void expand_row(double y, RowExpansion& out) const;
    // The restriction of the primary ray at continuous coordinate x of an expanded row, in the
    // variable s = t − origin_t().
    static RayPolynomial restriction(const RowExpansion& row, double x);
    // The same, written into `out` (coefficients 0..degree): the per-pixel loops keep one
    // RayPolynomial rather than zero-fill and copy 41 coefficients for every ray.
    static void restriction(const RowExpansion& row, double x, RayPolynomial& out);

  private:
    const Camera* camera_;
    LineRestrictor restrictor_;
    detail::ChebyshevInterpolation chebyshev_;
    double plane_t_;
    double center_x_, half_width_;
    // The row coefficients as polynomials in v = (y − centre)/half-height ∈ [−1, 1]: H_k is a
    // polynomial of degree ≤ n in (x, y) together, so each coefficient of u^i in H_k has degree
    // ≤ n in v, interpolated once per frame from n + 1 rows at Chebyshev nodes (the same two
    // steps as along a row). Restricting f along n + 1 rays for every row took 9 % of a
    // degree-10 frame (Barth's decic, 2816 restrictions); the frame now takes (n + 1)².
    // by_v_[(k·(n + 1) + i)·(n + 1) + m] is the coefficient of v^m.
    double center_y_, half_height_;
    std::vector<double> by_v_;
    // The row at y by restricting f along n + 1 rays of it (the frame's interpolation nodes).
    void expand_row_directly(double y, RowExpansion& out) const;
};

}  // namespace locus::render
