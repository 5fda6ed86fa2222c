// Roots of F as eigenvalues of its companion matrix (Edelman & Murakami, "Polynomial roots from
// companion matrix eigenvalues", Math. Comp. 64 (1995) 763–776), then Newton polishing of the
// (nearly) real ones on the original F and the smallest in [lo, hi].
//
// The companion matrix of the monic F/c_n (ones on the subdiagonal, −c_k/c_n in the last column)
// is already upper Hessenberg. Eigen's EigenSolver and RealSchur::compute do not balance (they
// only scale by the largest entry, Eigen 3.4 RealSchur.h), and an unbalanced companion matrix
// loses most digits when the coefficients span many orders of magnitude, so it is balanced here
// by Parlett & Reinsch ("Balancing a matrix for calculation of eigenvalues and eigenvectors",
// Numer. Math. 13 (1969) 293–304; radix 2, so exact). A diagonal similarity keeps the Hessenberg
// form, so the Hessenberg reduction is skipped and the Francis QR iteration runs directly
// (RealSchur::computeFromHessenberg). Matrices have a fixed maximum size: no heap allocation.
#include <Eigen/Eigenvalues>  // for Eigen::RealSchur

#include <algorithm>
#include <cmath>

#include "render/root_finder.h"
#include "render/root_finders/detail/univariate.h"

namespace locus::render {
namespace {

using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxDegree, kMaxDegree>;

constexpr int kMaxBalanceSweeps = 20;

// Parlett–Reinsch balancing, radix 2, in place (Numerical Recipes, 3rd ed., §11.6.1 `balance`).
void balance(Matrix& m) {
    const Eigen::Index n = m.rows();
    constexpr double kRadix = 2.0;
    constexpr double kRadix2 = kRadix * kRadix;
    for (int sweep = 0; sweep < kMaxBalanceSweeps; ++sweep) {
        bool done = true;
        for (Eigen::Index i = 0; i < n; ++i) {
            double r = 0.0;
            double c = 0.0;
            for (Eigen::Index j = 0; j < n; ++j) {
                if (j != i) {
                    c += std::abs(m(j, i));
                    r += std::abs(m(i, j));
                }
            }
            if (c == 0.0 || r == 0.0) {
                continue;
            }
            const double sum = c + r;
            double g = r / kRadix;
            double factor = 1.0;
            while (c < g) {
                factor *= kRadix;
                c *= kRadix2;
            }
            g = r * kRadix;
            while (c > g) {
                factor /= kRadix;
                c /= kRadix2;
            }
            if ((c + r) / factor < 0.95 * sum) {
                done = false;
                m.row(i) /= factor;
                m.col(i) *= factor;
            }
        }
        if (done) {
            break;
        }
    }
}

}  // namespace

RootResult CompanionRootFinder::first_root(const RayPolynomial& f, double lo, double hi) const {
    const detail::Screening screening = detail::screen(f, lo, hi);
    if (screening.done) {
        return screening.result;
    }
    const int n = screening.degree;
    const double* c = f.c.data();
    detail::Coefficients dc;
    detail::derivative(c, n, dc.data());
    const double slack = detail::end_slack(lo, hi);
    double best = HUGE_VAL;
    int work = 1;
    const auto consider = [&](double real, double imaginary) {
        double t;
        if (detail::polish_real_root(c, dc.data(), n, real, imaginary, work, t) &&
            t >= lo - slack && t <= hi + slack) {
            best = std::min(best, std::clamp(t, lo, hi));
        }
    };
    if (n == 1) {
        consider(-c[0] / c[1], 0.0);
    } else {
        Matrix companion = Matrix::Zero(n, n);
        const double inverse_lead = 1.0 / c[n];
        for (int i = 0; i < n; ++i) {
            if (i + 1 < n) {
                companion(i + 1, i) = 1.0;
            }
            companion(i, n - 1) = -c[i] * inverse_lead;
        }
        if (!companion.allFinite()) {
            return detail::unknown("companion matrix overflows", work);
        }
        balance(companion);
        Eigen::RealSchur<Matrix> schur(n);
        schur.computeFromHessenberg(companion, companion, false);
        if (schur.info() != Eigen::Success) {
            return detail::unknown("QR iteration limit reached", work);
        }
        const Matrix& t = schur.matrixT();
        for (int i = 0; i < n;) {
            if (i + 1 == n || t(i + 1, i) == 0.0) {
                consider(t(i, i), 0.0);
                ++i;
                continue;
            }
            // A 2×2 block holds a complex pair (RealSchur splits real pairs); its eigenvalues
            // are computed as in Eigen's EigenSolver::compute, safe from overflow.
            const double p = 0.5 * (t(i, i) - t(i + 1, i + 1));
            const double t0 = t(i + 1, i);
            const double t1 = t(i, i + 1);
            const double scale = std::max({std::abs(p), std::abs(t0), std::abs(t1)});
            const double imaginary =
                scale *
                std::sqrt(std::abs((p / scale) * (p / scale) + (t0 / scale) * (t1 / scale)));
            consider(t(i + 1, i + 1) + p, imaginary);
            i += 2;
        }
    }
    if (best != HUGE_VAL) {
        return detail::hit(best, work);
    }
    return detail::is_zero_within_rounding(c, n, hi) ? detail::hit(hi, work) : detail::miss(work);
}

}  // namespace locus::render
