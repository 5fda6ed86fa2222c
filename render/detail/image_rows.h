// The scaffolding both renderers share (render/renderer.h, render/sdf/sdf_renderer.h): the
// empty image with its AOVs, and the rows as units of parallel work with progress reports.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>

#include "render/renderer.h"

namespace locus::render::detail {

// Black colour and, with `aovs`, infinite depth, zero normals and work (else those stay empty).
RenderedImage blank_image(int width, int height, bool aovs);

// A frame's counts, added to by rows on any thread, and reported as RenderStats.
struct FrameCounters {
    std::atomic<long> hits{0}, unknown{0}, primary_work{0};
    void add_row(long row_hits, long row_unknown, long row_work) {
        hits += row_hits;
        unknown += row_unknown;
        primary_work += row_work;
    }
    // Fills `stats` (when not null) with these counts and the time since `start`.
    void report(RenderStats* stats, std::chrono::steady_clock::time_point start,
                long primary_rays) const;
};

// Writes pixel p: the colour (already averaged over the samples) and, when the image has its
// AOVs, the normal and depth of the nearest hit and the work spent.
void store_pixel(RenderedImage& image, std::size_t p, const Vec3& color, const Vec3& normal,
                 double depth, double work);

// Calls row(y) for y in [0, height) as oneTBB work on execution.threads threads (0: all),
// reporting the finished fraction through execution.progress (serialised; a report is skipped
// while another is being made). Once execution.deadline has passed no further row starts, and
// the call throws locus::Timeout saying how many rows were done.
void for_each_row(int height, const ExecutionSettings& execution,
                  const std::function<void(int)>& row);

}  // namespace locus::render::detail
