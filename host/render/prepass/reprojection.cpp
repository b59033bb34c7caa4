// SPDX-License-Identifier: Apache-2.0
#include "render/prepass/reprojection.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

namespace fgr {
namespace {

constexpr float kNone = std::numeric_limits<float>::infinity();

// The previous frame's hits as distances from the new eye, splatted nearest first over the new
// pixels each old pixel covers.
std::vector<float> splat_previous_hits(const DepthView& previous, const CameraModel& old_model,
                                       const CameraModel& new_model, int width, int height) {
    std::vector<float> nearest(static_cast<size_t>(width) * height, kNone);
    const CameraBasis& basis = new_model.basis;
    const glm::dvec3 old_eye = old_model.basis.eye, new_eye = basis.eye;
    const double tan_x = basis.tan_half_fov;
    const double tan_y = basis.tan_half_fov * double(height) / double(width);
    // An old pixel spans about this many new pixels (the views' fields of view alike).
    const int cover = std::max(1, static_cast<int>(std::ceil(double(width) / previous.width)));
    for (int y = 0; y < previous.height; ++y) {
        for (int x = 0; x < previous.width; ++x) {
            const float depth = previous.depth[static_cast<size_t>(y) * previous.width + x];
            if (!(depth >= 0.0f)) continue;
            const auto dir = projected_ray_direction(old_model, previous.width, previous.height,
                                                     float(x) + 0.5f, float(y) + 0.5f);
            if (!dir) continue;
            const glm::dvec3 point = old_eye + glm::dvec3(*dir) * double(depth);
            const glm::dvec3 local = point - new_eye;
            const double ahead = glm::dot(local, glm::dvec3(basis.forward));
            if (!(ahead > 0.0)) continue;
            const double u = glm::dot(local, glm::dvec3(basis.right)) / ahead / tan_x;
            const double v = glm::dot(local, glm::dvec3(basis.up)) / ahead / tan_y;
            const double px = (u + 1.0) * 0.5 * width, py = (1.0 - v) * 0.5 * height;
            // Off the new image (and far off it: no int conversion of a huge coordinate).
            if (!(px > -cover - 1.0 && px < width + cover + 1.0 && py > -cover - 1.0 &&
                  py < height + cover + 1.0)) {
                continue;
            }
            const auto distance = static_cast<float>(glm::length(local));
            const int x0 = static_cast<int>(std::floor(px - 0.5 * cover));
            const int y0 = static_cast<int>(std::floor(py - 0.5 * cover));
            for (int j = std::max(y0, 0); j <= std::min(y0 + cover, height - 1); ++j) {
                for (int i = std::max(x0, 0); i <= std::min(x0 + cover, width - 1); ++i) {
                    float& slot = nearest[static_cast<size_t>(j) * width + i];
                    slot = std::min(slot, distance);
                }
            }
        }
    }
    return nearest;
}

}  // namespace

std::vector<float> reproject_start_hints(const DepthView& previous, const CameraView& view,
                                         const Projection& projection, int width, int height,
                                         float margin, float max_spread) {
    std::vector<float> hints(static_cast<size_t>(width) * height, 0.0f);
    if (projection.kind != ProjectionKind::Pinhole ||
        previous.projection.kind != ProjectionKind::Pinhole || previous.width < 1 ||
        previous.height < 1 ||
        previous.depth.size() != static_cast<size_t>(previous.width) * previous.height) {
        return hints;
    }
    const CameraModel old_model = camera_model(previous.view, previous.projection);
    const CameraModel new_model = camera_model(view, projection);
    const std::vector<float> nearest =
        splat_previous_hits(previous, old_model, new_model, width, height);
    for (int y = 1; y + 1 < height; ++y) {
        for (int x = 1; x + 1 < width; ++x) {
            float low = kNone, high = 0.0f;
            for (int j = -1; j <= 1; ++j) {
                for (int i = -1; i <= 1; ++i) {
                    const float d = nearest[static_cast<size_t>(y + j) * width + x + i];
                    low = std::min(low, d);
                    high = std::max(high, d);
                }
            }
            if (high == kNone || high > low * (1.0f + max_spread)) continue;
            hints[static_cast<size_t>(y) * width + x] = low * (1.0f - margin);
        }
    }
    return hints;
}

}  // namespace fgr
