#include "implicit/dixon.h"

#include <flint/fmpq.h>
#include <flint/fmpz.h>
#include <flint/nmod_mat.h>
#include <flint/nmod_poly.h>
#include <flint/nmod_vec.h>
#include <flint/ulong_extras.h>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <array>
#include <random>

#include "algebra/deadline.h"
#include "algebra/error.h"
#include "algebra/flint_convert.h"
#include "algebra/flint_threads.h"
#include "algebra/modular/modular_polynomial.h"
#include "algebra/modular/rational_lift.h"
#include "implicit/detail/modular_lifting.h"

namespace locus::implicit {

using algebra::Integer;
using algebra::Polynomial;
using algebra::Rational;

namespace {

// A polynomial in (s, t) with integer coefficients, dense: c[a·(dt + 1) + b] of s^a t^b.
struct DenseBivariate {
    unsigned ds = 0, dt = 0;
    std::vector<Integer> c;
    const Integer& at(unsigned a, unsigned b) const { return c[a * (dt + 1) + b]; }
};

DenseBivariate dense_of(const Polynomial& f, const Integer& scale) {
    DenseBivariate d;
    d.ds = static_cast<unsigned>(std::max<long>(0, f.degree(0)));
    d.dt = static_cast<unsigned>(std::max<long>(0, f.degree(1)));
    d.c.resize((d.ds + 1) * (d.dt + 1));
    for (std::size_t i = 0; i < f.num_terms(); ++i) {
        const auto e = f.exponents(i);
        const fmpq* q = f.coefficient(i).get();
        Integer& target = d.c[e[0] * (d.dt + 1) + e[1]];
        fmpz_divexact(target.get(), scale.get(), fmpq_denref(q));
        fmpz_mul(target.get(), target.get(), fmpq_numref(q));
    }
    return d;
}

// The Dixon coefficient matrix of (g₀, g₁, g₂) for bidegree (m, n), row-major r × r with
// r = 2mn: rows s^i t^j (i < m, j < 2n), columns α^k β^l (k < 2m, l < n).
std::vector<Integer> dixon_matrix(const std::array<const DenseBivariate*, 3>& g, unsigned m,
                                  unsigned n) {
    // H(s, t, α, β) = det[g(s,t); g(α,t); g(α,β)] with dimensions (m+1, 2n+1, 2m+1, n+1).
    const unsigned S = m + 1, T = 2 * n + 1, A = 2 * m + 1, B = n + 1;
    std::vector<Integer> h(S * T * A * B);
    auto hx = [&](unsigned s, unsigned t, unsigned a, unsigned b) -> Integer& {
        return h[((s * T + t) * A + a) * B + b];
    };
    static constexpr int permutations[6][4] = {{0, 1, 2, 1},  {1, 2, 0, 1},  {2, 0, 1, 1},
                                               {0, 2, 1, -1}, {2, 1, 0, -1}, {1, 0, 2, -1}};
    Integer product;
    for (const auto& perm : permutations) {
        const DenseBivariate& f1 = *g[perm[0]];
        const DenseBivariate& f2 = *g[perm[1]];
        const DenseBivariate& f3 = *g[perm[2]];
        for (unsigned a1 = 0; a1 <= f1.ds; ++a1) {
            for (unsigned b1 = 0; b1 <= f1.dt; ++b1) {
                const Integer& c1 = f1.at(a1, b1);
                if (c1.is_zero()) {
                    continue;
                }
                for (unsigned a2 = 0; a2 <= f2.ds; ++a2) {
                    for (unsigned b2 = 0; b2 <= f2.dt; ++b2) {
                        const Integer& c2 = f2.at(a2, b2);
                        if (c2.is_zero()) {
                            continue;
                        }
                        fmpz_mul(product.get(), c1.get(), c2.get());
                        if (perm[3] < 0) {
                            fmpz_neg(product.get(), product.get());
                        }
                        for (unsigned a3 = 0; a3 <= f3.ds; ++a3) {
                            for (unsigned b3 = 0; b3 <= f3.dt; ++b3) {
                                const Integer& c3 = f3.at(a3, b3);
                                if (!c3.is_zero()) {
                                    // g(s,t)·g(α,t)·g(α,β): s^a1 t^(b1+b2) α^(a2+a3) β^b3
                                    fmpz_addmul(hx(a1, b1 + b2, a2 + a3, b3).get(), product.get(),
                                                c3.get());
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    // Divide by (s − α): with H = Σ h_i(α) s^i, the quotient's coefficients are
    // q_{i−1} = h_i + α·q_i (from the top), and h_0 + α·q_0 must vanish.
    std::vector<Integer> q1(m * T * A * B);
    auto q1x = [&](unsigned s, unsigned t, unsigned a, unsigned b) -> Integer& {
        return q1[((s * T + t) * A + a) * B + b];
    };
    for (unsigned t = 0; t < T; ++t) {
        for (unsigned b = 0; b < B; ++b) {
            std::vector<Integer> carry(A + 1);  // α·q_i, indexed by α-degree
            for (unsigned i = m; i >= 1; --i) {
                for (unsigned a = 0; a < A; ++a) {
                    Integer& q = q1x(i - 1, t, a, b);
                    fmpz_add(q.get(), hx(i, t, a, b).get(), carry[a].get());
                }
                for (unsigned a = A; a >= 1; --a) {
                    carry[a] = q1x(i - 1, t, a - 1, b);
                }
                carry[0] = Integer(0);
            }
            for (unsigned a = 0; a < A; ++a) {
                Integer remainder;
                fmpz_add(remainder.get(), hx(0, t, a, b).get(), carry[a].get());
                if (!remainder.is_zero() || !carry[A].is_zero()) {
                    throw Error(
                        "internal error: the Cayley–Dixon determinant is not divisible "
                        "by s - alpha");
                }
            }
        }
    }
    // Divide by (t − β) in the same way, leaving dimensions (m, 2n, 2m, n).
    const unsigned T2 = 2 * n, A2 = 2 * m, B2 = n;
    std::vector<Integer> matrix(static_cast<std::size_t>(m * T2) * (A2 * B2));
    const std::size_t r = static_cast<std::size_t>(m) * T2;
    for (unsigned s = 0; s < m; ++s) {
        for (unsigned a = 0; a < A; ++a) {
            std::vector<Integer> carry(B + 1);  // β·q_j
            std::vector<std::vector<Integer>> quotient(T2, std::vector<Integer>(B));
            for (unsigned j = T - 1; j >= 1; --j) {
                for (unsigned b = 0; b < B; ++b) {
                    fmpz_add(quotient[j - 1][b].get(), q1x(s, j, a, b).get(), carry[b].get());
                }
                for (unsigned b = B; b >= 1; --b) {
                    carry[b] = quotient[j - 1][b - 1];
                }
                carry[0] = Integer(0);
            }
            for (unsigned b = 0; b < B; ++b) {
                Integer remainder;
                fmpz_add(remainder.get(), q1x(s, 0, a, b).get(), carry[b].get());
                if (!remainder.is_zero() || !carry[B].is_zero()) {
                    throw Error(
                        "internal error: the Cayley–Dixon determinant is not divisible "
                        "by t - beta");
                }
            }
            for (unsigned j = 0; j < T2; ++j) {
                if (!quotient[j][B2].is_zero() || (a >= A2 && !quotient[j][0].is_zero())) {
                    throw Error("internal error: the Dixon polynomial exceeds its degree bounds");
                }
                if (a >= A2) {
                    continue;
                }
                for (unsigned b = 0; b < B2; ++b) {
                    matrix[(s * T2 + j) * r + a * B2 + b] = quotient[j][b];
                }
            }
        }
    }
    return matrix;
}

// An nmod_mat_t with value semantics enough for this file.
class ModMatrix {
  public:
    ModMatrix(std::size_t rows, std::size_t columns, ulong p) {
        nmod_mat_init(m_, static_cast<slong>(rows), static_cast<slong>(columns), p);
    }
    ModMatrix(const ModMatrix& o) { nmod_mat_init_set(m_, o.m_); }
    ModMatrix& operator=(const ModMatrix&) = delete;
    ~ModMatrix() { nmod_mat_clear(m_); }
    nmod_mat_struct* get() { return m_; }
    const nmod_mat_struct* get() const { return m_; }
    ulong& at(std::size_t i, std::size_t j) { return nmod_mat_entry(m_, i, j); }
    ulong at(std::size_t i, std::size_t j) const { return nmod_mat_entry(m_, i, j); }

  private:
    nmod_mat_t m_;
};

// The inverse of the Vandermonde matrix on the nodes 0, 1, …, d modulo p: its product with
// the values at the nodes is the coefficient vector.
ModMatrix inverse_vandermonde(std::size_t d, ulong p) {
    ModMatrix v(d + 1, d + 1, p);
    const algebra::modular::PrimeField field(p);
    for (std::size_t i = 0; i <= d; ++i) {
        ulong power = 1;
        for (std::size_t j = 0; j <= d; ++j) {
            v.at(i, j) = power;
            power = field.multiply(power, i % p);
        }
    }
    ModMatrix inverse(d + 1, d + 1, p);
    if (!nmod_mat_inv(inverse.get(), v.get())) {
        throw Error("internal error: singular Vandermonde matrix");
    }
    return inverse;
}

// Coefficients of det(M₀ + x·M₁ + y·M₂ + z·M₃) modulo p, dense over exponents (a, b, c) of
// (x, y, z) with a, b, c ≤ r: index (a·(r+1) + b)·(r+1) + c.
std::vector<ulong> pencil_determinant(const std::array<ModMatrix, 4>& m, ulong p) {
    const std::size_t r = static_cast<std::size_t>(nmod_mat_nrows(m[0].get()));
    const std::size_t d = r;  // total degree bound
    const std::size_t n = d + 1;
    nmod_t mod;
    nmod_init(&mod, p);
    // values[(a·n + j)·n + k]: coefficient of v^a at u₁ = j, u₂ = k.
    std::vector<ulong> values(n * n * n);
    int pencil = -1;
    ModMatrix inverse(r, r, p);
    for (int v = 1; v <= 3 && pencil < 0; ++v) {
        if (nmod_mat_inv(inverse.get(), m[v].get())) {
            pencil = v;
        }
    }
    std::array<int, 3> role{1, 2, 3};  // (v, u₁, u₂) as indices of M
    if (pencil > 0) {
        role = pencil == 1   ? std::array{1, 2, 3}
               : pencil == 2 ? std::array{2, 1, 3}
                             : std::array{3, 1, 2};
        const ulong scale = nmod_mat_det(m[pencil].get());
        ModMatrix n0(r, r, p), n1(r, r, p), n2(r, r, p), c(r, r, p);
        nmod_mat_mul(n0.get(), inverse.get(), m[0].get());
        nmod_mat_mul(n1.get(), inverse.get(), m[role[1]].get());
        nmod_mat_mul(n2.get(), inverse.get(), m[role[2]].get());
        nmod_poly_t chi;
        nmod_poly_init(chi, p);
        for (std::size_t j = 0; j < n; ++j) {
            for (std::size_t k = 0; k < n; ++k) {
                for (std::size_t i = 0; i < r; ++i) {
                    for (std::size_t l = 0; l < r; ++l) {
                        ulong e = nmod_add(n0.at(i, l), nmod_mul(n1.at(i, l), j, mod), mod);
                        e = nmod_add(e, nmod_mul(n2.at(i, l), k, mod), mod);
                        c.at(i, l) = nmod_neg(e, c.get()->mod);
                    }
                }
                // det(A + v·B) = det B · det(v·I + B⁻¹A) = det B · charpoly(−B⁻¹A)(v)
                nmod_mat_charpoly(chi, c.get());
                for (std::size_t a = 0; a < n; ++a) {
                    values[(a * n + j) * n + k] =
                        nmod_mul(nmod_poly_get_coeff_ui(chi, static_cast<slong>(a)), scale, mod);
                }
            }
        }
        nmod_poly_clear(chi);
    } else {
        // No coordinate's matrix is invertible: evaluate the determinant on the full grid and
        // interpolate in x as well.
        ModMatrix a(r, r, p);
        std::vector<ulong> grid(n * n * n);
        for (std::size_t i = 0; i < n; ++i) {
            for (std::size_t j = 0; j < n; ++j) {
                for (std::size_t k = 0; k < n; ++k) {
                    for (std::size_t row = 0; row < r; ++row) {
                        for (std::size_t col = 0; col < r; ++col) {
                            ulong e = m[0].at(row, col);
                            e = nmod_add(e, nmod_mul(m[1].at(row, col), i, mod), mod);
                            e = nmod_add(e, nmod_mul(m[2].at(row, col), j, mod), mod);
                            e = nmod_add(e, nmod_mul(m[3].at(row, col), k, mod), mod);
                            a.at(row, col) = e;
                        }
                    }
                    grid[(i * n + j) * n + k] = nmod_mat_det(a.get());
                }
            }
        }
        const ModMatrix vinv = inverse_vandermonde(d, p);
        for (std::size_t jk = 0; jk < n * n; ++jk) {
            for (std::size_t deg = 0; deg < n; ++deg) {
                ulong sum = 0;
                for (std::size_t i = 0; i < n; ++i) {
                    sum = nmod_add(sum, nmod_mul(vinv.at(deg, i), grid[i * n * n + jk], mod), mod);
                }
                values[deg * n * n + jk] = sum;
            }
        }
    }
    // Interpolate in u₁ (index j) and then in u₂ (index k).
    const ModMatrix vinv = inverse_vandermonde(d, p);
    std::vector<ulong> line(n);
    for (int pass = 0; pass < 2; ++pass) {
        for (std::size_t a = 0; a < n; ++a) {
            for (std::size_t other = 0; other < n; ++other) {
                auto index = [&](std::size_t along) {
                    return pass == 0 ? (a * n + along) * n + other : (a * n + other) * n + along;
                };
                for (std::size_t deg = 0; deg < n; ++deg) {
                    ulong sum = 0;
                    for (std::size_t i = 0; i < n; ++i) {
                        sum = nmod_add(sum, nmod_mul(vinv.at(deg, i), values[index(i)], mod), mod);
                    }
                    line[deg] = sum;
                }
                for (std::size_t deg = 0; deg < n; ++deg) {
                    values[index(deg)] = line[deg];
                }
            }
        }
    }
    // Back to (x, y, z) exponents.
    std::vector<ulong> result(n * n * n);
    for (std::size_t a = 0; a < n; ++a) {
        for (std::size_t b = 0; b < n; ++b) {
            for (std::size_t c = 0; c < n; ++c) {
                std::array<std::size_t, 4> e{};
                e[static_cast<std::size_t>(role[0])] = a;
                e[static_cast<std::size_t>(role[1])] = b;
                e[static_cast<std::size_t>(role[2])] = c;
                result[(e[1] * n + e[2]) * n + e[3]] = values[(a * n + b) * n + c];
            }
        }
    }
    return result;
}

// Is the map's image two-dimensional? A non-zero 2 × 2 minor of the Jacobian of (P/W) at some
// rational point proves it; a few points are tried.
bool image_is_surface(const std::array<Polynomial, 4>& pw) {
    std::vector<std::array<Polynomial, 2>> partial;
    for (const auto& f : pw) {
        partial.push_back({f.derivative(0), f.derivative(1)});
    }
    for (long trial = 0; trial < 8; ++trial) {
        const std::vector<Rational> point{Rational(2 + 3 * trial, 7), Rational(5 + 2 * trial, 11)};
        const Rational w = pw[3].evaluate(point);
        const Rational ws = partial[3][0].evaluate(point), wt = partial[3][1].evaluate(point);
        std::array<std::array<Rational, 2>, 3> j{};
        for (std::size_t i = 0; i < 3; ++i) {
            const Rational p = pw[i].evaluate(point);
            // d(P/W) · W² = W·dP − P·dW
            j[i][0] = w * partial[i][0].evaluate(point) - p * ws;
            j[i][1] = w * partial[i][1].evaluate(point) - p * wt;
        }
        if (w.is_zero()) {
            continue;
        }
        for (std::size_t a = 0; a < 3; ++a) {
            for (std::size_t b = a + 1; b < 3; ++b) {
                if (!(j[a][0] * j[b][1] - j[a][1] * j[b][0]).is_zero()) {
                    return true;
                }
            }
        }
    }
    return false;
}

}  // namespace

ImplicitResult implicitize_by_dixon(const Parametrization& map,
                                    std::optional<std::chrono::steady_clock::time_point> deadline,
                                    int threads, std::size_t max_size) {
    const auto start = std::chrono::steady_clock::now();
    auto check_deadline = [&] {
        if (deadline_passed(deadline)) {
            throw Timeout("the Dixon route stopped at the deadline");
        }
    };
    if (map.parameter_ring->num_vars() != 2 || map.coordinates.size() != 3) {
        throw InputError("method dixon", "applies to surfaces (two parameters, x, y, z)");
    }
    // Over a common denominator W: (x, y, z) = (P1, P2, P3) / W.
    CommonDenominatorForm form = over_common_denominator(map);
    std::array<Polynomial, 4> pw{std::move(form.numerators[0]), std::move(form.numerators[1]),
                                 std::move(form.numerators[2]), std::move(form.denominator)};
    if (!image_is_surface(pw)) {
        throw Error("the Dixon route needs a map whose image is a surface");
    }
    unsigned m = 0, n = 0;
    Integer scale(1);
    for (const auto& f : pw) {
        m = std::max<unsigned>(m, static_cast<unsigned>(std::max<long>(0, f.degree(0))));
        n = std::max<unsigned>(n, static_cast<unsigned>(std::max<long>(0, f.degree(1))));
        for (std::size_t i = 0; i < f.num_terms(); ++i) {
            fmpz_lcm(scale.get(), scale.get(), fmpq_denref(f.coefficient(i).get()));
        }
    }
    const std::size_t full = 2 * static_cast<std::size_t>(m) * n;
    if (full == 0 || full > max_size) {
        throw Error("the Dixon matrix would have size " + std::to_string(full) + " (limit " +
                    std::to_string(max_size) + ")");
    }
    std::array<DenseBivariate, 4> g;
    for (std::size_t i = 0; i < 4; ++i) {
        g[i] = dense_of(pw[i], scale);
    }
    // det(P₁ − xW, P₂ − yW, P₃ − zW) = D(P₁,P₂,P₃) − x·D(W,P₂,P₃) − y·D(P₁,W,P₃) − z·D(P₁,P₂,W)
    std::array<std::vector<Integer>, 4> matrices{
        dixon_matrix({&g[0], &g[1], &g[2]}, m, n), dixon_matrix({&g[3], &g[1], &g[2]}, m, n),
        dixon_matrix({&g[0], &g[3], &g[2]}, m, n), dixon_matrix({&g[0], &g[1], &g[3]}, m, n)};
    for (std::size_t k = 1; k < 4; ++k) {
        for (auto& e : matrices[k]) {
            fmpz_neg(e.get(), e.get());
        }
    }
    check_deadline();
    // Rows and columns of a maximal non-singular submatrix, chosen at a random point modulo
    // the first prime: the whole matrix unless it is singular everywhere.
    std::mt19937_64 rng(20261126);
    algebra::modular::PrimeSequence prime_sequence(algebra::modular::PrimeSequence::Width::wide);
    ulong p = prime_sequence.next();
    auto reduce = [&](const std::vector<Integer>& full_matrix, const std::vector<slong>& rows,
                      const std::vector<slong>& columns, ulong prime) {
        ModMatrix result(rows.size(), columns.size(), prime);
        for (std::size_t i = 0; i < rows.size(); ++i) {
            for (std::size_t j = 0; j < columns.size(); ++j) {
                result.at(i, j) =
                    fmpz_fdiv_ui(full_matrix[static_cast<std::size_t>(rows[i]) * full +
                                             static_cast<std::size_t>(columns[j])]
                                     .get(),
                                 prime);
            }
        }
        return result;
    };
    std::vector<slong> rows, columns;
    {
        std::vector<slong> all(full);
        for (std::size_t i = 0; i < full; ++i) {
            all[i] = static_cast<slong>(i);
        }
        ModMatrix at_point = reduce(matrices[0], all, all, p);
        std::uniform_int_distribution<ulong> coordinate(1, p - 1);
        nmod_t mod;
        nmod_init(&mod, p);
        for (std::size_t k = 1; k < 4; ++k) {
            const ModMatrix mk = reduce(matrices[k], all, all, p);
            const ulong value = coordinate(rng);
            for (std::size_t i = 0; i < full; ++i) {
                for (std::size_t j = 0; j < full; ++j) {
                    at_point.at(i, j) =
                        nmod_add(at_point.at(i, j), nmod_mul(mk.at(i, j), value, mod), mod);
                }
            }
        }
        ModMatrix transpose(full, full, p);
        nmod_mat_transpose(transpose.get(), at_point.get());
        const auto pivots = [&](ModMatrix& echelon) {
            const slong rank = nmod_mat_rref(echelon.get());
            std::vector<slong> result;
            for (slong i = 0; i < rank; ++i) {
                slong j = 0;
                while (nmod_mat_entry(echelon.get(), i, j) == 0) {
                    ++j;
                }
                result.push_back(j);
            }
            return result;
        };
        columns = pivots(at_point);
        rows = pivots(transpose);
    }
    if (rows.empty()) {
        throw Error("the Dixon matrix vanishes identically");
    }
    const std::size_t r = rows.size();
    const std::size_t side = r + 1;
    // Monomials of total degree ≤ r in x, y, z, and their places in the dense images.
    std::vector<std::array<std::uint32_t, 3>> support;
    std::vector<std::size_t> place;
    for (std::uint32_t a = 0; a <= r; ++a) {
        for (std::uint32_t b = 0; a + b <= r; ++b) {
            for (std::uint32_t c = 0; a + b + c <= r; ++c) {
                support.push_back({a, b, c});
                place.push_back((a * side + b) * side + c);
            }
        }
    }
    std::optional<detail::NormalizedLifting> lifting;
    std::size_t pivot = 0;
    bool stable = false;
    // The determinant modulo one prime, restricted to the support.
    const auto image_modulo = [&](ulong prime) {
        algebra::release_flint_caches_at_thread_exit();  // on oneTBB's workers
        const std::array<ModMatrix, 4> reduced{
            reduce(matrices[0], rows, columns, prime), reduce(matrices[1], rows, columns, prime),
            reduce(matrices[2], rows, columns, prime), reduce(matrices[3], rows, columns, prime)};
        const std::vector<ulong> dense = pencil_determinant(reduced, prime);
        std::vector<ulong> image(support.size());
        for (std::size_t i = 0; i < support.size(); ++i) {
            image[i] = dense[place[i]];
        }
        return image;
    };
    // Primes in batches of `threads`, lifted in order: at most threads − 1 images beyond the
    // stable one are wasted.
    const std::size_t batch = static_cast<std::size_t>(std::max(1, threads));
    tbb::task_arena arena(static_cast<int>(batch));
    std::vector<ulong> primes;
    std::vector<std::vector<ulong>> images;
    for (std::size_t used = 0; used < 2000 && !stable; used += batch) {
        if (used > 0) {
            check_deadline();
        }
        primes.clear();
        for (std::size_t i = 0; i < batch; ++i) {
            primes.push_back(p);
            p = prime_sequence.next();
        }
        images.assign(batch, {});
        if (batch == 1) {
            images[0] = image_modulo(primes[0]);
        } else {
            arena.execute([&] {
                tbb::parallel_for(std::size_t{0}, batch,
                                  [&](std::size_t i) { images[i] = image_modulo(primes[i]); });
            });
        }
        for (std::size_t i = 0; i < batch && !stable; ++i) {
            const std::vector<ulong>& image = images[i];
            if (!lifting) {
                while (pivot < image.size() && image[pivot] == 0) {
                    ++pivot;
                }
                if (pivot == image.size()) {
                    throw Error("the Dixon determinant vanishes identically");
                }
                lifting.emplace(support.size(), pivot);
            } else if (image[pivot] == 0) {
                continue;  // an unlucky prime
            }
            stable = lifting->add(image, primes[i]);
        }
    }
    if (!stable) {
        throw Error("the Dixon route did not converge within 2000 primes");
    }
    ImplicitResult result;
    result.ring = algebra::PolyRing::make(map.coordinates, algebra::MonomialOrder::grevlex(3));
    std::vector<std::pair<Rational, std::vector<std::uint32_t>>> terms;
    for (std::size_t i = 0; i < support.size(); ++i) {
        if (!lifting->values()[i].is_zero()) {
            terms.emplace_back(lifting->values()[i],
                               std::vector<std::uint32_t>(support[i].begin(), support[i].end()));
        }
    }
    const Polynomial determinant = Polynomial::from_terms(result.ring, std::move(terms));
    check_deadline();
    const algebra::Factorization factors = algebra::factor(determinant);
    for (const auto& [factor, multiplicity] : factors.factors) {
        if (factor.total_degree() > 0 && vanishes_on(factor, map, threads)) {
            result.equation = factor;
            break;
        }
    }
    if (!result.equation) {
        throw Error("no factor of the Dixon determinant vanishes on the map");
    }
    result.generators = {*result.equation};
    result.proved_on_map = true;
    result.image = ImageKind::hypersurface;
    result.method = r == full ? "dixon" : "dixon-minor";
    result.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace locus::implicit
