// The compile step from exact algebra to the renderer: a polynomial f(x, y, z) over Q becomes an
// immutable, thread-safe CompiledPolynomial with double coefficients for fast evaluation of f and
// its analytic gradient, while keeping the exact polynomial for what must stay exact (the
// certified `exact` root finder).
//
// This is the only header of algebra/ that render/ includes (STYLE.md P3, P7). Compiling first
// replaces f by its square-free part, computed exactly with FLINT, so that a non-reduced
// equation such as (x²+y²+z²−1)² has simple roots along rays and renders like the sphere;
// `made_square_free()` reports when that changed f. Variables are x, y, z by name; an equation
// in a subset of them (a cylinder over a curve) is allowed.
#pragma once

#include <array>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace locus::algebra {

class Polynomial;

// The compiled form evaluates with fixed-size power tables; higher degrees are refused.
inline constexpr int kMaxCompiledDegree = 64;

using Point3 = std::array<double, 3>;

// coefficient · x^ex · y^ey · z^ez, the coefficient rounded from the exact rational.
struct CompiledTerm {
    double coefficient;
    int ex, ey, ez;
};

// The axis (0, 1, 2 for x, y, z) a term is a pure power of, c·x^k with k ≥ 1; −1 for a
// mixed term or the constant.
int pure_power_axis(const CompiledTerm& term);
// Per axis, the highest exponent of that axis among the terms that are not its pure powers (0
// when there are none). An axis's pure powers above it can be taken by Horner-type schemes
// with no power table past it: enclose_on_line's chains here, and render's LineRestrictor.
std::array<int, 3> exponents_besides_pure_powers(std::span<const CompiledTerm> terms);

struct ValueGradient {
    double value;
    Point3 gradient;
};

// A real number known to lie within `radius` of value + value_low (value_low is the low word of
// a double-double value, zero for a plain double).
struct ValueEnclosure {
    double value = 0.0;
    double value_low = 0.0;
    double radius = 0.0;
    // +1 or −1 when every number in the enclosure has that sign, 0 when it may be zero (or the
    // enclosure is not finite).
    int sign() const {
        const double margin = (value_low < 0.0 ? -value_low : value_low) + radius;
        if (!(margin < 1e308) || !(value == value)) {
            return 0;
        }
        const double safe = margin * (1.0 + 0x1.0p-50);
        return value > safe ? 1 : (value < -safe ? -1 : 0);
    }
};

struct ExactRoot {
    enum class Status { hit, miss, identically_zero } status = Status::miss;
    double t = 0.0;
};

class CompiledPolynomial {
  public:
    int degree() const { return degree_; }
    std::span<const CompiledTerm> terms() const { return terms_; }
    // The square-free equation in normalized form (DESIGN.md), e.g. "x^2+y^2+z^2-1".
    const std::string& equation() const;
    // True when compiling replaced the input by its square-free part.
    bool made_square_free() const { return made_square_free_; }

    double value(const Point3& p) const;
    ValueGradient value_gradient(const Point3& p) const;
    // ∇f alone, for shading normals: no value to sum, and the groups summed in two interleaved
    // sums, so it may differ from value_gradient(p).gradient by rounding.
    Point3 gradient(const Point3& p) const;

    // Certified value of the exact (rational) f at the point o + t·d, where the doubles o, d
    // and t are read exactly, with a rigorous bound on every rounding (of the point, the
    // coefficients and the evaluation; see compiled.cpp). In `Precision::double_precision` an
    // a-priori bound in doubles, γ_N·Σ|c|·|x|^a|y|^b|z|^c for the N roundings a term meets, at
    // twice the cost of value(); in `Precision::double_double` in double-double arithmetic, with a
    // radius near 1e-31 of Σ|c|·|x|^a|y|^b|z|^c, at twenty times. Not finite when the evaluation
    // overflows.
    enum class Precision { double_precision, double_double };
    ValueEnclosure enclose_on_line(const Point3& origin, const Point3& direction, double t,
                                   Precision precision = Precision::double_double) const;

    // max over the terms of |c − c̃| / |c̃|, for the exact coefficient c and its double c̃:
    // 0 when every coefficient is a double (integers below 2^53, dyadic fractions), at most
    // 2^-53 otherwise, and +∞ when a coefficient left the range of normal doubles (so that no
    // floating-point bound built on the doubles can be trusted).
    double coefficient_error() const { return coefficient_error_; }
    // The coefficients as double-doubles: terms()[i].coefficient + low_words()[i], within
    // double_double_coefficient_error() (relative) of the exact ones — for restrictions to a
    // ray in double-double (render/ray_restriction.h).
    std::span<const double> low_words() const { return low_words_; }
    double double_double_coefficient_error() const { return double_double_coefficient_error_; }

  private:
    struct Exact;
    friend CompiledPolynomial compile_surface(const Polynomial& f);
    friend ExactRoot exact_first_root(const CompiledPolynomial& f, const Point3& origin,
                                      const Point3& direction, double lo, double hi, bool lo_open);
    CompiledPolynomial(std::shared_ptr<const Exact> exact, bool made_square_free);

    std::shared_ptr<const Exact> exact_;
    // Terms sorted by (ex, ey, ez); a group is a run with equal (ex, ey), evaluated as
    // x^ex·y^ey·Σ c·z^ez so that value and gradient cost two multiply-adds per term. The
    // evaluation reads the terms as separate arrays of doubles, with c·ez precomputed and the
    // group's exponents as doubles, rather than converting the integers at every call and
    // striding through CompiledTerm (with the fused power tables of compiled.cpp: Sarti's
    // dodecic 128 → 107–112 ns a call, the gradient alone 92–95 ns).
    struct Group {
        int ex, ey;
        double x_exponent, y_exponent;
        std::size_t begin, end;
    };
    std::vector<CompiledTerm> terms_;
    std::vector<Group> groups_;
    std::vector<double> coefficients_;  // terms_[i].coefficient
    std::vector<double> z_slopes_;      // terms_[i].coefficient · terms_[i].ez
    std::vector<int> z_exponents_;      // terms_[i].ez
    // Low words of the coefficients as double-doubles (c ≈ coefficients_[i] + low_words_[i]),
    // the relative error of that pair, and the rounding depth of enclose_on_line.
    std::vector<double> low_words_;
    double double_double_coefficient_error_ = 0.0;
    int double_double_depth_ = 0;
    // enclose_on_line's plan. An axis's pure powers c·x^k that go higher than the axis's
    // exponent in every other term form a chain, evaluated by Horner's rule in x^stride (stride:
    // the gcd of its exponents); the other terms are line_groups_ (groups_ without the chains'
    // terms), with power tables up to table_degree_ on each axis. Why: Chmutov's
    // T30(x) + T30(y) + T30(z) is three chains of 15 terms and the constant, and needs no
    // power tables, where the tables of x^k, y^k, z^k in double-double to k = 30 and the group
    // products were most of a probe of the certified renderer.
    struct Chain {
        int axis = 0, stride = 1;
        std::vector<double> high, low, magnitude;  // of x^(stride·m), m = 0, 1, …
    };
    std::vector<Chain> chains_;
    bool chains_exact_in_doubles_ = true;  // every chain coefficient's low word is 0
    std::vector<Group> line_groups_;
    std::array<int, 3> table_degree_{};
    // enclose_on_line's bound in doubles: radius = per_scale·Σ|terms| + the underflow floor,
    // multiplier·2^-1060·max(1, |x|, |y|, |z|)^degree at the point (given the largest of
    // |x|^degree, …), added by with_underflow.
    double with_underflow(double radius, double largest_power) const;
    // Sets chains_, line_groups_, table_degree_ and double_double_depth_ from terms_ and groups_.
    void plan_line_evaluation();
    double double_error_per_scale_ = 0.0;
    double underflow_multiplier_ = 0.0;
    double coefficient_error_ = 0.0;
    int degree_ = 0;
    bool made_square_free_ = false;
};

// Parses `equation` over the variables x, y, z (DESIGN.md "Polynomials"; errors carry the
// column) and compiles it. Throws InputError for a zero or constant polynomial (it defines no
// surface) and for a degree above kMaxCompiledDegree.
CompiledPolynomial compile_surface(std::string_view equation);
// The same for a polynomial whose variables are named among x, y, z (any ring order).
CompiledPolynomial compile_surface(const Polynomial& f);

// The certified first root of F(t) = f(o + t·d) with lo ≤ t ≤ hi, where o, d, lo, hi are read
// exactly as the rationals their doubles denote. F is computed in integers (up to a positive
// factor: exact_line_restriction.h), made square-free, and its roots isolated by Descartes'
// rule with bisection (Collins–Akritas); the first one is refined on exact signs until its
// enclosure rounds to one or two adjacent doubles, so `t` is within one ulp of the true root. Roots
// of every multiplicity count. With `lo_open`, a root at exactly lo is skipped (`locus trace` asks
// for t > 0).
ExactRoot exact_first_root(const CompiledPolynomial& f, const Point3& origin,
                           const Point3& direction, double lo, double hi, bool lo_open = false);

}  // namespace locus::algebra
