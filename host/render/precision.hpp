// SPDX-License-Identifier: Apache-2.0
#pragma once
// Float or double lanes for a render. Float is ~2x faster and resolves any view whose pixels are
// coarser than a few float steps of the coordinates; a deep zoom needs double, where float would
// round neighbouring pixels' rays onto the same points (flat blocks, noisy depth). `Auto` picks
// per view by one rule (auto_wants_double), which every front end (fgr render, fgr view,
// fgr bench) calls through PrecisionChooser, so all three decide alike on the same view.

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "camera/camera.hpp"
#include "device/kernel_assembly.hpp"
#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace fgr {

enum class Precision { Float, Double, Auto };

// "float", "double" or "auto"; throws std::invalid_argument naming the choices otherwise.
Precision parse_precision(std::string_view text);
std::string_view precision_name(Precision precision);

// --- The auto rule ---------------------------------------------------------------------------

// `--precision auto`'s one rule: double when one pixel's footprint (a `width`-pixel image of
// `view`) is under 16 float steps of the coordinates (finer_than_float) where the view's finest
// detail can be: at the camera target, or, when `surface_distance` (the DE at the camera) puts a
// surface nearer than the target, at that distance along the view. The DE bounds the distance to
// everything in view from below, so a camera close to a surface renders in double wherever its
// target is (the viewer's fly camera keeps its target far ahead), and the rule errs towards
// double; a camera far from every surface is judged at its target (a deep zoom's target is on
// the surface). A negative `surface_distance` (unknown) judges at the target alone.
bool auto_wants_double(const CameraView& view, int width, float surface_distance);

// The distance auto_wants_double takes: |DE| at the camera, evaluated once by `in_float`, the
// scene's float kernel (whichever precision renders, so every front end judges by the same
// number); -1 when it is not finite, or the scene has only an inside test (no distance to judge).
float surface_distance(Renderer& in_float, const CameraView& view,
                       const std::vector<float>& params);

// Asked for the surface distance only when the rule needs it (Auto, and the target alone does
// not already call for double): front ends pass a function that builds (or reuses) the float
// renderer and calls surface_distance. An empty function means "unknown".
using SurfaceDistance = std::function<float()>;

// Whether to render `view` at `width` pixels in double. Double on a device without cl_khr_fp64
// throws std::runtime_error; Auto there falls back to float (PrecisionChooser says so).
bool use_double_precision(Precision precision, const CameraView& view, int width,
                          const DeviceInfo& device, const SurfaceDistance& distance = {});

// Decides float or double view by view on one device, as use_double_precision does, and tells
// `warn` once (a line naming the device) the first time Auto wanted double on a device without it.
class PrecisionChooser {
public:
    using Warn = std::function<void(const std::string&)>;
    PrecisionChooser(const DeviceInfo& device, Warn warn);

    bool in_double(Precision precision, const CameraView& view, int width,
                   const SurfaceDistance& distance = {});

private:
    const DeviceInfo& device_;
    Warn warn_;
    bool warned_ = false;
};

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
