// Restriction of a compiled trivariate polynomial to a line: F(t) = f(o + t·d) as a
// RayPolynomial, for rays that do not belong to the per-frame primary family (shadow and
// ambient-occlusion rays, `locus trace`, the rows of the family itself).
//
// Terms are grouped once as f = Σ_a x^a · Σ_b y^b · Σ_c coef·z^c, and the restriction is
// evaluated in that nested form with the power tables of the three linear coordinates, which
// costs O(#terms · degree) plus small convolutions, never a full symbolic expansion.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "algebra/compiled.h"
#include "render/root_finder.h"
#include "render/vec3.h"

namespace locus::render {

// A restriction known only up to rounding: the exact coefficient k lies in
// [c[k] − radius[k], c[k] + radius[k]]. `certified` is false when no finite bound could be
// given (overflow, a coefficient of f outside the normal doubles); the radii are then +∞.
struct RestrictionBall {
    RayPolynomial polynomial;
    std::array<double, kMaxDegree + 1> radius{};
    bool certified = false;
};

// Where the exact line lies, componentwise, about the doubles a restriction is computed from:
// |exact origin − origin| ≤ origin_error, and likewise for the direction.
struct LineError {
    Vec3 origin{0.0};
    Vec3 direction{0.0};
};

// A line whose origin and direction are double-doubles (hi + lo, componentwise).
struct DoubleDoubleLine {
    Vec3 origin_hi{0.0}, origin_lo{0.0};
    Vec3 direction_hi{0.0}, direction_lo{0.0};
};

class LineRestrictor {
  public:
    // Precondition: every exponent sum is at most kMaxDegree. `low_words`, when given, are
    // the coefficients' low words (CompiledPolynomial::low_words), for the double-double
    // restriction; without them it reads the coefficients as the doubles of `terms`.
    explicit LineRestrictor(std::span<const algebra::CompiledTerm> terms,
                            std::span<const double> low_words = {});

    int degree() const { return degree_; }
    // f(origin + t·direction), exactly of degree `degree()` in layout (higher coefficients may
    // vanish for particular lines).
    RayPolynomial restrict_to(const Vec3& origin, const Vec3& direction) const;

    // The same with a rigorous radius for every coefficient, for the exact f (whose
    // coefficients lie within `coefficient_error`, relative, of the compiled ones: see
    // CompiledPolynomial::coefficient_error) along any line within `error` of the given one:
    // midpoint-radius arithmetic, each operation's rounding added to its radius as it happens
    // (a running error bound: about u·Σ|partial results|, where the a-priori bound γ_N·Σ|terms|
    // was 10–100 times larger on the degree-12 suite surface).
    RestrictionBall restrict_with_bounds(const Vec3& origin, const Vec3& direction,
                                         const LineError& error, double coefficient_error) const;
    // The same when the given origin and direction are within a factor (1 ± input_error) of
    // the exact line's, componentwise (each rounded once or twice from exact data).
    RestrictionBall restrict_with_relative_bounds(const Vec3& origin, const Vec3& direction,
                                                  double input_error,
                                                  double coefficient_error) const;
    // The same in double-double arithmetic, for a line given in double-double within `error`
    // of the exact one and coefficients within `coefficient_error` (relative) of the
    // double-doubles: radii near 1e-31 of the terms' magnitudes, where doubles give 1e-15 —
    // for the pieces of a ray that doubles cannot decide (a root near where F is tiny at a
    // degree like 30), before exact arithmetic. About three times restrict_with_bounds' cost.
    // The result is rounded to doubles, each coefficient's rounding added to its radius.
    RestrictionBall restrict_with_double_double_bounds(const DoubleDoubleLine& line,
                                                       const LineError& error,
                                                       double coefficient_error) const;
    // For every line whose origin and direction are componentwise at most `origin_magnitude`
    // and `direction_magnitude` in absolute value: a bound, per coefficient, on how much its
    // restriction changes when the line moves by at most `error` — S(M + δ) − S(M) for the
    // magnitudes S(M) = Σ|c|·(M_o + s·M_d)^… (an increment of a polynomial with positive
    // coefficients grows with the point it is taken at).
    std::array<double, kMaxDegree + 1> growth_bound(const Vec3& origin_magnitude,
                                                    const Vec3& direction_magnitude,
                                                    const LineError& error) const;
    // The most roundings any term meets in restrict_to (see the .cpp).
    int rounding_depth() const { return rounding_depth_; }

  private:
    struct ZTerm {
        int ez;
        double coefficient;
        double magnitude;  // |coefficient|
        double low_word;   // of the coefficient as a double-double (0 without low words)
    };
    struct YGroup {
        int ey;
        int max_ez;
        std::vector<ZTerm> z_terms;
    };
    struct XGroup {
        int ex;
        int max_yz;  // highest degree in y and z together
        std::vector<YGroup> y_groups;
    };
    std::vector<XGroup> x_groups_;
    // An axis whose pure powers (c·x^k, k ≥ 1) go higher than its exponents in every other
    // term takes them by a Taylor shift to o, scaled by d^j (about n²/2 multiply-adds for
    // degree n), instead of through its power table and the term loops, and its table stops at
    // the other terms' exponents. For Chmutov's T_n(x) + T_n(y) + T_n(z) that is every term but
    // the constant, and no power tables at all. by_exponent[k].ez is k for a term present, −1
    // else.
    struct Univariate {
        int degree = 0;  // 0: the axis uses its power table for everything
        std::vector<ZTerm> by_exponent;
    };
    std::array<Univariate, 3> univariate_;
    std::array<int, 3> table_exponent_{};  // each axis' power table goes up to this
    int degree_ = -1;
    int rounding_depth_ = 0;

    // The expansion itself, in the scalars of ray_restriction.cpp: doubles, or balls in
    // doubles or double-doubles that carry the inputs' errors and every rounding's. The line's
    // coordinates are given as scalars; `coefficient(z)` is the scalar of a term's coefficient.
    template <class Scalar, class Coefficient>
    void expand(const std::array<Scalar, 3>& origin, const std::array<Scalar, 3>& direction,
                Coefficient coefficient, std::array<Scalar, kMaxDegree + 1>& result) const;
};

}  // namespace locus::render
