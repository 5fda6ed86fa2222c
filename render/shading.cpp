#include "render/shading.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace locus::render {

namespace {

// SplitMix64: a tiny, good hash for per-pixel sample rotations.
std::uint64_t mix(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}
double unit_from(std::uint64_t x) {
    return static_cast<double>(mix(x) >> 11) * 0x1.0p-53;
}

// An orthonormal frame around a unit vector n (Duff et al., "Building an orthonormal basis,
// revisited", 2017).
void frame_around(const Vec3& n, Vec3& a, Vec3& b) {
    const double sign = std::copysign(1.0, n.z);
    const double p = -1.0 / (sign + n.z);
    const double q = n.x * n.y * p;
    a = {1.0 + sign * n.x * n.x * p, sign * q, -sign * n.x};
    b = {q, sign + n.y * n.y * p, -n.y};
}

}  // namespace

Shader::Shader(std::span<const ShadedSurface> surfaces, std::span<const Light> lights,
               const RenderOptions& options, double scale)
    : surfaces_(surfaces), lights_(lights), options_(options), scale_(scale) {}

bool Shader::is_occluded(const Ray& ray, double t_max, int& work) const {
    for (const ShadedSurface& surface : surfaces_) {
        const Interval interval = clip(surface.clip, ray, {1e-4 * scale_, t_max});
        if (interval.is_empty()) {
            continue;
        }
        const RootResult hit = surface.tracer->first_hit(ray, interval);
        work += hit.work;
        if (hit.status == RootStatus::hit) {
            return true;
        }
    }
    return false;
}

double Shader::visibility(const Vec3& point, const Vec3& normal, const Light& light,
                          std::uint64_t seed, int& work) const {
    const Vec3 origin = point + (1e-4 * scale_) * normal;
    const int samples = light.radius > 0.0 ? std::max(1, options_.soft_shadow_samples) : 1;
    // The light's disk is spanned by a frame around the direction to it, the same for all
    // samples of this point.
    Vec3 a, b;
    frame_around(light.kind == Light::Kind::directional ? light.direction
                                                        : glm::normalize(light.position - point),
                 a, b);
    int visible = 0;
    for (int s = 0; s < samples; ++s) {
        // A point on the light's disk (stratified in angle, random in radius).
        const double angle = 2.0 * std::numbers::pi *
                             (s + unit_from(seed * 31 + static_cast<std::uint64_t>(s))) / samples;
        const double r = std::sqrt(unit_from(seed * 17 + static_cast<std::uint64_t>(s)));
        Ray ray{origin, {}};
        double t_max = 1.0;
        if (light.kind == Light::Kind::directional) {
            const double spread = std::tan(light.radius) * r;
            ray.direction = light.direction + spread * (std::cos(angle) * a + std::sin(angle) * b);
            t_max = 1e3 * scale_;
        } else {
            Vec3 target = light.position;
            if (light.radius > 0.0) {
                target += light.radius * r * (std::cos(angle) * a + std::sin(angle) * b);
            }
            ray.direction = target - origin;
        }
        if (!is_occluded(ray, t_max, work)) {
            ++visible;
        }
    }
    return static_cast<double>(visible) / samples;
}

double Shader::ambient_occlusion(const Vec3& point, const Vec3& normal, std::uint64_t seed,
                                 int& work) const {
    const int samples = std::max(1, options_.ambient_occlusion_samples);
    Vec3 a, b;
    frame_around(normal, a, b);
    const Vec3 origin = point + (1e-4 * scale_) * normal;
    const double rotation = unit_from(seed);
    int open = 0;
    for (int s = 0; s < samples; ++s) {
        // Cosine-weighted directions on a Fibonacci spiral, rotated per pixel.
        const double u = (s + 0.5) / samples;
        const double angle = 2.0 * std::numbers::pi * (s * 0.6180339887498949 + rotation);
        const double radius = std::sqrt(u);
        const Vec3 direction = radius * (std::cos(angle) * a + std::sin(angle) * b) +
                               std::sqrt(std::max(0.0, 1.0 - u)) * normal;
        if (!is_occluded({origin, 0.5 * scale_ * direction}, 1.0, work)) {
            ++open;
        }
    }
    return static_cast<double>(open) / samples;
}

namespace {

// x^e, by squaring when the Blinn–Phong exponent is a whole number (the default 48 is):
// std::pow was 3 % of a degree-6 frame, two calls per hit.
double specular_power(double x, double e) {
    if (e >= 0.0 && e <= 1024.0 && e == std::floor(e)) {
        auto n = static_cast<unsigned>(e);
        double result = 1.0;
        double square = x;
        while (n != 0) {
            if ((n & 1u) != 0) {
                result *= square;
            }
            square *= square;
            n >>= 1u;
        }
        return result;
    }
    return std::pow(x, e);
}

}  // namespace

ShadingResult Shader::shade(const Ray& ray, std::size_t index, double t, std::uint64_t seed) const {
    const ShadedSurface& surface = surfaces_[index];
    const Vec3 point = ray.at(t);
    const Vec3 view = -glm::normalize(ray.direction);
    Vec3 normal = to_vec(surface.tracer->polynomial().gradient(to_point(point)));
    const double length = glm::length(normal);
    bool outside = true;
    if (length > 0.0 && std::isfinite(length)) {
        normal /= length;
        if (glm::dot(normal, view) < 0.0) {
            normal = -normal;
            outside = false;
        }
    } else {
        normal = view;
    }
    const Material& m = surface.material;
    const Vec3 base = outside ? m.outside : m.inside;
    ShadingResult result;
    double ambient = m.ambient;
    if (options_.ambient_occlusion) {
        ambient *= ambient_occlusion(point, normal, seed, result.work);
    }
    Vec3 color = ambient * base;
    for (const Light& light : lights_) {
        const Vec3 to_light = light.kind == Light::Kind::directional
                                  ? light.direction
                                  : glm::normalize(light.position - point);
        const double cosine = glm::dot(normal, to_light);
        if (cosine <= 0.0) {
            continue;
        }
        double visible = 1.0;
        if (options_.shadows) {
            visible = visibility(point, normal, light, seed, result.work);
            if (visible == 0.0) {
                continue;
            }
        }
        const Vec3 half = glm::normalize(to_light + view);
        const double highlight = specular_power(std::max(0.0, glm::dot(normal, half)), m.shininess);
        color += (visible * light.intensity) * light.color *
                 (m.diffuse * cosine * base + m.specular * highlight * Vec3(1.0));
    }
    result.color = color;
    result.normal = normal;
    return result;
}

std::uint8_t to_srgb8(double linear) {
    const double c = linear > 0.0 ? std::min(linear, 1.0) : 0.0;  // NaN → 0
    const double encoded = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
    return static_cast<std::uint8_t>(std::lround(encoded * 255.0));
}

}  // namespace locus::render
