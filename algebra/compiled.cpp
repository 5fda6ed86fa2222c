#include "algebra/compiled.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

#include "algebra/assert.h"
#include "algebra/double_double.h"
#include "algebra/error.h"
#include "algebra/exact_line_restriction.h"
#include "algebra/flint_convert.h"
#include "algebra/flint_threads.h"
#include "algebra/parse.h"
#include "algebra/print.h"
#include "algebra/real_roots.h"

namespace locus::algebra {

// The exact side, shared by all copies: the square-free polynomial in the ring x, y, z and its
// integer form for restricting to a ray (read-only after construction, so safe across threads).
struct CompiledPolynomial::Exact {
    Polynomial f;
    std::string equation;
    detail::ExactLineRestriction on_line;

    explicit Exact(Polynomial polynomial)
        : f(std::move(polynomial)), equation(to_string(f)), on_line(f) {}
};

namespace {

RingPtr xyz_ring() {
    static const RingPtr ring = PolyRing::make({"x", "y", "z"}, MonomialOrder::grevlex(3));
    return ring;
}

}  // namespace

CompiledPolynomial::CompiledPolynomial(std::shared_ptr<const Exact> exact, bool made_square_free)
    : exact_(std::move(exact)), made_square_free_(made_square_free) {
    const Polynomial& f = exact_->f;
    degree_ = static_cast<int>(f.total_degree());
    // Each coefficient as the double nearest to it and, for enclose_on_line, the double
    // nearest to the remainder; the relative errors of both are measured exactly.
    struct Rounded {
        CompiledTerm term;
        double low_word;
    };
    std::vector<Rounded> rounded;
    rounded.reserve(f.num_terms());
    Rational remainder, part;
    for (std::size_t i = 0; i < f.num_terms(); ++i) {
        const std::vector<std::uint32_t> e = f.exponents(i);
        const fmpq* c = f.coefficient(i).get();
        const double high = nearest_double(c);
        double low = 0.0;
        if (std::isnormal(high)) {
            set_exact_double(part.get(), high);
            fmpq_sub(remainder.get(), c, part.get());
            const double error = std::abs(fmpq_get_d(remainder.get()) / high);
            coefficient_error_ = std::max(coefficient_error_, error * (1.0 + 0x1.0p-50));
            low = nearest_double(remainder.get());
            if (low != 0.0) {
                set_exact_double(part.get(), low);
                fmpq_sub(remainder.get(), remainder.get(), part.get());
            }
            double_double_coefficient_error_ =
                std::max(double_double_coefficient_error_,
                         std::abs(fmpq_get_d(remainder.get()) / high) * (1.0 + 0x1.0p-50));
        } else {
            coefficient_error_ = INFINITY;
            double_double_coefficient_error_ = INFINITY;
        }
        rounded.push_back(
            {{high, static_cast<int>(e[0]), static_cast<int>(e[1]), static_cast<int>(e[2])}, low});
    }
    std::sort(rounded.begin(), rounded.end(), [](const Rounded& p, const Rounded& q) {
        return std::tie(p.term.ex, p.term.ey, p.term.ez) <
               std::tie(q.term.ex, q.term.ey, q.term.ez);
    });
    for (std::size_t i = 0; i < rounded.size(); ++i) {
        const CompiledTerm& t = rounded[i].term;
        terms_.push_back(t);
        low_words_.push_back(rounded[i].low_word);
        if (groups_.empty() || groups_.back().ex != t.ex || groups_.back().ey != t.ey) {
            groups_.push_back(
                {t.ex, t.ey, static_cast<double>(t.ex), static_cast<double>(t.ey), i, i});
        }
        groups_.back().end = i + 1;
        coefficients_.push_back(t.coefficient);
        z_slopes_.push_back(t.coefficient * t.ez);
        z_exponents_.push_back(t.ez);
    }
    plan_line_evaluation();
    // enclose_on_line in doubles errs by at most (γ_N + ρ)·Σ|terms|·(1 + 4(N + degree)u) (see
    // there). Underflow: each of a term's N roundings may lose 2^-1074 when its result is
    // subnormal, and the loss is then multiplied by what is left of the term — at most
    // |c̃|·max(1, |x|, |y|, |z|)^degree — so the floor is (N + 8)·2^-1060·Σ|c̃|·that power
    // (with_underflow).
    const double n = double_double_depth_;
    const double gamma = n * 0x1.0p-53 / (1.0 - n * 0x1.0p-53);
    double_error_per_scale_ =
        (gamma + coefficient_error_) * (1.0 + 4.0 * (n + degree_) * 0x1.0p-53) * 1.001;
    double sum_of_magnitudes = 0.0;
    for (const double c : coefficients_) {
        sum_of_magnitudes += std::abs(c);
    }
    // Kept as the multiplier of 2^-1060, a normal number: arithmetic on subnormals takes a
    // slow path in the processor (it cost the certified renderer 6 %).
    underflow_multiplier_ = (n + 8.0) * std::max(1.0, sum_of_magnitudes * 1.01);
}

int pure_power_axis(const CompiledTerm& term) {
    const int nonzero = (term.ex > 0) + (term.ey > 0) + (term.ez > 0);
    return nonzero != 1 ? -1 : (term.ex > 0 ? 0 : (term.ey > 0 ? 1 : 2));
}

std::array<int, 3> exponents_besides_pure_powers(std::span<const CompiledTerm> terms) {
    std::array<int, 3> besides{0, 0, 0};
    for (const CompiledTerm& t : terms) {
        const std::array<int, 3> e{t.ex, t.ey, t.ez};
        const int pure = pure_power_axis(t);
        for (int axis = 0; axis < 3; ++axis) {
            if (axis != pure) {
                besides[axis] = std::max(besides[axis], e[axis]);
            }
        }
    }
    return besides;
}

void CompiledPolynomial::plan_line_evaluation() {
    // The chains: each axis's pure powers above its exponents in the other terms.
    const std::array<int, 3> mixed = exponents_besides_pure_powers(terms_);
    const auto exponents = [](const CompiledTerm& t) {
        return std::array<int, 3>{t.ex, t.ey, t.ez};
    };
    const auto in_chain = [&](const CompiledTerm& t) {
        const int axis = pure_power_axis(t);
        return axis >= 0 && exponents(t)[axis] > mixed[axis];
    };
    std::array<int, 3> stride{0, 0, 0}, top{0, 0, 0};
    for (const CompiledTerm& t : terms_) {
        if (in_chain(t)) {
            const int axis = pure_power_axis(t), k = exponents(t)[axis];
            stride[axis] = std::gcd(stride[axis], k);
            top[axis] = std::max(top[axis], k);
        }
    }
    int chain_depth = 0;
    for (int axis = 0; axis < 3; ++axis) {
        if (top[axis] == 0) {
            continue;
        }
        Chain chain;
        chain.axis = axis;
        chain.stride = stride[axis];
        const auto length = static_cast<std::size_t>(top[axis] / stride[axis]) + 1;
        chain.high.assign(length, 0.0);
        chain.low.assign(length, 0.0);
        chain.magnitude.assign(length, 0.0);
        for (std::size_t i = 0; i < terms_.size(); ++i) {
            if (in_chain(terms_[i]) && pure_power_axis(terms_[i]) == axis) {
                const auto m = static_cast<std::size_t>(exponents(terms_[i])[axis] / chain.stride);
                chain.high[m] = terms_[i].coefficient;
                chain.low[m] = low_words_[i];
                chain.magnitude[m] = std::abs(terms_[i].coefficient);
            }
        }
        for (const double low : chain.low) {
            chains_exact_in_doubles_ = chains_exact_in_doubles_ && low == 0.0;
        }
        chains_.push_back(std::move(chain));
        // The term c·x^k, k = stride·m ≤ K = top: x^stride carries 2·stride − 1 roundings (the
        // point's, once per factor, and its multiplications), and m of those with m Horner
        // multiplications make 2k; the additions of steps m down to 0, at most K/stride + 1.
        chain_depth = std::max(chain_depth, 2 * top[axis] + top[axis] / stride[axis] + 1);
    }
    // The groups without the chains' terms: a chain's terms end their group (an x or y chain
    // term is alone in its (ex, ey); a z chain's are the highest powers of the group (0, 0)).
    std::size_t longest_group = 0;
    int line_degree = 0;
    for (const Group& g : groups_) {
        std::size_t end = g.begin;
        while (end < g.end && !in_chain(terms_[end])) {
            ++end;
        }
        for (std::size_t i = end; i < g.end; ++i) {
            LOCUS_ASSERT(in_chain(terms_[i]));
        }
        if (end == g.begin) {
            continue;
        }
        line_groups_.push_back({g.ex, g.ey, g.x_exponent, g.y_exponent, g.begin, end});
        longest_group = std::max(longest_group, end - g.begin);
        for (std::size_t i = g.begin; i < end; ++i) {
            const std::array<int, 3> e = exponents(terms_[i]);
            line_degree = std::max(line_degree, e[0] + e[1] + e[2]);
            for (int axis = 0; axis < 3; ++axis) {
                table_degree_[axis] = std::max(table_degree_[axis], e[axis]);
            }
        }
    }
    // Roundings any one term meets in enclose_on_line. A group's term: the point (1 per
    // factor) and the powers (1 per multiplication), at most 2·line_degree; c·z^ez, then ·y^ey
    // and ·x^ex; the sum within its group. A chain's term: chain_depth. Then the sum of the
    // groups' and the chains' values.
    const int group_depth =
        line_groups_.empty() ? 0 : 2 * line_degree + 3 + static_cast<int>(longest_group);
    double_double_depth_ =
        std::max(group_depth, chain_depth) + static_cast<int>(line_groups_.size() + chains_.size());
}

double CompiledPolynomial::with_underflow(double radius, double largest_power) const {
    const double multiplier = underflow_multiplier_ * std::max(1.0, largest_power) * 1.01;
    // Above 2^-800 the floor, multiplier·2^-1060 ≤ 1e75·2^-1060, is below the 0.1 % to spare
    // in the radius (the 1.001 of its factors) and needs no adding.
    if (radius >= 0x1.0p-800 && multiplier <= 1e75) {
        return radius;
    }
    return radius + std::ldexp(multiplier, -1060);
}

const std::string& CompiledPolynomial::equation() const {
    return exact_->equation;
}

namespace {
// powers[k + 1] = v^k for k ≤ degree, powers[0] = 0 (so that k·v^(k−1) reads powers[k] = 0·…
// safely for k = 0).
using PowerRow = std::array<double, kMaxCompiledDegree + 2>;
// The three coordinates' powers in one loop: three independent chains of multiplications
// overlap, where three loops one after the other waited for each chain in turn.
void fill_powers(PowerRow& xs, PowerRow& ys, PowerRow& zs, const Point3& p, int degree) {
    xs[0] = ys[0] = zs[0] = 0.0;
    xs[1] = ys[1] = zs[1] = 1.0;
    for (int k = 1; k <= degree; ++k) {
        xs[k + 1] = xs[k] * p[0];
        ys[k + 1] = ys[k] * p[1];
        zs[k + 1] = zs[k] * p[2];
    }
}
}  // namespace

double CompiledPolynomial::value(const Point3& p) const {
    PowerRow xs, ys, zs;
    fill_powers(xs, ys, zs, p, degree_);
    double sum = 0.0;
    for (const Group& g : groups_) {
        double in_z = 0.0;
        for (std::size_t i = g.begin; i < g.end; ++i) {
            in_z += coefficients_[i] * zs[z_exponents_[i] + 1];
        }
        sum += xs[g.ex + 1] * ys[g.ey + 1] * in_z;
    }
    return sum;
}

ValueGradient CompiledPolynomial::value_gradient(const Point3& p) const {
    PowerRow xs, ys, zs;
    fill_powers(xs, ys, zs, p, degree_);
    ValueGradient result{0.0, {0.0, 0.0, 0.0}};
    for (const Group& g : groups_) {
        double in_z = 0.0, in_z_derivative = 0.0;
        for (std::size_t i = g.begin; i < g.end; ++i) {
            in_z += coefficients_[i] * zs[z_exponents_[i] + 1];
            in_z_derivative += z_slopes_[i] * zs[z_exponents_[i]];
        }
        const double x = xs[g.ex + 1], y = ys[g.ey + 1];
        result.value += x * y * in_z;
        result.gradient[0] += g.x_exponent * xs[g.ex] * y * in_z;
        result.gradient[1] += g.y_exponent * x * ys[g.ey] * in_z;
        result.gradient[2] += x * y * in_z_derivative;
    }
    return result;
}

Point3 CompiledPolynomial::gradient(const Point3& p) const {
    PowerRow xs, ys, zs;
    fill_powers(xs, ys, zs, p, degree_);
    // Even and odd groups add into separate sums: with one running sum per component every
    // group waits for the previous one's additions. The data pointers are locals so that the
    // sums, kept in registers, are seen not to alias them.
    const double* coefficients = coefficients_.data();
    const double* slopes = z_slopes_.data();
    const int* z = z_exponents_.data();
    double even_x = 0.0, even_y = 0.0, even_z = 0.0, odd_x = 0.0, odd_y = 0.0, odd_z = 0.0;
    auto add_group = [&](const Group& g, double& sum_x, double& sum_y, double& sum_z) {
        double in_z = 0.0, in_z_derivative = 0.0;
        for (std::size_t i = g.begin; i < g.end; ++i) {
            in_z += coefficients[i] * zs[z[i] + 1];
            in_z_derivative += slopes[i] * zs[z[i]];
        }
        const double x = xs[g.ex + 1], y = ys[g.ey + 1];
        sum_x += g.x_exponent * xs[g.ex] * y * in_z;
        sum_y += g.y_exponent * x * ys[g.ey] * in_z;
        sum_z += x * y * in_z_derivative;
    };
    std::size_t k = 0;
    for (; k + 1 < groups_.size(); k += 2) {
        add_group(groups_[k], even_x, even_y, even_z);
        add_group(groups_[k + 1], odd_x, odd_y, odd_z);
    }
    if (k < groups_.size()) {
        add_group(groups_[k], even_x, even_y, even_z);
    }
    return {even_x + odd_x, even_y + odd_y, even_z + odd_z};
}

namespace {

// The powers 0..degree of a point's coordinates (in the evaluation's arithmetic) and of their
// magnitudes (in doubles, for the error bound), for enclose_on_line.
template <typename Value>
struct PowerTables {
    using Row = std::array<Value, kMaxCompiledDegree + 1>;
    using MagnitudeRow = std::array<double, kMaxCompiledDegree + 1>;
    Row xs, ys, zs;
    MagnitudeRow axs, ays, azs;
    // Powers to degree[axis] on each axis (the three chains side by side while all run).
    void fill(const std::array<Value, 3>& point, const std::array<double, 3>& magnitude,
              const Value& one, const std::array<int, 3>& degree) {
        xs[0] = ys[0] = zs[0] = one;
        axs[0] = ays[0] = azs[0] = 1.0;
        const int common = std::min({degree[0], degree[1], degree[2]});
        for (int k = 1; k <= common; ++k) {
            xs[k] = xs[k - 1] * point[0];
            ys[k] = ys[k - 1] * point[1];
            zs[k] = zs[k - 1] * point[2];
            axs[k] = axs[k - 1] * magnitude[0];
            ays[k] = ays[k - 1] * magnitude[1];
            azs[k] = azs[k - 1] * magnitude[2];
        }
        fill_axis(xs, axs, point[0], magnitude[0], common, degree[0]);
        fill_axis(ys, ays, point[1], magnitude[1], common, degree[1]);
        fill_axis(zs, azs, point[2], magnitude[2], common, degree[2]);
    }
    static void fill_axis(Row& values, MagnitudeRow& magnitudes, const Value& v, double magnitude,
                          int from, int to) {
        for (int k = from + 1; k <= to; ++k) {
            values[k] = values[k - 1] * v;
            magnitudes[k] = magnitudes[k - 1] * magnitude;
        }
    }
};

// The chains' values Σ c_m·X^m, X = v^stride, by Horner's rule, side by side (each step of
// one waits for the one before: three chains in one loop overlap, where one after the other
// waited for each in turn), and beside them the same sums of magnitudes (|c_m|·|X|^m in
// doubles, for the error bound). Returns the sum of the values and adds the magnitudes to
// `scale`; `coefficient(chain, m)` is c_m of a chain in the evaluation's arithmetic.
// Always inlined: enclose_on_line is compiled twice (with FMA and without, below), and a
// separate function would be compiled once, without, each fused multiply-add of the
// double-double products a call into libm.
template <typename Value, typename Chains, typename Coefficient>
[[gnu::always_inline]] inline Value evaluate_chains(const Chains& chains,
                                                    const Coefficient& coefficient,
                                                    const std::array<Value, 3>& point,
                                                    const std::array<double, 3>& magnitude,
                                                    double& scale) {
    std::array<Value, 3> power{}, value{};
    std::array<double, 3> power_magnitude{}, value_magnitude{};
    std::size_t longest = 0;
    for (std::size_t c = 0; c < chains.size(); ++c) {
        power[c] = point[chains[c].axis];
        power_magnitude[c] = magnitude[chains[c].axis];
        for (int s = 1; s < chains[c].stride; ++s) {
            power[c] = power[c] * point[chains[c].axis];
            power_magnitude[c] *= magnitude[chains[c].axis];
        }
        longest = std::max(longest, chains[c].magnitude.size());
    }
    for (std::size_t m = longest; m-- > 0;) {
        for (std::size_t c = 0; c < chains.size(); ++c) {
            if (m < chains[c].magnitude.size()) {
                value[c] = value[c] * power[c] + coefficient(chains[c], m);
                value_magnitude[c] =
                    value_magnitude[c] * power_magnitude[c] + chains[c].magnitude[m];
            }
        }
    }
    Value sum{};
    for (std::size_t c = 0; c < chains.size(); ++c) {
        sum = sum + value[c];
        scale += value_magnitude[c];
    }
    return sum;
}

// max(1, |x|, |y|, |z|)^degree (for with_underflow), by squaring: a dozen roundings at most,
// which the 1% it is given covers.
double largest_power(const std::array<double, 3>& magnitude, int degree) {
    const double base = std::max({1.0, magnitude[0], magnitude[1], magnitude[2]});
    double result = 1.0, square = base;
    for (int e = degree; e > 0; e >>= 1) {
        if (e & 1) {
            result *= square;
        }
        square *= square;
    }
    return result;
}

}  // namespace

// The double-double evaluation is a chain of fused multiply-adds (two_product); where the
// build's baseline processor has no FMA instruction each std::fma is a call into libm, which
// cost a degree-30 frame a sixth of its time. So the function is also compiled for processors
// with FMA and chosen when the program loads (the roundings are the same: -ffp-contract=off,
// and std::fma is exact-then-rounded either way). GCC only: clang 14 emits the clones of a
// member function without the symbol other files call (the fuzz build failed to link); and
// glibc only, whose dynamic loader resolves the choice (an ifunc).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__GLIBC__)
__attribute__((target_clones("fma", "default")))
#endif
ValueEnclosure
CompiledPolynomial::enclose_on_line(const Point3& origin, const Point3& direction, double t,
                                    Precision precision) const {
    if (precision == Precision::double_precision) {
        // The point rounded once (an FMA), the value in doubles beside Σ|terms| (the
        // magnitudes of the same products). Each term meets at most N = double_double_depth_
        // roundings — the point's, the powers', its products and the sums it enters — so the
        // value errs by at most γ_N·Σ|terms| (Higham, "Accuracy and Stability of Numerical
        // Algorithms", §3.1) and the coefficients' own rounding adds ρ·Σ|terms|. Σ|terms| is
        // itself rounded N + degree times at most: (1 + 4(N + degree)u) covers it. The factors
        // are the constructor's.
        std::array<double, 3> point, magnitude;
        for (int axis = 0; axis < 3; ++axis) {
            point[axis] = std::fma(t, direction[axis], origin[axis]);
            magnitude[axis] = std::abs(point[axis]);
        }
        PowerTables<double> powers;
        powers.fill(point, magnitude, 1.0, table_degree_);
        const auto& [xs, ys, zs, axs, ays, azs] = powers;
        double sum = 0.0, scale = 0.0;
        for (const Group& g : line_groups_) {
            double in_z = 0.0, scale_in_z = 0.0;
            for (std::size_t i = g.begin; i < g.end; ++i) {
                in_z += coefficients_[i] * zs[z_exponents_[i]];
                scale_in_z += std::abs(coefficients_[i]) * azs[z_exponents_[i]];
            }
            sum += xs[g.ex] * ys[g.ey] * in_z;
            scale += axs[g.ex] * ays[g.ey] * scale_in_z;
        }
        sum += evaluate_chains(
            chains_, [](const Chain& chain, std::size_t m) { return chain.high[m]; }, point,
            magnitude, scale);
        ValueEnclosure result;
        result.value = sum;
        result.radius =
            with_underflow(double_error_per_scale_ * scale, largest_power(magnitude, degree_));
        if (!std::isfinite(sum) || !std::isfinite(result.radius)) {
            result.radius = INFINITY;
        }
        return result;
    }
    // The point's coordinates o_i + t·d_i, each within kOperationError of exact (one accurate
    // double-double sum of exact parts), their magnitudes rounded up, and the power tables of
    // both: the values in double-double, the magnitudes in double for the error bound.
    std::array<DoubleDouble, 3> point;
    std::array<double, 3> magnitude;
    for (int axis = 0; axis < 3; ++axis) {
        point[axis] = from_double(origin[axis]) + two_product(t, direction[axis]);
        magnitude[axis] = std::abs(point[axis].hi) * (1.0 + 0x1.0p-51);
    }
    PowerTables<DoubleDouble> powers;
    powers.fill(point, magnitude, from_double(1.0), table_degree_);
    const auto& [xs, ys, zs, axs, ays, azs] = powers;
    DoubleDouble sum;
    double scale = 0.0;  // Σ |c̃|·|x|^a|y|^b|z|^c, up to the rounding of its own evaluation
    for (const Group& g : line_groups_) {
        DoubleDouble in_z;
        double scale_in_z = 0.0;
        for (std::size_t i = g.begin; i < g.end; ++i) {
            in_z = in_z + DoubleDouble{coefficients_[i], low_words_[i]} * zs[z_exponents_[i]];
            scale_in_z += std::abs(coefficients_[i]) * azs[z_exponents_[i]];
        }
        sum = sum + xs[g.ex] * ys[g.ey] * in_z;
        scale += axs[g.ex] * ays[g.ey] * scale_in_z;
    }
    // Coefficients that are doubles (integers, Chmutov's) are added as doubles: the cheaper
    // sum of a double-double and a double, within the same kOperationError.
    sum = sum + (chains_exact_in_doubles_
                     ? evaluate_chains(
                           chains_, [](const Chain& chain, std::size_t m) { return chain.high[m]; },
                           point, magnitude, scale)
                     : evaluate_chains(
                           chains_,
                           [](const Chain& chain, std::size_t m) {
                               return DoubleDouble{chain.high[m], chain.low[m]};
                           },
                           point, magnitude, scale));
    // Each term carries at most N = double_double_depth_ factors (1 + θ) with |θ| ≤
    // kOperationError, so the evaluation errs by at most γ_N·Σ|terms| with
    // γ_N = N·v/(1 − N·v); the coefficients' own rounding adds their relative error times the
    // same sum. The magnitudes were evaluated in doubles with at most N + degree roundings;
    // (1 + 4(N + degree)u) covers them, and the last term covers underflow (each operation may
    // lose 2^-1074 when its result is subnormal).
    const double n = double_double_depth_;
    const double gamma = n * kOperationError / (1.0 - n * kOperationError);
    const double bound_of_scale = scale * (1.0 + 4.0 * (n + degree_) * 0x1.0p-53);
    ValueEnclosure result;
    result.value = sum.hi;
    result.value_low = sum.lo;
    result.radius =
        with_underflow((gamma + double_double_coefficient_error_) * bound_of_scale * 1.001,
                       largest_power(magnitude, degree_));
    if (!std::isfinite(sum.hi) || !std::isfinite(sum.lo) || !std::isfinite(result.radius)) {
        result.radius = INFINITY;
    }
    return result;
}

CompiledPolynomial compile_surface(std::string_view equation) {
    return compile_surface(parse_polynomial(equation, xyz_ring()));
}

CompiledPolynomial compile_surface(const Polynomial& f) {
    const RingPtr& ring = xyz_ring();
    std::vector<std::size_t> variable_map;
    for (const std::string& name : f.ring()->variable_names()) {
        const auto index = ring->variable_index(name);
        if (!index) {
            throw InputError("variable " + name,
                             "a surface equation may only use the variables x, y, z");
        }
        variable_map.push_back(*index);
    }
    const Polynomial g = f.in_ring(ring, variable_map);
    if (g.is_zero()) {
        throw InputError("equation", "the zero polynomial defines no surface");
    }
    if (g.is_constant()) {
        throw InputError("equation", "a non-zero constant defines no surface");
    }
    // The square-free part has a positive leading coefficient; it takes g's sign, so that the
    // sides f > 0 and f < 0 (a two-sided material's colours, an SDF leaf's inside) stay those
    // of the equation as written: 1 − x² − y² − z² is positive inside the ball. (Where g has a
    // repeated factor the signs agree wherever that factor is positive: a square does not
    // change sign across its surface, and the surface of a square-free part does.)
    Polynomial reduced = square_free_part(g);
    if (g.leading_coefficient().sign() < 0) {
        reduced = -reduced;
    }
    if (reduced.total_degree() > kMaxCompiledDegree) {
        throw InputError("equation", "degree " + std::to_string(reduced.total_degree()) +
                                         " exceeds the supported maximum " +
                                         std::to_string(kMaxCompiledDegree));
    }
    const bool made_square_free = reduced.total_degree() < g.total_degree();
    return CompiledPolynomial(std::make_shared<const CompiledPolynomial::Exact>(std::move(reduced)),
                              made_square_free);
}

ExactRoot exact_first_root(const CompiledPolynomial& f, const Point3& origin,
                           const Point3& direction, double lo, double hi, bool lo_open) {
    release_flint_caches_at_thread_exit();  // the renderer's workers come here
    // F(t) = f(o + t·d) up to a positive factor, in integers (exact_line_restriction.h).
    detail::FmpzPoly restriction, derivative, common;
    f.exact_->on_line.restrict(origin, direction, restriction.p);
    ExactRoot result;
    if (fmpz_poly_is_zero(restriction.p)) {
        result.status = ExactRoot::Status::identically_zero;
        result.t = lo;
    } else {
        // Square-free part F / gcd(F, F'): every distinct root, whatever its multiplicity.
        fmpz_poly_derivative(derivative.p, restriction.p);
        fmpz_poly_gcd(common.p, restriction.p, derivative.p);
        fmpz_poly_div(restriction.p, restriction.p, common.p);
        Rational lo_exact, hi_exact;
        set_exact_double(lo_exact.get(), lo);
        set_exact_double(hi_exact.get(), hi);
        const std::optional<double> root =
            first_real_root(restriction.p, lo_exact.get(), hi_exact.get(), lo_open);
        if (root) {
            result.status = ExactRoot::Status::hit;
            result.t = *root;
        }
    }
    return result;
}

}  // namespace locus::algebra
