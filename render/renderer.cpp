#include "render/renderer.h"

#include <chrono>
#include <cmath>

#include "render/detail/image_rows.h"
#include "render/detail/thread_scratch.h"
#include "render/primary_tracer.h"
#include "render/shading.h"

namespace locus::render {

RenderedImage render(const Scene& scene, std::span<const algebra::CompiledPolynomial> surfaces,
                     const ExecutionSettings& execution, RenderStats* stats) {
    const auto start = std::chrono::steady_clock::now();
    const Camera camera(scene.camera.value_or(default_camera(scene)), scene.width, scene.height);
    const std::vector<Light> lights = scene.lights.empty() ? default_lights() : scene.lights;
    double scale = 0.0;
    for (const Surface& surface : scene.surfaces) {
        scale = std::max(scale, bounding_sphere(surface.clip).radius);
    }
    std::vector<SurfaceTracer> tracers;
    std::vector<ShadedSurface> shaded;
    tracers.reserve(surfaces.size());
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        tracers.emplace_back(surfaces[i], scene.options.method, scale, render_tolerance(scale),
                             scene.surfaces[i].frame);
    }
    std::vector<PrimaryTracer> primaries;
    primaries.reserve(surfaces.size());
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        primaries.emplace_back(surfaces[i], camera, scene.surfaces[i].clip, scene.width,
                               scene.height, tracers[i]);
        shaded.push_back({&tracers[i], scene.surfaces[i].clip, scene.surfaces[i].material,
                          scene.surfaces[i].trim.get()});
    }
    const Shader shader(shaded, lights, scene.options, scale);

    RenderedImage image = detail::blank_image(scene.width, scene.height, execution.aovs);
    const std::size_t pixels = static_cast<std::size_t>(scene.width) * scene.height;

    const int k = scene.options.samples;
    detail::FrameCounters frame;

    // The change of a primary ray's direction to the next sample across and down.
    const Vec3 step_x = camera.per_column() / static_cast<double>(k);
    const Vec3 step_y = camera.per_row() / static_cast<double>(k);
    // A row of samples is traced first and its hits shaded after, together
    // (Shader::shade_hits: several at a time where the processor and the scene allow). Sample
    // s of a row (k a pixel, across) is in column s / k; hit_of[s] is its place in `hits`.
    constexpr std::size_t kMiss = static_cast<std::size_t>(-1);
    struct RowBuffers {
        std::vector<std::size_t> hit_of;  // or kMiss
        std::vector<HitToShade> hits;
        std::vector<ShadingResult> shadings;
    };
    auto render_row = [&](int y) {
        std::vector<PrimaryTracer::Row> rows(surfaces.size());
        long row_hits = 0, row_unknown = 0, row_work = 0;
        std::vector<Vec3> sums(static_cast<std::size_t>(scene.width), Vec3(0.0));
        std::vector<double> nearest(static_cast<std::size_t>(scene.width), INFINITY);
        std::vector<Vec3> normals(static_cast<std::size_t>(scene.width), Vec3(0.0));
        std::vector<int> work(static_cast<std::size_t>(scene.width), 0);
        // A thread's, kept from row to row: a row's worth allocated afresh each time was
        // given back to the system and faulted in again (the 1024² frame 45 % slower).
        detail::ThreadScratch<RowBuffers> scratch;
        RowBuffers& buffers = scratch.get();
        std::vector<std::size_t>& hit_of = buffers.hit_of;
        std::vector<HitToShade>& hits = buffers.hits;
        std::vector<ShadingResult>& shadings = buffers.shadings;
        for (int sy = 0; sy < k; ++sy) {
            hit_of.clear();
            hits.clear();
            const double image_y = y + (sy + 0.5) / k;
            for (std::size_t s = 0; s < surfaces.size(); ++s) {
                primaries[s].begin_row(image_y, rows[s]);
            }
            for (int x = 0; x < scene.width; ++x) {
                const auto column = static_cast<std::size_t>(x);
                for (int sx = 0; sx < k; ++sx) {
                    const double image_x = x + (sx + 0.5) / k;
                    const Ray ray = camera.ray(image_x, image_y);
                    double best_t = INFINITY;
                    std::size_t best = 0;
                    for (std::size_t s = 0; s < surfaces.size(); ++s) {
                        const Interval interval = clip(scene.surfaces[s].clip, ray, {0.0, best_t});
                        if (interval.is_empty()) {
                            continue;
                        }
                        const RootResult hit = first_hit_trimmed(
                            scene.surfaces[s].trim.get(), ray, interval, kTrimTolerance * scale,
                            surfaces[s].degree(), [&](const Interval& within) {
                                return primaries[s].first_hit(rows[s], image_x, ray, within);
                            });
                        row_work += hit.work;
                        work[column] += hit.work;
                        if (hit.status == RootStatus::unknown) {
                            ++row_unknown;
                        } else if (hit.status == RootStatus::hit && hit.t < best_t) {
                            best_t = hit.t;
                            best = s;
                        }
                    }
                    if (std::isfinite(best_t)) {
                        const std::uint64_t seed =
                            (static_cast<std::uint64_t>(y) * scene.width + x) * 64 +
                            static_cast<std::uint64_t>(sy * k + sx);
                        hit_of.push_back(hits.size());
                        hits.push_back({ray, best, best_t, seed});
                    } else {
                        hit_of.push_back(kMiss);
                    }
                }
            }
            shadings.resize(hits.size());
            shader.shade_hits(hits, step_x, step_y, shadings);
            row_hits += static_cast<long>(hits.size());
            // In the order of the samples, as they were added one at a time.
            for (std::size_t sample = 0; sample < hit_of.size(); ++sample) {
                const std::size_t column = sample / static_cast<std::size_t>(k);
                const std::size_t hit_index = hit_of[sample];
                if (hit_index == kMiss) {
                    sums[column] += scene.background;
                    continue;
                }
                const ShadingResult& shading = shadings[hit_index];
                sums[column] += shading.color;
                work[column] += shading.work;
                // The depth and normal layers (AOVs) only: a square root a hit.
                if (execution.aovs) {
                    const HitToShade& hit = hits[hit_index];
                    const double distance = hit.t * glm::length(hit.ray.direction);
                    if (distance < nearest[column]) {
                        nearest[column] = distance;
                        normals[column] = shading.normal;
                    }
                }
            }
        }
        const double weight = 1.0 / (k * k);
        for (int x = 0; x < scene.width; ++x) {
            const auto column = static_cast<std::size_t>(x);
            detail::store_pixel(image, static_cast<std::size_t>(y) * scene.width + column,
                                sums[column] * weight, normals[column], nearest[column],
                                work[column]);
        }
        frame.add_row(row_hits, row_unknown, row_work);
    };

    detail::for_each_row(scene.height, execution, render_row);
    frame.report(stats, start, static_cast<long>(pixels) * k * k);
    return image;
}

}  // namespace locus::render
