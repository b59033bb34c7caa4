// SPDX-License-Identifier: Apache-2.0
#pragma once
// What an environment is called: `--environment`'s value, and a scene's own environment (ABI 1.5
// `fgr_scene_desc::environment`, a scene file's "environment"), which the path mode lights the
// scene with when the user names none. render/environment.hpp makes one ready to render.

#include <filesystem>
#include <glm/vec3.hpp>
#include <string>
#include <string_view>

namespace fgr {

enum class EnvironmentKind {
    Sky,      // Preetham's daylight sky with its sun (the default)
    Studio,   // fgr's generated photo studio: soft boxes in a grey room
    Uniform,  // the same radiance from every direction (furnace tests)
    File,     // an equirectangular .hdr or .exr
};

struct EnvironmentSpec {
    EnvironmentKind kind = EnvironmentKind::Sky;
    glm::vec3 radiance{1.0f};    // Uniform
    std::filesystem::path file;  // File
};

// "sky", "studio", "uniform" (radiance 1), "uniform:V" or "uniform:R,G,B" (finite, non-negative),
// or else the path of an .hdr or .exr file. Throws std::invalid_argument, its message starting
// with `what` (the option or field that gave the text).
EnvironmentSpec parse_environment_spec(std::string_view text, std::string_view what);

// A scene's own environment checked: what parse_environment_spec takes but a file (a scene names a
// generated environment; a map on disk is the user's `--environment FILE`), at most
// scene_limits::kMaxIdLength bytes. "" (none: the sky) passes. Throws std::invalid_argument with
// a one-line reason that quotes the text printably.
void check_scene_environment(std::string_view text);

}  // namespace fgr
