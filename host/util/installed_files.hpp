// SPDX-License-Identifier: Apache-2.0
#pragma once
// Where fgr's installed files are, found from the running executable: the build tree has the
// install layout (bin/, lib/fgr/plugins/, share/fgr/schemas/), so a built fgr and an installed one
// find them the same way.

#include <filesystem>
#include <string>
#include <string_view>

namespace fgr {

// Directory holding the running executable (/proc/self/exe); empty when it cannot be resolved.
std::filesystem::path executable_dir();

// share/fgr/schemas beside the running executable's bin/: the JSON Schemas of fgr's file formats.
// Empty when the executable's directory is unknown.
std::filesystem::path schema_dir();

// The "$schema" value fgr writes into a JSON file of the format `schema_file` describes (e.g.
// "camera-path.schema.json"): the file:// URI of that schema in schema_dir(), so an editor finds
// it in the build tree and in an installed tree alike. When the executable's directory is
// unknown, `schema_file` itself (the schema's "$id").
std::string schema_reference(std::string_view schema_file);

// The file:// URI of an absolute path (RFC 8089): "file://" and the path, each byte outside
// [A-Za-z0-9-._~/] percent-encoded.
std::string file_uri(const std::filesystem::path& absolute);

}  // namespace fgr
