// SPDX-License-Identifier: Apache-2.0
#pragma once
// Assembling a scene's OpenCL program: switches + kernel library prelude + generated parameter
// accessors + the scene's source + the library's marching, shading and entry points. Every
// piece starts with a #line directive, so compiler messages name the scene's own file and line.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "fgr/plugin.h"
#include "scene/effects.hpp"
#include "scene/render_mode.hpp"
#include "scene/scene.hpp"

namespace fgr {

// A parameter compiled into the kernel as a constant: its accessor reads `value`, never the
// parameter buffer, so the compiler folds what it shapes.
struct SpecialisedParam {
    std::string id;
    float value = 0.0f;
    bool operator==(const SpecialisedParam&) const = default;
};

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
    // Parameters compiled in as constants (specialisation_for); empty: the generic kernel, which
    // reads every parameter from the buffer. A renderer so built renders only those values.
    std::vector<SpecialisedParam> specialised{};
};

struct AssembledProgram {
    std::string source;
    std::string options;  // clBuildProgram options: the -D switches
    int kernel_api = 1;   // the version the scene's source declares (scene/kernel_api.hpp)
};

AssembledProgram assemble_program(const Scene& scene, const KernelSwitches& switches);

// Whether the shaded kernel takes two tiles a work-item and marches their camera rays together
// (FGR_PAIRED_TILES, kernels/modes/fgr_mode_shaded.cl): for a DE scene that gives its DE at two
// points in one call, in packets (the processor overlaps the two chains; a GPU hides latency
// with other work-items instead), without glow (the paired march keeps no closest approach).
bool pairs_tiles(const Scene& scene, const KernelSwitches& switches);

// "#define param_<id> ..." lines reading each parameter from the buffer `fgr_params`, as the
// kernel API version the scene's source declares reads it (a vec3 is a float3 from version 4).
// Parameters in `specialised` read as their constant value instead.
std::string param_accessors(const Scene& scene, int kernel_api,
                            const std::vector<SpecialisedParam>& specialised = {});

// The largest magnitude a specialised value may have: beyond it the generic kernel is used.
inline constexpr float kMaxSpecialisedValue = 4096.0f;

// What of `params` (the scene's values) to compile in: each parameter the scene's source declares
// specialisable (declared_specialisable) whose value is a whole number no larger than
// kMaxSpecialisedValue; empty when none is. Throws std::invalid_argument naming the source file
// when the declaration names no parameter of the scene, or one that is not an int or a float.
std::vector<SpecialisedParam> specialisation_for(const Scene& scene,
                                                 const std::vector<float>& params);

// Writes the values `specialised` compiled in into `params` (the scene's values).
void set_specialised_values(const Scene& scene, const std::vector<SpecialisedParam>& specialised,
                            std::vector<float>& params);

// "" when `params` holds the values `specialised` compiled in, else a one-line reason.
std::string specialisation_mismatch(const Scene& scene,
                                    const std::vector<SpecialisedParam>& specialised,
                                    const std::vector<float>& params);

// What to change when a build log shows a lane value and a uniform one mixed up, as reading
// parameters invites: a `real` (one value per lane) where a float is wanted, which a vec3
// parameter's component is before kernel API 4, or (from version 4) a vec3 parameter's float3
// where a vec3 is wanted. "" when the log shows neither.
std::string build_error_hint(int kernel_api, std::string_view log);

// The -D options for the switches, e.g. "-DFGR_WIDTH=16 -DFGR_EFFECT_SHADOWS".
std::string switch_options(const KernelSwitches& switches);

}  // namespace fgr
