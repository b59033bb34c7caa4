// SPDX-License-Identifier: Apache-2.0
#include "scene/render_mode.hpp"

#include <fmt/format.h>

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "util/suggest.hpp"

namespace fgr {

std::span<const RenderModeInfo> render_modes() {
    static constexpr std::array modes{
        RenderModeInfo{RenderMode::Shaded, "shaded",
                       "Blinn-Phong with the scene's lights and effects (fast, interactive)"},
        RenderModeInfo{RenderMode::Path, "path",
                       "unbiased path tracing: materials, sun, sky and image-based lighting"},
        RenderModeInfo{RenderMode::Brute, "brute",
                       "brute-force sampling of the inside test, screen-space shading: renders "
                       "sets with no distance estimator (progressive: more passes, closer hits)"},
    };
    return modes;
}

std::string_view render_mode_name(RenderMode mode) {
    for (const RenderModeInfo& info : render_modes()) {
        if (info.mode == mode) return info.name;
    }
    return "shaded";
}

std::string render_mode_choices() {
    std::string choices;
    for (const RenderModeInfo& info : render_modes()) {
        if (!choices.empty()) choices += '|';
        choices += info.name;
    }
    return choices;
}

RenderMode parse_render_mode(std::string_view name) {
    for (const RenderModeInfo& info : render_modes()) {
        if (info.name == name) return info.mode;
    }
    std::vector<std::string> names;
    for (const RenderModeInfo& info : render_modes()) names.emplace_back(info.name);
    throw std::invalid_argument(fmt::format("unknown render mode '{}' (choose {}){}", name,
                                            render_mode_choices(), did_you_mean(name, names)));
}

}  // namespace fgr
