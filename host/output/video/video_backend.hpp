// SPDX-License-Identifier: Apache-2.0
#pragma once
// The FFmpeg half of video encoding, built as a module of its own (libfgr_video_ffmpeg.so,
// host/video_ffmpeg/) that fgr loads the first time something encodes a video. FFmpeg's libraries
// and the ~130 they pull in (every codec's) are then loaded only by the processes that write
// videos: linked into fgr, binding their symbols took 32 ms of every fgr process, `fgr --help`
// and a 26 ms render alike.
//
// Both sides are built from this tree with the same compiler, so the table passes C++ types and
// exceptions; the entry point is extern "C" only so dlsym finds it by name.

#include <filesystem>
#include <string>

#include "image/image_io.hpp"
#include "output/video/video_encoder.hpp"

namespace fgr::video_backend {

// One open video: the encoder, the muxer and the file they write.
struct Encoder;

// Bumped whenever the table below or a type it passes (VideoSettings) changes, so a stale module
// is refused, not called.
inline constexpr int kVersion = 2;

struct Table {
    int version;
    std::string (*default_codec)(const std::filesystem::path& output);
    void (*check_settings)(const std::filesystem::path& output, const VideoSettings& settings);
    // Opens `temporary` as a video of `settings` (codec already chosen) in `output`'s container
    // and writes its header; sets *description. Throws as VideoEncoder's constructor does.
    Encoder* (*open)(const std::filesystem::path& output, const std::filesystem::path& temporary,
                     const VideoSettings& settings, std::string* description);
    void (*add_frame)(Encoder* encoder, const Image8& image);
    // Flushes the encoder, writes the trailer and closes the file.
    void (*finish)(Encoder* encoder);
    // Frees the encoder (closing the file if finish was not reached).
    void (*close)(Encoder* encoder);
};

// The module's file name (in module_directory(), scene/modules.hpp) and its entry point.
inline constexpr const char* kModuleName = "libfgr_video_ffmpeg.so";
inline constexpr const char* kEntryPoint = "fgr_video_backend";

}  // namespace fgr::video_backend
