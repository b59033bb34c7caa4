// SPDX-License-Identifier: Apache-2.0
#pragma once

#include <memory>

#include "render/modes/mode_kernel.hpp"

namespace fgr {

// Render mode "path" (kernels/modes/fgr_mode_path.cl): its arguments are the lights (the scene's
// and the sky's sun), the path settings and the environment's tables; it writes the radiance, the
// first hit's depth, albedo, normal and coverage, each pixel's sample count and variance (from
// the odd samples' radiance, summed apart), and with stats its lanes' work.
class PathMode final : public ModeKernel {
public:
    PathMode(const ComputeDevice& device, const Scene& scene, const KernelSwitches& switches);
    int extra_planes(const KernelSwitches& switches) const override;
    void bind(cl::Kernel& kernel, const FrameRequest& request, const TileLayout& layout) override;
    // The sample limit plane (FrameRequest::sample_limits, or every sample).
    void write_inputs(const cl::CommandQueue& queue, const cl::Buffer& planes,
                      const TileLayout& layout, const FrameRequest& request) override;
    int launch_samples(const FrameRequest& request) const override;
    void bind_launch(cl::Kernel& kernel, int count) override;
    void read_back(std::span<const float> planes, const TileLayout& layout,
                   const FrameRequest& request, int samples, Frame& frame) const override;

private:
    // Whether the regrouped kernel renders with these settings.
    bool regrouped(const PathSettings& settings) const;
    // Uploads the environment's tables and the light list when they change.
    void prepare(const PathSettings& settings);

    const ComputeDevice& device_;
    const Scene& scene_;
    bool stats_;  // KernelSwitches::stats: FGR_PATH_STATS_PLANES after the auxiliary ones
    bool aovs_;   // KernelSwitches::aovs: the foreground's three planes after those
    std::shared_ptr<const PreparedEnvironment> default_environment_;  // the sky, made once
    std::shared_ptr<const PreparedEnvironment> bound_environment_;
    bool bound_scene_lights_ = true;
    cl::Buffer environment_data_;
    cl::Buffer lights_;
    int light_count_ = 0;
    float environment_weight_ = 0.0f;
    layout::path_settings bound_settings_{};  // the kernel's settings, as bind set them
};

}  // namespace fgr
