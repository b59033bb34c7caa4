// SPDX-License-Identifier: Apache-2.0
// VideoEncoder: the file handling (a temporary beside the output, renamed at the end) here; the
// encoding in the FFmpeg module, loaded the first time a video is checked or written.
#include "output/video/video_encoder.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <system_error>

#include "image/embedded_view.hpp"
#include "output/video/video_backend.hpp"
#include "scene/modules.hpp"
#include "util/errors.hpp"

namespace fgr {
namespace {

// Loaded once per process (the module stays loaded: FFmpeg keeps global state).
const video_backend::Table& backend() {
    static const video_backend::Table& table =
        module_table<video_backend::Table>(video_backend::kModuleName, video_backend::kEntryPoint,
                                           video_backend::kVersion, "video encoding");
    return table;
}

}  // namespace

std::string default_video_codec(const std::filesystem::path& output) {
    return backend().default_codec(output);
}

void check_video_settings(const std::filesystem::path& output, const VideoSettings& settings) {
    check_embedded_view(output, settings.embedded_view);
    backend().check_settings(output, settings);
}

struct VideoEncoder::State {
    const video_backend::Table& backend;
    video_backend::Encoder* encoder = nullptr;

    ~State() {
        if (encoder) backend.close(encoder);
    }
};

VideoEncoder::VideoEncoder(const std::filesystem::path& output, VideoSettings settings)
    : state_(std::make_unique<State>(State{backend()})), output_(output) {
    check_embedded_view(output, settings.embedded_view);
    if (settings.codec.empty()) settings.codec = state_->backend.default_codec(output);
    // Beside the output (same file system, so the rename is atomic), hidden, named after it.
    temporary_ = output.parent_path() / fmt::format(".{}.partial", output.filename().string());
    registration_ = std::make_unique<TemporaryFileRegistration>(temporary_);
    try {
        state_->encoder = state_->backend.open(output, temporary_, settings, &description_);
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(temporary_, ignored);  // opened before the header failed
        throw;
    }
}

VideoEncoder::~VideoEncoder() {
    if (finished_) return;
    state_.reset();  // closes the temporary first
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
}

void VideoEncoder::add_frame(const Image8& image) {
    state_->backend.add_frame(state_->encoder, image);
}

void VideoEncoder::finish() {
    state_->backend.finish(state_->encoder);
    std::error_code error;
    std::filesystem::rename(temporary_, output_, error);
    if (error) fail_write(output_, error.message());
    finished_ = true;
}

}  // namespace fgr
