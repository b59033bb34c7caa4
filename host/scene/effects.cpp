// SPDX-License-Identifier: Apache-2.0
#include "scene/effects.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

#include "scene/scene.hpp"

namespace fgr {
namespace {

constexpr std::array kEffectSwitches{
    EffectSwitch{FGR_EFFECT_SHADOWS, "FGR_EFFECT_SHADOWS", "shadows"},
    EffectSwitch{FGR_EFFECT_AMBIENT_OCCLUSION, "FGR_EFFECT_AMBIENT_OCCLUSION", "ambient_occlusion"},
    EffectSwitch{FGR_EFFECT_SOFT_SHADOWS, "FGR_EFFECT_SOFT_SHADOWS", "soft_shadows"},
    EffectSwitch{FGR_EFFECT_REFLECTIONS, "FGR_EFFECT_REFLECTIONS", "reflections"},
    EffectSwitch{FGR_EFFECT_SAMPLED_OCCLUSION, "FGR_EFFECT_SAMPLED_OCCLUSION", "sampled_occlusion"},
    EffectSwitch{FGR_EFFECT_GLOW, "FGR_EFFECT_GLOW", "glow"},
    EffectSwitch{FGR_EFFECT_FOG, "FGR_EFFECT_FOG", "fog"},
    EffectSwitch{FGR_EFFECT_DEPTH_OF_FIELD, "FGR_EFFECT_DEPTH_OF_FIELD", "depth_of_field"},
    EffectSwitch{FGR_EFFECT_REFRACTION, "FGR_EFFECT_REFRACTION", "refraction"},
};

}  // namespace

std::span<const EffectSwitch> effect_switches() { return kEffectSwitches; }

std::string effect_names(uint64_t effects) {
    std::string names;
    for (const auto& effect : kEffectSwitches) {
        if (!(effects & effect.bit)) continue;
        if (!names.empty()) names += ",";
        names += effect.name;
    }
    return names.empty() ? "none" : names;
}

uint64_t supported_effects(const Scene& scene) { return scene.ifs ? kIfsEffects : ~uint64_t{0}; }

uint64_t apply_effect_changes(uint64_t effects, std::string_view changes) {
    size_t start = 0;
    while (start <= changes.size()) {
        const size_t comma = std::min(changes.find(',', start), changes.size());
        std::string_view item = changes.substr(start, comma - start);
        start = comma + 1;
        if (item.empty()) continue;
        if (item == "none") {
            effects = 0;
            continue;
        }
        const bool remove = item.front() == '-';
        if (item.front() == '-' || item.front() == '+') item.remove_prefix(1);
        const auto known =
            std::find_if(kEffectSwitches.begin(), kEffectSwitches.end(),
                         [&](const EffectSwitch& effect) { return item == effect.name; });
        if (known == kEffectSwitches.end()) {
            throw std::invalid_argument(
                fmt::format("unknown effect '{}' (known: {})", item, effect_names(~uint64_t{0})));
        }
        effects = remove ? (effects & ~known->bit) : (effects | known->bit);
    }
    return effects;
}

void check_supported_effects(const Scene& scene, uint64_t effects) {
    if (const uint64_t unsupported = effects & ~supported_effects(scene)) {
        throw std::invalid_argument(fmt::format(
            "the IFS scene '{}' cannot have {}: exact IFS tracing has no distance estimate (it "
            "can have {})",
            scene.id, effect_names(unsupported), effect_names(kIfsEffects)));
    }
}

}  // namespace fgr
