// SPDX-License-Identifier: Apache-2.0
#pragma once
// `fgr new-scene`: a new scene plugin project from the SDK template (sdk/template, built into fgr
// so it works from any install): a CMakeLists.txt that finds the installed fgr, a C file with the
// description, a .cl file with a distance estimator and a colour, and a README; or, with --text,
// one text scene file (scene/text_scene.hpp).

#include <filesystem>
#include <string>
#include <vector>

namespace fgr {

// What the template's placeholders become for a scene id such as "my-kifs".
struct ScaffoldNames {
    std::string id;            // @SCENE_ID@: my-kifs (file name of the .so, the scene's id)
    std::string symbol;        // @SCENE_SYMBOL@: my_kifs (C identifiers and source file names)
    std::string display_name;  // @SCENE_NAME@: My Kifs
};

// Throws UsageError unless `id` is a valid scene id ([a-z][a-z0-9_-]*, at most 63 characters).
ScaffoldNames scaffold_names(const std::string& id);

// Replaces every @KEY@ of `text` with its value; unknown @...@ sequences stay as they are.
std::string fill_template(const std::string& text,
                          const std::vector<std::pair<std::string, std::string>>& values);

// Writes the text scene `id` (sdk/template/text_scene.cl: a bumpy ball, every header key shown) as
// `directory`/ID.cl and returns its path: one file that `fgr render` and `fgr view` open as it is.
// Refuses (UsageError) a bad id, a missing directory and a file that is already there; written
// atomically.
std::filesystem::path scaffold_text_scene(const std::string& id,
                                          const std::filesystem::path& directory);

// Writes the project for `id` into `directory` (which must not exist, or be empty) and returns
// the files written. `fgr_prefix` is where find_package(fgr) should look first. All or nothing:
// the files are written to a temporary directory beside `directory`, then renamed into place.
// Throws UsageError (bad id, directory not empty) or std::runtime_error (file system).
std::vector<std::filesystem::path> scaffold_scene(const std::string& id,
                                                  const std::filesystem::path& directory,
                                                  const std::filesystem::path& fgr_prefix);

}  // namespace fgr
