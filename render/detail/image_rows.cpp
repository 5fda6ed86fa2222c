#include "render/detail/image_rows.h"

#include <atomic>
#include <cmath>
#include <mutex>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "algebra/deadline.h"
#include "algebra/error.h"

namespace locus::render::detail {

RenderedImage blank_image(int width, int height, bool aovs) {
    const double pixels_asked = static_cast<double>(width) * height;
    if (pixels_asked > kMaxImagePixels) {
        throw ResourceLimit("an image of " + std::to_string(width) + "x" + std::to_string(height) +
                            " pixels is more than the limit of " +
                            std::to_string(static_cast<long>(kMaxImagePixels)) +
                            " pixels (8192x8192)");
    }
    RenderedImage image;
    image.width = width;
    image.height = height;
    const std::size_t pixels = static_cast<std::size_t>(width) * height;
    image.color.assign(3 * pixels, 0.0f);
    if (aovs) {
        image.depth.assign(pixels, INFINITY);
        image.normal.assign(3 * pixels, 0.0f);
        image.work.assign(pixels, 0.0f);
    }
    return image;
}

void FrameCounters::report(RenderStats* stats, std::chrono::steady_clock::time_point start,
                           long primary_rays) const {
    if (stats == nullptr) {
        return;
    }
    stats->seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stats->primary_rays = primary_rays;
    stats->hits = hits;
    stats->unknown = unknown;
    stats->primary_work = primary_work;
}

void store_pixel(RenderedImage& image, std::size_t p, const Vec3& color, const Vec3& normal,
                 double depth, double work) {
    for (int c = 0; c < 3; ++c) {
        image.color[3 * p + c] = static_cast<float>(color[c]);
    }
    if (image.depth.empty()) {
        return;
    }
    for (int c = 0; c < 3; ++c) {
        image.normal[3 * p + c] = static_cast<float>(normal[c]);
    }
    image.depth[p] = static_cast<float>(depth);
    image.work[p] = static_cast<float>(work);
}

void for_each_row(int height, const ExecutionSettings& execution,
                  const std::function<void(int)>& row) {
    std::atomic<int> rows_done{0};
    std::atomic<bool> expired{false};
    std::mutex progress_mutex;
    const int threads =
        execution.threads > 0 ? execution.threads : tbb::this_task_arena::max_concurrency();
    tbb::task_arena arena(threads);
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, height, 1),
                          [&](const tbb::blocked_range<int>& range) {
                              for (int y = range.begin(); y < range.end(); ++y) {
                                  if (expired || deadline_passed(execution.deadline) ||
                                      (execution.cancel != nullptr &&
                                       execution.cancel->load(std::memory_order_relaxed))) {
                                      expired = true;
                                      return;
                                  }
                                  row(y);
                                  const int done = ++rows_done;
                                  if (execution.progress) {
                                      std::unique_lock lock(progress_mutex, std::try_to_lock);
                                      if (lock.owns_lock()) {
                                          execution.progress(static_cast<double>(done) / height);
                                      }
                                  }
                              }
                          });
    });
    if (expired && execution.cancel != nullptr && execution.cancel->load()) {
        throw Cancelled("rendering cancelled with " + std::to_string(rows_done.load()) + " of " +
                        std::to_string(height) + " rows done");
    }
    if (expired) {
        throw Timeout("rendering stopped with " + std::to_string(rows_done.load()) + " of " +
                      std::to_string(height) + " rows done");
    }
}

}  // namespace locus::render::detail
