// SPDX-License-Identifier: Apache-2.0
#include "output/parts/frame_merge.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <vector>

namespace fgr {
namespace {

// merged = (merged * n_merged + part * n_part) / (n_merged + n_part), in double.
void weighted_mean(std::vector<float>& merged, const std::vector<float>& part,
                   double merged_share) {
    const double part_share = 1.0 - merged_share;
    for (size_t i = 0; i < merged.size(); ++i) {
        merged[i] =
            static_cast<float>(double(merged[i]) * merged_share + double(part[i]) * part_share);
    }
}

void check_same_planes(const Frame& merged, const Frame& part) {
    const auto differ = [](const std::vector<float>& a, const std::vector<float>& b) {
        return a.size() != b.size();
    };
    if (merged.image.width != part.image.width || merged.image.height != part.image.height) {
        throw std::invalid_argument(
            fmt::format("cannot add samples of a {}x{} frame to a {}x{} one", part.image.width,
                        part.image.height, merged.image.width, merged.image.height));
    }
    if (differ(merged.linear, part.linear) || differ(merged.albedo, part.albedo) ||
        differ(merged.normal, part.normal) || differ(merged.alpha, part.alpha) ||
        differ(merged.foreground, part.foreground)) {
        throw std::invalid_argument("cannot add samples of frames that hold different layers");
    }
}

}  // namespace

void add_samples(Frame& merged, const Frame& part) {
    if (merged.samples == 0) {
        merged = part;
        return;
    }
    check_same_planes(merged, part);
    const double total = double(merged.samples) + double(part.samples);
    const double merged_share = double(merged.samples) / total;
    weighted_mean(merged.linear, part.linear, merged_share);
    weighted_mean(merged.albedo, part.albedo, merged_share);
    weighted_mean(merged.normal, part.normal, merged_share);
    weighted_mean(merged.alpha, part.alpha, merged_share);
    weighted_mean(merged.foreground, part.foreground, merged_share);
    merged.samples += part.samples;
}

}  // namespace fgr
