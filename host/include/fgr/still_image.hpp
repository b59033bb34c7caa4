#pragma once
// One still image of a scene, as `fgr render` makes it: the scene's kernel built with the
// requested switches, float or double chosen for the view, the frame rendered and written as PNG.

#include <cstdint>
#include <filesystem>

#include "fgr/opencl_device.hpp"
#include "fgr/precision.hpp"
#include "fgr/program_cache.hpp"
#include "fgr/renderer.hpp"
#include "fgr/scene.hpp"

namespace fgr {

struct StillSettings {
    int packet_width = 0;   // rays per work-item; 0: the device's preference
    uint64_t effects = 0;   // fgr_effect_flag bits compiled in
    bool stats = false;     // count the primary rays' work (Frame::stats)
    Precision precision = Precision::Auto;
};

// Builds the scene's kernel (logging what it builds and how long it took) and renders `request`.
// Float or double as PrecisionChooser decides for the view (Auto: auto_wants_double, with the DE
// at the camera from the float kernel when the target alone does not call for double). Throws
// KernelBuildError when the scene does not compile, std::runtime_error when double was asked of a
// device without it, and std::runtime_error when a pixel's colour or depth came out NaN or
// infinite (non_finite_pixels): an image that could not be computed is an error, never a file.
Frame render_still(const Scene& scene, const FrameRequest& request, const ComputeDevice& device,
                   ProgramCache& cache, const StillSettings& settings);

// Pixels of `frame` whose linear colour or depth is NaN or infinite.
long non_finite_pixels(const Frame& frame);

// Writes `frame` as a PNG: bit_depth 8, the tone-mapped sRGB image; 16, its linear colour times
// `exposure` in a linear 16-bit PNG. Atomic and throwing like write_png.
void write_still(const std::filesystem::path& path, const Frame& frame, int bit_depth,
                 float exposure);

}  // namespace fgr
