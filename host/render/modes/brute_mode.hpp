// SPDX-License-Identifier: Apache-2.0
#pragma once

#include "render/modes/mode_kernel.hpp"

namespace fgr {

// Render mode "brute" (kernels/modes/fgr_mode_brute.cl): each sample is one pass of stratified
// inside tests along every pixel's ray, refining a depth buffer that the mode keeps on the device
// from one render call to the next (a call starting at sample 0 starts it afresh; a later first
// sample continues it, as the viewer does while the view stands still). Once the passes are done,
// fgr_brute_shade shades the depth buffer in screen space. Beyond colour and depth it writes the
// shading's albedo and normal (FGR_BRUTE_ALBEDO_PLANE and FGR_BRUTE_NORMAL_PLANE, for EXR layers)
// and with stats each pixel's inside tests (FGR_BRUTE_STATS_PLANE).
class BruteMode final : public ModeKernel {
public:
    BruteMode(const ComputeDevice& device, const cl::Program& program, const Scene& scene,
              const KernelSwitches& switches);
    int extra_planes(const KernelSwitches& switches) const override;
    void bind(cl::Kernel& kernel, const FrameRequest& request, const TileLayout& layout) override;
    cl::Kernel* resolve_kernel() override { return &shade_kernel_; }
    bool sums_samples() const override { return false; }
    void read_back(std::span<const float> planes, const TileLayout& layout,
                   const FrameRequest& request, int samples, Frame& frame) const override;

private:
    const ComputeDevice& device_;
    cl::Kernel shade_kernel_;
    cl::Buffer lights_;
    cl_int light_count_;
    bool stats_;        // KernelSwitches::stats: the inside tests' plane
    bool aovs_;         // KernelSwitches::aovs: coverage and foreground, from the depth on the host
    cl::Buffer state_;  // each pixel's best depth, tile-major; -1: no hit yet
    int state_floats_ = 0;  // its size
    int state_width_ = 0, state_height_ = 0;
};

}  // namespace fgr
