#include "render/ray_restriction.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <new>
#include <type_traits>

#include "algebra/double_double.h"
#include "render/detail/uninitialized_array.h"

namespace locus::render {

LineRestrictor::LineRestrictor(std::span<const algebra::CompiledTerm> terms,
                               std::span<const double> low_words) {
    const std::array<int, 3> other_exponent = algebra::exponents_besides_pure_powers(terms);
    std::array<int, 3> pure_degree{};
    for (const algebra::CompiledTerm& term : terms) {
        const int axis = algebra::pure_power_axis(term);
        if (axis >= 0) {
            pure_degree[axis] = std::max(pure_degree[axis], term.ex + term.ey + term.ez);
        }
    }
    for (int a = 0; a < 3; ++a) {
        if (pure_degree[a] > other_exponent[a]) {
            univariate_[a].degree = pure_degree[a];
            univariate_[a].by_exponent.assign(pure_degree[a] + 1, ZTerm{-1, 0.0, 0.0, 0.0});
            table_exponent_[a] = other_exponent[a];
        } else {
            table_exponent_[a] = std::max(pure_degree[a], other_exponent[a]);
        }
    }
    std::map<int, std::map<int, std::vector<ZTerm>>> grouped;
    for (std::size_t i = 0; i < terms.size(); ++i) {
        const algebra::CompiledTerm& term = terms[i];
        const double low_word = i < low_words.size() ? low_words[i] : 0.0;
        degree_ = std::max(degree_, term.ex + term.ey + term.ez);
        const int axis = algebra::pure_power_axis(term);
        if (axis >= 0 && univariate_[axis].degree > 0) {
            const int k = term.ex + term.ey + term.ez;
            ZTerm& slot = univariate_[axis].by_exponent[k];
            // Compiled terms are distinct monomials: one coefficient per exponent.
            slot = {k, term.coefficient, std::abs(term.coefficient), low_word};
            continue;
        }
        grouped[term.ex][term.ey].push_back(
            {term.ez, term.coefficient, std::abs(term.coefficient), low_word});
    }
    for (auto& [ex, by_y] : grouped) {
        XGroup x_group{ex, 0, {}};
        for (auto& [ey, z_terms] : by_y) {
            YGroup y_group{ey, 0, std::move(z_terms)};
            for (const ZTerm& z : y_group.z_terms) {
                y_group.max_ez = std::max(y_group.max_ez, z.ez);
            }
            x_group.max_yz = std::max(x_group.max_yz, ey + y_group.max_ez);
            x_group.y_groups.push_back(std::move(y_group));
        }
        x_groups_.push_back(std::move(x_group));
    }
    // Roundings on any one path of restrict_to: a power (o + t·d)^e takes two per factor (a
    // product and a sum), 2·degree in all; then c·z-power, y-power·(z-sum) and x-power·(yz-sum)
    // one each; and the three running sums, a chain as long as the contributions they collect
    // (the z-terms of a y-group; Σ(ey + 1) over an x-group's y-groups; Σ(ex + 1) over the
    // x-groups).
    int longest_z = 0, longest_yz = 0, x_sum = 0;
    for (const XGroup& x_group : x_groups_) {
        int yz_sum = 0;
        for (const YGroup& y_group : x_group.y_groups) {
            longest_z = std::max(longest_z, static_cast<int>(y_group.z_terms.size()));
            yz_sum += y_group.ey + 1;
        }
        longest_yz = std::max(longest_yz, yz_sum);
        x_sum += x_group.ex + 1;
    }
    // The pure powers' Taylor shift: a radius' path goes through at most n multiply-adds (five
    // roundings each: (|b| + r_b), its product with r_o, the two inner sums and the sum into
    // the radius), then d^j (j products) and the product a_j·d^j added into the result; the
    // result's chains gain an addend per such axis.
    int longest_horner = 0;
    for (const Univariate& u : univariate_) {
        longest_horner = std::max(longest_horner, 6 * u.degree + 8);
    }
    rounding_depth_ =
        2 * std::max(degree_, 0) + 3 + longest_z + longest_yz + x_sum + 3 + longest_horner;
}

namespace {
constexpr double kUnit = 0x1.0p-53;

using detail::UninitializedArray;

// The scalars of LineRestrictor::expand. `Plain` is a double. `Ball` is a double with a bound
// on its error, propagated by the running error analysis of each operation (midpoint-radius
// arithmetic, as in Rump's INTLAB and Johansson's Arb): for z = x·y,
// e_z = |x|·e_y + (|y| + e_y)·e_x + u·|z|; for z = x + y, e_z = e_x + e_y + u·|z|. The radii
// are themselves rounded to nearest; restrict_with_bounds inflates the final ones by
// (1 + 2γ_N) to cover that (every radius is a sum of products of positive numbers, reached by
// at most N = rounding_depth() roundings).
struct Plain {
    double v;
    static Plain zero() { return {0.0}; }
    static Plain one() { return {1.0}; }
    friend Plain operator*(const Plain& a, const Plain& b) { return {a.v * b.v}; }
    // acc + a·b
    static void multiply_add(Plain& acc, const Plain& a, const Plain& b) { acc.v += a.v * b.v; }
    static Plain sum_of_products(const Plain& a, const Plain& b, const Plain& c, const Plain& d) {
        return {a.v * b.v + c.v * d.v};
    }
};

struct Ball {
    double v, r;
    static Ball zero() { return {0.0, 0.0}; }
    static Ball one() { return {1.0, 0.0}; }
    friend Ball operator*(const Ball& a, const Ball& b) {
        const double p = a.v * b.v;
        return {p, std::abs(a.v) * b.r + (std::abs(b.v) + b.r) * a.r + kUnit * std::abs(p)};
    }
    static void multiply_add(Ball& acc, const Ball& a, const Ball& b) {
        const double p = a.v * b.v;
        acc.v += p;
        acc.r += std::abs(a.v) * b.r + (std::abs(b.v) + b.r) * a.r +
                 kUnit * (std::abs(p) + std::abs(acc.v));
    }
    static Ball sum_of_products(const Ball& a, const Ball& b, const Ball& c, const Ball& d) {
        Ball z = a * b;
        multiply_add(z, c, d);
        return z;
    }
};

// `DoubleDoubleBall`: the same running error analysis with double-double midpoints, each
// operation's error at most algebra::kOperationError (5u²) of its result's magnitude. A
// double-double's magnitude |hi + lo| is taken as |hi|·(1 + 2^-52), above it.
struct DoubleDoubleBall {
    algebra::DoubleDouble v;
    double r;
    static DoubleDoubleBall zero() { return {{0.0, 0.0}, 0.0}; }
    static DoubleDoubleBall one() { return {{1.0, 0.0}, 0.0}; }
    static double magnitude(const algebra::DoubleDouble& x) {
        return std::abs(x.hi) * (1.0 + 0x1.0p-52);
    }
    friend DoubleDoubleBall operator*(const DoubleDoubleBall& a, const DoubleDoubleBall& b) {
        const algebra::DoubleDouble p = a.v * b.v;
        return {p, magnitude(a.v) * b.r + (magnitude(b.v) + b.r) * a.r +
                       algebra::kOperationError * magnitude(p)};
    }
    static void multiply_add(DoubleDoubleBall& acc, const DoubleDoubleBall& a,
                             const DoubleDoubleBall& b) {
        const algebra::DoubleDouble p = a.v * b.v;
        acc.v = acc.v + p;
        acc.r += magnitude(a.v) * b.r + (magnitude(b.v) + b.r) * a.r +
                 algebra::kOperationError * (magnitude(p) + magnitude(acc.v));
    }
    static DoubleDoubleBall sum_of_products(const DoubleDoubleBall& a, const DoubleDoubleBall& b,
                                            const DoubleDoubleBall& c, const DoubleDoubleBall& d) {
        DoubleDoubleBall z = a * b;
        multiply_add(z, c, d);
        return z;
    }
};

// The Taylor shift's diagonals (LineRestrictor::expand) for balls, as Ball::multiply_add does
// each step, on separate arrays of values and radii so that the steps of a diagonal become
// vector operations.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__GLIBC__)
__attribute__((target_clones("avx2", "default")))
#endif
void shift_balls(std::array<std::array<Ball, kMaxDegree + 1>, 3>& a, const std::array<Ball, 3>& o,
                 const std::array<int, 3>& n) {
    std::array<std::array<double, kMaxDegree + 2>, 3> v{}, r{};
    for (std::size_t axis = 0; axis < 3; ++axis) {
        for (int k = 0; k <= n[axis]; ++k) {
            v[axis][static_cast<std::size_t>(k)] = a[axis][static_cast<std::size_t>(k)].v;
            r[axis][static_cast<std::size_t>(k)] = a[axis][static_cast<std::size_t>(k)].r;
        }
    }
    std::array<double, 3> value{}, magnitude{}, radius{};
    for (std::size_t axis = 0; axis < 3; ++axis) {
        value[axis] = o[axis].v;
        magnitude[axis] = std::abs(o[axis].v);
        radius[axis] = o[axis].r;
    }
    const int longest = std::max({n[0], n[1], n[2]});
    for (int diagonal = 0; diagonal < longest; ++diagonal) {
        for (std::size_t axis = 0; axis < 3; ++axis) {
            double* values = v[axis].data();
            double* radii = r[axis].data();
            const double ov = value[axis], om = magnitude[axis], orad = radius[axis];
            // An axis of lower degree has had all its n diagonals.
            for (int k = n[axis] - 1 - diagonal; k >= 0 && k < n[axis]; ++k) {
                const auto i = static_cast<std::size_t>(k);
                const double bv = values[i + 1], br = radii[i + 1];
                const double p = ov * bv;
                const double sum = values[i] + p;
                radii[i] +=
                    om * br + (std::abs(bv) + br) * orad + kUnit * (std::abs(p) + std::abs(sum));
                values[i] = sum;
            }
        }
    }
    for (std::size_t axis = 0; axis < 3; ++axis) {
        for (int k = 0; k <= n[axis]; ++k) {
            a[axis][static_cast<std::size_t>(k)] = {v[axis][static_cast<std::size_t>(k)],
                                                    r[axis][static_cast<std::size_t>(k)]};
        }
    }
}

// The restriction as balls: value(k) ± radius(k, inflate), where inflate = 1 + 2γ_N covers the
// rounding of radii reached by at most N = depth roundings (sums of products of positive
// doubles); every radius infinite when anything is not finite.
template <class Value, class Radius>
RestrictionBall restriction_ball(int degree, int depth, bool certified, Value value,
                                 Radius radius) {
    const double n = depth;
    const double inflate = 1.0 + 2.0 * n * kUnit / (1.0 - n * kUnit);
    RestrictionBall ball;
    ball.polynomial.degree = degree;
    ball.certified = certified;
    for (int k = 0; k <= degree; ++k) {
        ball.polynomial.c[k] = value(k);
        ball.radius[k] = radius(k, inflate);
        ball.certified =
            ball.certified && std::isfinite(ball.radius[k]) && std::isfinite(ball.polynomial.c[k]);
    }
    if (!ball.certified) {
        ball.radius.fill(INFINITY);
    }
    return ball;
}

// The balls of a line's coordinates: value ± error, componentwise.
std::array<Ball, 3> balls(const Vec3& value, const Vec3& error) {
    return {Ball{value[0], error[0]}, Ball{value[1], error[1]}, Ball{value[2], error[2]}};
}

}  // namespace

RayPolynomial LineRestrictor::restrict_to(const Vec3& origin, const Vec3& direction) const {
    RayPolynomial result;
    result.degree = degree_;
    std::array<Plain, kMaxDegree + 1> c;
    expand<Plain>(
        {Plain{origin[0]}, Plain{origin[1]}, Plain{origin[2]}},
        {Plain{direction[0]}, Plain{direction[1]}, Plain{direction[2]}},
        [](const ZTerm& z) { return Plain{z.coefficient}; }, c);
    for (int k = 0; k <= degree_; ++k) {
        result.c[k] = c[k].v;
    }
    return result;
}

RestrictionBall LineRestrictor::restrict_with_bounds(const Vec3& origin, const Vec3& direction,
                                                     const LineError& error,
                                                     double coefficient_error) const {
    std::array<Ball, kMaxDegree + 1> c;
    expand<Ball>(
        balls(origin, error.origin), balls(direction, error.direction),
        [coefficient_error](const ZTerm& z) {
            return Ball{z.coefficient, z.magnitude * coefficient_error};
        },
        c);
    const double floor = (rounding_depth_ + 8.0) * 0x1.0p-1060;
    return restriction_ball(
        degree_, rounding_depth_, std::isfinite(coefficient_error), [&](int k) { return c[k].v; },
        [&](int k, double inflate) { return c[k].r * inflate + floor; });
}

RestrictionBall LineRestrictor::restrict_with_double_double_bounds(const DoubleDoubleLine& line,
                                                                   const LineError& error,
                                                                   double coefficient_error) const {
    std::array<DoubleDoubleBall, 3> origin, direction;
    for (std::size_t i = 0; i < 3; ++i) {
        const auto axis = static_cast<glm::length_t>(i);
        origin[i] = {{line.origin_hi[axis], line.origin_lo[axis]}, error.origin[axis]};
        direction[i] = {{line.direction_hi[axis], line.direction_lo[axis]}, error.direction[axis]};
    }
    std::array<DoubleDoubleBall, kMaxDegree + 1> c;
    expand<DoubleDoubleBall>(
        origin, direction,
        [coefficient_error](const ZTerm& z) {
            return DoubleDoubleBall{{z.coefficient, z.low_word},
                                    z.magnitude * (1.0 + 0x1.0p-52) * coefficient_error};
        },
        c);
    // The radii's own rounding as in restrict_with_bounds. A double-double's error-free parts
    // lose up to 2^-1074 each when they underflow; the floor covers that as the doubles' does,
    // with room for the factors such a loss is multiplied by. hi is the double nearest
    // hi + lo: |lo| joins the radius.
    const double floor = (rounding_depth_ + 8.0) * 0x1.0p-1000;
    return restriction_ball(
        degree_, rounding_depth_, std::isfinite(coefficient_error),
        [&](int k) { return std::isfinite(c[k].v.lo) ? c[k].v.hi : NAN; },
        [&](int k, double inflate) {
            return (c[k].r * inflate + std::abs(c[k].v.lo)) * (1.0 + 2.0 * kUnit) + floor;
        });
}

RestrictionBall LineRestrictor::restrict_with_relative_bounds(const Vec3& origin,
                                                              const Vec3& direction,
                                                              double input_error,
                                                              double coefficient_error) const {
    LineError error;
    error.origin = glm::abs(origin) * input_error;
    error.direction = glm::abs(direction) * input_error;
    return restrict_with_bounds(origin, direction, error, coefficient_error);
}

std::array<double, kMaxDegree + 1> LineRestrictor::growth_bound(const Vec3& origin_magnitude,
                                                                const Vec3& direction_magnitude,
                                                                const LineError& error) const {
    // The magnitudes' expansion in balls: with every input and coefficient positive, the
    // radius bounds S(M + δ) − S(M) (and S(M)'s own rounding).
    std::array<Ball, kMaxDegree + 1> c;
    expand<Ball>(
        balls(origin_magnitude, error.origin), balls(direction_magnitude, error.direction),
        [](const ZTerm& z) {
            return Ball{z.magnitude, 0.0};
        },
        c);
    const double n = rounding_depth_;
    const double inflate = 1.0 + 2.0 * n * kUnit / (1.0 - n * kUnit);
    std::array<double, kMaxDegree + 1> growth{};
    for (int k = 0; k <= degree_; ++k) {
        growth[k] = std::isfinite(c[k].r) ? c[k].r * inflate + (n + 8.0) * 0x1.0p-1060 : INFINITY;
    }
    return growth;
}

template <class Scalar, class Coefficient>
void LineRestrictor::expand(const std::array<Scalar, 3>& origin,
                            const std::array<Scalar, 3>& direction, Coefficient coefficient,
                            std::array<Scalar, kMaxDegree + 1>& result) const {
    for (int k = 0; k <= std::max(degree_, 0); ++k) {
        result[k] = Scalar::zero();
    }
    if (degree_ < 0) {
        return;
    }
    // Powers (o + t·d)^k for k ≤ max exponent as coefficient rows: row k has k + 1
    // coefficients, row[j] = previous[j]·o + previous[j − 1]·d. Packed, row k from k(k + 1)/2
    // on, and left uninitialized (every entry read is written first): square tables for the
    // largest degree, zeroed, took a 300 KB stack frame of which each thread faulted in the
    // pages on its first double-double restriction (a hundred page faults of a 512² frame, at
    // 5–12 µs each on this project's machines), and zeroed 200 KB at every call.
    using PowerTable = UninitializedArray<Scalar, (kMaxDegree + 1) * (kMaxDegree + 2) / 2>;
    PowerTable powers[3];
    const auto row_of = [&powers](int axis, int k) {
        return powers[axis].data() + static_cast<std::size_t>(k) * (k + 1) / 2;
    };
    for (int axis = 0; axis < 3; ++axis) {
        const Scalar& o = origin[static_cast<std::size_t>(axis)];
        const Scalar& d = direction[static_cast<std::size_t>(axis)];
        row_of(axis, 0)[0] = Scalar::one();
        for (int k = 1; k <= table_exponent_[static_cast<std::size_t>(axis)]; ++k) {
            const Scalar* previous = row_of(axis, k - 1);
            Scalar* row = row_of(axis, k);
            row[0] = previous[0] * o;
            for (int j = 1; j < k; ++j) {
                row[j] = Scalar::sum_of_products(previous[j], o, previous[j - 1], d);
            }
            row[k] = previous[k - 1] * d;
        }
    }
    std::array<Scalar, kMaxDegree + 1> in_z, in_yz;
    for (const XGroup& x_group : x_groups_) {
        std::fill_n(in_yz.begin(), x_group.max_yz + 1, Scalar::zero());
        for (const YGroup& y_group : x_group.y_groups) {
            std::fill_n(in_z.begin(), y_group.max_ez + 1, Scalar::zero());
            for (const ZTerm& z : y_group.z_terms) {
                const Scalar* power = row_of(2, z.ez);
                const Scalar c = coefficient(z);
                for (int j = 0; j <= z.ez; ++j) {
                    Scalar::multiply_add(in_z[j], c, power[j]);
                }
            }
            const Scalar* y_power = row_of(1, y_group.ey);
            for (int i = 0; i <= y_group.ey; ++i) {
                for (int j = 0; j <= y_group.max_ez; ++j) {
                    Scalar::multiply_add(in_yz[i + j], y_power[i], in_z[j]);
                }
            }
        }
        const Scalar* x_power = row_of(0, x_group.ex);
        for (int i = 0; i <= x_group.ex; ++i) {
            for (int j = 0; j <= x_group.max_yz; ++j) {
                Scalar::multiply_add(result[i + j], x_power[i], in_yz[j]);
            }
        }
    }
    // Pure powers p(x) = Σ c_k·x^k (the constant left to the groups: c_0 = 0 here):
    // p(o + t·d) = Σ_j a_j·d^j·t^j, where a_j = Σ_k c_k·C(k, j)·o^(k−j) are p's Taylor
    // coefficients at o, by repeated synthetic division (von zur Gathen and Gerhard's method
    // A): n(n + 1)/2 multiply-adds, where Horner's rule in the polynomial o + t·d took as many
    // sums of two products — at degree 30 the restriction's largest cost.
    // The three axes' shifts run side by side (diagonals outer): a diagonal waits for the one
    // before it, and another axis' diagonal fills that wait.
    std::array<int, 3> n{};
    for (std::size_t axis = 0; axis < 3; ++axis) {
        n[axis] = univariate_[axis].degree;
    }
    if (n[0] + n[1] + n[2] == 0) {
        return;
    }
    // c_k of an axis' pure powers, k ≤ n[axis]: zero for k = 0 (the groups' constant; the only
    // k asked of an axis without pure powers, whose by_exponent is empty) and for absent powers.
    const auto coefficient_of = [&](std::size_t axis, int k) {
        if (k == 0) {
            return Scalar::zero();
        }
        const ZTerm& term = univariate_[axis].by_exponent[static_cast<std::size_t>(k)];
        return term.ez >= 0 ? coefficient(term) : Scalar::zero();
    };
    // Pass j sets a_k += o·a_(k+1) for k from n − 1 down to j: each step waits for the one
    // before it, so the passes run as a wavefront, the steps (j, k) of one diagonal
    // s = j + n − 1 − k together (each needs only steps of diagonal s − 1): one pass after
    // another was slower than Horner's rule, whose steps are independent. A diagonal is
    // k = n − 1 − s … n − 1 in ascending order, each step reading a_(k+1) before the next step
    // writes it: for balls (shift_balls, on separate arrays of values and radii), a loop the
    // compiler turns into vector operations. Then a_j·d^j is added into the result.
    std::array<std::array<Scalar, kMaxDegree + 1>, 3> a;
    for (std::size_t axis = 0; axis < 3; ++axis) {
        for (int k = 0; k <= n[axis]; ++k) {
            a[axis][static_cast<std::size_t>(k)] = coefficient_of(axis, k);
        }
    }
    if constexpr (std::is_same_v<Scalar, Ball>) {
        shift_balls(a, origin, n);
    } else {
        const int longest = std::max({n[0], n[1], n[2]});
        for (int diagonal = 0; diagonal < longest; ++diagonal) {
            for (std::size_t axis = 0; axis < 3; ++axis) {
                // An axis of lower degree has had all its n diagonals.
                for (int k = n[axis] - 1 - diagonal; k >= 0 && k < n[axis]; ++k) {
                    Scalar::multiply_add(a[axis][static_cast<std::size_t>(k)], origin[axis],
                                         a[axis][static_cast<std::size_t>(k) + 1]);
                }
            }
        }
    }
    for (std::size_t axis = 0; axis < 3; ++axis) {
        if (n[axis] == 0) {
            continue;
        }
        Scalar power = Scalar::one();  // d^j
        for (int j = 0; j <= n[axis]; ++j) {
            Scalar::multiply_add(result[static_cast<std::size_t>(j)],
                                 a[axis][static_cast<std::size_t>(j)], power);
            power = power * direction[axis];
        }
    }
}

}  // namespace locus::render
