#pragma once
// What a render mode's host module does for Renderer: the kernel's own arguments (after the six
// every mode takes, see FGR_RENDER_ARGS in kernels/fgr_camera.cl) and the planes it writes beyond
// colour and depth. One implementation per mode, in this folder; mode_registry.cpp makes them.

#include <memory>
#include <vector>

#include "fgr/opencl_device.hpp"
#include "fgr/render_mode.hpp"
#include "fgr/renderer.hpp"
#include "fgr/scene.hpp"

namespace fgr {

// Index of a mode's first own argument of fgr_render.
constexpr int kFirstModeArgument = 6;

// The planes every mode writes: r, g, b (summed over samples) and depth (sample 0).
constexpr int kCommonPlanes = 4;

class ModeKernel {
public:
    virtual ~ModeKernel() = default;

    // Planes the kernel writes after the common four, with these switches.
    virtual int extra_planes(const KernelSwitches& switches) const = 0;

    // Sets the kernel's arguments from kFirstModeArgument on, for this frame.
    virtual void bind(cl::Kernel& kernel, const FrameRequest& request) = 0;

    // Fills what the mode adds to a frame from the planes read back (plane p of pixel (x, y) at
    // planes[p * layout.plane_size() + layout.index(x, y)]), `samples` samples summed in them.
    virtual void read_back(const std::vector<float>& planes, const TileLayout& layout,
                           const FrameRequest& request, int samples, Frame& frame) const = 0;
};

// A read-only device buffer holding `values` (one unused float when empty).
cl::Buffer upload_floats(const ComputeDevice& device, const std::vector<float>& values);

std::unique_ptr<ModeKernel> make_mode_kernel(RenderMode mode, const ComputeDevice& device,
                                             const Scene& scene);

}  // namespace fgr
