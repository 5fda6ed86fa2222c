#include "implicit/implicitize.h"

#include <algorithm>
#include <chrono>
#include <numeric>

#include "algebra/error.h"
#include "algebra/flint_convert.h"
#include "algebra/ideal_ops.h"
#include "implicit/dixon.h"

namespace locus::implicit {

using algebra::MonomialOrder;
using algebra::Polynomial;
using algebra::PolyRing;
using algebra::Rational;
using algebra::RingPtr;

namespace {

// Q[params, (w,) x, y(, z)] under grevlex, with w given a fresh name; the coordinates start at
// the returned index.
std::pair<RingPtr, std::size_t> joint_ring(const Parametrization& map, bool with_w) {
    std::vector<std::string> names = map.parameter_ring->variable_names();
    if (with_w) {
        std::string w_name = "w";
        while (std::find(names.begin(), names.end(), w_name) != names.end() ||
               std::find(map.coordinates.begin(), map.coordinates.end(), w_name) !=
                   map.coordinates.end()) {
            w_name += "_";
        }
        names.push_back(w_name);
    }
    const std::size_t first_coordinate = names.size();
    for (const auto& c : map.coordinates) {
        if (std::find(names.begin(), names.end(), c) != names.end()) {
            throw InputError("'" + c + "'", "a parameter may not be named like a coordinate");
        }
        names.push_back(c);
    }
    return {PolyRing::make(names, MonomialOrder::grevlex(names.size())), first_coordinate};
}

// qᵢ·xᵢ − pᵢ for every coordinate, in the joint ring.
std::vector<Polynomial> coordinate_relations(const Parametrization& map, const RingPtr& ring,
                                             std::size_t first_coordinate) {
    std::vector<std::size_t> lift(map.parameter_ring->num_vars());
    std::iota(lift.begin(), lift.end(), 0);
    std::vector<Polynomial> relations;
    for (std::size_t i = 0; i < map.coordinates.size(); ++i) {
        relations.push_back(map.components[i].denominator().in_ring(ring, lift) *
                                Polynomial::variable(ring, first_coordinate + i) -
                            map.components[i].numerator().in_ring(ring, lift));
    }
    return relations;
}

}  // namespace

EliminationIdeal elimination_ideal(const Parametrization& map) {
    const std::size_t k = map.parameter_ring->num_vars();
    bool rational = false;
    for (const auto& c : map.components) {
        rational = rational || !c.is_polynomial();
    }
    const auto [big, first_coordinate] = joint_ring(map, rational);
    std::vector<Polynomial> generators = coordinate_relations(map, big, first_coordinate);
    if (rational) {
        std::vector<std::size_t> lift(k);
        std::iota(lift.begin(), lift.end(), 0);
        Polynomial denominators = Polynomial::constant(big, Rational(1));
        for (const auto& c : map.components) {
            denominators *= c.denominator().in_ring(big, lift);
        }
        // Saturating by the product of the denominators or by its square-free part gives the
        // same ideal (saturation depends only on the radical), and the square-free part keeps
        // the degree of w·q low: the trigonometric torus, whose denominators multiply to
        // (1+u²)²(1+v²)³, took 22 s with the product.
        generators.push_back(Polynomial::constant(big, Rational(1)) -
                             Polynomial::variable(big, k) *
                                 algebra::square_free_part(denominators));
    }
    EliminationIdeal ideal{big, std::move(generators), {}, first_coordinate};
    ideal.eliminated.resize(first_coordinate);
    std::iota(ideal.eliminated.begin(), ideal.eliminated.end(), 0);
    return ideal;
}

ImplicitResult implicitize(const Parametrization& map, const algebra::GroebnerOptions& options) {
    const EliminationIdeal ideal = elimination_ideal(map);
    const std::size_t n = map.coordinates.size();
    const std::size_t first_coordinate = ideal.first_coordinate;
    const std::vector<std::string>& names = ideal.ring->variable_names();
    const auto start = std::chrono::steady_clock::now();
    const std::vector<Polynomial> kept =
        algebra::eliminate(ideal.generators, ideal.eliminated, options);

    ImplicitResult result;
    result.ring = PolyRing::make(map.coordinates, MonomialOrder::grevlex(n));
    std::vector<std::size_t> down(names.size(), 0);
    for (std::size_t i = 0; i < n; ++i) {
        down[first_coordinate + i] = i;
    }
    std::vector<Polynomial> in_coordinates;
    for (const auto& g : kept) {
        in_coordinates.push_back(g.in_ring(result.ring, down));
    }
    if (!in_coordinates.empty()) {
        // The basis in the coordinates' own ring, under the same deadline as the elimination
        // (it ran without one: a hostile map could hold --timeout up here).
        algebra::GroebnerOptions graded;
        graded.deadline = options.deadline;
        graded.threads = options.threads;
        in_coordinates = algebra::basis_of(in_coordinates, graded);
    }
    result.generators = std::move(in_coordinates);
    result.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (result.generators.size() == 1) {
        result.equation = result.generators[0].primitive_part();
        result.image = ImageKind::hypersurface;
    } else if (result.generators.empty()) {
        result.image = ImageKind::dense;
    } else {
        const auto dim = algebra::zero_dimension_test(result.generators);
        result.image = dim.kind == algebra::Dimension::zero_dimensional
                           ? ImageKind::point
                           : ImageKind::lower_dimensional;
    }
    return result;
}

namespace {

// f(x(u), y(u), z(u)) == 0 at one rational parameter point u where no denominator vanishes:
// necessary for f to vanish on the map, and exact.
bool vanishes_at_sample(const Polynomial& f, const Parametrization& map) {
    const std::size_t k = map.parameter_ring->num_vars();
    for (long attempt = 0; attempt < 8; ++attempt) {
        std::vector<Rational> u;
        for (std::size_t i = 0; i < k; ++i) {
            u.emplace_back(static_cast<long>(3 + 2 * i + attempt), 7UL + 4 * i);
        }
        std::vector<Rational> point;
        bool defined = true;
        for (const auto& c : map.components) {
            const Rational q = c.denominator().evaluate(u);
            if (q.is_zero()) {
                defined = false;
                break;
            }
            point.push_back(c.numerator().evaluate(u) / q);
        }
        if (defined) {
            return f.evaluate(point).is_zero();
        }
    }
    return true;  // every sample hit a pole: let the exact check decide
}

}  // namespace

ImplicitResult implicitize_by_resultant(const Parametrization& map) {
    const RingPtr& params = map.parameter_ring;
    const std::size_t k = params->num_vars();
    const std::size_t n = map.coordinates.size();
    if (!((k == 1 && n == 2) || (k == 2 && n == 3))) {
        throw InputError("method resultant",
                         "applies to plane curves (one parameter, x and y) "
                         "and surfaces (two parameters, x, y and z) only");
    }
    const auto start = std::chrono::steady_clock::now();
    const auto [big, first_coordinate] = joint_ring(map, false);
    const std::vector<Polynomial> h = coordinate_relations(map, big, first_coordinate);
    const std::vector<std::string>& names = big->variable_names();
    Polynomial r = k == 1 ? algebra::resultant(h[0], h[1], 0)
                          : algebra::resultant(algebra::resultant(h[0], h[1], 0),
                                               algebra::resultant(h[0], h[2], 0), 1);
    if (r.is_zero()) {
        throw Error("the resultant vanishes identically (the map is degenerate for this route)");
    }
    ImplicitResult result;
    result.method = "resultant";
    result.ring = PolyRing::make(map.coordinates, MonomialOrder::grevlex(n));
    std::vector<std::size_t> down(names.size(), 0);
    for (std::size_t i = 0; i < n; ++i) {
        down[k + i] = i;
    }
    const Polynomial in_coordinates = r.in_ring(result.ring, down);
    for (const auto& [factor, multiplicity] : algebra::factor(in_coordinates).factors) {
        // The exact substitution of an extraneous factor of high degree is expensive (a
        // degree-18 factor of a cubic Bézier triangle took 9 s); one exact evaluation at a
        // rational parameter point rules most of them out first.
        if (!factor.is_constant() && vanishes_at_sample(factor, map) && vanishes_on(factor, map)) {
            result.equation = factor.primitive_part();
            break;
        }
    }
    if (!result.equation) {
        throw Error("no factor of the resultant vanishes on the parametrization");
    }
    result.generators = {*result.equation};
    result.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

namespace {

// The symbolic check: Σ c_α Π pᵢ^αᵢ qᵢ^(dᵢ−αᵢ) expanded in the parameter ring.
}  // namespace

std::string describe_image(ImageKind kind, std::size_t num_params, std::size_t num_coordinates) {
    switch (kind) {
    case ImageKind::hypersurface:
        return num_coordinates == 2 ? "the image is a plane curve" : "the image is a surface";
    case ImageKind::point:
        return "the map is constant: its image is a point, cut out by one linear equation per "
               "coordinate, so there is no single implicit equation";
    case ImageKind::lower_dimensional:
        return num_params == 1 && num_coordinates == 3
                   ? "the image is a curve in space: a curve needs at least two equations, so "
                     "the elimination ideal is not principal; all its generators are printed"
                   : "the image has lower dimension than the parameter count suggests (the map "
                     "is degenerate): the elimination ideal is not principal; all its "
                     "generators are printed";
    case ImageKind::dense:
        return "no polynomial vanishes on the image: it fills the whole space";
    }
    return "";
}

namespace {

// The most terms of a component's numerator or of the common denominator.
std::size_t most_terms(const Parametrization& map) {
    const CommonDenominatorForm form = over_common_denominator(map);
    std::size_t most = form.denominator.num_terms();
    for (const Polynomial& n : form.numerators) {
        most = std::max(most, n.num_terms());
    }
    return most;
}

}  // namespace

// Why this order: every classic case but one finishes elimination in under 5 ms (Enneper in
// 1.2 ms, where interpolation needs 25 ms of primes), and interpolation answers where
// elimination does not (the cubic Bézier triangle in 0.14 s, where resultants take 2.5 s and
// elimination over 30 s).
ImplicitResult implicitize_auto(const Parametrization& map, const algebra::GroebnerOptions& options,
                                std::string* fallback_reason) {
    auto note_fallback = [&](const char* reason) {
        if (fallback_reason != nullptr) {
            *fallback_reason += (fallback_reason->empty() ? "" : "; ") + std::string(reason);
        }
    };
    const std::size_t num_params = map.parameter_ring->num_vars();
    const bool one_equation = (num_params == 1 && map.coordinates.size() == 2) ||
                              (num_params == 2 && map.coordinates.size() == 3);
    // Dense surface maps go straight to the Dixon determinant, without the probe below: the
    // Bézier patches of the bench (every numerator or denominator with 9–16 terms over a common
    // denominator) never finished elimination in the probe's 20 ms, which then only added to
    // Dixon's time (the rational biquadratic patch 3 → 25 ms, the teapot's 32 patches 0.3 s),
    // while every classic map has at most 6 terms (Steiner's Roman surface, the trigonometric
    // torus) and finishes elimination in under 5 ms. Decided from the map, not from time; a
    // dense map whose image is not a surface still ends in elimination, below.
    constexpr std::size_t kDenseTerms = 9;
    const bool dense_surface = num_params == 2 && one_equation && most_terms(map) >= kDenseTerms;
    if (one_equation && !dense_surface) {
        // A 20 ms Gröbner probe first: elimination wins on small maps with large coefficients
        // (Enneper: 1.2 ms against 25 ms of primes), interpolation on large supports.
        algebra::GroebnerOptions probe = options;
        const auto probe_deadline =
            std::chrono::steady_clock::now() + std::chrono::milliseconds(20);
        probe.deadline =
            options.deadline ? std::min(*options.deadline, probe_deadline) : probe_deadline;
        try {
            return implicitize(map, probe);
        } catch (const Timeout&) {
            // go on with the structured routes
        }
    }
    if (one_equation) {
        if (num_params == 2) {
            // The Dixon determinant: one characteristic polynomial per grid line and prime,
            // where interpolation needs an elimination of the whole support per prime (the
            // bicubic patch: 18 × 18 pencils against a 1330-column kernel).
            try {
                return implicitize_by_dixon(map, options.deadline, options.threads);
            } catch (const Timeout&) {
                throw;
            } catch (const Error& e) {
                note_fallback(e.what());
            }
        }
        try {
            return implicitize_by_interpolation(map, options.deadline);
        } catch (const Timeout&) {
            throw;
        } catch (const Error& e) {
            note_fallback(e.what());
        }
        try {
            return implicitize_by_resultant(map);
        } catch (const InputError&) {
            throw;
        } catch (const Error& e) {
            note_fallback(e.what());
        }
    }
    return implicitize(map, options);
}

std::optional<ImplicitMethod> parse_implicit_method(std::string_view name) {
    if (name == "auto") {
        return ImplicitMethod::automatic;
    }
    if (name == "groebner") {
        return ImplicitMethod::groebner;
    }
    if (name == "resultant") {
        return ImplicitMethod::resultant;
    }
    if (name == "interpolate") {
        return ImplicitMethod::interpolate;
    }
    if (name == "dixon") {
        return ImplicitMethod::dixon;
    }
    return std::nullopt;
}

ImplicitResult implicitize_by(const Parametrization& map, ImplicitMethod method,
                              const algebra::GroebnerOptions& options,
                              std::string* fallback_reason) {
    switch (method) {
    case ImplicitMethod::automatic:
        return implicitize_auto(map, options, fallback_reason);
    case ImplicitMethod::resultant:
        return implicitize_by_resultant(map);
    case ImplicitMethod::interpolate:
        return implicitize_by_interpolation(map, options.deadline);
    case ImplicitMethod::dixon:
        return implicitize_by_dixon(map, options.deadline, options.threads);
    case ImplicitMethod::groebner:
        break;
    }
    return implicitize(map, options);
}

}  // namespace locus::implicit
