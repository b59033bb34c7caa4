// SPDX-License-Identifier: Apache-2.0
#pragma once
// Loading scene plugins: dlopen one file, look up its single entry symbol, validate and copy the
// description it returns (description_validation.hpp), and unload it again on any failure.

#include <filesystem>

#include "fgr/plugin.h"
#include "scene/description_validation.hpp"

namespace fgr {

// dlopen(RTLD_LAZY | RTLD_LOCAL), find FGR_SCENE_ENTRY_SYMBOL, call it, validate and copy.
// The library is closed again before returning: the host keeps only its copy.
LoadResult load_scene_plugin(const std::filesystem::path& file);

// Loads a plugin that may have changed since it was last loaded (the viewer's hot reload): as
// load_scene_plugin, but from a copy of `file` under a unique name in the temporary directory,
// removed again before returning. dlopen hands back a library it still has loaded when asked for
// the same path or file again, and dlclose need not unload one (a C++ plugin with a
// function-local static in an inline function gets a unique symbol that pins it, as
// -z nodelete does), so loading a rebuilt plugin from its own path could return the old image.
// The scene's plugin_file is `file`, and reasons name `file`.
LoadResult reload_scene_plugin(const std::filesystem::path& file);

}  // namespace fgr
