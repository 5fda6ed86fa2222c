// Implicitization of surfaces by the Dixon resultant (`--method dixon`).
//
// For x = P₁/W, y = P₂/W, z = P₃/W of bidegree (m, n) in (s, t), the Cayley–Dixon polynomial
//     δ = det[F(s,t); F(α,t); F(α,β)] / ((s − α)(t − β)),   Fᵢ = Pᵢ − xᵢ·W,
// has coefficients, in the monomials s^i t^j (i < m, j < 2n) against α^k β^l (k < 2m, l < n),
// that form a square matrix of size 2mn whose entries are affine in x, y, z (Sederberg's
// 18 × 18 matrix for a bicubic patch). Every point of the image makes it singular, so its
// determinant — or, when the matrix is singular everywhere (base points, degenerate patches),
// the determinant of a maximal non-singular submatrix — is a multiple of the implicit equation.
//
// The determinant is computed modulo primes near 2^62 by evaluation and interpolation: along a
// grid of lines in one coordinate, det(A + v·B) = det B · charpoly(−B⁻¹A)(v), so each line costs
// one characteristic polynomial; the images are lifted to Q (CRT, rational reconstruction).
// FLINT factors the lift; the factor that vanishes on the map — proved by vanishes_on, with the
// map's image proved two-dimensional by a non-zero Jacobian minor — is the implicit equation.
// Nothing here is trusted without that proof: a route that cannot produce it throws Error.
#pragma once

#include <chrono>
#include <optional>

#include "implicit/implicitize.h"

namespace locus::implicit {

// Throws InputError for maps that are not surfaces, Error when the route gives up (the
// determinant vanishes, no factor vanishes on the map, the matrix is larger than `max_size`),
// Timeout when `deadline` passes (checked per batch of primes). `threads` primes are computed
// at a time, and the proof runs on as many threads.
ImplicitResult implicitize_by_dixon(
    const Parametrization& map,
    std::optional<std::chrono::steady_clock::time_point> deadline = std::nullopt, int threads = 1,
    std::size_t max_size = 72);

}  // namespace locus::implicit
