// SPDX-License-Identifier: Apache-2.0
#pragma once
// The cone-marched depth prepass (kernels/geometry/fgr_prepass.cl) for Renderer: one cone per block
// of FGR_PREPASS_BLOCK x FGR_PREPASS_BLOCK pixels finds how far the block's camera rays can start
// from the eye; the render kernel reads the distances (its argument `march_starts`).

#include <CL/opencl.hpp>
#include <vector>

#include "device/kernel_assembly.hpp"
#include "device/kernel_layout.hpp"
#include "device/opencl_device.hpp"
#include "render/camera_frame.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace fgr {

// Whether the prepass can serve a program built with `switches` for `scene`: the DE modes' camera
// rays from one eye, no depth of field (rays leave the lens), no glow (it needs the whole ray's
// closest approach), no IFS scene (traced exactly) and none without a DE.
bool prepass_applies(const Scene& scene, const KernelSwitches& switches);

class ConePrepass {
public:
    ConePrepass(const ComputeDevice& device, const cl::Program& program, const Scene& scene,
                const KernelSwitches& switches);

    // The per-block start distances for this frame (FGR_PREPASS_STARTS_PLANE, and each cone's DE
    // evaluations, FGR_PREPASS_EVALUATIONS_PLANE): marched when the prepass applies and the
    // request wants it, zeros otherwise.
    cl::Buffer starts(const FrameRequest& request, const CameraFrame& camera,
                      const cl::Buffer& params, int group);

    // The request's start hints laid out as the image's planes (`layout`), and whether there are
    // any the kernel may take (has_hints); a one-float buffer when not.
    cl::Buffer hints(const FrameRequest& request, const TileLayout& layout, int* has_hints) const;

    // DE evaluations of the last frame's cones, read back from its buffer (0 when none ran).
    long evaluations(const cl::Buffer& starts, const CameraFrame& camera) const;

    bool available() const { return available_; }

private:
    const ComputeDevice& device_;
    int packet_width_;
    bool available_;
    cl::Kernel kernel_;
    bool ran_ = false;
};

}  // namespace fgr
