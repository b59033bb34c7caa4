// SPDX-License-Identifier: Apache-2.0
#pragma once
// Render modes: how a frame's pixels are computed from the scene. Each mode is one kernel file
// (kernels/fgr_mode_<name>.cl, entry point fgr_render) and one host module
// (host/render/modes/<name>_mode.cpp) that sets the kernel's own arguments and reads back its
// planes; host/render/modes/mode_registry.cpp lists them. A new mode adds an enumerator here, a row
// there, its kernel file and its module, and touches no other mode.

#include <span>
#include <string>
#include <string_view>

namespace fgr {

enum class RenderMode {
    Shaded,  // Blinn-Phong plus the effects the scene asks for: fast, interactive
    Path,    // unbiased Monte Carlo path tracing with materials, sky and image-based lighting
    Brute,   // brute-force sampling of an inside test, screen-space shading: sets with no DE
};

struct RenderModeInfo {
    RenderMode mode;
    std::string_view name;     // what users type: --mode NAME
    std::string_view summary;  // one line for --help and fgr info
};

std::span<const RenderModeInfo> render_modes();

std::string_view render_mode_name(RenderMode mode);

// A mode by name; throws std::invalid_argument naming the choices otherwise.
RenderMode parse_render_mode(std::string_view name);

// "shaded|path", for usage lines.
std::string render_mode_choices();

}  // namespace fgr
