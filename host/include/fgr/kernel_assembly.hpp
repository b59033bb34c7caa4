#pragma once
// Assembling a scene's OpenCL program: switches + kernel library prelude + generated parameter
// accessors + the scene's source + the library's marching, shading and entry points. Every
// piece starts with a #line directive, so compiler messages name the scene's own file and line.

#include <cstdint>
#include <string>
#include <string_view>

#include "fgr/plugin.h"
#include "fgr/render_mode.hpp"
#include "fgr/scene.hpp"

namespace fgr {

// Compile-time choices: each distinct set is a distinct program.
struct KernelSwitches {
    int packet_width = 1;  // rays per work-item: 1, 4, 8 or 16
    uint64_t effects = 0;  // fgr_effect_flag bits compiled in
    bool stats = false;    // also record each pixel's march steps and whether it ran out of them
    bool double_precision = false;  // march and shade in double (needs cl_khr_fp64)
    RenderMode mode = RenderMode::Shaded;  // which entry point (kernels/fgr_mode_<name>.cl)
    // Also write what a still's alpha and layers need (Frame::albedo, normal, alpha, foreground)
    // where the mode does not always write it: the shaded mode's layers, the path mode's
    // foreground. Off, the kernel is exactly the plain one.
    bool aovs = false;
};

struct AssembledProgram {
    std::string source;
    std::string options;  // clBuildProgram options: the -D switches
};

AssembledProgram assemble_program(const Scene& scene, const KernelSwitches& switches);

// "#define param_<id> ..." lines reading each parameter from the buffer `fgr_params`.
std::string param_accessors(const Scene& scene);

// The -D options for the switches, e.g. "-DFGR_WIDTH=16 -DFGR_EFFECT_SHADOWS".
std::string switch_options(const KernelSwitches& switches);

// Names of the effect bits, in bit order ("shadows,ambient_occlusion"), or "none".
std::string effect_names(uint64_t effects);

// The effects an IFS scene can have: those that need only rays and hits. Soft shadows, both
// occlusions, glow and refraction read a distance estimate (or march step counts) along the way,
// which exact IFS tracing does not have.
constexpr uint64_t kIfsEffects =
    FGR_EFFECT_SHADOWS | FGR_EFFECT_REFLECTIONS | FGR_EFFECT_FOG | FGR_EFFECT_DEPTH_OF_FIELD;

// The effects the brute-force mode renders (in screen space, or with its inside test); it ignores
// the others, which need a distance estimate or a traced ray.
constexpr uint64_t kBruteModeEffects = FGR_EFFECT_SHADOWS | FGR_EFFECT_SOFT_SHADOWS |
                                       FGR_EFFECT_AMBIENT_OCCLUSION |
                                       FGR_EFFECT_SAMPLED_OCCLUSION | FGR_EFFECT_GLOW |
                                       FGR_EFFECT_FOG;

// The effects `scene` can be built with: all for DE scenes, kIfsEffects for IFS scenes.
uint64_t supported_effects(const Scene& scene);

// Throws std::invalid_argument, naming the scene and the effects, when `effects` holds one the
// scene cannot have (assemble_program checks it too).
void check_supported_effects(const Scene& scene, uint64_t effects);

// Applies a comma-separated list of changes to `effects`: "+name" or "name" adds an effect,
// "-name" removes it, "none" removes all, e.g. "+shadows,-ambient_occlusion" or "none,+fog". Throws std::invalid_argument naming an
// unknown effect and listing the known ones.
uint64_t apply_effect_changes(uint64_t effects, std::string_view changes);

}  // namespace fgr
