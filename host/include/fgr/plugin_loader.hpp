#pragma once
// Loading scene plugins: dlopen one file, look up its single entry symbol, validate and copy the
// description it returns, and unload it again on any failure.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "fgr/plugin.h"
#include "fgr/scene.hpp"

namespace fgr {

// Either a scene or the reason there is none (one line, no file name: callers add that).
struct LoadResult {
    std::optional<Scene> scene;
    std::string error;
};

// Validates `desc` field by field (reading only fields its struct_size covers) and copies it into
// a host-owned Scene, built-in quality parameters included. Never dereferences a pointer it has
// not checked for NULL.
LoadResult copy_scene_description(const fgr_scene_desc* desc);

// dlopen(RTLD_LAZY | RTLD_LOCAL), find FGR_SCENE_ENTRY_SYMBOL, call it, validate and copy.
// The library is closed again before returning: the host keeps only its copy.
LoadResult load_scene_plugin(const std::filesystem::path& file);

}  // namespace fgr
