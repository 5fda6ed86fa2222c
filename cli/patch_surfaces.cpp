#include "cli/patch_surfaces.h"

#include <flint/fmpq.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>

#include "algebra/error.h"
#include "algebra/print.h"
#include "algebra/real_roots.h"
#include "cli/command_support.h"
#include "cli/exit_codes.h"
#include "implicit/bezier_patch.h"
#include "implicit/implicitize.h"

namespace locus::cli {
namespace {

std::vector<implicit::BezierPatch> read_patches(const std::string& path, const std::string& text) {
    try {
        if (path.ends_with(".bpt") || implicit::looks_like_bpt(text)) {
            return implicit::parse_bpt(text);
        }
        return {implicit::parse_bezier_param(text, nullptr)};
    } catch (const Error& e) {
        throw failure_about(path, e);
    }
}

void append_terms(const algebra::Polynomial& f, std::vector<render::BivariateTerm>& terms) {
    for (std::size_t i = 0; i < f.num_terms(); ++i) {
        const auto e = f.exponents(i);
        terms.push_back(
            {fmpq_get_d(f.coefficient(i).get()), static_cast<int>(e[0]), static_cast<int>(e[1])});
    }
}

// The patch's map with double coefficients, for the trim test.
std::shared_ptr<const render::PatchTrim> trim_of(const implicit::BezierPatch& patch,
                                                 const algebra::RingPtr& ring) {
    const auto map = implicit::homogeneous_map(patch, ring);
    std::array<std::vector<render::BivariateTerm>, 4> terms;
    for (std::size_t c = 0; c < 4; ++c) {
        append_terms(map[c], terms[c]);
    }
    return std::make_shared<const render::PatchTrim>(
        std::move(terms), patch.kind == implicit::BezierPatch::Kind::triangle
                              ? render::PatchTrim::Domain::triangle
                              : render::PatchTrim::Domain::box);
}

// The box of the control points, widened by a millionth of its size (rounding of the decimals).
render::ClipBox box_of(const implicit::BezierPatch& patch) {
    render::ClipBox box{render::Vec3(INFINITY), render::Vec3(-INFINITY)};
    for (const auto& point : patch.points) {
        for (int c = 0; c < 3; ++c) {
            const double v = fmpq_get_d(point[static_cast<std::size_t>(c)].get());
            box.min[c] = std::min(box.min[c], v);
            box.max[c] = std::max(box.max[c], v);
        }
    }
    const double margin = 1e-6 * std::max(1.0, glm::length(box.max - box.min));
    box.min -= render::Vec3(margin);
    box.max += render::Vec3(margin);
    return box;
}

}  // namespace

// A frame centred on the box and scaled to it, and the equation f written in it:
// g(x') = f(origin + scale·x'), exactly (render/surface_frame.h says why). The origin is the
// box's centre rounded to a multiple of scale/1024, a dyadic number, so the double the renderer
// subtracts and the rational substituted here are the same number.
std::pair<render::SurfaceFrame, algebra::Polynomial> framed(const algebra::Polynomial& f,
                                                            const render::ClipBox& box) {
    render::SurfaceFrame frame;
    const render::Vec3 half = 0.5 * (box.max - box.min);
    frame.scale = render::power_of_two_at_least(std::max({half.x, half.y, half.z}));
    const double grid = frame.scale / 1024.0;
    const algebra::RingPtr& ring = f.ring();
    std::vector<algebra::Polynomial> values;
    for (std::size_t var = 0; var < ring->num_vars(); ++var) {
        values.push_back(algebra::Polynomial::variable(ring, var));
    }
    for (int c = 0; c < 3; ++c) {
        frame.origin[c] = std::round(0.5 * (box.min[c] + box.max[c]) / grid) * grid;
        const auto var = ring->variable_index(std::string(1, static_cast<char>('x' + c)));
        if (!var) {
            continue;
        }
        algebra::Rational origin, scale;
        algebra::set_exact_double(origin.get(), frame.origin[c]);
        algebra::set_exact_double(scale.get(), frame.scale);
        values[*var] = algebra::Polynomial::constant(ring, origin) +
                       algebra::Polynomial::constant(ring, scale) * values[*var];
    }
    // Divided by its (positive) content, not made primitive: primitive_part() also makes the
    // leading coefficient positive, and the sides f > 0 and f < 0 must stay the equation's.
    const algebra::Polynomial local = f.substitute(values);
    if (local.is_zero()) {
        return {frame, local};
    }
    algebra::Rational inverse;
    fmpq_inv(inverse.get(), local.content().get());
    return {frame, local * inverse};
}

void trim_to_domain(const std::string& path, const std::string& text, render::Surface& surface) {
    implicit::Parametrization map;
    try {
        map = implicit::parse_parametrization(text);
    } catch (const Error& e) {
        throw failure_about(path, e);
    }
    if (map.domain.empty() || map.parameter_ring->num_vars() != 2) {
        return;
    }
    const implicit::CommonDenominatorForm form = implicit::over_common_denominator(map);
    std::array<std::vector<render::BivariateTerm>, 4> terms;
    for (std::size_t i = 0; i < 3 && i < form.numerators.size(); ++i) {
        append_terms(form.numerators[i], terms[i]);
    }
    append_terms(form.denominator, terms[3]);
    const render::PatchTrim::Box domain{
        fmpq_get_d(map.domain[0].first.get()), fmpq_get_d(map.domain[0].second.get()),
        fmpq_get_d(map.domain[1].first.get()), fmpq_get_d(map.domain[1].second.get())};
    auto trim = std::make_shared<const render::PatchTrim>(std::move(terms),
                                                          render::PatchTrim::Domain::box, domain);
    // The clip box: the image of a 65 × 65 grid of the domain, widened by 5 % of its diagonal
    // on every side (sampled, not proved: a patch that bulges further between samples is cut).
    render::ClipBox box{render::Vec3(INFINITY), render::Vec3(-INFINITY)};
    constexpr int kGrid = 64;
    for (int i = 0; i <= kGrid; ++i) {
        for (int j = 0; j <= kGrid; ++j) {
            const render::Vec3 p = trim->at(domain.s0 + (domain.s1 - domain.s0) * i / kGrid,
                                            domain.t0 + (domain.t1 - domain.t0) * j / kGrid);
            if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) {
                box.min = glm::min(box.min, p);
                box.max = glm::max(box.max, p);
            }
        }
    }
    if (!(box.min.x <= box.max.x)) {
        throw CommandFailure(exit_input, path + ": the domain's image has no finite point");
    }
    const double margin = 0.05 * std::max(1e-9, glm::length(box.max - box.min));
    box.min -= render::Vec3(margin);
    box.max += render::Vec3(margin);
    surface.clip = box;
    surface.fit_clip = false;
    surface.trim = std::move(trim);
}

bool holds_patches(const std::string& path, const std::string& text) {
    if (path.ends_with(".bpt") || implicit::looks_like_bpt(text)) {
        return true;
    }
    for (const auto& [line, number] : algebra::split_lines(text)) {
        const std::size_t start = line.find_first_not_of(" \t");
        if (start != std::string_view::npos && line.substr(start).starts_with("bezier") &&
            line.find(':') != std::string_view::npos) {
            return true;
        }
    }
    return false;
}

std::vector<render::Surface> patch_surfaces(const std::string& path, const std::string& text,
                                            Deadline deadline) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<implicit::BezierPatch> patches = read_patches(path, text);
    std::vector<render::Surface> surfaces;
    std::map<std::string, int> routes;
    for (std::size_t k = 0; k < patches.size(); ++k) {
        const std::string name = path + ": patch " + std::to_string(k + 1);
        const implicit::Parametrization map = implicit::to_parametrization(patches[k]);
        algebra::GroebnerOptions options;
        options.deadline = deadline;
        implicit::ImplicitResult result;
        try {
            result = implicit::implicitize_auto(map, options);
        } catch (const Timeout&) {
            throw;
        } catch (const Error& e) {
            throw CommandFailure(exit_input, name + ": " + e.what());
        }
        if (!result.equation) {
            throw CommandFailure(exit_input, name + ": " +
                                                 implicit::describe_image(result.image, 2, 3) +
                                                 "; there is no surface to render");
        }
        if (!result.proved_on_map && !implicit::vanishes_on(*result.equation, map)) {
            throw CommandFailure(exit_check_failed,
                                 name +
                                     ": verification FAILED: the implicit equation does not "
                                     "vanish on the patch");
        }
        ++routes[result.method];
        render::Surface surface;
        surface.clip = box_of(patches[k]);
        auto [frame, local] = framed(*result.equation, std::get<render::ClipBox>(surface.clip));
        surface.equation = algebra::to_string(local);
        surface.frame = frame;
        surface.source = name;
        surface.fit_clip = false;
        surface.trim = trim_of(patches[k], map.parameter_ring);
        // Which side of a patch's implicit surface is "inside" depends on the sign its equation
        // happened to get: one colour for both sides.
        surface.material = render::Material::plain(render::Material{}.color);
        surfaces.push_back(std::move(surface));
    }
    std::string summary;
    for (const auto& [route, count] : routes) {
        summary += (summary.empty() ? "" : ", ") + route + " " + std::to_string(count);
    }
    std::fprintf(stderr, "%s: %zu patch%s implicitized and verified (%s) in %.2f s\n", path.c_str(),
                 patches.size(), patches.size() == 1 ? "" : "es", summary.c_str(),
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    return surfaces;
}

}  // namespace locus::cli
