// SPDX-License-Identifier: Apache-2.0
#pragma once
// The effects a scene can be rendered with: their names on the command line and in files, the
// compile-time switch each one is in the kernel, and which effects each kind of scene and mode can
// have.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "fgr/plugin.h"

namespace fgr {

struct Scene;

// One effect: its fgr_effect_flag bit, the kernel's switch (-D macro) and its name.
struct EffectSwitch {
    uint64_t bit;
    const char* macro;
    const char* name;
};

// Every effect, in bit order.
std::span<const EffectSwitch> effect_switches();

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
                                       FGR_EFFECT_AMBIENT_OCCLUSION | FGR_EFFECT_SAMPLED_OCCLUSION |
                                       FGR_EFFECT_GLOW | FGR_EFFECT_FOG;

// The effects `scene` can be built with: all for DE scenes, kIfsEffects for IFS scenes.
uint64_t supported_effects(const Scene& scene);

// Throws std::invalid_argument, naming the scene and the effects, when `effects` holds one the
// scene cannot have (assemble_program checks it too).
void check_supported_effects(const Scene& scene, uint64_t effects);

// Applies a comma-separated list of changes to `effects`: "+name" or "name" adds an effect,
// "-name" removes it, "none" removes all, e.g. "+shadows,-ambient_occlusion" or "none,+fog". Throws
// std::invalid_argument naming an unknown effect and listing the known ones.
uint64_t apply_effect_changes(uint64_t effects, std::string_view changes);

}  // namespace fgr
