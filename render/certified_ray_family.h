// The primary rays of one frame restricted to a surface all at once, with rigorous bounds: the
// certified counterpart of render/ray_family.h, which the `certified` method uses.
//
// Every primary ray meets the plane through the clip sphere's centre c perpendicular to the
// viewing direction w at the same parameter D = (c − e)·w (render/ray_family.h), and stays in
// the clip sphere only for t ∈ [D − R, D + R]. On that range each ray's restriction, as a
// polynomial in x = (t − D)/R ∈ [−1, 1], has Bernstein coefficients B_i(u, v) that are
// polynomials of degree ≤ n in each of the image coordinates u, v ∈ [−1, 1] (the ray's direction
// is affine in them). The frame restricts f along the (n + 1)² rays at the Chebyshev nodes with
// rigorous radii (in double-double: LineRestrictor::restrict_with_double_double_bounds),
// interpolates each B_i in u and v, and bounds, per tile of 64 pixels, how far the interpolant
// can be from the exact B_i there:
//   * at the nodes, the interpolant's value against the node's ball;
//   * everywhere, that difference (a polynomial of degree ≤ n in u and in v) times the tensor
//     Lebesgue constant of the nodes (ChebyshevInterpolation::lebesgue_bound squared);
//   * the roundings of evaluating the interpolant for a row and a pixel;
//   * the difference between the exact affine ray of a pixel's coordinates and the ray the
//     camera computes in doubles (LineRestrictor::growth_bound over the tile's magnitudes).
// So the ball of every pixel's ray holds the exact restriction of the exact surface along the
// camera's ray, and a pixel costs (n + 1)² multiply-adds to get it.
#pragma once

#include <array>
#include <vector>

#include "algebra/compiled.h"
#include "render/bernstein_ball.h"
#include "render/camera.h"

namespace locus::render {

// A rectangle of continuous image coordinates: x0 ≤ x ≤ x1, y0 ≤ y ≤ y1.
struct ImageRect {
    double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
    bool contains(double x, double y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
};

class CertifiedRayFamily {
  public:
    // `center`, `radius`: a sphere holding every clip interval of the frame. `rect`: the image
    // points whose rays the family serves (all of them: {0, 0, width, height}); the balls hold
    // for those only. The smaller the rectangle, the narrower the balls: a surface that covers
    // a small part of the picture gets a family over its own part (PrimaryTracer).
    CertifiedRayFamily(const algebra::CompiledPolynomial& f, const Camera& camera,
                       const Vec3& center, double radius, const ImageRect& rect);

    // False when no finite bound could be had (overflow; a coefficient of f outside the normal
    // doubles): every ray is then traced alone.
    bool certified() const { return certified_; }
    // The balls are restrictions to t ∈ [t_start, t_start + t_width].
    double t_start() const { return t_start_; }
    double t_width() const { return t_width_; }

    // The Bernstein coefficients along one image row, as polynomials in u: by_u[a][i] is the
    // coefficient of u^a in B_i (a pixel's Horner steps then run over i in parallel).
    struct Row {
        int degree = -1;
        int tile_row = 0;  // which row of tiles the radii come from
        std::array<std::array<double, kMaxDegree + 1>, kMaxDegree + 1> by_u;
    };
    void expand_row(double y, Row& out) const;
    // The ball of the primary ray through (x, y) on the row expanded at y; (x, y) in the
    // family's rectangle.
    void ball_at(const Row& row, double x, BernsteinBall& out) const;

    // Whether a family is worth building: whether the exact balls of a grid × grid sample of
    // the rectangle's rays, over the range of t a family would take and with the least radius
    // a family's balls could have (Λ² times the samples' largest), decide their first root by
    // subdivision to `depth` for at least `fraction` of those not of one sign throughout
    // (true when none is). A prediction: building a family costs (n + 1)² such balls and its
    // interpolation, this grid² (at degree 30: 961 against 16).
    static bool worth_building(const algebra::CompiledPolynomial& f, const Camera& camera,
                               const Vec3& center, double radius, const ImageRect& rect, int grid,
                               int depth, double fraction);

    // Whether the family's balls decide the first root on the whole range — found, or shown
    // absent — by subdivision to `depth` for at least `fraction` of a grid × grid sample of the
    // rectangle's rays (the cells' centres; it stops as soon as the answer is known).
    // Deterministic: a frame asks once, before any ray, whether its rays should search the
    // family's balls at all. False when not certified().
    bool decides_often(int grid, int depth, double fraction) const;

  private:
    int degree_ = -1;
    double center_x_, half_width_, center_y_, half_height_;
    double t_start_ = 0.0, t_width_ = 1.0;
    bool certified_ = false;
    // by_uv_[(i·(n + 1) + a)·(n + 1) + b]: the coefficient of u^a·v^b in B_i.
    std::vector<double> by_uv_;
    // The radii of the coefficients for the pixels of each tile of the rectangle (row-major,
    // n + 1 a tile): the interpolation's bound, the same everywhere, and the tile's own bound
    // on how far its pixels' rays are from their references.
    static constexpr double kTilePixels = 64.0;
    static constexpr int kMostTiles = 16;
    int tiles_x_ = 1, tiles_y_ = 1;
    double tile_width_ = 1.0, tile_height_ = 1.0;
    std::vector<double> tile_radius_;
};

}  // namespace locus::render
