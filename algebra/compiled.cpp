#include "algebra/compiled.h"

#include <flint/fmpq_poly.h>

#include <cmath>

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
}

const std::string& CompiledPolynomial::equation() const {
    return exact_->equation;
}

double CompiledPolynomial::value(const Point3& p) const {
    std::array<std::array<double, kMaxCompiledDegree + 1>, 3> powers;
    for (int axis = 0; axis < 3; ++axis) {
        powers[axis][0] = 1.0;
        for (int k = 1; k <= degree_; ++k) {
            powers[axis][k] = powers[axis][k - 1] * p[axis];
        }
    }
    double sum = 0.0;
    for (const CompiledTerm& term : terms_) {
        sum += term.coefficient * powers[0][term.ex] * powers[1][term.ey] * powers[2][term.ez];
    }
    return sum;
}

ValueGradient CompiledPolynomial::value_gradient(const Point3& p) const {
    // powers[axis][k + 1] = p^k, powers[axis][0] = 0 stands for p^(−1)·0 in the derivative.
    std::array<std::array<double, kMaxCompiledDegree + 2>, 3> powers;
    for (int axis = 0; axis < 3; ++axis) {
        powers[axis][0] = 0.0;
        powers[axis][1] = 1.0;
        for (int k = 1; k <= degree_; ++k) {
            powers[axis][k + 1] = powers[axis][k] * p[axis];
        }
    }
    ValueGradient result{0.0, {0.0, 0.0, 0.0}};
    for (const CompiledTerm& t : terms_) {
        const double px = powers[0][t.ex + 1], py = powers[1][t.ey + 1], pz = powers[2][t.ez + 1];
        const double c = t.coefficient;
        result.value += c * px * py * pz;
        result.gradient[0] += c * t.ex * powers[0][t.ex] * py * pz;
        result.gradient[1] += c * t.ey * px * powers[1][t.ey] * pz;
        result.gradient[2] += c * t.ez * px * py * powers[2][t.ez];
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
    fmpq_t value;
    fmpq_init(value);
    for (int axis = 0; axis < 3; ++axis) {
        fmpq_poly_init(line[axis]);
        set_exact_double(value, origin[axis]);
        fmpq_poly_set_coeff_fmpq(line[axis], 0, value);
        set_exact_double(value, direction[axis]);
        fmpq_poly_set_coeff_fmpq(line[axis], 1, value);
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
        fmpq_t lo_exact, hi_exact;
        fmpq_init(lo_exact);
        fmpq_init(hi_exact);
        set_exact_double(lo_exact, lo);
        set_exact_double(hi_exact, hi);
        const std::optional<double> root =
            first_real_root(integer_restriction, lo_exact, hi_exact, lo_open);
        if (root) {
            result.status = ExactRoot::Status::hit;
            result.t = *root;
        }
        fmpq_clear(lo_exact);
        fmpq_clear(hi_exact);
        fmpz_poly_clear(integer_restriction);
    }
    fmpq_poly_clear(restriction);
    fmpq_poly_clear(derivative);
    fmpq_poly_clear(common);
    for (auto& l : line) {
        fmpq_poly_clear(l);
    }
    fmpq_clear(value);
    return result;
}

}  // namespace locus::algebra
