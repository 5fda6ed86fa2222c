#include "render/primary_tracer.h"

#include <algorithm>
#include <cmath>
#include <variant>

namespace locus::render {

namespace {

// The family tests' samples (kNodeSampleGrid² rays' exact balls, kFamilySampleGrid² of the
// family's) and the fraction of them they must decide.
constexpr int kNodeSampleGrid = 4;
constexpr int kFamilySampleGrid = 8;
constexpr double kFamilyDecidedEnough = 0.25;

// The image points whose rays can meet the region: the box of the projections of the corners
// of a box around it (the projection of a convex set in front of the eye is the hull of its
// corners' projections), widened by two pixels for the roundings, within the image. The whole
// image when a corner is not well in front of the eye.
ImageRect footprint(const ClipRegion& region, const Camera& camera, int width, int height) {
    const ImageRect whole{0.0, 0.0, static_cast<double>(width), static_cast<double>(height)};
    ClipBox box;
    if (const auto* sphere = std::get_if<ClipSphere>(&region)) {
        box = {sphere->center - Vec3(sphere->radius), sphere->center + Vec3(sphere->radius)};
    } else {
        box = std::get<ClipBox>(region);
    }
    const Vec3 u = camera.per_column() / glm::dot(camera.per_column(), camera.per_column());
    const Vec3 v = camera.per_row() / glm::dot(camera.per_row(), camera.per_row());
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 p((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                     (corner & 4) ? box.max.z : box.min.z);
        const Vec3 q = p - camera.eye();
        const double depth = glm::dot(q, camera.forward());
        if (!(depth > 1e-6 * glm::length(q)) || !std::isfinite(depth)) {
            return whole;
        }
        // q/depth = base + x·per_column + y·per_row, with per_column ⟂ per_row ⟂ forward.
        const Vec3 on_plane = q / depth - camera.base();
        const double x = glm::dot(on_plane, u), y = glm::dot(on_plane, v);
        x0 = std::min(x0, x);
        x1 = std::max(x1, x);
        y0 = std::min(y0, y);
        y1 = std::max(y1, y);
    }
    if (!std::isfinite(x0 + x1 + y0 + y1)) {
        return whole;
    }
    return {std::clamp(x0 - 2.0, 0.0, whole.x1), std::clamp(y0 - 2.0, 0.0, whole.y1),
            std::clamp(x1 + 2.0, 0.0, whole.x1), std::clamp(y1 + 2.0, 0.0, whole.y1)};
}

}  // namespace

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
        // In the world's coordinates: the frame's camera has the same image coordinates.
        rect_ = footprint(clip, camera, width, height);
        // A family whose balls decide few rays (degree 30: over the whole frame their radii
        // are far above F's values near the roots) would cost most rays a fruitless search of
        // the ball before they are traced alone — a tenth of a Chmutov T30 frame, with the
        // rows' rests (NeighbourHint). Asked once, before any ray is traced, of 16 rays'
        // exact balls (where those do not decide, the family's wider balls would not: it is
        // not built, which at degree 30 cost 961 of them) and then of 64 of the family's:
        // the choice is the same on every run and thread count.
        family_ = Family::none;
        if (CertifiedRayFamily::worth_building(f, *local_camera_, bounds.center, bounds.radius,
                                               rect_, kNodeSampleGrid, kFamilyDepth,
                                               kFamilyDecidedEnough)) {
            certified_ = std::make_unique<CertifiedRayFamily>(f, *local_camera_, bounds.center,
                                                              bounds.radius, rect_);
            if (certified_->decides_often(kFamilySampleGrid, kFamilyDepth, kFamilyDecidedEnough)) {
                family_ = Family::certified;
            }
        }
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
    row.neighbour = NeighbourHint{};
    row.image_y = image_y;
    if (family_ == Family::floating) {
        floating_->expand_row(image_y, row.floating);
    } else if (family_ == Family::certified && image_y >= rect_.y0 && image_y <= rect_.y1) {
        certified_->expand_row(image_y, row.certified);
    }
}

RootResult PrimaryTracer::first_hit(Row& row, double image_x, const Ray& ray,
                                    const Interval& interval) const {
    RootResult hit;
    switch (family_) {
    case Family::floating:
        RayFamily::restriction(row.floating, image_x, row.restriction.polynomial);
        row.restriction.origin = floating_->origin_t();
        hit = tracer_->first_hit(ray, interval, row.restriction, row.previous_hit);
        break;
    case Family::certified:
        // The family's balls hold inside its rectangle only (no ray from outside meets the
        // clip region, but the ray is traced alone rather than trusted to that).
        if (!rect_.contains(image_x, row.image_y)) {
            hit = tracer_->first_hit(ray, interval);
            break;
        }
        certified_->ball_at(row.certified, image_x, row.ball);
        hit = tracer_->first_hit_from(row.ball, certified_->t_start(), certified_->t_width(), ray,
                                      interval, &row.neighbour);
        break;
    case Family::none:
        hit = tracer_->first_hit(ray, interval, row.neighbour);
        break;
    }
    row.previous_hit = hit.status == RootStatus::hit ? hit.t : NAN;
    return hit;
}

}  // namespace locus::render
