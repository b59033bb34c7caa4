// SPDX-License-Identifier: Apache-2.0
#include "render/camera_frame.hpp"

#include <glm/geometric.hpp>

namespace fgr {
namespace {

cl_float4 to_float4(glm::vec3 v, float w = 0.0f) { return {{v.x, v.y, v.z, w}}; }

}  // namespace

CameraFrame camera_frame(const CameraView& view, const Projection& projection, int width,
                         int height, PixelRegion region) {
    const CameraModel model = camera_model(view, projection);
    const CameraBasis& basis = model.basis;
    const glm::vec3 eye_hi(basis.eye);
    const glm::vec3 eye_lo(basis.eye - glm::dvec3(eye_hi));
    return {to_float4(eye_hi, eye_lo.x),
            to_float4(basis.forward, eye_lo.y),
            to_float4(basis.right, eye_lo.z),
            to_float4(basis.up),
            basis.tan_half_fov,
            pixel_angle(model, width, height),
            width,
            height,
            static_cast<cl_int>(model.kind),
            model.fisheye_half_fov,
            model.eye_separation,
            model.convergence,
            region.x,
            region.y,
            region.width,
            region.height};
}

}  // namespace fgr
