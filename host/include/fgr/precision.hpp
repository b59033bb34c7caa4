#pragma once
// Float or double lanes for a render. Float is ~2x faster and resolves any view whose pixels are
// coarser than a few float steps of the coordinates; a deep zoom needs double, where float would
// round neighbouring pixels' rays onto the same points (flat blocks, noisy depth). `Auto` picks
// per view, so every front end (render, view, bench) switches the same way.

#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "fgr/camera.hpp"
#include "fgr/kernel_assembly.hpp"
#include "fgr/opencl_device.hpp"
#include "fgr/program_cache.hpp"
#include "fgr/renderer.hpp"
#include "fgr/scene.hpp"

namespace fgr {

enum class Precision { Float, Double, Auto };

// "float", "double" or "auto"; throws std::invalid_argument naming the choices otherwise.
Precision parse_precision(std::string_view text);
std::string_view precision_name(Precision precision);

// Whether to render `view` at `width` pixels in double. Double on a device without cl_khr_fp64
// throws std::runtime_error; Auto there falls back to float (PrecisionChooser says so).
bool use_double_precision(Precision precision, const CameraView& view, int width,
                          const DeviceInfo& device);

// Decides float or double view by view on one device, as use_double_precision does, and tells
// `warn` once (a line naming the device) the first time Auto wanted double on a device without it.
class PrecisionChooser {
public:
    using Warn = std::function<void(const std::string&)>;
    PrecisionChooser(const DeviceInfo& device, Warn warn);

    bool in_double(Precision precision, const CameraView& view, int width);

private:
    const DeviceInfo& device_;
    Warn warn_;
    bool warned_ = false;
};

// Whether the surface a float render found is finer than float resolves, judged at the hits
// rather than at the camera target: more than 1% of the frame's hit pixels have a footprint
// (depth times the pixel angle of a `width`-pixel image of the view) under 16 float steps of the
// coordinates there. `frame` may be a smaller probe render of the same view.
bool hits_finer_than_float(const Frame& frame, const CameraView& view, int width);

// Auto judges a view at its camera target; the camera may still stand close to a surface finer
// than float resolves while the target is far. This renders a float probe of `request`'s view at
// an eighth of its size (under 2% of the render's work) with `in_float` and judges it at the hits
// (hits_finer_than_float).
bool float_probe_finds_fine_surface(Renderer& in_float, const FrameRequest& request);

// OpenCL C's scalar double overloads are ambiguous with the kernel library's float literals;
// vector lanes are not, so double runs at least this many rays per work-item.
constexpr int kMinDoublePacketWidth = 4;

// `switches` with double lanes on or off, the packet width raised for double where needed.
KernelSwitches with_precision(KernelSwitches switches, bool double_precision);

// One scene's float and double renderers on one device (the same switches otherwise), each built
// the first time it is asked for: front ends that switch precision view by view hold one.
class PrecisionRenderers {
public:
    PrecisionRenderers(const ComputeDevice& device, ProgramCache& cache, const Scene& scene,
                       const KernelSwitches& switches);

    // The renderer in that precision, or null when it has not been built yet.
    Renderer* built(bool double_precision);
    // The renderer in that precision, built now if need be (throws KernelBuildError).
    Renderer& get(bool double_precision);

private:
    const ComputeDevice& device_;
    ProgramCache& cache_;
    const Scene& scene_;
    KernelSwitches switches_;
    std::unique_ptr<Renderer> renderers_[2];  // float, double
};

}  // namespace fgr
