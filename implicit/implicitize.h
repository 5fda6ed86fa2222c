// Implicitization by elimination (Cox–Little–O'Shea, IVA ch. 3 §3, Theorems 1 and 2): for
// xᵢ = pᵢ/qᵢ, the smallest variety containing the image is V(I ∩ Q[x]) with
// I = ⟨q₁x₁ − p₁, …, qₙxₙ − pₙ, 1 − q₁⋯qₙ·w⟩ (w only when some qᵢ is not constant), computed
// with a Gröbner basis in an elimination order for the parameters and w.
//
// If the elimination ideal is principal its generator is the implicit equation, printed as a
// primitive integer polynomial with positive leading coefficient under grevlex x > y > z. If it
// is not (space curves, degenerate maps), all generators are returned and `image` says what
// the image is.
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "algebra/groebner/buchberger.h"
#include "implicit/parametrization.h"
#include "implicit/verify.h"

namespace locus::implicit {

enum class ImageKind {
    hypersurface,       // principal: one implicit equation
    point,              // the map is constant
    lower_dimensional,  // a curve in space, or a surface map whose image is a curve
    dense,              // no polynomial vanishes on the image (more parameters than dimensions)
};

struct ImplicitResult {
    algebra::RingPtr ring;                        // Q[x, y(, z)], grevlex
    std::vector<algebra::Polynomial> generators;  // reduced basis of the elimination ideal
    std::optional<algebra::Polynomial> equation;  // when principal: primitive, lc > 0
    ImageKind image = ImageKind::hypersurface;
    std::string method = "groebner";
    algebra::GroebnerStats stats;
    // The route proved `equation` by vanishes_on (interpolation, Dixon): checking it again on
    // a map without angles would repeat the same proof.
    bool proved_on_map = false;
};

// The ideal that implicitize() eliminates from: generators qᵢxᵢ − pᵢ (and 1 − w·q for rational
// maps, q the square-free part of the denominators' product) in Q[params, (w,) coordinates]
// under grevlex; `eliminated` lists the parameters and w, coordinates start at
// `first_coordinate`. Public so that benchmarks can hand the same ideal to other systems.
struct EliminationIdeal {
    algebra::RingPtr ring;
    std::vector<algebra::Polynomial> generators;
    std::vector<std::size_t> eliminated;
    std::size_t first_coordinate = 0;
};
EliminationIdeal elimination_ideal(const Parametrization& map);

// Throws Timeout when options.deadline passes before the elimination finishes.
ImplicitResult implicitize(const Parametrization& map,
                           const algebra::GroebnerOptions& options = {});

// The same by iterated resultants (Sylvester): Res_t(q₁x − p₁, q₂y − p₂) for plane curves,
// Res_t(Res_s(h₁, h₂), Res_s(h₁, h₃)) for surfaces, then exact factorization (FLINT) keeps the
// irreducible factor that vanishes on the parametrization; the extraneous factors (from
// denominators and from the elimination itself) are dropped. Applies to plane curves and
// surfaces only (InputError otherwise); throws Error when the resultant vanishes identically
// or no factor vanishes on the map, so the caller can fall back to implicitize().
ImplicitResult implicitize_by_resultant(const Parametrization& map);

// Interpolation modulo primes (implicit/interpolate.cpp): the least-degree polynomial vanishing
// at sample points, found as a kernel modulo primes near 2^62, lifted to Q by CRT and rational
// reconstruction, and proved by vanishes_on before it is returned. Plane curves and surfaces
// only (InputError otherwise); throws Error when the kernel is not one-dimensional (the image
// is not a hypersurface, or the degree needs more than 1330 monomials) so the caller can fall
// back to implicitize(); throws Timeout when `deadline` passes (checked per degree and prime).
ImplicitResult implicitize_by_interpolation(
    const Parametrization& map,
    std::optional<std::chrono::steady_clock::time_point> deadline = std::nullopt);

// The route `--method auto` takes: for plane curves and surfaces, Gröbner elimination for at
// most 20 ms, except for dense surface maps (a numerator or the common denominator with 9 terms
// or more: the Bézier patches), which skip it; for surfaces then the Dixon determinant
// (implicit/dixon.h); then interpolation modulo primes, then, if it gives up (the image is not
// a hypersurface, too many monomials), resultants, then Gröbner elimination under
// options.deadline; space curves and other shapes go to elimination directly. When a route gave up,
// `fallback_reason` (if given) receives why.
ImplicitResult implicitize_auto(const Parametrization& map,
                                const algebra::GroebnerOptions& options = {},
                                std::string* fallback_reason = nullptr);

// The routes by name, for the CLI's --method and the Python bindings' method=.
enum class ImplicitMethod { automatic, groebner, resultant, interpolate, dixon };
// "auto", "groebner", "resultant", "interpolate", "dixon"; nothing for any other name.
std::optional<ImplicitMethod> parse_implicit_method(std::string_view name);

// The route `method` names: implicitize_auto, implicitize (elimination under options),
// implicitize_by_resultant, implicitize_by_interpolation or implicitize_by_dixon (dixon.h),
// with their errors. `fallback_reason` as for implicitize_auto.
ImplicitResult implicitize_by(const Parametrization& map, ImplicitMethod method,
                              const algebra::GroebnerOptions& options = {},
                              std::string* fallback_reason = nullptr);

// Human-readable sentence for an ImageKind ("the image is a curve in space: ...").
std::string describe_image(ImageKind kind, std::size_t num_params, std::size_t num_coordinates);

}  // namespace locus::implicit
