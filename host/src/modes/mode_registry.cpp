// Which host module serves which render mode.
#include "modes/mode_kernel.hpp"
#include "modes/path_mode.hpp"
#include "modes/shaded_mode.hpp"

#include <stdexcept>

namespace fgr {

cl::Buffer upload_floats(const ComputeDevice& device, const std::vector<float>& values) {
    // A zero-sized buffer is invalid in OpenCL: an empty list uploads one unused float.
    const std::vector<float> padded = values.empty() ? std::vector<float>{0.0f} : values;
    return cl::Buffer(device.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                      padded.size() * sizeof(float), const_cast<float*>(padded.data()));
}

std::unique_ptr<ModeKernel> make_mode_kernel(RenderMode mode, const ComputeDevice& device,
                                             const Scene& scene) {
    switch (mode) {
        case RenderMode::Shaded: return std::make_unique<ShadedMode>(device, scene);
        case RenderMode::Path: return std::make_unique<PathMode>(device, scene);
    }
    throw std::invalid_argument("unknown render mode");
}

}  // namespace fgr
