#include "fgr/video_progress.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <unistd.h>

namespace fgr {

VideoProgress::VideoProgress(int total_frames, std::FILE* stream)
    : total_(std::max(total_frames, 1)),
      stream_(stream),
      terminal_(isatty(fileno(stream)) != 0),
      start_(std::chrono::steady_clock::now()),
      last_plain_(start_) {}

std::string VideoProgress::line(int done, int total, double seconds) {
    constexpr int kBarWidth = 20;
    const int filled = total > 0 ? done * kBarWidth / total : kBarWidth;
    const double fps = seconds > 0.0 ? done / seconds : 0.0;
    std::string eta = "--:--";
    if (fps > 0.0) {
        const long left = std::lround((total - done) / fps);
        eta = left >= 3600 ? fmt::format("{}:{:02}:{:02}", left / 3600, left / 60 % 60, left % 60)
                           : fmt::format("{}:{:02}", left / 60, left % 60);
    }
    return fmt::format("frame {}/{} [{}{}] {:.2f} fps, ETA {}", done, total,
                       std::string(filled, '#'), std::string(kBarWidth - filled, '.'), fps, eta);
}

void VideoProgress::frame_done(int done) {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - start_).count();
    if (terminal_) {
        // \r back to the line's start, \033[K clears what a longer previous line left.
        std::fprintf(stream_, "\r%s\033[K", line(done, total_, seconds).c_str());
        std::fflush(stream_);
        return;
    }
    const bool tenth = (done - last_plain_done_) * 10 >= total_;
    const bool while_ago = now - last_plain_ >= std::chrono::seconds(10);
    if (tenth || while_ago || done == total_) {
        std::fprintf(stream_, "fgr: %s\n", line(done, total_, seconds).c_str());
        std::fflush(stream_);
        last_plain_ = now;
        last_plain_done_ = done;
    }
}

void VideoProgress::finish() {
    if (terminal_) std::fputc('\n', stream_);
}

}  // namespace fgr
