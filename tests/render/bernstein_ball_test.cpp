// Bernstein balls against exact rational arithmetic (and brute force) that share no code with
// them: de Casteljau's splits, the midpoint polynomial, Descartes' bound under uncertainty, the
// conversion from the power basis (to_bernstein), and the mean-value step of the certified
// tracer (slope_bounds, mean_value_bracket). A ball's exact polynomial is a random choice
// inside every radius; its coefficients, values and slopes are computed over Q by another
// route, and a bracket holds the root exactly when the exact signs at its ends say so. The
// balls are not tuned to the method: degrees up to 64, coefficients over twelve orders of
// magnitude, monotone and non-monotone pieces, points near and far from the root, points
// known only up to a blur, values known only up to an error.
#include <gtest/gtest.h>

#include <flint/fmpq.h>
#include <flint/fmpz.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "algebra/rational.h"
#include "render/bernstein_ball.h"
#include "render/certified_isolation.h"
#include "tests/support/test_data.h"

namespace locus::render {
namespace {

using algebra::Rational;

// The exact value of a finite double.
Rational exact(double v) {
    Rational out;
    int exponent = 0;
    const double mantissa = std::frexp(v, &exponent);
    fmpz_set_d(fmpq_numref(out.get()), std::ldexp(mantissa, 53));
    fmpz_one(fmpq_denref(out.get()));
    if (exponent >= 53) {
        fmpq_mul_2exp(out.get(), out.get(), static_cast<ulong>(exponent - 53));
    } else {
        fmpq_div_2exp(out.get(), out.get(), static_cast<ulong>(53 - exponent));
    }
    return out;
}

// Σ c_i·C(m, i)·σ^i·(1 − σ)^(m − i), exactly.
Rational bernstein_sum(const std::vector<Rational>& c, const Rational& sigma) {
    const auto m = static_cast<ulong>(c.size() - 1);
    Rational keep(1), sum, term, power_sigma(1), binomial;
    fmpq_sub(keep.get(), keep.get(), sigma.get());
    std::vector<Rational> power_keep(c.size());
    fmpq_one(power_keep[0].get());
    for (std::size_t i = 1; i < c.size(); ++i) {
        fmpq_mul(power_keep[i].get(), power_keep[i - 1].get(), keep.get());
    }
    fmpz_t choose;
    fmpz_init(choose);
    for (ulong i = 0; i <= m; ++i) {
        fmpz_bin_uiui(choose, m, i);
        fmpq_mul(term.get(), c[i].get(), power_sigma.get());
        fmpq_mul(term.get(), term.get(), power_keep[m - i].get());
        fmpq_mul_fmpz(term.get(), term.get(), choose);
        fmpq_add(sum.get(), sum.get(), term.get());
        fmpq_mul(power_sigma.get(), power_sigma.get(), sigma.get());
    }
    fmpz_clear(choose);
    return sum;
}

// An exact polynomial inside a ball: its Bernstein coefficients, and those of its derivative.
struct ExactPiece {
    std::vector<Rational> value;
    std::vector<Rational> slope;  // n·(β_{i+1} − β_i)
};

ExactPiece exact_inside(const BernsteinBall& g, std::mt19937_64& random) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    ExactPiece piece;
    const int n = g.degree;
    for (int i = 0; i <= n; ++i) {
        // A point of [b − r, b + r]: r·x rounds to at most r in magnitude; the ends themselves
        // now and then.
        const double x = random() % 8 == 0 ? (random() % 2 == 0 ? 1.0 : -1.0) : unit(random);
        Rational beta = exact(g.b[i]), offset = exact(g.r[i] * x);
        fmpq_add(beta.get(), beta.get(), offset.get());
        piece.value.push_back(beta);
    }
    for (int i = 0; i < n; ++i) {
        Rational d;
        fmpq_sub(d.get(), piece.value[i + 1].get(), piece.value[i].get());
        fmpq_mul_si(d.get(), d.get(), n);
        piece.slope.push_back(d);
    }
    return piece;
}

bool at_most(const Rational& a, double bound) {
    return fmpq_cmp(a.get(), exact(bound).get()) <= 0;
}

Rational absolute_difference(const Rational& a, const Rational& b) {
    Rational d;
    fmpq_sub(d.get(), a.get(), b.get());
    fmpq_abs(d.get(), d.get());
    return d;
}

// A random ball of degree n: coefficients of random signs (or one sign change, for a single
// root) over magnitudes 10^±6, radii 0 or up to 10^-3 of the coefficient.
BernsteinBall random_ball(int n, std::mt19937_64& random, bool one_root) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0), fraction(0.0, 1.0);
    BernsteinBall g;
    g.degree = n;
    const int change = one_root ? 1 + static_cast<int>(random() % static_cast<unsigned>(n)) : 0;
    const double first_sign = random() % 2 == 0 ? 1.0 : -1.0;
    const double spread = random() % 3 == 0 ? 6.0 : 1.0;
    for (int i = 0; i <= n; ++i) {
        const double magnitude = std::pow(10.0, spread * unit(random));
        g.b[i] = one_root ? (i < change ? first_sign : -first_sign) * magnitude *
                                (0.5 + fraction(random))
                          : unit(random) * magnitude;
        // Radii below half the coefficient keep every exact coefficient's sign (one root).
        g.r[i] = random() % 3 == 0
                     ? 0.0
                     : std::abs(g.b[i]) * std::pow(10.0, -3.0 - 12.0 * fraction(random));
    }
    return g;
}

// De Casteljau may write a piece over the ball it splits (the isolation's stack relies on it).
TEST(BernsteinSplit, MayWriteOverItsInput) {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        BernsteinBall whole;
        whole.degree = trial % 24;  // the unrolled kernels (1–12) and the generic one
        for (int i = 0; i <= whole.degree; ++i) {
            whole.b[i] = unit(random) * std::pow(10.0, 3.0 * unit(random));
            whole.r[i] = std::abs(whole.b[i]) * 1e-12 * (1.0 + unit(random));
        }
        const double tau = trial % 3 == 0 ? 0.5 : 0.5 + 0.49 * unit(random);
        BernsteinBall left, right;
        split_at(whole, tau, left, right);
        BernsteinBall over_left = whole, over_right = whole;
        BernsteinBall other_left, other_right;
        split_at(over_left, tau, over_left, other_right);
        split_at(over_right, tau, other_left, over_right);
        for (int i = 0; i <= whole.degree; ++i) {
            EXPECT_EQ(over_left.b[i], left.b[i]);
            EXPECT_EQ(over_left.r[i], left.r[i]);
            EXPECT_EQ(over_right.b[i], right.b[i]);
            EXPECT_EQ(over_right.r[i], right.r[i]);
        }
    }
}

// The radii of de Casteljau's scheme against the scheme in exact rationals (FLINT), shares no
// code with it: every computed coefficient of both pieces, and every value, within its radius
// of the exact one — at degrees up to 64, cuts on both sides of 1/2, coefficients of mixed
// magnitudes.
TEST(BernsteinSplit, RadiiHoldAgainstExactArithmetic) {
    std::mt19937_64 random(17);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), fraction(0.0, 1.0);
    const auto within = [&](const algebra::Rational& truth, double value, double radius) {
        return at_most(absolute_difference(truth, exact(value)), radius);
    };
    for (int trial = 0; trial < 195; ++trial) {
        BernsteinBall whole;
        whole.degree = trial % 65;
        const int n = whole.degree;
        for (int i = 0; i <= n; ++i) {
            whole.b[i] = unit(random) * std::pow(10.0, 6.0 * unit(random));
            whole.r[i] = 0.0;
        }
        const double tau = trial % 4 == 0 ? 0.5 : fraction(random) * 0.98 + 0.01;
        BernsteinBall left, right;
        split_at(whole, tau, left, right);
        // Exact de Casteljau with the double τ read exactly.
        std::vector<algebra::Rational> row(static_cast<std::size_t>(n + 1));
        algebra::Rational t = exact(tau), keep(1), a, b;
        fmpq_sub(keep.get(), keep.get(), t.get());
        for (int i = 0; i <= n; ++i) {
            row[static_cast<std::size_t>(i)] = exact(whole.b[i]);
        }
        EXPECT_TRUE(within(row[0], left.b[0], left.r[0]));
        EXPECT_TRUE(within(row[static_cast<std::size_t>(n)], right.b[n], right.r[n]));
        for (int level = 1; level <= n; ++level) {
            for (int i = 0; i <= n - level; ++i) {
                const auto k = static_cast<std::size_t>(i);
                fmpq_mul(a.get(), keep.get(), row[k].get());
                fmpq_mul(b.get(), t.get(), row[k + 1].get());
                fmpq_add(row[k].get(), a.get(), b.get());
            }
            EXPECT_TRUE(within(row[0], left.b[level], left.r[level]))
                << "degree " << n << ", τ " << tau << ", left " << level;
            EXPECT_TRUE(within(row[static_cast<std::size_t>(n - level)], right.b[n - level],
                               right.r[n - level]))
                << "degree " << n << ", τ " << tau << ", right " << n - level;
        }
        // The value at τ is the shared vertex: evaluate() must enclose it too.
        const BallValue value = evaluate(whole, tau);
        EXPECT_TRUE(within(row[0], value.value, value.radius)) << "degree " << n;
    }
}

// split_half, the isolation's every split, has its own kernel (sums without the halvings): its
// pieces against exact de Casteljau at 1/2, at degrees up to 64, with coefficients and radii
// from subnormal to past the kernel's overflow limit (those take the weighted scheme), and
// written over its input.
TEST(BernsteinSplit, HalvesHoldAgainstExactArithmetic) {
    std::mt19937_64 random(23);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const auto within = [&](const Rational& truth, double value, double radius) {
        return std::isfinite(value) && std::isfinite(radius) &&
               at_most(absolute_difference(truth, exact(value)), radius);
    };
    const double magnitudes[] = {1.0, 1e-300, 1e-310, 1e250, 1e300};
    for (int trial = 0; trial < 260; ++trial) {
        BernsteinBall whole;
        whole.degree = trial % 65;
        const int n = whole.degree;
        const double magnitude = magnitudes[trial % 5];
        for (int i = 0; i <= n; ++i) {
            whole.b[i] = unit(random) * magnitude * std::pow(10.0, 4.0 * unit(random));
            whole.r[i] = trial % 3 == 0 ? 0.0 : std::abs(whole.b[i]) * 1e-9;
        }
        BernsteinBall left, right;
        split_half(whole, left, right);
        BernsteinBall over_left = whole, other_right;
        split_half(over_left, over_left, other_right);
        std::vector<Rational> row(static_cast<std::size_t>(n + 1));
        for (int i = 0; i <= n; ++i) {
            row[static_cast<std::size_t>(i)] = exact(whole.b[i]);
        }
        for (int level = 0; level <= n; ++level) {
            if (level > 0) {
                for (int i = 0; i <= n - level; ++i) {
                    const auto k = static_cast<std::size_t>(i);
                    fmpq_add(row[k].get(), row[k].get(), row[k + 1].get());
                    fmpq_div_2exp(row[k].get(), row[k].get(), 1);
                }
            }
            // The exact pieces of the midpoints b_i: within each radius, which covers the
            // roundings and carries the input's radii (weights summing to one).
            EXPECT_TRUE(within(row[0], left.b[level], left.r[level]))
                << "degree " << n << ", magnitude " << magnitude << ", left " << level;
            EXPECT_TRUE(within(row[static_cast<std::size_t>(n - level)], right.b[n - level],
                               right.r[n - level]))
                << "degree " << n << ", magnitude " << magnitude << ", right " << n - level;
            EXPECT_EQ(over_left.b[level], left.b[level]);
            EXPECT_EQ(over_left.r[level], left.r[level]);
        }
        EXPECT_EQ(left.degree, n);
        EXPECT_EQ(right.degree, n);
    }
}

// The prepared midpoint polynomial (Horner on binomially weighted coefficients) against de
// Casteljau's scheme, which shares nothing with it: the value, and the slope as a central
// difference.
TEST(MidpointPolynomial, AgreesWithDeCasteljau) {
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), fraction(0.0, 1.0);
    for (int trial = 0; trial < 300; ++trial) {
        BernsteinBall g;
        g.degree = trial % 16;
        double scale = 0.0;
        for (int i = 0; i <= g.degree; ++i) {
            g.b[i] = unit(random);
            g.r[i] = 0.0;
            scale += std::abs(g.b[i]);
        }
        const MidpointPolynomial midpoint(g);
        const double sigma = fraction(random);
        const ValueSlope prepared = midpoint.at(sigma);
        const BallValue reference = evaluate(g, sigma);
        EXPECT_NEAR(prepared.value, reference.value, 1e-13 * scale + reference.radius);
        // The slope against a central difference of de Casteljau values.
        if (g.degree > 0 && sigma > 1e-3 && sigma < 1.0 - 1e-3) {
            const double h = 1e-6;
            const double difference =
                (evaluate(g, sigma + h).value - evaluate(g, sigma - h).value) / (2.0 * h);
            EXPECT_NEAR(prepared.slope, difference, 1e-5 * (1.0 + std::abs(difference)) * scale);
        }
    }
}

// MidpointPolynomial::enclose, the O(n) certified value, against the exact polynomial inside
// the ball (a random choice within every radius) evaluated over Q: at degrees up to 64, radii
// of zero and of 10^-3 of the coefficient, magnitudes over twelve orders, points from the ends
// to the middle (σ near 1, where 1 − σ is exact, and near 0, where it rounds).
TEST(MidpointPolynomial, EnclosesTheExactValue) {
    std::mt19937_64 random(53);
    std::uniform_real_distribution<double> fraction(0.0, 1.0);
    const int count = test::seed_count(390);
    for (int trial = 0; trial < count; ++trial) {
        const int n = trial % 65;
        BernsteinBall g = random_ball(std::max(1, n), random, trial % 2 == 0);
        if (trial % 5 == 0) {
            for (int i = 0; i <= g.degree; ++i) {
                g.r[i] = 0.0;
            }
        }
        const ExactPiece piece = exact_inside(g, random);
        const MidpointPolynomial midpoint(g);
        for (int k = 0; k < 4; ++k) {
            const double u = fraction(random);
            const double sigma = k == 0 ? u * 1e-6 : (k == 1 ? 1.0 - u * 1e-6 : u);
            const BallValue enclosed = midpoint.enclose(sigma);
            const Rational truth = bernstein_sum(piece.value, exact(sigma));
            EXPECT_TRUE(at_most(absolute_difference(truth, exact(enclosed.value)), enclosed.radius))
                << "degree " << g.degree << ", σ " << sigma;
            // Not vacuous: the radius is the ball's own plus roundings, no more.
            double largest_radius = 0.0, largest = 0.0;
            for (int i = 0; i <= g.degree; ++i) {
                largest_radius = std::max(largest_radius, g.r[i]);
                largest = std::max(largest, std::abs(g.b[i]));
            }
            EXPECT_LE(enclosed.radius, 1.01 * largest_radius + 1e-12 * largest);
        }
    }
}

// A radius or coefficient that is not finite leaves no sign certain (the largest radius was
// taken with std::max, which skips a NaN).
TEST(MidpointPolynomial, EnclosesNothingWithARadiusThatIsNotFinite) {
    for (const double bad : {NAN, INFINITY}) {
        for (int at = 0; at <= 4; ++at) {
            BernsteinBall g;
            g.degree = 4;
            for (int i = 0; i <= 4; ++i) {
                g.b[i] = 1.0 + i;
                g.r[i] = 1e-12;
            }
            g.r[at] = bad;
            EXPECT_EQ(MidpointPolynomial(g).enclose(0.5).sign(), 0) << "radius " << at;
            g.r[at] = 1e-12;
            g.b[at] = bad;
            EXPECT_EQ(MidpointPolynomial(g).enclose(0.5).sign(), 0) << "coefficient " << at;
        }
    }
}

// Descartes' bound under uncertainty against brute force: every choice of signs (±1) for the
// coefficients the ball leaves uncertain, counting the changes of each.
TEST(MostSignChanges, IsTheMostOverEveryChoiceOfTheUncertainSigns) {
    std::mt19937_64 random(5);
    std::uniform_int_distribution<int> kind(0, 2);
    for (int trial = 0; trial < 3000; ++trial) {
        BernsteinBall g;
        g.degree = trial % 15;
        std::vector<int> uncertain;
        for (int i = 0; i <= g.degree; ++i) {
            switch (kind(random)) {
            case 0:
                g.b[i] = 1.0;
                g.r[i] = 0.5;
                break;
            case 1:
                g.b[i] = -1.0;
                g.r[i] = 0.5;
                break;
            default:
                g.b[i] = 0.25 * (trial % 3 - 1);
                g.r[i] = 0.5;
                uncertain.push_back(i);
                break;
            }
        }
        if (uncertain.size() > 10) {
            continue;
        }
        int most = 0;
        for (unsigned choice = 0; choice < (1u << uncertain.size()); ++choice) {
            std::vector<int> signs;
            std::size_t next = 0;
            for (int i = 0; i <= g.degree; ++i) {
                if (next < uncertain.size() && uncertain[next] == i) {
                    signs.push_back((choice >> next) & 1u ? 1 : -1);
                    ++next;
                } else {
                    signs.push_back(g.b[i] > 0.0 ? 1 : -1);
                }
            }
            int changes = 0;
            for (std::size_t i = 1; i < signs.size(); ++i) {
                changes += signs[i] != signs[i - 1] ? 1 : 0;
            }
            most = std::max(most, changes);
        }
        EXPECT_EQ(most_sign_changes(g), most) << "trial " << trial;
    }
}

// The same at every degree to 64 (the unrolled counts to 12, the generic one to 62, the
// search over choices past it), with at most two signs left uncertain.
TEST(MostSignChanges, CountsAtEveryDegree) {
    std::mt19937_64 random(31);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int trial = 0; trial < 650; ++trial) {
        BernsteinBall g;
        g.degree = trial % 65;
        const int n = g.degree;
        const int hidden_count = trial % 3;  // 0, 1 or 2 uncertain coefficients
        std::vector<int> signs;
        for (int i = 0; i <= n; ++i) {
            g.b[i] = unit(random);
            g.r[i] = 0.5 * std::abs(g.b[i]);
            signs.push_back(g.b[i] > 0.0 ? 1 : -1);
        }
        std::vector<int> hidden;
        for (int h = 0; h < hidden_count; ++h) {
            const int at = static_cast<int>(random() % static_cast<unsigned>(n + 1));
            g.r[at] = 2.0 * std::abs(g.b[at]) + 0.1;
            hidden.push_back(at);
        }
        int most = 0;
        for (unsigned choice = 0; choice < 4u; ++choice) {
            std::vector<int> chosen = signs;
            for (std::size_t h = 0; h < hidden.size(); ++h) {
                chosen[static_cast<std::size_t>(hidden[h])] = (choice >> h) & 1u ? 1 : -1;
            }
            int changes = 0;
            for (std::size_t i = 1; i < chosen.size(); ++i) {
                changes += chosen[i] != chosen[i - 1] ? 1 : 0;
            }
            most = std::max(most, changes);
        }
        EXPECT_EQ(most_sign_changes(g), most) << "degree " << n << ", trial " << trial;
    }
}

// The exact polynomial Σ c_k x^k for a choice inside every radius, carried to σ = (1 + x)/2
// by expanding (2σ − 1)^k and then to the Bernstein basis by b_i = Σ_{j ≤ i} C(i, j)/C(n, j)·a_j
// (Farouki & Rajan 1987) — not the conversion's own formula, the centred weights β_ik —
// against every coefficient's ball.
TEST(BernsteinConversion, RadiiHoldAgainstExactArithmetic) {
    std::mt19937_64 random(41);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), fraction(0.0, 1.0);
    fmpz_t choose, other;
    fmpz_init(choose);
    fmpz_init(other);
    const int count = test::seed_count(260);
    for (int trial = 0; trial < count; ++trial) {
        const int n = trial % 65;
        RestrictionBall power;
        power.polynomial.degree = n;
        power.certified = true;
        const double spread = trial % 2 == 0 ? 6.0 : 1.0;
        for (int k = 0; k <= n; ++k) {
            power.polynomial.c[k] = unit(random) * std::pow(10.0, spread * unit(random));
            power.radius[k] = random() % 3 == 0 ? 0.0
                                                : std::abs(power.polynomial.c[k]) *
                                                      std::pow(10.0, -16.0 * fraction(random));
        }
        const BernsteinBall ball = to_bernstein(power);
        ASSERT_EQ(ball.degree, n);
        // c' inside the balls, then a_j = Σ_k c'_k·C(k, j)·2^j·(−1)^(k − j).
        std::vector<Rational> a(static_cast<std::size_t>(n + 1));
        for (int k = 0; k <= n; ++k) {
            Rational c = exact(power.polynomial.c[k]);
            fmpq_add(c.get(), c.get(), exact(power.radius[k] * unit(random)).get());
            for (int j = 0; j <= k; ++j) {
                fmpz_bin_uiui(choose, static_cast<ulong>(k), static_cast<ulong>(j));
                Rational term;
                fmpq_mul_fmpz(term.get(), c.get(), choose);
                fmpq_mul_2exp(term.get(), term.get(), static_cast<ulong>(j));
                if ((k - j) % 2 != 0) {
                    fmpq_neg(term.get(), term.get());
                }
                fmpq_add(a[static_cast<std::size_t>(j)].get(), a[static_cast<std::size_t>(j)].get(),
                         term.get());
            }
        }
        for (int i = 0; i <= n; ++i) {
            Rational b;
            for (int j = 0; j <= i; ++j) {
                fmpz_bin_uiui(choose, static_cast<ulong>(i), static_cast<ulong>(j));
                fmpz_bin_uiui(other, static_cast<ulong>(n), static_cast<ulong>(j));
                Rational term;
                fmpq_mul_fmpz(term.get(), a[static_cast<std::size_t>(j)].get(), choose);
                fmpq_div_fmpz(term.get(), term.get(), other);
                fmpq_add(b.get(), b.get(), term.get());
            }
            EXPECT_TRUE(at_most(absolute_difference(b, exact(ball.b[i])), ball.r[i]))
                << "degree " << n << ", coefficient " << i;
        }
    }
    fmpz_clear(choose);
    fmpz_clear(other);
}

TEST(SlopeBounds, HoldAgainstExactArithmetic) {
    std::mt19937_64 random(23);
    std::uniform_real_distribution<double> fraction(0.0, 1.0);
    int informative = 0;
    const int count = test::seed_count(240);
    for (int trial = 0; trial < count; ++trial) {
        const int n = 1 + trial % 64;
        const BernsteinBall g = random_ball(n, random, trial % 2 == 0);
        const ExactPiece piece = exact_inside(g, random);
        const SlopeBounds bounds = slope_bounds(g);
        const MidpointPolynomial midpoint(g);
        std::vector<double> points = {0.0, 1.0};
        for (int k = 0; k < 4; ++k) {
            points.push_back(fraction(random));
        }
        std::vector<Rational> slopes;
        for (double sigma : points) {
            const Rational slope = bernstein_sum(piece.slope, exact(sigma));
            EXPECT_LE(fmpq_cmp(exact(bounds.hull_lo).get(), slope.get()), 0)
                << "degree " << n << " σ " << sigma;
            EXPECT_LE(fmpq_cmp(slope.get(), exact(bounds.hull_hi).get()), 0)
                << "degree " << n << " σ " << sigma;
            EXPECT_TRUE(at_most(absolute_difference(slope, exact(midpoint.at(sigma).slope)),
                                bounds.point_error))
                << "degree " << n << " σ " << sigma;
            slopes.push_back(slope);
        }
        for (std::size_t a = 0; a < points.size(); ++a) {
            for (std::size_t b = a + 1; b < points.size(); ++b) {
                // |G'(a) − G'(b)| ≤ curvature·|a − b|, both sides exact.
                Rational limit = exact(bounds.curvature);
                fmpq_mul(limit.get(), limit.get(),
                         absolute_difference(exact(points[a]), exact(points[b])).get());
                EXPECT_LE(fmpq_cmp(absolute_difference(slopes[a], slopes[b]).get(), limit.get()), 0)
                    << "degree " << n;
            }
        }
        // Not vacuous: the point error is far below the slope's scale when the radii are small.
        double largest = 0.0;
        for (int i = 0; i < n; ++i) {
            largest = std::max(largest, std::abs(g.b[i + 1] - g.b[i]));
        }
        informative += bounds.point_error < 1e-2 * n * largest ? 1 : 0;
    }
    EXPECT_GT(informative, count * 5 / 6);
}

// The estimate of a simple root takes a few Newton steps, also where rounding gives the value at
// the root the wrong sign (which had sent the search back to bisecting its whole bracket: 14 to
// 100 steps for 13 % of the Whitney umbrella's roots). Balls G = ±(σ − ρ)·Q(σ), Q ≥ 1 on [0, 1],
// in the Bernstein basis (Farouki & Rajan's conversion), radii at the rounding level; and one
// ball of that umbrella's frame as it was met. Each bracket must hold ρ.
TEST(NarrowRoot, PlacesASimpleRootInAFewNewtonSteps) {
    const auto check = [](const BernsteinBall& g, int sign_at_zero, double width, double root) {
        const MidpointPolynomial midpoint(g);
        const Bracket bracket = narrow_root(g, midpoint, sign_at_zero, width);
        EXPECT_LE(bracket.newton_steps, 8) << "degree " << g.degree << ", root " << root;
        EXPECT_TRUE(bracket.certified);
        if (root >= 0.0) {
            EXPECT_LE(bracket.lo, root + 1e-12);
            EXPECT_GE(bracket.hi, root - 1e-12);
        }
    };
    BernsteinBall met;
    met.degree = 3;
    const double met_b[] = {1.28251, -2.07869, -4.71549, -7.07457};
    for (int i = 0; i <= 3; ++i) {
        met.b[i] = met_b[i];
        met.r[i] = 1.47563e-12;
    }
    check(met, 1, 9.26658e-10, -1.0);

    std::mt19937_64 random(43);
    std::uniform_real_distribution<double> fraction(0.0, 1.0);
    for (int trial = 0; trial < 600; ++trial) {
        const int n = 1 + trial % 12;
        const double root = 0.05 + 0.9 * fraction(random);
        const double sign = trial % 2 == 0 ? 1.0 : -1.0;
        // Power coefficients of sign·(σ − root)·(1 + Σ q_k σ^k), then b_i = Σ_{j ≤ i}
        // C(i, j)/C(n, j)·a_j.
        std::vector<double> q(static_cast<std::size_t>(n), 0.0), a(static_cast<std::size_t>(n + 1));
        q[0] = 1.0;
        for (int k = 1; k < n; ++k) {
            q[static_cast<std::size_t>(k)] = fraction(random);
        }
        for (int k = 0; k <= n; ++k) {
            const double from_sigma = k > 0 ? q[static_cast<std::size_t>(k - 1)] : 0.0;
            const double from_root = k < n ? -root * q[static_cast<std::size_t>(k)] : 0.0;
            a[static_cast<std::size_t>(k)] = sign * (from_sigma + from_root);
        }
        BernsteinBall g;
        g.degree = n;
        double largest = 0.0;
        for (int i = 0; i <= n; ++i) {
            double sum = 0.0;
            for (int j = 0; j <= i; ++j) {
                sum += std::tgamma(i + 1.0) / (std::tgamma(j + 1.0) * std::tgamma(i - j + 1.0)) /
                       (std::tgamma(n + 1.0) / (std::tgamma(j + 1.0) * std::tgamma(n - j + 1.0))) *
                       a[static_cast<std::size_t>(j)];
            }
            g.b[i] = sum;
            largest = std::max(largest, std::abs(sum));
        }
        for (int i = 0; i <= n; ++i) {
            g.r[i] = 1e-13 * largest;
        }
        check(g, sign > 0.0 ? -1 : 1, 1e-9, root);
    }
}

TEST(MeanValueBracket, HoldsTheRootAndPlacesItFromOneValue) {
    std::mt19937_64 random(31);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), fraction(0.0, 1.0);
    int tight = 0, trials = 0;
    const int count = test::seed_count(400);
    for (int trial = 0; trial < count; ++trial) {
        const int n = 1 + trial % 64;
        const BernsteinBall g = random_ball(n, random, true);
        const ExactPiece piece = exact_inside(g, random);
        const int sign_at_zero = g.b[0] > 0.0 ? 1 : -1;
        const auto sign_at = [&](double sigma) {
            return fmpq_sgn(bernstein_sum(piece.value, exact(sigma)).get());
        };
        // The root to about 1e-15, by bisection on exact signs.
        double lo = 0.0, hi = 1.0;
        for (int step = 0; step < 50; ++step) {
            const double middle = 0.5 * (lo + hi);
            (sign_at(middle) == sign_at_zero ? lo : hi) = middle;
        }
        const double root = 0.5 * (lo + hi);
        // A point near the root (or far from it), known exactly or only up to a blur, and G
        // there, rounded, with its rounding error or a larger one.
        const double distance = std::pow(10.0, -14.0 + 13.0 * fraction(random)) * unit(random);
        const double s = std::clamp(root + distance, 0.0, 1.0);
        const double blur = trial % 3 == 0 ? std::abs(distance) * 1e-3 * fraction(random) : 0.0;
        const double sigma = std::clamp(s + blur * unit(random), 0.0, 1.0);
        const Rational value = bernstein_sum(piece.value, exact(s));
        double rounded = fmpq_get_d(value.get());
        if (trial % 4 == 1) {
            // Known only roughly: off by up to the whole value, and said to be (the bound a
            // little above the actual error, which the step must allow for).
            rounded *= 1.0 + std::pow(10.0, -12.0 * fraction(random)) * unit(random);
        }
        const double error = fmpq_get_d(absolute_difference(value, exact(rounded)).get()) *
                             (1.01 + (trial % 4 == 1 ? 0.5 * fraction(random) : 0.0));
        const double known_blur = blur > 0.0 ? std::abs(sigma - s) * 1.01 : 0.0;
        const RootRange range = mean_value_bracket(MidpointPolynomial(g), slope_bounds(g),
                                                   sign_at_zero, sigma, known_blur, rounded, error);
        ASSERT_LE(range.lo, range.hi);
        const int at_lo = sign_at(range.lo), at_hi = sign_at(range.hi);
        EXPECT_TRUE(at_lo == sign_at_zero || at_lo == 0)
            << "degree " << n << ": [" << range.lo << ", " << range.hi << "] misses the root "
            << root << " (point " << sigma << ")";
        EXPECT_TRUE(at_hi == -sign_at_zero || at_hi == 0)
            << "degree " << n << ": [" << range.lo << ", " << range.hi << "] misses the root "
            << root << " (point " << sigma << ")";
        if (std::abs(distance) < 1e-6 && blur == 0.0 && trial % 4 != 1) {
            ++trials;
            tight += range.hi - range.lo < 1e-3 * std::abs(distance) + 1e-13 ? 1 : 0;
        }
    }
    // From a point within 1e-6 of the root, known exactly, the bracket is usually a thousand
    // times narrower than that distance.
    EXPECT_GT(tight, trials / 2) << tight << " of " << trials;
}

// A search that ends before three quarters of its piece is cut at its end first
// (isolate_first_root_near): the cut must never fall short of the end, or a root just before it
// would go unseen. The ball holds G(σ) = (σ − c)·Q(σ), Q > 0, exactly (its coefficients over Q,
// rounded, with radii covering the rounding), so c is the only root; searches end a few
// roundings before c, at c, or just past it, with no guess, a window before the root (the cut
// after the window) and one around it.
TEST(IsolationNear, CutAtTheEndKeepsEveryRootBeforeIt) {
    std::mt19937_64 random(47);
    std::uniform_real_distribution<double> fraction(0.0, 1.0);
    const double u = 0x1.0p-53;
    int inside = 0;
    const int count = test::seed_count(300);
    for (int trial = 0; trial < count; ++trial) {
        const int n = 2 + trial % 11;
        const double c = 0.05 + 0.6 * fraction(random);
        // Power coefficients of (σ − c)·Σ q_k σ^k with q_k > 0, then b_i = Σ_{j ≤ i}
        // C(i, j)/C(n, j)·a_j, all over Q.
        std::vector<Rational> q(static_cast<std::size_t>(n)), a(static_cast<std::size_t>(n + 1));
        for (int k = 0; k < n; ++k) {
            q[static_cast<std::size_t>(k)] = exact(0.1 + fraction(random));
        }
        const Rational root = exact(c);
        for (int k = 0; k <= n; ++k) {
            Rational term;
            if (k > 0) {
                fmpq_add(term.get(), term.get(), q[static_cast<std::size_t>(k - 1)].get());
            }
            if (k < n) {
                Rational product;
                fmpq_mul(product.get(), root.get(), q[static_cast<std::size_t>(k)].get());
                fmpq_sub(term.get(), term.get(), product.get());
            }
            a[static_cast<std::size_t>(k)] = term;
        }
        BernsteinBall g;
        g.degree = n;
        fmpz_t choose_i, choose_n;
        fmpz_init(choose_i);
        fmpz_init(choose_n);
        for (int i = 0; i <= n; ++i) {
            Rational beta, term;
            for (int j = 0; j <= i; ++j) {
                fmpz_bin_uiui(choose_i, static_cast<ulong>(i), static_cast<ulong>(j));
                fmpz_bin_uiui(choose_n, static_cast<ulong>(n), static_cast<ulong>(j));
                fmpq_mul_fmpz(term.get(), a[static_cast<std::size_t>(j)].get(), choose_i);
                fmpq_div_fmpz(term.get(), term.get(), choose_n);
                fmpq_add(beta.get(), beta.get(), term.get());
            }
            g.b[i] = fmpq_get_d(beta.get());
            g.r[i] =
                fmpq_get_d(absolute_difference(beta, exact(g.b[i])).get()) * (1.0 + 0x1.0p-50) +
                0x1.0p-1074;
        }
        fmpz_clear(choose_i);
        fmpz_clear(choose_n);
        for (const double end : {c - 64.0 * u, c - 2.0 * u, c, c + 2.0 * u, c + 1e-9}) {
            const double start = trial % 2 == 0 ? 0.0 : c * fraction(random);
            struct Guess {
                double at, reach;
            };
            const Guess guesses[] = {
                {NAN, 0.0}, {0.5 * (start + c), 0.25 * (c - start)}, {c, 0.5 * (c - start)}};
            for (const Guess& guess : guesses) {
                const Isolation found =
                    isolate_first_root_near(g, 40, start, end, guess.at, guess.reach);
                // A one_root piece holds c; an undecided one says only that no root comes
                // before it (the radii blur G's sign next to c).
                const bool holds_c =
                    found.kind == Isolation::Kind::one_root
                        ? found.lo <= c + 8.0 * u && found.hi >= c - 8.0 * u
                        : found.kind == Isolation::Kind::undecided && found.lo <= c + 8.0 * u;
                const char* kind = found.kind == Isolation::Kind::no_root    ? "no root"
                                   : found.kind == Isolation::Kind::one_root ? "one root"
                                                                             : "undecided";
                if (c <= end) {
                    ++inside;
                    EXPECT_TRUE(holds_c)
                        << "degree " << n << ": the root " << c << " before the end " << end
                        << " (start " << start << ", guess " << guess.at << "): " << kind << " ["
                        << found.lo << ", " << found.hi << "]";
                } else {
                    EXPECT_TRUE(found.kind == Isolation::Kind::no_root || holds_c)
                        << "degree " << n << ": the only root is " << c << ", past the end " << end
                        << ": " << kind << " [" << found.lo << ", " << found.hi << "]";
                }
            }
        }
    }
    EXPECT_GT(inside, count);
}

}  // namespace
}  // namespace locus::render
