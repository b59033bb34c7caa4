// SPDX-License-Identifier: Apache-2.0
#pragma once

#include "render/modes/mode_kernel.hpp"

namespace fgr {

class ShadedMode final : public ModeKernel {
public:
    ShadedMode(const ComputeDevice& device, const Scene& scene, const KernelSwitches& switches);
    int extra_planes(const KernelSwitches& switches) const override;
    void bind(cl::Kernel& kernel, const FrameRequest& request, const TileLayout& layout) override;
    void read_back(std::span<const float> planes, const TileLayout& layout,
                   const FrameRequest& request, int samples, Frame& frame) const override;

private:
    cl::Buffer lights_;
    cl_int light_count_;
    bool ifs_;    // an IFS scene: one more plane, the level each pixel's hit reached
    bool stats_;  // KernelSwitches::stats: the primary rays' work (FGR_SHADED_STATS_PLANES)
    bool aovs_;   // KernelSwitches::aovs: the layers (FGR_SHADED_AOV_PLANES)
};

}  // namespace fgr
