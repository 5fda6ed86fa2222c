#include "render/framing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace locus::render {

namespace {

// Whether the box [low, high] lies inside the region (for a sphere: all eight corners do).
bool contains(const ClipRegion& region, const Vec3& low, const Vec3& high) {
    if (const auto* box = std::get_if<ClipBox>(&region)) {
        return glm::all(glm::greaterThanEqual(low, box->min)) &&
               glm::all(glm::lessThanEqual(high, box->max));
    }
    const auto& sphere = std::get<ClipSphere>(region);
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 p{(corner & 1) != 0 ? high.x : low.x, (corner & 2) != 0 ? high.y : low.y,
                     (corner & 4) != 0 ? high.z : low.z};
        if (!(scaled_length(p - sphere.center) <= sphere.radius)) {
            return false;
        }
    }
    return true;
}

std::string describe(const ClipRegion& region) {
    if (const auto* sphere = std::get_if<ClipSphere>(&region)) {
        char text[48];
        std::snprintf(text, sizeof text, "the sphere of radius %.4g about ", sphere->radius);
        return text + format_point(sphere->center);
    }
    const auto& box = std::get<ClipBox>(region);
    return "the box from " + format_point(box.min) + " to " + format_point(box.max);
}

// A framed surface's extent, found in its frame, in the world's coordinates.
SurfaceExtent in_world(SurfaceExtent extent, const SurfaceFrame& frame) {
    extent.low = frame.to_world(extent.low);
    extent.high = frame.to_world(extent.high);
    return extent;
}

ClipRegion to_local(const ClipRegion& region, const SurfaceFrame& frame) {
    if (const auto* sphere = std::get_if<ClipSphere>(&region)) {
        return ClipSphere{frame.to_local(sphere->center), sphere->radius / frame.scale};
    }
    const auto& box = std::get<ClipBox>(region);
    return ClipBox{frame.to_local(box.min), frame.to_local(box.max)};
}

}  // namespace

std::vector<std::optional<SurfaceExtent>> fit_clip_regions(
    Scene& scene, std::span<const algebra::CompiledPolynomial> surfaces, bool force,
    std::optional<std::chrono::steady_clock::time_point> deadline) {
    std::vector<std::optional<SurfaceExtent>> extents(scene.surfaces.size());
    for (std::size_t i = 0; i < scene.surfaces.size(); ++i) {
        Surface& surface = scene.surfaces[i];
        if (!force && !surface.fit_clip) {
            continue;
        }
        extents[i] = in_world(estimate_extent(surfaces[i], 1024, deadline), surface.frame);
        surface.clip = fitted_clip_sphere(*extents[i]).value_or(ClipSphere{});
    }
    return extents;
}

EmptyPictureReason why_not_hit(const Surface& surface, const algebra::CompiledPolynomial& f,
                               const CameraSpec& camera, int width, int height,
                               std::optional<SurfaceExtent> extent,
                               std::optional<std::chrono::steady_clock::time_point> deadline) {
    using Remedy = EmptyPictureReason::Remedy;
    if (!extent) {
        extent = in_world(estimate_extent(f, 1024, deadline), surface.frame);
    }
    if (extent->kind == SurfaceExtent::Kind::none_found) {
        const std::string near = extent->newton_points == 0
                                     ? ""
                                     : " and through " + std::to_string(extent->newton_points) +
                                           " points near f = 0 that Newton's steps reached";
        return {"no real point of it was found on " + std::to_string(extent->lines) +
                    " lines through the origin" + near +
                    ": it may have none (as x^2+y^2+z^2+1), or be too small or too far from the "
                    "origin to be met without a clip region around it",
                Remedy::clip_region};
    }
    std::optional<ClipBox> inside =
        box_in_region(f, to_local(surface.clip, surface.frame), 1024, deadline);
    if (inside) {
        *inside = {surface.frame.to_world(inside->min), surface.frame.to_world(inside->max)};
    }
    if (!inside) {
        // Points were found, all of them inside the clip region, yet none by the region's own
        // sampling: the surface is a speck of a region far larger than it (a unit sphere in a
        // clip sphere of radius 1e150), not outside it.
        if (extent->kind == SurfaceExtent::Kind::bounded &&
            contains(surface.clip, extent->low, extent->high)) {
            return {"it lies inside its clip region, " + describe(surface.clip) +
                        ", but spans only " + format_point(extent->low) + " to " +
                        format_point(extent->high) + ", too small a part of it for a pixel",
                    Remedy::fit};
        }
        const std::string missed =
            "no point of it was found inside its clip region, " + describe(surface.clip);
        if (extent->kind == SurfaceExtent::Kind::bounded) {
            return {missed + "; the points found elsewhere span " + format_point(extent->low) +
                        " to " + format_point(extent->high),
                    Remedy::fit};
        }
        // Not bounded (or not known to be): where it is nearest the region's centre, so that
        // a larger region can take it in (a plane 100 away, a surface whose f_d vanishes).
        const ClipSphere around = bounding_sphere(surface.clip);
        const std::optional<Vec3> nearest =
            nearest_point_on_lines(f, surface.frame.to_local(around.center), 1024, deadline);
        if (!nearest) {
            return {missed, Remedy::none};
        }
        const Vec3 point = surface.frame.to_world(*nearest);
        char distance[32];
        std::snprintf(distance, sizeof distance, "%.4g", scaled_length(point - around.center));
        return {missed + "; the nearest point found on lines through its centre is " +
                    format_point(point) + ", " + distance + " away",
                Remedy::larger_clip_region};
    }
    const ClipSphere visible = bounding_sphere(ClipRegion(*inside));
    const Vec3 forward = scaled_normalize(camera.target - camera.eye);
    const Vec3 to_centre = visible.center - camera.eye;
    const double distance = scaled_length(to_centre);
    const double along = glm::dot(to_centre, forward);
    if (along < -visible.radius) {
        return {"what can be seen of it, about " + format_point(visible.center) +
                    ", lies behind the camera (eye " + format_point(camera.eye) + ", looking at " +
                    format_point(camera.target) + ")",
                Remedy::none};
    }
    if (distance > visible.radius) {
        // Half the diagonal field of view against the angle to the visible part's centre less
        // the angle it subtends.
        const double tan_half = std::tan(camera.fov_degrees * std::numbers::pi / 360.0);
        const double aspect = static_cast<double>(width) / height;
        const double half_diagonal = std::atan(tan_half * std::sqrt(1.0 + aspect * aspect));
        const double off_axis = std::acos(std::clamp(along / distance, -1.0, 1.0));
        const double subtended = std::asin(std::min(1.0, visible.radius / distance));
        if (off_axis - subtended > half_diagonal) {
            return {"what can be seen of it, about " + format_point(visible.center) +
                        ", lies outside the camera's field of view (eye " +
                        format_point(camera.eye) + ", looking at " + format_point(camera.target) +
                        ")",
                    Remedy::none};
        }
    }
    return {"no pixel's ray met it inside its clip region, " + describe(surface.clip) +
                ": it may be thinner than a pixel there",
            Remedy::finer_sampling};
}

}  // namespace locus::render
