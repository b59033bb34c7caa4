// SPDX-License-Identifier: Apache-2.0
#pragma once
// Assembling a scene's OpenCL program: switches + kernel library prelude + generated parameter
// accessors + the scene's source + the library's marching, shading and entry points. Every
// piece starts with a #line directive, so compiler messages name the scene's own file and line.

#include <cstdint>
#include <string>
#include <string_view>

#include "fgr/plugin.h"
#include "scene/effects.hpp"
#include "scene/render_mode.hpp"
#include "scene/scene.hpp"

namespace fgr {

// Compile-time choices: each distinct set is a distinct program.
struct KernelSwitches {
    int packet_width = 1;  // rays per work-item: 1, 4, 8 or 16
    uint64_t effects = 0;  // fgr_effect_flag bits compiled in
    bool stats = false;    // also record each pixel's march steps and whether it ran out of them
    bool double_precision = false;         // march and shade in double (needs cl_khr_fp64)
    RenderMode mode = RenderMode::Shaded;  // which entry point (kernels/fgr_mode_<name>.cl)
    // Also write what a still's alpha and layers need (Frame::albedo, normal, alpha, foreground)
    // where the mode does not always write it: the shaded mode's layers, the path mode's
    // foreground. Off, the kernel is exactly the plain one.
    bool aovs = false;
};

struct AssembledProgram {
    std::string source;
    std::string options;  // clBuildProgram options: the -D switches
    int kernel_api = 1;   // the version the scene's source declares (scene/kernel_api.hpp)
};

AssembledProgram assemble_program(const Scene& scene, const KernelSwitches& switches);

// "#define param_<id> ..." lines reading each parameter from the buffer `fgr_params`, as the
// kernel API version the scene's source declares reads it (a vec3 is a float3 from version 4).
std::string param_accessors(const Scene& scene, int kernel_api);

// What to change when a build log shows a lane value and a uniform one mixed up, as reading
// parameters invites: a `real` (one value per lane) where a float is wanted, which a vec3
// parameter's component is before kernel API 4, or (from version 4) a vec3 parameter's float3
// where a vec3 is wanted. "" when the log shows neither.
std::string build_error_hint(int kernel_api, std::string_view log);

// The -D options for the switches, e.g. "-DFGR_WIDTH=16 -DFGR_EFFECT_SHADOWS".
std::string switch_options(const KernelSwitches& switches);

}  // namespace fgr
