// First hits of a frame's primary rays with one surface, through the per-frame ray family the
// method uses: the certified family (render/certified_ray_family.h) for `certified`, the
// floating-point family (render/ray_family.h) for the restriction methods up to
// kMaxFamilyDegree, none for sphere-gradient and exact. The renderer and the benchmark's
// unshaded primary rays both trace through this, row by row.
#pragma once

#include <memory>

#include "render/camera.h"
#include "render/certified_ray_family.h"
#include "render/clip_region.h"
#include "render/ray_family.h"
#include "render/surface_tracer.h"

namespace locus::render {

class PrimaryTracer {
  public:
    // The polynomial and the camera must outlive the tracer. The ray families work in the
    // tracer's frame (with the camera moved into it: Camera::in_frame).
    PrimaryTracer(const algebra::CompiledPolynomial& f, const Camera& camera,
                  const ClipRegion& clip, int width, int height, const SurfaceTracer& tracer);

    // Per-row state: the row's expansion and the last hit (the next pixel's hint).
    struct Row {
        RowExpansion floating;
        CertifiedRayFamily::Row certified;
        RayRestriction restriction;
        BernsteinBall ball;
        double previous_hit = 0.0;
        NeighbourHint neighbour;  // for the certified family's search
        double image_y = 0.0;
    };
    void begin_row(double image_y, Row& row) const;
    // The first hit of camera.ray(image_x, image_y) (image_y as in begin_row) in `interval`.
    RootResult first_hit(Row& row, double image_x, const Ray& ray, const Interval& interval) const;

  private:
    enum class Family { none, floating, certified };
    const SurfaceTracer* tracer_;
    std::unique_ptr<const Camera> local_camera_;  // the families keep a pointer to it
    Family family_ = Family::none;
    std::unique_ptr<RayFamily> floating_;
    std::unique_ptr<CertifiedRayFamily> certified_;
    ImageRect rect_;  // the image points the certified family serves
};

}  // namespace locus::render
