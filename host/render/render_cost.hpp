// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a render will cost, estimated from its settings before anything is built or launched, so
// that settings implying hours are refused in one line (what is costly, the estimate, what to
// change, and the override) instead of running silently, and so that a long frame reports its
// progress (the renderer splits its launches into bands by it).
//
// Work is counted in steps, the time of one IFS ball test; a DE formula's iteration or an inside
// test's costs a fixed fraction of one (kMarchIterationSteps, kInsideIterationSteps). Per pixel
// sample: a marched ray takes up to `max_steps` DE evaluations of `iterations` each (counted at
// kTypicalMarchSteps); the path mode traces a ray per bounce; the brute mode makes `brute_samples`
// + `brute_bisection` inside tests a pass; an IFS ray the tests scene/ifs/ifs_cost.hpp estimates.
// The pace a device keeps is a rough figure per compute unit, measured on a 2-core CPU with PoCL;
// the estimate says "about" for that reason.

#include <cstdint>
#include <string>

#include "device/opencl_device.hpp"
#include "render/renderer.hpp"
#include "scene/render_mode.hpp"
#include "scene/scene.hpp"

namespace fgr {

// Estimated seconds past which a render is refused unless the user lifts the limit
// (`--no-cost-limit`).
inline constexpr double kCostLimitSeconds = 3600.0;

// DE evaluations a marched ray is counted at: the march ends well before max_steps for most rays.
inline constexpr double kTypicalMarchSteps = 64.0;
// What one DE iteration of a marched ray, and one of the brute mode's inside tests, cost in
// steps: packets of rays march in SIMD lanes and most rays stop early, where an IFS ray is traced
// alone. Measured on the same CPU: mandelbulb at 640x480 took 0.08 s shaded, 51 s path traced at
// 64 samples and 1.2 s in the brute mode at 16 passes.
inline constexpr double kMarchIterationSteps = 1.0 / 64.0;
inline constexpr double kInsideIterationSteps = 1.0 / 32.0;
// A shaded pixel sample of a DE scene at the defaults (a camera ray and a shadow ray of
// kTypicalMarchSteps DE evaluations of 12 iterations).
inline constexpr double kPlainSampleSteps = 2.0 * kTypicalMarchSteps * 12.0 * kMarchIterationSteps;

struct RenderCost {
    double steps_per_sample = 0.0;  // per pixel sample, all of its rays
    double steps = 0.0;             // the whole frame: pixels x samples x steps_per_sample
    // IFS only: rays would need more nodes than the kernel lets one visit (max_steps x 256), so
    // they would stop unfinished and the image would be wrong as well as slow.
    bool rays_unfinished = false;
    std::string costly;  // what makes it cost that: "64 maps overlapping 55x a level, depth 24"
    std::string remedy;  // what to change: "lower ifs_depth to 3"
};

// The estimate for one frame of `request` (its size, samples and parameters) in `mode`.
RenderCost estimate_render_cost(const Scene& scene, const FrameRequest& request, RenderMode mode);

// Steps a second `device` keeps, roughly.
double estimated_pace(const DeviceInfo& device);

// "" when `frames` frames of `cost` at `pace` steps a second (estimated_pace, times the devices
// sharing the work) fit `limit_seconds` and no IFS ray would stop unfinished; else the one-line
// refusal: the estimate, what is costly, what to change, then `override_hint` (e.g. "pass
// --no-cost-limit to render it anyway").
std::string cost_refusal(const RenderCost& cost, double frames, double pace, double limit_seconds,
                         const std::string& override_hint);

}  // namespace fgr
