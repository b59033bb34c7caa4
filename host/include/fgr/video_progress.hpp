#pragma once
// A video's progress on stderr: frames done, frames per second and the time left. On a terminal
// one line rewritten in place; otherwise (a log, CI) a plain line every tenth of the frames or
// every 10 seconds, whichever comes first, so logs stay short and still show it moving.

#include <chrono>
#include <cstdio>
#include <string>

namespace fgr {

class VideoProgress {
public:
    VideoProgress(int total_frames, std::FILE* stream = stderr);
    // After each finished frame: `done` frames of the total are written.
    void frame_done(int done);
    // Ends the in-place line (a newline on a terminal).
    void finish();

    // "frame 12/120 [###.......] 3.2 fps, ETA 0:34" for `done` frames after `seconds`.
    static std::string line(int done, int total, double seconds);

private:
    int total_;
    std::FILE* stream_;
    bool terminal_;
    std::chrono::steady_clock::time_point start_, last_plain_;
    int last_plain_done_ = 0;
};

}  // namespace fgr
