// SPDX-License-Identifier: Apache-2.0
#pragma once
// Camera paths as JSON files: what the viewer records and saves, and what
// `fgr render --camera-path FILE.json --time T` renders.
//
//   {"$schema": "file:///.../share/fgr/schemas/camera-path.schema.json",
//    "format": "fgr-camera-path", "version": 1, "scene": "mandelbulb", "name": "recorded",
//    "keyframes": [{"time": 0, "position": [x, y, z], "target": [x, y, z], "up": [x, y, z],
//                   "fov": 60}, ...]}
//
// "fov" is the horizontal field of view in degrees, as everywhere in fgr. "$schema" is for
// editors (schemas/camera-path.schema.json, which agrees with the reader) and is not read; any
// other key is refused, so a misspelt one never passes silently.

#include <cstdint>
#include <filesystem>
#include <string>

#include "camera/view.hpp"

namespace fgr {

struct CameraPathFile {
    std::string scene;  // id of the scene it was recorded in (informative)
    CameraPath path;
};

// The JSON text of a path (pretty-printed, ends with a newline), its "$schema" the schema beside
// the running executable (util/installed_files.hpp).
std::string camera_path_json(const CameraPathFile& file);

// A camera path file larger than this is refused before it is read: kMaxPathKeyframes keyframes
// of about a kilobyte each at most.
inline constexpr std::uintmax_t kMaxCameraPathFileBytes = std::uintmax_t{16} << 20;

// Parses and validates: no unknown keys, 2 to kMaxPathKeyframes keyframes, strictly increasing
// finite times, finite vectors, position != target, fov in (0, 180). Throws std::runtime_error with
// a one-line reason.
CameraPathFile parse_camera_path_json(const std::string& text);

// Reads `file`; errors name the file.
CameraPathFile read_camera_path_file(const std::filesystem::path& file);

// Writes atomically (temporary file, then rename). Throws std::runtime_error naming the file.
void write_camera_path_file(const std::filesystem::path& file, const CameraPathFile& contents);

// Whether a --camera-path argument names a file rather than one of the scene's paths.
bool looks_like_camera_path_file(const std::string& argument);

}  // namespace fgr
