#include "algebra/compiled.h"

#include <flint/fmpq_poly.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "algebra/error.h"
#include "algebra/flint_convert.h"
#include "algebra/parse.h"
#include "algebra/print.h"
#include "algebra/real_roots.h"

namespace locus::algebra {

// The exact side, shared by all copies: the square-free polynomial in the ring x, y, z and its
// FLINT form for composing with a ray (read-only after construction, so safe across threads).
struct CompiledPolynomial::Exact {
    Polynomial f;
    std::string equation;
    std::unique_ptr<FlintContext> context;
    std::unique_ptr<FlintPolynomial> flint_f;

    explicit Exact(Polynomial polynomial)
        : f(std::move(polynomial)),
          equation(to_string(f)),
          context(std::make_unique<FlintContext>(f.ring())),
          flint_f(std::make_unique<FlintPolynomial>(to_fmpq_mpoly(f, *context))) {}
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
    terms_.reserve(f.num_terms());
    for (std::size_t i = 0; i < f.num_terms(); ++i) {
        const std::vector<std::uint32_t> e = f.exponents(i);
        terms_.push_back({fmpq_get_d(f.coefficient(i).get()), static_cast<int>(e[0]),
                          static_cast<int>(e[1]), static_cast<int>(e[2])});
    }
    std::sort(terms_.begin(), terms_.end(), [](const CompiledTerm& p, const CompiledTerm& q) {
        return std::tie(p.ex, p.ey, p.ez) < std::tie(q.ex, q.ey, q.ez);
    });
    for (std::size_t i = 0; i < terms_.size(); ++i) {
        const CompiledTerm& t = terms_[i];
        if (groups_.empty() || groups_.back().ex != t.ex || groups_.back().ey != t.ey) {
            groups_.push_back(
                {t.ex, t.ey, static_cast<double>(t.ex), static_cast<double>(t.ey), i, i});
        }
        groups_.back().end = i + 1;
        coefficients_.push_back(t.coefficient);
        z_slopes_.push_back(t.coefficient * t.ez);
        z_exponents_.push_back(t.ez);
    }
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
    Polynomial reduced = square_free_part(g);
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
    const CompiledPolynomial::Exact& exact = *f.exact_;
    // The ray's coordinates o_i + t·d_i as exact univariate polynomials.
    std::array<fmpq_poly_t, 3> line;
    std::array<fmpq_poly_struct*, 3> line_pointers;
    Rational value;
    for (int axis = 0; axis < 3; ++axis) {
        fmpq_poly_init(line[axis]);
        set_exact_double(value.get(), origin[axis]);
        fmpq_poly_set_coeff_fmpq(line[axis], 0, value.get());
        set_exact_double(value.get(), direction[axis]);
        fmpq_poly_set_coeff_fmpq(line[axis], 1, value.get());
        line_pointers[axis] = line[axis];
    }
    fmpq_poly_t restriction, derivative, common;
    fmpq_poly_init(restriction);
    fmpq_poly_init(derivative);
    fmpq_poly_init(common);
    fmpq_mpoly_compose_fmpq_poly(restriction, exact.flint_f->get(), line_pointers.data(),
                                 exact.context->get());
    ExactRoot result;
    if (fmpq_poly_is_zero(restriction)) {
        result.status = ExactRoot::Status::identically_zero;
        result.t = lo;
    } else {
        // Square-free part F / gcd(F, F'): every distinct root, whatever its multiplicity.
        fmpq_poly_derivative(derivative, restriction);
        fmpq_poly_gcd(common, restriction, derivative);
        fmpq_poly_div(restriction, restriction, common);
        fmpz_poly_t integer_restriction;
        fmpz_poly_init(integer_restriction);
        fmpq_poly_get_numerator(integer_restriction, restriction);
        Rational lo_exact, hi_exact;
        set_exact_double(lo_exact.get(), lo);
        set_exact_double(hi_exact.get(), hi);
        const std::optional<double> root =
            first_real_root(integer_restriction, lo_exact.get(), hi_exact.get(), lo_open);
        if (root) {
            result.status = ExactRoot::Status::hit;
            result.t = *root;
        }
        fmpz_poly_clear(integer_restriction);
    }
    fmpq_poly_clear(restriction);
    fmpq_poly_clear(derivative);
    fmpq_poly_clear(common);
    for (auto& l : line) {
        fmpq_poly_clear(l);
    }
    return result;
}

}  // namespace locus::algebra
