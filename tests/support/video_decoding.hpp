// SPDX-License-Identifier: Apache-2.0
#pragma once
// Decoding what `fgr video` wrote, for tests: every frame of a file's video stream as sRGB bytes.

#include <filesystem>
#include <string>
#include <vector>

#include "image/image_io.hpp"

namespace fgr::test {

struct DecodedVideo {
    std::string codec;
    long frames_in_header = 0;  // the stream's frame count as the container records it
    double duration = 0.0;      // seconds, the container's
    std::vector<Image8> frames;
};

// Every frame of the file's video stream as sRGB bytes, converted back with the BT.709 matrix the
// stream is tagged with (the one fgr encodes with). A failure to open or decode is a test failure.
DecodedVideo decode_video(const std::filesystem::path& file);

}  // namespace fgr::test
