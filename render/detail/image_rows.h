// The scaffolding both renderers share (render/renderer.h, render/sdf/sdf_renderer.h): the
// empty image with its AOVs, and the rows as units of parallel work with progress reports.
#pragma once

#include <functional>

#include "render/renderer.h"

namespace locus::render::detail {

// Black colour, infinite depth, zero normals and work.
RenderedImage blank_image(int width, int height);

// Calls row(y) for y in [0, height) as oneTBB work on execution.threads threads (0: all),
// reporting the finished fraction through execution.progress (serialised; a report is skipped
// while another is being made).
void for_each_row(int height, const ExecutionSettings& execution,
                  const std::function<void(int)>& row);

}  // namespace locus::render::detail
