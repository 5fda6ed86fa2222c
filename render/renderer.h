// Rendering a scene of compiled surfaces to an image: primary rays from the per-frame ray
// family, first hits by the scene's TraceMethod, Blinn–Phong shading, k×k supersampling.
// Rows are the unit of parallel work (oneTBB): a row is expanded once per surface and sample
// row, then each pixel costs a small polynomial evaluation plus its root finding.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "algebra/compiled.h"
#include "render/large_page_allocator.h"
#include "render/scene.h"

namespace locus::render {

// The largest image rendered (8192×8192: 0.8 GB of colour and 1.3 GB more with the AOVs);
// larger ones are a ResourceLimit before anything is allocated.
inline constexpr double kMaxImagePixels = 8192.0 * 8192.0;

// Linear-light colour plus the per-pixel arbitrary output variables (AOVs).
struct RenderedImage {
    int width = 0;
    int height = 0;
    PixelBuffer<float> color;  // RGB, linear, row-major from the top row
    std::vector<float> depth;  // distance from the eye to the first hit (+inf on a miss), per pixel
    std::vector<float> normal;  // unit normal, xyz per pixel, zero on a miss
    std::vector<float> work;    // root-finder work (steps or iterations) summed over the samples
    // depth, normal and work are empty when ExecutionSettings::aovs is false.
};

struct RenderStats {
    double seconds = 0.0;
    long primary_rays = 0;
    long hits = 0;
    long unknown = 0;       // rays whose method could not decide (drawn as background)
    long primary_work = 0;  // work spent on primary rays only
};

struct ExecutionSettings {
    int threads = 0;  // 0: all hardware threads
    // Called with the finished fraction, from whichever thread finished a row (serialised).
    std::function<void(double)> progress;
    // Rows not started by then are skipped and the render throws locus::Timeout: a picture
    // with missing rows is not a result (`locus render --timeout`).
    std::optional<std::chrono::steady_clock::time_point> deadline;
    // When set and true, rows not started are skipped and the render throws locus::Cancelled
    // (`locus view` cancels the frame in flight when a newer one is asked for).
    const std::atomic<bool>* cancel = nullptr;
    // Fill the AOVs (depth, normal, work). Without them RenderedImage holds the colour only
    // and a frame allocates and writes a third of the memory.
    bool aovs = true;
};

// Precondition: one compiled polynomial per scene surface, in order. Throws InputError for a
// degenerate camera, Timeout when execution.deadline passes.
RenderedImage render(const Scene& scene, std::span<const algebra::CompiledPolynomial> surfaces,
                     const ExecutionSettings& execution, RenderStats* stats = nullptr);

}  // namespace locus::render
