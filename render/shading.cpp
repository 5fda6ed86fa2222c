#include "render/shading.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <numbers>
#include <vector>

#include "render/blinn_phong.h"
#include "render/detail/shading_lanes.h"
#include "render/detail/thread_scratch.h"

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

bool has_avx512() {
    static const bool supported = __builtin_cpu_supports("avx512f") != 0;
    return supported;
}

}  // namespace

Shader::Shader(std::span<const ShadedSurface> surfaces, std::span<const Light> lights,
               const RenderOptions& options, double scale)
    : surfaces_(surfaces), lights_(lights), options_(options), scale_(scale) {
    batched_ = has_avx512() && !options_.ambient_occlusion;
    for (const Light& light : lights_) {
        batched_ = batched_ && light.kind == Light::Kind::directional;
    }
    for (const ShadedSurface& surface : surfaces_) {
        batched_ =
            batched_ && !surface.material.checker && squares_for_power(surface.material.shininess);
    }
}

bool Shader::is_occluded(const Ray& ray, double t_max, int& work) const {
    for (const ShadedSurface& surface : surfaces_) {
        const Interval interval = clip(surface.clip, ray, {1e-4 * scale_, t_max});
        if (interval.is_empty()) {
            continue;
        }
        // A trimmed patch needs each root's place (is it on the patch?); a whole surface only
        // whether there is one.
        const RootResult hit =
            surface.trim == nullptr
                ? surface.tracer->occluded(ray, interval)
                : first_hit_trimmed(surface.trim, ray, interval, kTrimTolerance * scale_,
                                    surface.tracer->polynomial().degree(),
                                    [&](const Interval& within) {
                                        return surface.tracer->first_hit(ray, within);
                                    });
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
                                                        : scaled_normalize(light.position - point),
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

ShadingResult Shader::shade(const Ray& ray, std::size_t index, double t, std::uint64_t seed,
                            const SampleDirections& sample) const {
    const ShadedSurface& surface = surfaces_[index];
    const Vec3 point = ray.at(t);
    const Vec3 view = -glm::normalize(ray.direction);
    const FacingSide side = facing_side(surface.tracer->gradient(point), view);
    // A pattern is decided just inside the surface (against the outward normal), the same
    // for every pixel of a flat cell boundary.
    const Vec3 outward = side.outside ? side.normal : -side.normal;
    // Only a pattern needs the footprint (two more normalisations and divisions a hit).
    const Material material =
        surface.material.checker ? surface.material.at(point - (1e-6 * scale_) * outward,
                                                       surface_footprint(ray.origin, sample, point,
                                                                         side.normal, 1e6 * scale_))
                                 : surface.material;
    ShadingResult result;
    const double ambient_factor =
        options_.ambient_occlusion ? ambient_occlusion(point, side.normal, seed, result.work) : 1.0;
    auto visibility = [&](const Light& light, const Vec3&, double) {
        return options_.shadows ? this->visibility(point, side.normal, light, seed, result.work)
                                : 1.0;
    };
    result.color = blinn_phong(material, side, point, view, lights_, ambient_factor, visibility);
    result.normal = side.normal;
    return result;
}

void Shader::shade_hits(std::span<const HitToShade> hits, const Vec3& step_x, const Vec3& step_y,
                        std::span<ShadingResult> out) const {
    if (!batched_) {
        for (std::size_t i = 0; i < hits.size(); ++i) {
            const HitToShade& hit = hits[i];
            out[i] =
                shade(hit.ray, hit.surface, hit.t, hit.seed, {hit.ray.direction, step_x, step_y});
        }
        return;
    }
    const std::size_t n = hits.size();
    // A thread's arrays, kept between calls.
    detail::ThreadScratch<detail::HitLanes> scratch;
    detail::HitLanes& h = scratch.get();
    h.resize(n, options_.shadows ? lights_.size() : 0);
    for (std::size_t i = 0; i < n; ++i) {
        const HitToShade& hit = hits[i];
        const Vec3 gradient = surfaces_[hit.surface].tracer->gradient(hit.ray.at(hit.t));
        h.dx[i] = hit.ray.direction.x, h.dy[i] = hit.ray.direction.y, h.dz[i] = hit.ray.direction.z;
        h.gx[i] = gradient.x, h.gy[i] = gradient.y, h.gz[i] = gradient.z;
    }
    detail::facing_sides_avx512(h, n);
    for (std::size_t i = 0; i < n; ++i) {
        const Material& material = surfaces_[hits[i].surface].material;
        const Vec3& base = h.outside[i] != 0 ? material.color : material.inside;
        h.bx[i] = base.x, h.by[i] = base.y, h.bz[i] = base.z;
        h.ambient[i] = material.ambient;
        h.diffuse[i] = material.diffuse;
        h.specular[i] = material.specular;
        h.shininess[i] = static_cast<std::uint64_t>(material.shininess);
        out[i].work = 0;
        // Shadow rays as shade() casts them: for each light in turn that the normal faces.
        if (options_.shadows) {
            const Vec3 point = hits[i].ray.at(hits[i].t), normal{h.nx[i], h.ny[i], h.nz[i]};
            for (std::size_t l = 0; l < lights_.size(); ++l) {
                const Light& light = lights_[l];
                h.visible[l * n + i] =
                    !(glm::dot(normal, light.direction) <= 0.0)  // as blinn_phong tests it
                        ? visibility(point, normal, light, hits[i].seed, out[i].work)
                        : 0.0;
            }
        }
    }
    detail::blinn_phong_avx512(h, n, lights_, options_.shadows, out.data());
}

namespace {

// The sRGB transfer function, rounded to 8 bits.
std::uint8_t encode_srgb8(double c) {
    const double encoded = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
    return static_cast<std::uint8_t>(std::lround(encoded * 255.0));
}

// The 8-bit code as a table lookup that gives exactly encode_srgb8(c): `thresholds[k]` is the
// smallest double in [0, 1] that encodes to k + 1 or more, and `bucket_start[i]` the code at
// i/4096 (the number of thresholds at or below it). The steepest slope of the encoding,
// 12.92 · 255 codes per unit near 0, is 0.8 codes per bucket, so at most one threshold lies in a
// bucket and one comparison finishes the lookup. A pow per channel was 5 % of a whole `locus
// render` of a sphere at 512², a binary search over the thresholds 13 %.
//
// The table is built at every start of a render, so each threshold is found by bisection on
// encode_srgb8 itself (monotone) over the bit patterns of the doubles near the inverse of the
// transfer function, about 15 pows, instead of over [0, 1] (about 60): bisecting all of [0, 1]
// and encoding every bucket took 19 000 pows, 3–7 % of a 1×1 render.
class Srgb8Table {
  public:
    static constexpr int kBuckets = 4096;

    Srgb8Table() {
        for (int k = 0; k < 255; ++k) {
            thresholds_[static_cast<std::size_t>(k)] = threshold(k);
        }
        thresholds_[255] = INFINITY;
        int code = 0;
        for (int i = 0; i < kBuckets; ++i) {
            const double c = static_cast<double>(i) / kBuckets;
            while (c >= thresholds_[static_cast<std::size_t>(code)]) {
                ++code;
            }
            bucket_start_[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(code);
        }
    }

    // Any c: clamped to [0, 1] first, NaN to 0.
    std::uint8_t operator()(double c) const {
        c = c > 0.0 ? std::min(c, 1.0) : 0.0;
        const int bucket = std::min(static_cast<int>(c * kBuckets), kBuckets - 1);
        std::uint8_t code = bucket_start_[static_cast<std::size_t>(bucket)];
        if (c >= thresholds_[code]) {
            ++code;
        }
        return code;
    }

  private:
    // The smallest double c in [0, 1] with encode_srgb8(c) > k (k < 255).
    static double threshold(int k) {
        // Non-negative doubles are ordered as their bit patterns, so the search runs on those:
        // encode(below) ≤ k < encode(above) throughout.
        const auto bits = [](double x) { return std::bit_cast<std::uint64_t>(x); };
        const auto value = [](std::uint64_t b) { return std::bit_cast<double>(b); };
        std::uint64_t below = bits(0.0), above = bits(1.0);
        // The inverse of the transfer function at the code's upper half-way point, and a
        // bracket of a millionth around it, used only where it is one.
        const double y = (k + 0.5) / 255.0;
        const double guess = y <= 0.04045 ? y / 12.92 : std::pow((y + 0.055) / 1.055, 2.4);
        const std::uint64_t near_lo = bits(guess * (1.0 - 1e-6)),
                            near_hi = bits(std::min(guess * (1.0 + 1e-6), 1.0));
        if (encode_srgb8(value(near_lo)) <= k) {
            below = near_lo;
        }
        if (encode_srgb8(value(near_hi)) > k) {
            above = near_hi;
        }
        while (above - below > 1) {
            const std::uint64_t middle = below + (above - below) / 2;
            (encode_srgb8(value(middle)) > k ? above : below) = middle;
        }
        return value(above);
    }

    std::array<double, 256> thresholds_{};
    std::array<std::uint8_t, kBuckets> bucket_start_{};
};

}  // namespace

namespace {

const Srgb8Table& srgb8_table() {
    static const Srgb8Table table;
    return table;
}

}  // namespace

std::uint8_t to_srgb8(double linear) {
    return srgb8_table()(linear);
}

void to_srgb8(const float* linear, std::uint8_t* codes, std::size_t n) {
    const Srgb8Table& table = srgb8_table();
    for (std::size_t i = 0; i < n; ++i) {
        codes[i] = table(linear[i]);
    }
}

}  // namespace locus::render
