// SPDX-License-Identifier: Apache-2.0
#pragma once
// Validating a plugin's scene description (fgr_scene_desc) and copying it into a host-owned Scene:
// the ABI version and struct sizes, ids and names, string lengths, parameter ranges and types,
// cameras and camera paths, lights, effects and march settings. The first problem found is the
// reason given.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fgr/plugin.h"
#include "scene/scene.hpp"
#include "scene/scene_limits.hpp"

namespace fgr {

// Either a scene or the reason there is none (one line, no file name: callers add that).
struct LoadResult {
    std::optional<Scene> scene;
    std::string error;
    // On a refusal, the scene id the description declared if it got as far as a valid one (""
    // otherwise): `fgr render ID` can then say why scene ID is missing.
    std::string declared_id = {};
};

// Validates `desc` field by field (reading only fields its struct_size covers) and copies it into
// a host-owned Scene, built-in quality parameters included. Never dereferences a pointer it has
// not checked for NULL.
LoadResult copy_scene_description(const fgr_scene_desc* desc);

// Parameters described as a plugin describes them (fgr_param_desc, e.g. scene_helpers.h's
// FGR_COLOUR_PARAMS), checked and copied as a plugin's are: for scenes the host writes itself
// (formula files), so that their colour parameters are a plugin's. Throws std::invalid_argument
// (one line) for a description a plugin would be refused.
std::vector<ParamInfo> copy_param_descriptions(std::span<const fgr_param_desc> descriptions);

// `text` as it may appear in a one-line refusal: bytes outside printable ASCII become \xNN.
std::string printable(std::string_view text);

}  // namespace fgr
