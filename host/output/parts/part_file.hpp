// SPDX-License-Identifier: Apache-2.0
#pragma once
// A part file's channels and its reader (output/parts/render_parts.hpp), shared by rendering a part
// and merging parts.

#include <ImfForward.h>

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "output/parts/render_parts.hpp"
#include "render/renderer.hpp"

namespace fgr {

// The channels of a part, in the order rendering interleaves them: R, G, B, depth.Z, then with
// layers albedo.R/G/B, normal.X/Y/Z, alpha.A, foreground.R/G/B.
std::vector<std::string> part_channels(bool layers);

// The part `path` (named in messages) whose fgr.part header is `text`: every field checked against
// its type and range (sizes within kMaxTiledImageSide, the region inside the image, samples within
// kMaxSamples, the exposure within its parameter's range, a known tone map and render mode), and
// the identity's size, display and layers against the numbers. Throws std::runtime_error, one line
// naming the file and the field. The header alone: read_part_info checks the file against it.
PartInfo parse_part_header(std::string_view text, const std::filesystem::path& path);

// Reads rows of a part into Frames of its region's width, the planes as rendered.
class PartReader {
public:
    explicit PartReader(const PartInfo& info);
    ~PartReader();
    PartReader(const PartReader&) = delete;
    PartReader& operator=(const PartReader&) = delete;

    // Rows first_row .. first_row + rows - 1 (of the whole image, within the part's region):
    // linear, depth and (with layers) albedo, normal, alpha, foreground, and Frame::samples.
    Frame read_rows(int first_row, int rows);

private:
    const PartInfo& info_;
    std::unique_ptr<Imf::InputFile> file_;
};

}  // namespace fgr
