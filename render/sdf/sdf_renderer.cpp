#include "render/sdf/sdf_renderer.h"

#include <chrono>
#include <cmath>

#include "render/blinn_phong.h"
#include "render/detail/image_rows.h"
#include "render/sdf/algebraic_leaf.h"

namespace locus::render {

std::vector<sdf::NodePtr> scene_items(const Scene& scene,
                                      std::span<const algebra::CompiledPolynomial> surfaces) {
    std::vector<sdf::NodePtr> items = scene.objects;
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        items.push_back(sdf::make_algebraic(
            std::make_shared<const algebra::CompiledPolynomial>(surfaces[i]),
            scene.surfaces[i].clip, std::make_shared<const Material>(scene.surfaces[i].material),
            scene.options.method));
    }
    return items;
}

namespace {

class SdfShader {
  public:
    SdfShader(const sdf::SceneTracer& tracer, std::span<const Light> lights,
              const RenderOptions& options, double far)
        : tracer_(tracer), lights_(lights), options_(options), far_(far) {}

    // Colour and unit normal (towards the viewer) of the hit of a unit-direction ray.
    // `sample`: the unnormalised direction of the sample's ray and its steps to the
    // neighbouring samples, for the footprint over which patterns are filtered.
    Vec3 shade(const Ray& ray, const sdf::SceneHit& hit, double epsilon,
               const SampleDirections& sample, Vec3& normal, sdf::TraceCounters& counters) const {
        const Vec3 point = ray.at(hit.t);
        const Vec3 view = -ray.direction;
        const FacingSide side = facing_side(
            tracer_.normal(hit.item, point, std::max(epsilon, 1e-7 * tracer_.scale())), view);
        normal = side.normal;
        // The material just inside the surface (against the outward normal), where patterns
        // such as a checker are decided the same way for every pixel of a flat floor.
        const Vec3 outward = side.outside ? side.normal : -side.normal;
        const Material material =
            tracer_.material_at(hit.item, point - (epsilon + 1e-6 * tracer_.scale()) * outward,
                                surface_footprint(ray.origin, sample, point, side.normal, far_));
        const double ambient_factor =
            options_.ambient_occlusion ? occlusion(point, side.normal, counters) : 1.0;
        const Vec3 origin = point + (4.0 * epsilon + 1e-6 * tracer_.scale()) * side.normal;
        auto visibility = [&](const Light& light, const Vec3& to_light, double distance) {
            if (!options_.shadows) {
                return 1.0;
            }
            double penumbra = 0.0;
            if (light.radius > 0.0) {
                penumbra = light.kind == Light::Kind::point
                               ? distance / light.radius
                               : 1.0 / std::tan(std::min(light.radius, 1.5));
            }
            return tracer_.transmittance({origin, to_light},
                                         light.kind == Light::Kind::point ? distance : far_,
                                         penumbra, counters);
        };
        return blinn_phong(material, side, point, view, lights_, ambient_factor, visibility);
    }

  private:
    // Five samples of the field along the normal (Quilez): where the field is smaller than
    // the distance from the surface, something is near and the point is occluded.
    double occlusion(const Vec3& point, const Vec3& n, sdf::TraceCounters& counters) const {
        const double reach = 0.15 * tracer_.scale();
        double occluded = 0.0, weight = 1.0;
        for (int i = 0; i < 5; ++i) {
            const double h = reach * (0.05 + 0.95 * i / 4.0);
            const double d = tracer_.value(point + h * n, counters);
            occluded += (h - std::max(d, 0.0)) / reach * weight;
            weight *= 0.85;
        }
        return std::clamp(1.0 - 1.2 * occluded, 0.0, 1.0);
    }

    const sdf::SceneTracer& tracer_;
    std::span<const Light> lights_;
    RenderOptions options_;
    double far_;
};

}  // namespace

RenderedImage render_sdf_scene(const Scene& scene,
                               std::span<const algebra::CompiledPolynomial> surfaces,
                               const ExecutionSettings& execution, RenderStats* stats,
                               sdf::SpeedUps speed_ups) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<sdf::NodePtr> items = scene_items(scene, surfaces);
    const sdf::Bounds finite = sdf::finite_bounds(items);
    const double scale = sdf::scene_scale(finite);
    const Vec3 center = finite.min.x <= finite.max.x ? 0.5 * (finite.min + finite.max) : Vec3(0.0);
    const Camera camera(scene.camera.value_or(default_camera(scene)), scene.width, scene.height);
    const std::vector<Light> lights = scene.lights.empty() ? default_lights() : scene.lights;
    const double far = 200.0 * (scale + glm::length(camera.eye() - center));
    const sdf::SceneTracer tracer(items, scale, speed_ups);
    const SdfShader shader(tracer, lights, scene.options, far);
    const int k = scene.options.samples;
    // The width of a pixel (of a sample) per unit distance along the view direction.
    const double footprint = glm::length(camera.per_row()) /
                             glm::length(camera.direction(0.5 * scene.width, 0.5 * scene.height)) /
                             k;

    RenderedImage image = detail::blank_image(scene.width, scene.height, execution.aovs);
    const std::size_t pixels = static_cast<std::size_t>(scene.width) * scene.height;
    detail::FrameCounters frame;

    auto render_row = [&](int y) {
        long row_hits = 0, row_work = 0;
        sdf::TraceCounters row_counters;
        for (int x = 0; x < scene.width; ++x) {
            const std::size_t p = static_cast<std::size_t>(y) * scene.width + x;
            Vec3 sum(0.0);
            double nearest = INFINITY;
            Vec3 nearest_normal(0.0);
            long pixel_work = 0;
            for (int sy = 0; sy < k; ++sy) {
                for (int sx = 0; sx < k; ++sx) {
                    const Vec3 d = camera.direction(x + (sx + 0.5) / k, y + (sy + 0.5) / k);
                    const Ray ray{camera.eye(), glm::normalize(d)};
                    sdf::TraceCounters counters;
                    const sdf::SceneHit hit =
                        tracer.first_hit(ray, {0.0, far}, footprint, counters);
                    row_work += counters.evaluations + counters.root_work;
                    row_counters.undecided += counters.undecided;
                    if (!hit.found()) {
                        sum += scene.background;
                    } else {
                        ++row_hits;
                        Vec3 normal;
                        sum += shader.shade(ray, hit, 0.5 * footprint * hit.t,
                                            {d, camera.per_column() / static_cast<double>(k),
                                             camera.per_row() / static_cast<double>(k)},
                                            normal, counters);
                        if (hit.t < nearest) {
                            nearest = hit.t;
                            nearest_normal = normal;
                        }
                    }
                    pixel_work += counters.evaluations + counters.root_work;
                }
            }
            detail::store_pixel(image, p, sum * (1.0 / (k * k)), nearest_normal, nearest,
                                pixel_work);
        }
        frame.add_row(row_hits, row_counters.undecided, row_work);
    };

    detail::for_each_row(scene.height, execution, render_row);
    frame.report(stats, start, static_cast<long>(pixels) * k * k);
    return image;
}

}  // namespace locus::render
