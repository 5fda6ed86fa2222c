#include "render/primary_rays.h"

#include <chrono>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "render/primary_tracer.h"

namespace locus::render {

PrimaryRays trace_primary_rays(const algebra::CompiledPolynomial& f, const ClipRegion& region,
                               const Camera& camera, int width, int height, TraceMethod method,
                               int threads, double tolerance_factor) {
    const auto start = std::chrono::steady_clock::now();
    PrimaryRays result;
    const std::size_t pixels = static_cast<std::size_t>(width) * height;
    result.hits.resize(pixels);
    result.ray_lengths.resize(pixels);
    const double scale = bounding_sphere(region).radius;
    // SurfaceTracer's scale sets only the sphere-tracing tolerances.
    const SurfaceTracer tracer(f, method, scale * tolerance_factor, render_tolerance(scale));
    const PrimaryTracer primary(f, camera, region, width, height, tracer);
    auto trace_row = [&](int y) {
        PrimaryTracer::Row row;
        const double image_y = y + 0.5;
        primary.begin_row(image_y, row);
        for (int x = 0; x < width; ++x) {
            const double image_x = x + 0.5;
            const Ray ray = camera.ray(image_x, image_y);
            const std::size_t p = static_cast<std::size_t>(y) * width + x;
            result.ray_lengths[p] = glm::length(ray.direction);
            const Interval interval = clip(region, ray, {0.0, INFINITY});
            result.hits[p] =
                interval.is_empty() ? RootResult{} : primary.first_hit(row, image_x, ray, interval);
        }
    };
    tbb::task_arena arena(threads > 0 ? threads : tbb::this_task_arena::max_concurrency());
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, height, 1),
                          [&](const tbb::blocked_range<int>& range) {
                              for (int y = range.begin(); y < range.end(); ++y) {
                                  trace_row(y);
                              }
                          });
    });
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace locus::render
