// SPDX-License-Identifier: Apache-2.0
#pragma once
// Encoding frames into a video file in-process with FFmpeg's libraries (libavcodec, libavformat,
// libswscale). The container comes from the file's extension (.mp4, .mkv, .webm, .gif, .webp,
// .apng ...); the codec is the container's default (default_video_codec) or one named. The file
// appears only when finish() succeeds: frames go to a temporary beside it, renamed at the end,
// and an encoder destroyed before finish() (an error, Ctrl-C) removes the temporary.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "image/image_io.hpp"
#include "util/interruption.hpp"

namespace fgr {

struct VideoSettings {
    std::string codec;  // an FFmpeg encoder name (libx264, mpeg4, libvpx-vp9 ...); "": the default
    int width = 0;
    int height = 0;
    double fps = 30.0;
    // Constant-quality level for the codecs that have one (x264, x265: 0-51, default 18;
    // VP9, AV1: 0-63, default 24): lower is better and bigger; 0 is lossless in x264's 4:2:0.
    std::optional<int> crf;
    // A document the file carries (image/embedded_view.hpp: the view that made it) as the
    // container's "comment" metadata; "": none. MP4, Matroska and WebM keep it, MOV up to 65535
    // bytes (check_video_settings refuses more); FFmpeg's GIF, animated WebP and APNG muxers write
    // no metadata, so those files go without.
    std::string embedded_view{};
};

// The codec a file gets unless told: H.264 (libx264) for .mp4/.mkv/.mov when this FFmpeg has it
// (mpeg4 when not), VP9 for .webm, and the format's own for .gif, .webp (libwebp_anim) and .apng.
// Throws std::invalid_argument for an extension FFmpeg knows no container for.
std::string default_video_codec(const std::filesystem::path& output);

// Throws std::invalid_argument (one line) unless `settings` can be encoded into `output`: a known
// container, an encoder by that name, a size the codec's pixel format allows (yuv420p: even width
// and height), an embedded view check_embedded_view takes and the container can hold.
void check_video_settings(const std::filesystem::path& output, const VideoSettings& settings);

class VideoEncoder {
public:
    // Opens the temporary and writes the container header. Throws std::invalid_argument as
    // check_video_settings does and std::runtime_error when FFmpeg cannot open or write it.
    VideoEncoder(const std::filesystem::path& output, VideoSettings settings);
    ~VideoEncoder();
    VideoEncoder(const VideoEncoder&) = delete;
    VideoEncoder& operator=(const VideoEncoder&) = delete;

    // Appends one frame (settings' size, sRGB). Throws std::runtime_error.
    void add_frame(const Image8& image);
    // Flushes the encoder, writes the trailer and renames the temporary onto the output.
    void finish();
    // The encoder's name and pixel format, e.g. "libx264 (yuv420p, crf 18)".
    const std::string& description() const { return description_; }

private:
    struct State;
    std::unique_ptr<State> state_;
    std::filesystem::path output_, temporary_;
    // A signal removes the temporary too (util/interruption.hpp).
    std::unique_ptr<TemporaryFileRegistration> registration_;
    std::string description_;
    bool finished_ = false;
};

}  // namespace fgr
