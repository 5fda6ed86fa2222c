// Univariate root finders: the first real root of a ray restriction F(t) = f(o + t·d) in an
// interval, the question every renderer method answers per pixel and `locus trace` per line.
//
// Conventions shared by every method (DESIGN.md, "locus trace"):
//  * the answer is the smallest root t of F with lo ≤ t ≤ hi, roots of even multiplicity
//    (tangent rays, singular curves) included;
//  * a method that cannot decide says so (RootStatus::unknown with a reason) instead of
//    reporting a silent miss;
//  * `work` counts the method's unit of effort (Sturm/Bernstein subdivisions, Laguerre or
//    Newton iterations, QR sweeps) so that benchmarks can chart work per ray.
// Root finders are closed and hot, so they are plain classes behind a concept and a variant
// (STYLE.md P8), not virtual classes. None allocates; all scratch lives on the stack.
#pragma once

#include <array>
#include <concepts>
#include <limits>
#include <string_view>
#include <variant>

namespace locus::render {

// Highest degree a restriction may have. Fixed so that per-ray scratch space is a stack array.
inline constexpr int kMaxDegree = 64;

// F(t) = Σ c[k]·t^k with double coefficients; degree −1 is the zero polynomial.
struct RayPolynomial {
    int degree = -1;
    std::array<double, kMaxDegree + 1> c{};

    double operator()(double t) const {
        double value = 0.0;
        for (int k = degree; k >= 0; --k) {
            value = value * t + c[k];
        }
        return value;
    }
};

enum class RootStatus { hit, miss, unknown };

// Set by Sturm as the `reason` of a hit or miss that deserves a second opinion (see sturm.cpp):
// its chain ended at a near-common factor of F and F' (multiple or very close roots), or the
// degree is 16 or more.
inline constexpr const char* kNearCommonFactor =
    "near-common factor of F and F' (multiple or very close roots)";
inline constexpr const char* kSecondOpinion = "high degree";

// Which arithmetic settled a certified answer (render/certified_tracer.h); `floating` for the
// uncertified methods.
enum class Decision : unsigned char { floating, double_double, exact };

struct RootResult {
    RootStatus status = RootStatus::miss;
    double t = 0.0;           // the root when status == hit
    int work = 0;             // method-specific units of effort (see above)
    const char* reason = "";  // why, when status == unknown (a static string)
    Decision decided_by = Decision::floating;
};

// A root finder: `first_root(F, lo, hi)` with lo < hi finite.
template <class T>
concept RootFinder = requires(const T& finder, const RayPolynomial& f, double lo, double hi) {
    { finder.first_root(f, lo, hi) } -> std::same_as<RootResult>;
    { T::name } -> std::convertible_to<std::string_view>;
};

// Sturm sequence isolation of the first root, then safeguarded refinement (bracketed Halley
// steps with a regula falsi fallback).
// `hint`, when not NaN, is where the first root probably lies (the neighbouring pixel's): see
// sturm.cpp. The answer is the same first root with or without it.
struct SturmRootFinder {
    static constexpr std::string_view name = "sturm";
    RootResult first_root(const RayPolynomial& f, double lo, double hi,
                          double hint = std::numeric_limits<double>::quiet_NaN()) const;
};

// Descartes' rule of signs on Bernstein coefficients, with de Casteljau subdivision.
struct BernsteinRootFinder {
    static constexpr std::string_view name = "bernstein";
    RootResult first_root(const RayPolynomial& f, double lo, double hi) const;
};

// Laguerre's method for all complex roots with deflation, then polishing on the original F.
struct LaguerreRootFinder {
    static constexpr std::string_view name = "laguerre";
    RootResult first_root(const RayPolynomial& f, double lo, double hi) const;
};

// Eigenvalues of the (balanced) companion matrix with Eigen, then polishing on F.
struct CompanionRootFinder {
    static constexpr std::string_view name = "eigen";
    RootResult first_root(const RayPolynomial& f, double lo, double hi) const;
};

static_assert(RootFinder<SturmRootFinder>);
static_assert(RootFinder<BernsteinRootFinder>);
static_assert(RootFinder<LaguerreRootFinder>);
static_assert(RootFinder<CompanionRootFinder>);

using AnyRootFinder =
    std::variant<SturmRootFinder, BernsteinRootFinder, LaguerreRootFinder, CompanionRootFinder>;

// `hint` reaches the methods that take one (SturmRootFinder); the others ignore it.
inline RootResult first_root(const AnyRootFinder& finder, const RayPolynomial& f, double lo,
                             double hi, double hint = std::numeric_limits<double>::quiet_NaN()) {
    return std::visit(
        [&](const auto& m) {
            if constexpr (requires { m.first_root(f, lo, hi, hint); }) {
                return m.first_root(f, lo, hi, hint);
            } else {
                return m.first_root(f, lo, hi);
            }
        },
        finder);
}

}  // namespace locus::render
