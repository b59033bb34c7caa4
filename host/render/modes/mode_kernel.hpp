// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a render mode's host module does for Renderer: the kernel's own arguments (after the
// FGR_RENDER_ARGS_COUNT every mode takes, see device/kernel_layout.hpp) and the planes it writes
// beyond colour and depth. One implementation per mode, in this folder; mode_registry.cpp makes
// them.

#include <memory>
#include <span>
#include <vector>

#include "device/kernel_layout.hpp"
#include "device/opencl_device.hpp"
#include "render/renderer.hpp"
#include "scene/render_mode.hpp"
#include "scene/scene.hpp"

namespace fgr {

class ModeKernel {
public:
    virtual ~ModeKernel() = default;

    // Planes the kernel writes after the FGR_COMMON_PLANES, with these switches.
    virtual int extra_planes(const KernelSwitches& switches) const = 0;

    // Sets the kernel's arguments from FGR_RENDER_ARGS_COUNT on, for this frame (and those of its
    // resolve kernel, if it has one).
    virtual void bind(cl::Kernel& kernel, const FrameRequest& request,
                      const TileLayout& layout) = 0;

    // Samples of each pixel one launch may trace, at most, for `request` (each launch renders
    // samples first .. first + count - 1 of every pixel): 1 for a mode that adds one a launch.
    virtual int launch_samples(const FrameRequest&) const { return 1; }

    // Sets what changes between the launches of a frame: `count` samples in the next one (at
    // most launch_samples()).
    virtual void bind_launch(cl::Kernel&, int /*count*/) {}

    // A second kernel the renderer runs once after the samples, over the same tiles and with the
    // same first arguments (FGR_RENDER_ARGS, `sample` being the samples done), for a mode whose
    // colour needs the whole image (the brute-force mode's screen-space shading); null for modes
    // that shade as they sample.
    virtual cl::Kernel* resolve_kernel() { return nullptr; }

    // Writes the planes the kernel reads (after the renderer has zeroed those it sums into),
    // before the frame's first launch; nothing for modes that only write planes.
    virtual void write_inputs(const cl::CommandQueue& queue, const cl::Buffer& planes,
                              const TileLayout& layout, const FrameRequest& request) {
        static_cast<void>(queue);
        static_cast<void>(planes);
        static_cast<void>(layout);
        static_cast<void>(request);
    }

    // Whether the colour planes hold a sum over the samples, which the renderer divides by their
    // count, or the finished colour.
    virtual bool sums_samples() const { return true; }

    // Fills what the mode adds to a frame from the planes read back (plane p of pixel (x, y) at
    // planes[p * layout.plane_size() + layout.index(x, y)]), `samples` samples summed in them.
    virtual void read_back(std::span<const float> planes, const TileLayout& layout,
                           const FrameRequest& request, int samples, Frame& frame) const = 0;
};

// Planes `first` .. first + count - 1 of each pixel in rows (count floats per pixel), times
// `scale` (1 / samples for planes that sum them).
std::vector<float> planes_in_rows(std::span<const float> planes, const TileLayout& layout,
                                  int first, int count, int width, int height, float scale = 1.0f);

// A read-only device buffer holding `values` (one unused float when empty).
cl::Buffer upload_floats(const ComputeDevice& device, const std::vector<float>& values);

// The scene's lights as fgr_shade.cl reads them: FGR_LIGHT_FLOATS floats each (type, vector with
// directions normalised, colour, intensity; kernels/shared/fgr_layout_lights.h).
std::vector<float> scene_light_values(const Scene& scene);

// The module for switches.mode, for a program built with `switches`.
std::unique_ptr<ModeKernel> make_mode_kernel(const KernelSwitches& switches,
                                             const ComputeDevice& device,
                                             const cl::Program& program, const Scene& scene);

}  // namespace fgr
