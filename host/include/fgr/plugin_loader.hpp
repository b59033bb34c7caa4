#pragma once
// Loading scene plugins: dlopen one file, look up its single entry symbol, validate and copy the
// description it returns (description_validation.hpp), and unload it again on any failure.

#include <filesystem>

#include "fgr/description_validation.hpp"
#include "fgr/plugin.h"

namespace fgr {

// dlopen(RTLD_LAZY | RTLD_LOCAL), find FGR_SCENE_ENTRY_SYMBOL, call it, validate and copy.
// The library is closed again before returning: the host keeps only its copy.
LoadResult load_scene_plugin(const std::filesystem::path& file);

}  // namespace fgr
