#include "render/bernstein_ball.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <vector>

#include "render/detail/fixed_degree.h"

namespace locus::render {

namespace {

constexpr double kUnit = 0x1.0p-53;

// γ_k = k·u/(1 − k·u), the bound on k roundings (a constant where k is).
constexpr double gamma(int k) {
    return k * kUnit / (1.0 - k * kUnit);
}

// What a subnormal result may lose per rounding, summed over every rounding of a kernel below
// (at most 3·41² of them): covers underflow, which the relative bounds do not.
constexpr double kUnderflow = 0x1.0p-1040;

// Binomial coefficients C(n, k) for n ≤ kMaxDegree: exact in 64-bit integers (C(64, 32) < 2^61),
// and as doubles rounded once from them (exact up to C(56, 28) < 2^53).
// Computed at compile time: built at the first frame, the table's 67 KB were 16 page faults
// of fresh memory (about 11 µs each here); in the executable they are read-only data.
struct Binomials {
    std::array<std::array<long long, kMaxDegree + 1>, kMaxDegree + 1> exact{};
    std::array<std::array<double, kMaxDegree + 1>, kMaxDegree + 1> c{};
    constexpr Binomials() {
        for (int n = 0; n <= kMaxDegree; ++n) {
            exact[n][0] = exact[n][n] = 1;
            for (int k = 1; k < n; ++k) {
                exact[n][k] = exact[n - 1][k - 1] + exact[n - 1][k];
            }
            for (int k = 0; k <= n; ++k) {
                c[n][k] = static_cast<double>(exact[n][k]);
            }
        }
    }
};
constexpr Binomials kBinomials;
const Binomials& binomials() {
    return kBinomials;
}

// β[n][i][k]: Bernstein coefficient i (degree n, on [−1, 1]) of x^k, i.e. x^k =
// Σ_i β_ik·C(n, i)·((1 − x)/2)^(n − i)·((1 + x)/2)^i, for n ≤ kMaxDegree:
//     β_ik = Σ_j C(i, j)·C(n − i, k − j)·(−1)^(k − j) / C(n, k),
// the sum exact in 128-bit integers (its terms' magnitudes sum to C(n, k) < 2^61, Vandermonde)
// and the quotient rounded once in long double, then to double. Every |β_ik| ≤ 1 (x^k lies in
// [−1, 1]), so converting a ball does not magnify its radii.
__extension__ using Int128 = __int128;  // GCC's 128-bit integers (not ISO C++)

// One degree's weights. Only the first half of the rows is kept: B_i(−x) = B_{n−i}(x), so
// β_{n−i,k} = (−1)^k·β_ik, and to_bernstein forms coefficients i and n − i together from the
// even and odd columns.
struct CenteredWeights {
    // [k·(n/2 + 1) + i] for i ≤ n/2: by column (k), so that to_bernstein adds a coefficient's
    // column to every output in one contiguous loop; and their magnitudes, for the radii.
    std::vector<double> weights, magnitudes;
    explicit CenteredWeights(int n) {
        const auto& c = binomials().exact;
        const int half = n / 2;
        weights.assign(static_cast<std::size_t>((n + 1) * (half + 1)), 0.0);
        magnitudes.assign(weights.size(), 0.0);
        for (int i = 0; i <= half; ++i) {
            for (int k = 0; k <= n; ++k) {
                Int128 sum = 0;
                for (int j = std::max(0, k - (n - i)); j <= std::min(i, k); ++j) {
                    const Int128 term = static_cast<Int128>(c[i][j]) * c[n - i][k - j];
                    sum += (k - j) % 2 == 0 ? term : -term;
                }
                const auto at = static_cast<std::size_t>(k * (half + 1) + i);
                weights[at] = static_cast<double>(static_cast<long double>(sum) /
                                                  static_cast<long double>(c[n][k]));
                magnitudes[at] = std::abs(weights[at]);
            }
        }
    }
};

// Built for a degree when a ball of that degree is first converted (a render needs one or two
// degrees; all 65 took 1 % of a whole `locus render` of a sphere), once per process.
const CenteredWeights& centered_weights(int n) {
    static std::array<std::once_flag, kMaxDegree + 1> built;
    static std::array<std::unique_ptr<CenteredWeights>, kMaxDegree + 1> tables;
    const auto at = static_cast<std::size_t>(n);
    std::call_once(built[at], [&] { tables[at] = std::make_unique<CenteredWeights>(n); });
    return *tables[at];
}

}  // namespace

namespace {

// For i ≤ n/2: even[i] += Σ_{k even} β_ik·c_k, odd[i] += Σ_{k odd} β_ik·c_k and
// radii[i] += Σ_k |β_ik|·e_k, column by column: the inner loops run over the outputs, which
// vector operations do several at a time (a dot product per output would be a chain of
// dependent additions). AVX2 where the processor has it: a target clone, GCC only.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__GLIBC__)
__attribute__((target_clones("avx2", "default")))
#endif
void add_columns(int n, const double* weights, const double* magnitudes, const double* values,
                 const double* errors, double* even, double* odd, double* radii) {
    const auto size = static_cast<std::size_t>(n + 1);
    const auto rows = static_cast<std::size_t>(n / 2 + 1);
    for (std::size_t k = 0; k < size; ++k) {
        const double c = values[k], e = errors[k];
        const double* column = weights + k * rows;
        const double* column_magnitude = magnitudes + k * rows;
        double* target = k % 2 == 0 ? even : odd;
        for (std::size_t i = 0; i < rows; ++i) {
            target[i] += column[i] * c;
            radii[i] += column_magnitude[i] * e;
        }
    }
}

}  // namespace

BernsteinBall to_bernstein(const RestrictionBall& g) {
    BernsteinBall out;
    const int n = g.polynomial.degree;
    out.degree = n;
    if (n < 0) {
        return out;
    }
    const CenteredWeights& weights = centered_weights(n);
    // Every term meets at most n + 5 roundings: the weight's (and the long double quotient's),
    // the product, the running sum (in any order), and the even and odd parts' sum.
    const double rounding = gamma(n + 5);
    std::array<double, kMaxDegree + 1> errors{};
    for (int k = 0; k <= n; ++k) {
        errors[k] = g.radius[k] + rounding * std::abs(g.polynomial.c[k]);
    }
    const int half = n / 2;
    std::array<double, kMaxDegree / 2 + 1> even{}, odd{}, radii{};
    add_columns(n, weights.weights.data(), weights.magnitudes.data(), g.polynomial.c.data(),
                errors.data(), even.data(), odd.data(), radii.data());
    for (int i = 0; i <= half; ++i) {
        const double radius = radii[i] * (1.0 + 2.0 * rounding) + kUnderflow;
        // b_{n−i} = Σ_k (−1)^k β_ik c_k; at i = n/2 (n even) the odd part is 0 exactly.
        out.b[i] = even[i] + odd[i];
        out.b[n - i] = even[i] - odd[i];
        out.r[i] = out.r[n - i] = radius;
    }
    return out;
}

namespace {

// A coefficient and its radius, which de Casteljau's scheme combines with the same weights: one
// SSE2 operation does both (GCC's vector extension, also understood by Clang).
using ValueRadius = double __attribute__((vector_size(16)));

// The largest |b_i|: every entry of de Casteljau's triangle is a convex combination of the b_i
// (up to the roundings of the weights), so its rounding is bounded by γ·(this), which spares
// the scheme a third triangle of magnitudes.
double largest_magnitude(const BernsteinBall& g) {
    double largest = 0.0;
    for (int i = 0; i <= g.degree; ++i) {
        largest = std::max(largest, std::abs(g.b[i]));
    }
    return largest;
}

}  // namespace

namespace {

// Every entry is reached by at most one rounding per level at τ = 1/2 (the halving is exact)
// and three otherwise (the weight 1 − τ, the products, the sum), each at most u times an entry
// no larger than (1 + u)^(3·level)·max|b_i|; the radii, all positive, are rounded as often. A
// piece's radius is its computed radius widened by that, as it is written.
class PieceRadius {
  public:
    PieceRadius(int n, double tau, double largest) {
        const double rounding = gamma(tau == 0.5 ? n + 1 : 3 * n + 3);
        widen_ = 1.0 + 2.0 * rounding;
        value_error_ = rounding * largest * widen_;
    }
    double operator()(double r) const { return (r + value_error_) * widen_ + kUnderflow; }

  private:
    double value_error_ = 0.0, widen_ = 1.0;
};

// De Casteljau's triangle row by row: the left piece takes each row's first entry, the right
// piece each row's last (in reverse order). For a degree known at compile time (`Fixed` ≥ 0)
// the loops unroll and the row stays in registers — the subdivisions of the certified tracer
// are most of a frame at degree ≤ 12; `Fixed` = −1 takes the degree from the ball.
// Everything is read from `whole` before anything is written: the outputs may alias it.
template <int Fixed>
void de_casteljau(const BernsteinBall& whole, double tau, BernsteinBall& left,
                  BernsteinBall& right) {
    const int n = Fixed >= 0 ? Fixed : whole.degree;
    std::array<ValueRadius, (Fixed >= 0 ? Fixed : kMaxDegree) + 1> p;
    double largest = 0.0;
#pragma GCC unroll 16
    for (int i = 0; i <= n; ++i) {
        p[i] = ValueRadius{whole.b[i], whole.r[i]};
        largest = std::max(largest, std::abs(whole.b[i]));
    }
    const PieceRadius radius(n, tau, largest);
    left.degree = right.degree = n;
    left.b[0] = p[0][0];
    left.r[0] = radius(p[0][1]);
    right.b[n] = p[n][0];
    right.r[n] = radius(p[n][1]);
    // At τ = 1/2 both weights are 1/2 and the products exact: one rounding per level.
    const double keep = 1.0 - tau;
    const ValueRadius weight_keep = {keep, keep}, weight_tau = {tau, tau};
#pragma GCC unroll 16
    for (int level = 1; level <= n; ++level) {
#pragma GCC unroll 16
        for (int i = 0; i <= n - level; ++i) {
            p[i] = weight_keep * p[i] + weight_tau * p[i + 1];
        }
        left.b[level] = p[0][0];
        left.r[level] = radius(p[0][1]);
        right.b[n - level] = p[n - level][0];
        right.r[n - level] = radius(p[n - level][1]);
    }
}

// A safe limit for de_casteljau_half's sums: entries below it stay below 2^950·2^64·(1 + u)^64
// < 2^1024 at degree 64. Balls with larger entries take the weighted scheme, whose entries never
// grow.
constexpr double kHalvingLimit = 0x1.0p950;

// De Casteljau at τ = 1/2 without the halvings: the row's sums p_i + p_{i+1} are 2^level times
// the weighted scheme's entries and round exactly as they do (scaling by a power of two commutes
// with rounding), so each piece's coefficient is the sum times 2^−level, the same double as
// before — one addition per entry where the weights cost two multiplications and an addition,
// and one multiplication per coefficient — and each radius is widened as it is written (as
// the τ-weighted scheme does: the same doubles). Halving is the isolation's every
// split. Returns false, having written nothing, when an entry reaches kHalvingLimit.
template <int Fixed>
bool de_casteljau_half(const BernsteinBall& whole, BernsteinBall& left, BernsteinBall& right) {
    const int n = Fixed >= 0 ? Fixed : whole.degree;
    std::array<ValueRadius, (Fixed >= 0 ? Fixed : kMaxDegree) + 1> p;
    ValueRadius largest = {0.0, 0.0};  // max|b_i|, max r_i
#pragma GCC unroll 16
    for (int i = 0; i <= n; ++i) {
        p[i] = ValueRadius{whole.b[i], whole.r[i]};
        const ValueRadius magnitude = {std::abs(whole.b[i]), whole.r[i]};
        largest = magnitude > largest ? magnitude : largest;
    }
    if (!(largest[0] < kHalvingLimit && largest[1] < kHalvingLimit)) {
        return false;
    }
    const PieceRadius radius(n, 0.5, largest[0]);
    left.degree = right.degree = n;
    left.b[0] = p[0][0];
    left.r[0] = radius(p[0][1]);
    right.b[n] = p[n][0];
    right.r[n] = radius(p[n][1]);
    double scale = 1.0;
#pragma GCC unroll 16
    for (int level = 1; level <= n; ++level) {
#pragma GCC unroll 16
        for (int i = 0; i <= n - level; ++i) {
            p[i] = p[i] + p[i + 1];
        }
        scale *= 0.5;  // exact down to 2^−64
        const ValueRadius to_piece = {scale, scale};
        const ValueRadius first = p[0] * to_piece, last = p[n - level] * to_piece;
        left.b[level] = first[0];
        left.r[level] = radius(first[1]);
        right.b[n - level] = last[0];
        right.r[n - level] = radius(last[1]);
    }
    return true;
}

}  // namespace

void split_half(const BernsteinBall& whole, BernsteinBall& left, BernsteinBall& right) {
    const bool done = whole.degree >= 0 && detail::with_fixed_degree(whole.degree, [&](auto fixed) {
                          return de_casteljau_half<decltype(fixed)::value>(whole, left, right);
                      });
    if (!done) {
        split_at(whole, 0.5, left,
                 right);  // the zero polynomial, or entries the sums would overflow
    }
}

void split_at(const BernsteinBall& whole, double tau, BernsteinBall& left, BernsteinBall& right) {
    if (whole.degree < 0) {
        left.degree = right.degree = whole.degree;
        return;
    }
    detail::with_fixed_degree(whole.degree, [&](auto fixed) {
        de_casteljau<decltype(fixed)::value>(whole, tau, left, right);
    });
}

BallValue evaluate(const BernsteinBall& g, double sigma) {
    BallValue out;
    const int n = g.degree;
    if (n < 0) {
        return out;
    }
    const double keep = 1.0 - sigma;
    std::array<ValueRadius, kMaxDegree + 1> p;
    for (int i = 0; i <= n; ++i) {
        p[i] = ValueRadius{g.b[i], g.r[i]};
    }
    const ValueRadius weight_keep = {keep, keep}, weight_sigma = {sigma, sigma};
    for (int level = 1; level <= n; ++level) {
        for (int i = 0; i <= n - level; ++i) {
            p[i] = weight_keep * p[i] + weight_sigma * p[i + 1];
        }
    }
    const double rounding = gamma(3 * n + 3);
    const double widen = 1.0 + 2.0 * rounding;
    out.value = p[0][0];
    out.radius = (p[0][1] + rounding * largest_magnitude(g) * widen) * widen + kUnderflow;
    if (!std::isfinite(out.value) || !std::isfinite(out.radius)) {
        out.radius = INFINITY;
    }
    return out;
}

MidpointPolynomial::MidpointPolynomial(const BernsteinBall& g) : degree_(g.degree) {
    const int n = degree_;
    // The largest |b_i| and r_i; a coefficient or radius that is not finite (std::max would
    // skip a NaN) makes the radius infinite below.
    double largest = 0.0, radius = 0.0;
    bool finite = true;
    for (int i = 0; i <= n; ++i) {
        finite = finite && std::isfinite(g.b[i]) && std::isfinite(g.r[i]);
        largest = std::max(largest, std::abs(g.b[i]));
        radius = std::max(radius, g.r[i]);
    }
    // at() forms each term b_i·C(n, i)·σ^i·s^(n−i) (s = fl(1 − σ) = (1 − σ)(1 + δ)) in at most
    // 2n + 3 roundings: the binomial past 2^53 and the product with it, δ once for each of the
    // n − i factors s, the n − i − 1 products of the power (the first, 1·s, is exact), the
    // product with the weight, the i products by σ and the i + 1 sums. Against the exact
    // weights, which sum to one, the value is within γ_{2n+3}·Σ|b_i|·B_i(σ) ≤ γ_{3n+8}·max|b_i|
    // of the midpoint polynomial's (γ_{3n+8}: room to spare). A product that underflows loses at
    // most 2^-1075 absolute: in the powers, times a weight below 2^62·max|b_i|, over the terms
    // about 2^-1005·max|b_i|, which 2^-990·max|b_i| covers; elsewhere kUnderflow.
    const double rounding = gamma(3 * n + 8);
    radius_ = (radius + rounding * largest * (1.0 + 2.0 * rounding) + 0x1.0p-990 * largest) *
                  (1.0 + 2.0 * rounding) +
              kUnderflow;
    if (!finite || !std::isfinite(radius_)) {
        radius_ = INFINITY;
    }
    if (n <= 0) {
        value_[0] = n == 0 ? g.b[0] : 0.0;
        return;
    }
    const auto& c = binomials().c;
    for (int i = 0; i <= n; ++i) {
        value_[i] = g.b[i] * c[n][i];
    }
    for (int i = 0; i < n; ++i) {
        slope_[i] = (g.b[i + 1] - g.b[i]) * c[n - 1][i];
    }
}

ValueSlope MidpointPolynomial::at(double sigma) const {
    const int n = degree_;
    ValueSlope out;
    if (n <= 0) {
        out.value = value_[0];
        return out;
    }
    // Σ w_i σ^i (1 − σ)^(n − i) by Horner in σ with the powers of 1 − σ formed on the way
    // (((w_n σ + w_{n−1} s) σ + w_{n−2} s²) σ + …, s = 1 − σ): no division and no branch, and
    // every weight positive. The derivative n·Σ (b_{i+1} − b_i) C(n − 1, i) σ^i s^(n − 1 − i)
    // the same way.
    // Both in one loop: the value's step i and the slope's step i − 1 take the same power
    // s^(n−i), each formed as before (the same roundings, so the same results).
    const double s = 1.0 - sigma;
    double value = value_[n], slope = slope_[n - 1], power = 1.0;
    for (int i = n - 1; i >= 1; --i) {
        power *= s;
        value = value * sigma + value_[i] * power;
        slope = slope * sigma + slope_[i - 1] * power;
    }
    power *= s;
    value = value * sigma + value_[0] * power;
    out.value = value;
    out.slope = n * slope;
    return out;
}

BallValue MidpointPolynomial::enclose(double sigma) const {
    const int n = degree_;
    BallValue out;
    out.radius = radius_;
    if (n < 0) {
        out.radius = 0.0;  // the zero polynomial
        return out;
    }
    if (n == 0) {
        out.value = value_[0];
        return out;
    }
    // at()'s value alone, in the same operations.
    const double s = 1.0 - sigma;
    double value = value_[n], power = 1.0;
    for (int i = n - 1; i >= 0; --i) {
        power *= s;
        value = value * sigma + value_[i] * power;
    }
    out.value = value;
    if (!std::isfinite(value) || !(sigma >= 0.0 && sigma <= 1.0)) {
        out.radius = INFINITY;
    }
    return out;
}

SlopeBounds slope_bounds(const BernsteinBall& g) {
    SlopeBounds out;
    const int n = g.degree;
    if (n < 1) {
        out.hull_lo = out.hull_hi = out.point_error = out.curvature = 0.0;
        return out;
    }
    // Each first difference fl(b_{i+1} − b_i) is within u of its exact value, and the exact
    // coefficients' differences within r_i + r_{i+1} of that.
    double hull_lo = INFINITY, hull_hi = -INFINITY, largest_difference = 0.0, radii = 0.0;
    for (int i = 0; i < n; ++i) {
        const double difference = g.b[i + 1] - g.b[i];
        const double blur =
            (g.r[i] + g.r[i + 1] + 2.0 * kUnit * std::abs(difference)) * (1.0 + 4.0 * kUnit) +
            kUnderflow;
        hull_lo = std::min(hull_lo, difference - blur);
        hull_hi = std::max(hull_hi, difference + blur);
        largest_difference = std::max(largest_difference, std::abs(difference));
        radii = std::max(radii, g.r[i] + g.r[i + 1]);
    }
    // n·x and the subtractions above round once more each: 4u of the result covers both.
    const double widen = 1.0 + gamma(8);
    const auto down = [&](double x) {
        return n * x - std::abs(n * x) * (widen - 1.0) - kUnderflow;
    };
    const auto up = [&](double x) { return n * x + std::abs(n * x) * (widen - 1.0) + kUnderflow; };
    out.hull_lo = down(hull_lo);
    out.hull_hi = up(hull_hi);
    // MidpointPolynomial::at sums (b_{i+1} − b_i)·C(n − 1, i)·σ^i·s^(n−1−i), s = fl(1 − σ): every
    // term meets at most 3n + 5 roundings (the difference, the binomial's own past 2^53, the
    // weight, the n − 1 − i products of s and s's own rounding, i products by σ and i + 1 sums,
    // the final n·), so the slope is within γ_{3n+5}·n·Σ|b_{i+1} − b_i|·B_{i,n−1}(σ) ≤
    // γ_{3n+5}·n·max|b_{i+1} − b_i| of the
    // midpoint polynomial's (the B_{i,n−1} ≥ 0 sum to 1), which is within n·max(r_i + r_{i+1})
    // of the exact one's.
    out.point_error = n * (radii + gamma(4 * n + 8) * largest_difference) * widen + kUnderflow;
    if (n < 2) {
        out.curvature = 0.0;
    } else {
        double curvature = 0.0;
        for (int i = 0; i + 2 <= n; ++i) {
            const double second = g.b[i + 2] - 2.0 * g.b[i + 1] + g.b[i];
            const double magnitude =
                std::abs(g.b[i + 2]) + 2.0 * std::abs(g.b[i + 1]) + std::abs(g.b[i]);
            curvature = std::max(curvature, std::abs(second) + g.r[i] + 2.0 * g.r[i + 1] +
                                                g.r[i + 2] + gamma(3) * magnitude);
        }
        out.curvature = static_cast<double>(n) * (n - 1) * curvature * widen + kUnderflow;
    }
    if (!std::isfinite(out.hull_lo) || !std::isfinite(out.hull_hi) ||
        !std::isfinite(out.point_error) || !std::isfinite(out.curvature)) {
        out = SlopeBounds{};
    }
    return out;
}

}  // namespace locus::render
