#include "render/primary_tracer.h"

#include <cmath>

namespace locus::render {

PrimaryTracer::PrimaryTracer(const algebra::CompiledPolynomial& f, const Camera& camera,
                             const ClipRegion& clip, int width, int height,
                             const SurfaceTracer& tracer)
    : tracer_(&tracer),
      local_camera_(std::make_unique<const Camera>(camera.in_frame(tracer.frame()))) {
    const SurfaceFrame& frame = tracer.frame();
    const ClipSphere world_bounds = bounding_sphere(clip);
    // The families take the sphere's centre in the frame and its radius as a range of t: the
    // world's radius, since t is the same in both (widened by what moving the centre into the
    // frame may have rounded away).
    const Vec3 center = frame.to_local(world_bounds.center);
    const double radius = world_bounds.radius;
    const ClipSphere bounds{center, radius + 1e-15 * (glm::length(center) * frame.scale + radius)};
    switch (tracer.method()) {
    case TraceMethod::certified:
        certified_ = std::make_unique<CertifiedRayFamily>(f, *local_camera_, bounds.center,
                                                          bounds.radius, width, height);
        family_ = certified_->certified() ? Family::certified : Family::none;
        break;
    case TraceMethod::sphere_gradient:
    case TraceMethod::exact:
        break;
    default:
        if (f.degree() <= kMaxFamilyDegree) {
            floating_ =
                std::make_unique<RayFamily>(f, *local_camera_, bounds.center, width, height);
            family_ = Family::floating;
        }
        break;
    }
}

void PrimaryTracer::begin_row(double image_y, Row& row) const {
    row.previous_hit = NAN;
    if (family_ == Family::floating) {
        floating_->expand_row(image_y, row.floating);
    } else if (family_ == Family::certified) {
        certified_->expand_row(image_y, row.certified);
    }
}

RootResult PrimaryTracer::first_hit(Row& row, double image_x, const Ray& ray,
                                    Interval interval) const {
    RootResult hit;
    switch (family_) {
    case Family::floating:
        RayFamily::restriction(row.floating, image_x, row.restriction.polynomial);
        row.restriction.origin = floating_->origin_t();
        hit = tracer_->first_hit(ray, interval, row.restriction, row.previous_hit);
        break;
    case Family::certified:
        certified_->ball_at(row.certified, image_x, row.ball);
        hit = tracer_->first_hit_from(row.ball, certified_->t_start(), certified_->t_width(), ray,
                                      interval);
        break;
    case Family::none:
        hit = tracer_->first_hit(ray, interval);
        break;
    }
    row.previous_hit = hit.status == RootStatus::hit ? hit.t : NAN;
    return hit;
}

}  // namespace locus::render
