#include "view/frame_builder.h"

#include <cctype>
#include <cmath>
#include <sstream>

#include "algebra/error.h"
#include "algebra/parse.h"
#include "algebra/poly_ring.h"
#include "render/framing.h"
#include "render/trace_method.h"

namespace locus::view {
namespace {

[[noreturn]] void refuse(const std::string& name, const std::string& message) {
    throw RequestError{name + ": " + message, name};
}

std::vector<double> numbers(const Fields& fields, const std::string& name, std::size_t count) {
    const auto text = field(fields, name);
    if (!text) {
        refuse(name, "missing");
    }
    std::vector<double> out;
    std::stringstream in(*text);
    for (std::string item; std::getline(in, item, ',');) {
        char* end = nullptr;
        const double value = std::strtod(item.c_str(), &end);
        if (end == item.c_str() || *end != '\0' || !std::isfinite(value)) {
            refuse(name, "expected " + std::to_string(count) + " numbers separated by commas");
        }
        out.push_back(value);
    }
    if (out.size() != count) {
        refuse(name, "expected " + std::to_string(count) + " numbers separated by commas");
    }
    return out;
}

int integer(const Fields& fields, const std::string& name, int low, int high) {
    const double value = numbers(fields, name, 1)[0];
    if (value != std::floor(value) || value < low || value > high) {
        refuse(name,
               "expected an integer from " + std::to_string(low) + " to " + std::to_string(high));
    }
    return static_cast<int>(value);
}

render::Vec3 colour(const Fields& fields, const std::string& name) {
    const std::vector<double> c = numbers(fields, name, 3);
    for (const double v : c) {
        if (v < 0.0 || v > 1.0) {
            refuse(name, "expected a linear colour R,G,B with each value from 0 to 1");
        }
    }
    return {c[0], c[1], c[2]};
}

// name=value;name=value (the page's parameter values) as the map of exact values, each a
// decimal literal; the text of the sorted pairs is the cache key.
std::map<std::string, algebra::Rational> parameter_values(const std::string& text,
                                                          std::size_t max_parameters) {
    std::map<std::string, algebra::Rational> values;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ';');) {
        if (item.empty()) {
            continue;
        }
        const auto equals = item.find('=');
        std::string value = equals == std::string::npos ? "" : item.substr(equals + 1);
        const bool negative = !value.empty() && value[0] == '-';
        algebra::Rational r;
        if (equals == std::string::npos || value.size() > 40 ||
            !algebra::Rational::from_literal(negative ? value.substr(1) : value, r)) {
            refuse("params", "expected name=decimal pairs separated by ';'");
        }
        values[item.substr(0, equals)] = negative ? -r : r;
    }
    if (values.size() > max_parameters) {
        refuse("params", "at most " + std::to_string(max_parameters) + " parameters");
    }
    return values;
}

}  // namespace

std::optional<std::string> field(const Fields& fields, const std::string& name) {
    const auto it = fields.find(name);
    if (it == fields.end()) {
        return std::nullopt;
    }
    return it->second;
}

std::vector<std::string> equation_parameters(const std::string& equation) {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < equation.size();) {
        const unsigned char c = static_cast<unsigned char>(equation[i]);
        if (std::isalpha(c) || c == '_') {
            std::size_t j = i;
            while (j < equation.size() &&
                   (std::isalnum(static_cast<unsigned char>(equation[j])) || equation[j] == '_')) {
                ++j;
            }
            const std::string name = equation.substr(i, j - i);
            if (name != "x" && name != "y" && name != "z" &&
                std::find(names.begin(), names.end(), name) == names.end()) {
                names.push_back(name);
            }
            i = j;
        } else if (std::isdigit(c)) {
            while (i < equation.size() &&
                   (std::isalnum(static_cast<unsigned char>(equation[i])) || equation[i] == '.')) {
                ++i;  // a number, and what follows it without a space is not a name
            }
        } else {
            ++i;
        }
    }
    std::vector<std::string> ring_names = {"x", "y", "z"};
    ring_names.insert(ring_names.end(), names.begin(), names.end());
    // Parsing checks the whole text (and gives a ParseError at its column).
    algebra::parse_polynomial(
        equation,
        algebra::PolyRing::make(ring_names, algebra::MonomialOrder::grevlex(ring_names.size())));
    return names;
}

algebra::CompiledPolynomial FrameBuilder::compiled_equation(const std::string& equation,
                                                            const std::string& values_text) {
    const std::vector<std::string> names = equation_parameters(equation);
    if (names.size() > options_.limits.max_parameters) {
        refuse("equation", "at most " + std::to_string(options_.limits.max_parameters) +
                               " parameters (names other than x, y, z)");
    }
    const auto values = parameter_values(values_text, options_.limits.max_parameters);
    std::string key = equation + '\n';
    for (const std::string& name : names) {
        const auto it = values.find(name);
        key += name + "=" + (it == values.end() ? std::string("1") : it->second.to_string()) + ";";
    }
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        const auto hit = compiled_.find(key);
        if (hit != compiled_.end()) {
            return hit->second;
        }
    }
    std::vector<std::string> ring_names = {"x", "y", "z"};
    ring_names.insert(ring_names.end(), names.begin(), names.end());
    const auto ring =
        algebra::PolyRing::make(ring_names, algebra::MonomialOrder::grevlex(ring_names.size()));
    const auto xyz = algebra::PolyRing::make({"x", "y", "z"}, algebra::MonomialOrder::grevlex(3));
    const algebra::Polynomial f = algebra::parse_polynomial(equation, ring);
    // Each parameter becomes its value (1 when the page has none yet).
    std::vector<algebra::Polynomial> images;
    for (std::size_t v = 0; v < 3; ++v) {
        images.push_back(algebra::Polynomial::variable(xyz, v));
    }
    for (const std::string& name : names) {
        const auto it = values.find(name);
        images.push_back(algebra::Polynomial::constant(
            xyz, it == values.end() ? algebra::Rational(1) : it->second));
    }
    algebra::CompiledPolynomial compiled = algebra::compile_surface(f.substitute(images));
    const std::lock_guard<std::mutex> lock(mutex_);
    if (compiled_.size() > 64) {
        compiled_.clear();  // a slider's sweep: keep the memory bounded
    }
    compiled_.emplace(key, compiled);
    return compiled;
}

FrameBuilder::Framing FrameBuilder::framing_of(const std::string& key,
                                               const algebra::CompiledPolynomial& f) {
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        const auto hit = framing_.find(key);
        if (hit != framing_.end()) {
            return hit->second;
        }
    }
    render::Scene scene;
    render::Surface surface;
    surface.equation = f.equation();
    scene.surfaces.push_back(surface);
    const auto deadline = std::chrono::steady_clock::now() +
                          std::chrono::duration_cast<std::chrono::nanoseconds>(
                              std::chrono::duration<double>(options_.limits.fit_seconds));
    const std::vector<algebra::CompiledPolynomial> one = {f};
    render::fit_clip_regions(scene, one, false, deadline);
    Framing framing{scene.surfaces[0].clip, true, render::default_camera(scene)};
    const std::lock_guard<std::mutex> lock(mutex_);
    if (framing_.size() > 64) {
        framing_.clear();
    }
    framing_.emplace(key, framing);
    return framing;
}

Frame FrameBuilder::build(const Fields& fields) {
    const ViewLimits& limits = options_.limits;
    Frame frame;
    const std::string source = field(fields, "source").value_or("equation");
    if (source == "startup") {
        if (!options_.startup || options_.startup->compiled.empty()) {
            refuse("source", "no scene was given on the command line");
        }
        frame.scene = options_.startup->scene;
        frame.compiled = options_.startup->compiled;
        frame.camera = frame.scene.camera.value_or(render::default_camera(frame.scene));
    } else if (source == "equation") {
        const auto equation = field(fields, "equation");
        if (!equation || equation->empty()) {
            refuse("equation", "missing");
        }
        if (equation->size() > limits.max_equation_chars) {
            refuse("equation",
                   "longer than " + std::to_string(limits.max_equation_chars) + " characters");
        }
        const std::string values = field(fields, "params").value_or("");
        const algebra::CompiledPolynomial f = compiled_equation(*equation, values);
        const Framing framing = framing_of(*equation + '\n' + values, f);
        render::Surface surface;
        surface.equation = *equation;
        surface.source = "equation";
        surface.clip = framing.clip;
        surface.fit_clip = false;
        frame.scene.surfaces.push_back(surface);
        frame.compiled.push_back(f);
        const std::lock_guard<std::mutex> lock(mutex_);
        frame.camera = cameras_.try_emplace(*equation, framing.camera).first->second;
        if (cameras_.size() > 64) {
            cameras_.clear();
        }
    } else {
        refuse("source", "expected startup or equation");
    }
    frame.scene.width = integer(fields, "width", 1, limits.max_image_side);
    frame.scene.height = integer(fields, "height", 1, limits.max_image_side);
    if (const auto camera = field(fields, "camera"); camera && *camera != "auto") {
        const std::vector<double> c = numbers(fields, "camera", 10);
        frame.camera = {{c[0], c[1], c[2]}, {c[3], c[4], c[5]}, {c[6], c[7], c[8]}, c[9]};
    }
    frame.scene.camera = frame.camera;
    if (const auto method = field(fields, "method"); method && *method != "default") {
        try {
            frame.scene.options.method = render::parse_trace_method(*method);
        } catch (const Error& e) {
            refuse("method", e.what());
        }
    }
    if (field(fields, "front")) {
        const render::Vec3 front = colour(fields, "front");
        const render::Vec3 back = field(fields, "back") ? colour(fields, "back") : front;
        for (render::Surface& surface : frame.scene.surfaces) {
            surface.material.color = front;
            surface.material.inside = back;
        }
    }
    if (field(fields, "light")) {
        const std::vector<double> angles = numbers(fields, "light", 2);  // degrees
        const double azimuth = angles[0] * M_PI / 180.0, elevation = angles[1] * M_PI / 180.0;
        if (frame.scene.lights.empty()) {
            frame.scene.lights = render::default_lights();
        }
        frame.scene.lights[0].direction = {std::cos(elevation) * std::sin(azimuth),
                                           std::sin(elevation),
                                           std::cos(elevation) * std::cos(azimuth)};
    }
    if (const auto shadows = field(fields, "shadows")) {
        frame.scene.options.shadows = *shadows == "1";
    }
    frame.scene.options.samples = 1;
    frame.scene.options.threads = options_.render_threads;
    return frame;
}

}  // namespace locus::view
