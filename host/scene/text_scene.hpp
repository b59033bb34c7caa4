// SPDX-License-Identifier: Apache-2.0
#pragma once
// Text scenes: a scene in one OpenCL C file, `NAME.cl`, no compiler needed. The file starts (after
// blank space) with a block comment whose first word is `fgr-scene` and whose rest is a JSON
// object describing the scene as a plugin's fgr_scene_desc does; the whole file, that comment
// included, is the scene's source, so the OpenCL compiler's line numbers are the file's (the SDK
// guide's page docs/sdk/text-scenes.md). The header is turned into an
// fgr_scene_desc and checked by copy_scene_description, so a text scene is refused exactly as a
// plugin with the same description would be.

#include <filesystem>
#include <string_view>

#include "scene/description_validation.hpp"

namespace fgr {

// The word that opens a text scene's header comment.
inline constexpr std::string_view kTextSceneTag = "fgr-scene";
// How deep the header's JSON may nest (a keyframe's position is 5 levels down): deeper input is
// refused before it is parsed, so nothing that recurses over a document meets a deep one.
inline constexpr int kTextSceneMaxDepth = 16;
// Bytes of a file read to tell whether it starts with the header.
inline constexpr std::size_t kTextSceneSniffBytes = 4096;

// Whether `file` is named like a text scene (`*.cl`); whether it is one, its first bytes say
// (is_text_scene_file): a plugin folder may hold .cl files that other sources include.
bool is_text_scene_file_name(const std::filesystem::path& file);

// Whether `text` starts with a text scene's header: after blank space (and a UTF-8 byte order
// mark), `/*` and then, after blank space, the word fgr-scene on its own.
bool starts_with_text_scene_header(std::string_view text);

// Whether `file` is a regular file that starts with the header, whatever its name (reads at most
// kTextSceneSniffBytes of it).
bool file_has_text_scene_header(const std::filesystem::path& file);

// Whether `file` is a *.cl file that starts with the header: a text scene. A .cl file without it
// is not a scene; one with a broken header is.
bool is_text_scene_file(const std::filesystem::path& file);

// The scene that `text`, the contents of `file`, describes: the header read and checked, the
// whole text its source, `file` its source_name and plugin_file. A refusal is one line without
// the file's name (LoadResult's convention), e.g. `header "parameters[2].max": must be a
// number`, and declares the scene's id when the header gave a valid one.
LoadResult parse_text_scene(std::string_view text, const std::filesystem::path& file);

// The text scene in `file`, read (at most scene_limits::kMaxSourceBytes) and parsed.
LoadResult load_text_scene(const std::filesystem::path& file);

}  // namespace fgr
