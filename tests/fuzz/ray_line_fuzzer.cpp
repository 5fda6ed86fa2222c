// The `locus trace` ray-line reader (render/ray_line.h) on arbitrary bytes, and, for every ray
// it accepts, a differential check of the default method on t in (0, 100], for a sphere, a
// torus and a surface with a singular point: the certified first hit against exact isolation
// over Q (algebra::exact_first_root, the certified method's last tier), and both against the
// tests' exact oracle (tests/support/exact_ray_oracle.h: FLINT's parser and Sturm sequences,
// which share no code with either). A certified answer may be "unknown", never wrong.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string_view>

#include "algebra/compiled.h"
#include "algebra/error.h"
#include "render/ray_line.h"
#include "render/surface_tracer.h"
#include "tests/fuzz/fuzz_input.h"
#include "tests/support/exact_ray_oracle.h"

namespace {

constexpr const char* kEquations[] = {
    "x^2+y^2+z^2-1", "(x^2+y^2+z^2+3)^2-16*(x^2+y^2)",
    "x^2+y^2-z^3",  // a cusp at the origin
};

const locus::algebra::CompiledPolynomial& surface(std::size_t which) {
    static const locus::algebra::CompiledPolynomial surfaces[] = {
        locus::algebra::compile_surface(kEquations[0]),
        locus::algebra::compile_surface(kEquations[1]),
        locus::algebra::compile_surface(kEquations[2]),
    };
    return surfaces[which % 3];
}

const locus::test::ExactRayOracle& oracle(std::size_t which) {
    static const locus::test::ExactRayOracle oracles[] = {
        locus::test::ExactRayOracle(kEquations[0]),
        locus::test::ExactRayOracle(kEquations[1]),
        locus::test::ExactRayOracle(kEquations[2]),
    };
    return oracles[which % 3];
}

void check_ray(const locus::render::Ray& ray, std::size_t which, std::string_view input) {
    const locus::algebra::CompiledPolynomial& f = surface(which);
    const double t_max = 100.0;
    const locus::algebra::ExactRoot exact = locus::algebra::exact_first_root(
        f, {ray.origin.x, ray.origin.y, ray.origin.z},
        {ray.direction.x, ray.direction.y, ray.direction.z}, 0.0, t_max, true);
    if (exact.status == locus::algebra::ExactRoot::Status::identically_zero) {
        return;  // the ray lies in the surface: every t is a root
    }
    const locus::render::SurfaceTracer tracer(f, locus::render::TraceMethod::certified, 1.0);
    const locus::render::RootResult hit = tracer.first_hit(ray, {0.0, t_max});
    if (hit.status == locus::render::RootStatus::unknown) {
        return;
    }
    const bool exact_hit = exact.status == locus::algebra::ExactRoot::Status::hit;
    // Both against the independent oracle: exact's t is the double nearest the root (within
    // an ulp), the certified t within its tolerance.
    const std::array<double, 3> origin{ray.origin.x, ray.origin.y, ray.origin.z};
    const std::array<double, 3> direction{ray.direction.x, ray.direction.y, ray.direction.z};
    const locus::test::ExactRayOracle::Restriction restriction =
        oracle(which).restrict(origin, direction);
    if (!locus::test::ExactRayOracle::is_right(restriction, t_max, exact_hit, exact.t, 1e-15)) {
        std::fprintf(stderr, "surface %zu: exact %s (t = %.17g) against the oracle\n", which % 3,
                     exact_hit ? "hits" : "misses", exact.t);
        locus::fuzz::property_failed("exact isolation disagrees with the Sturm oracle", input);
    }
    if ((hit.status == locus::render::RootStatus::hit) != exact_hit) {
        std::fprintf(stderr, "surface %zu: certified %s, exact %s (t = %.17g)\n", which % 3,
                     exact_hit ? "misses" : "hits", exact_hit ? "hits" : "misses",
                     exact_hit ? exact.t : hit.t);
        locus::fuzz::property_failed("certified and exact disagree on hit or miss", input);
    }
    if (!locus::test::ExactRayOracle::is_right(
            restriction, t_max, hit.status == locus::render::RootStatus::hit, hit.t, 1e-12)) {
        std::fprintf(stderr, "surface %zu: certified %s (t = %.17g) against the oracle\n",
                     which % 3, hit.status == locus::render::RootStatus::hit ? "hits" : "misses",
                     hit.t);
        locus::fuzz::property_failed("certified answer disagrees with the Sturm oracle", input);
    }
    // The contract: within 1e-12·max(1, |t*|), plus the ulp by which exact's t may differ.
    if (exact_hit && std::abs(hit.t - exact.t) > 1.01e-12 * std::max(1.0, std::abs(exact.t))) {
        std::fprintf(stderr, "surface %zu: certified t = %.17g, exact t = %.17g\n", which % 3,
                     hit.t, exact.t);
        locus::fuzz::property_failed("certified hit outside its tolerance", input);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto text = locus::fuzz::input_text(data, size);
    if (!text) {
        return 0;
    }
    std::size_t line = 0;
    std::size_t rays = 0;
    for (std::size_t start = 0; start <= text->size() && rays < 4;) {
        const std::size_t newline = std::min(text->find('\n', start), text->size());
        ++line;
        try {
            if (const auto ray =
                    locus::render::parse_ray_line(text->substr(start, newline - start), line)) {
                check_ray(*ray, size + line, *text);
                ++rays;
            }
        } catch (const locus::Error&) {
            return 0;  // like `locus trace`, which stops at the first bad line
        }
        start = newline + 1;
    }
    return 0;
}
