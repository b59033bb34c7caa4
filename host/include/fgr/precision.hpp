#pragma once
// Float or double lanes for a render. Float is ~2x faster and resolves any view whose pixels are
// coarser than a few float steps of the coordinates; a deep zoom needs double, where float would
// round neighbouring pixels' rays onto the same points (flat blocks, noisy depth). `Auto` picks
// per view, so every front end (render, view, bench) switches the same way.

#include <string>
#include <string_view>

#include "fgr/camera.hpp"
#include "fgr/kernel_assembly.hpp"
#include "fgr/opencl_device.hpp"

namespace fgr {

enum class Precision { Float, Double, Auto };

// "float", "double" or "auto"; throws std::invalid_argument naming the choices otherwise.
Precision parse_precision(std::string_view text);
std::string_view precision_name(Precision precision);

// Whether to render `view` at `width` pixels in double. Double on a device without cl_khr_fp64
// throws std::runtime_error; Auto there falls back to float (the caller may warn, see
// `precision_fallback`).
bool use_double_precision(Precision precision, const CameraView& view, int width,
                          const DeviceInfo& device);

// True when Auto wanted double for this view but the device cannot do it.
bool precision_fallback(Precision precision, const CameraView& view, int width,
                        const DeviceInfo& device);
// The warning for a fallback, one line naming the device.
std::string precision_fallback_message(const DeviceInfo& device);

// OpenCL C's scalar double overloads are ambiguous with the kernel library's float literals;
// vector lanes are not, so double runs at least this many rays per work-item.
constexpr int kMinDoublePacketWidth = 4;

// `switches` with double lanes on or off, the packet width raised for double where needed.
KernelSwitches with_precision(KernelSwitches switches, bool double_precision);

}  // namespace fgr
