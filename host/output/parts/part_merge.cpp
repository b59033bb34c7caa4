// SPDX-License-Identifier: Apache-2.0
// Merging parts (output/parts/render_parts.hpp): the checks that they make one image, and the band
// by band merge into an output file.
#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <tuple>

#include "image/display.hpp"
#include "output/parts/frame_merge.hpp"
#include "output/parts/part_file.hpp"
#include "output/parts/render_parts.hpp"
#include "output/tiled/row_encoder.hpp"
#include "output/tiled/streaming_image.hpp"
#include "render/sample_budget.hpp"
#include "util/interruption.hpp"
#include "util/strings.hpp"

namespace fgr {
namespace {

// "rows 0..20" for a full-width region, "rows 0..20, columns 8..15" otherwise.
std::string region_text(const PixelRegion& region, int width) {
    std::string text = fmt::format("rows {}..{}", region.y, region.y + region.height - 1);
    if (region.x != 0 || region.width != width) {
        text += fmt::format(", columns {}..{}", region.x, region.x + region.width - 1);
    }
    return text;
}

std::string named(const PartInfo& part) {
    return fmt::format("{} ({})", quoted(part.path), region_text(part.region, part.width));
}

// The first field in which `part` differs from `first` (which fixes the order), or "".
std::string first_difference(const PartInfo& first, const PartInfo& part, std::string* mine,
                             std::string* theirs) {
    for (const auto& [key, value] : first.identity) {
        const auto found = std::find_if(part.identity.begin(), part.identity.end(),
                                        [&](const auto& field) { return field.first == key; });
        const std::string other = found == part.identity.end() ? "none" : found->second;
        if (other != value) {
            *mine = value;
            *theirs = other;
            return key;
        }
    }
    if (part.identity.size() != first.identity.size()) {
        *mine = *theirs = "";
        return "set of identity fields";
    }
    return "";
}

std::vector<std::string> words(const std::string& text) {
    std::vector<std::string> result;
    size_t start = 0;
    while (start <= text.size()) {
        const size_t end = std::min(text.find(' ', start), text.size());
        result.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return result;
}

// "'a' and 'b'", or for long lists of values (the parameters) the first that differs:
// "value 16 of 38: '1' and '2'".
std::string difference_text(const std::string& mine, const std::string& theirs) {
    const std::vector<std::string> a = words(mine), b = words(theirs);
    if (a.size() == b.size() && a.size() > 4) {
        for (size_t i = 0; i < a.size(); ++i) {
            if (a[i] != b[i]) {
                return fmt::format("value {} of {}: '{}' and '{}'", i + 1, a.size(),
                                   printable_excerpt(a[i]), printable_excerpt(b[i]));
            }
        }
    }
    // Each side shortened: a damaged part's identity can hold text of any length.
    return fmt::format("'{}' and '{}'", printable_excerpt(mine, 80), printable_excerpt(theirs, 80));
}

void check_same_render(const std::vector<PartInfo>& parts) {
    for (size_t i = 1; i < parts.size(); ++i) {
        std::string mine, theirs;
        const std::string field = first_difference(parts[0], parts[i], &mine, &theirs);
        if (!field.empty()) {
            throw std::invalid_argument(
                fmt::format("{} and {} are not parts of one image: they differ in {} ({})",
                            quoted(parts[0].path), quoted(parts[i].path), field,
                            difference_text(mine, theirs)));
        }
    }
}

// What the merge sizes and shows by, the same in every part and inside the image: the width and
// height (the first part's: the image's), the regions, the samples, the layers and the display
// transform. read_part_info checks these numbers against each part's identity; here they are
// checked against one another, so that no part can make the merge write outside its rows.
void check_same_numbers(const std::vector<PartInfo>& parts) {
    const PartInfo& first = parts.front();
    if (first.width < 1 || first.height < 1 || first.width > kMaxTiledImageSide ||
        first.height > kMaxTiledImageSide) {
        throw std::invalid_argument(fmt::format("{} is {}x{}, not an image fgr renders",
                                                quoted(first.path), first.width, first.height));
    }
    for (const PartInfo& part : parts) {
        if (part.width != first.width || part.height != first.height) {
            throw std::invalid_argument(
                fmt::format("{} is {}x{} but {} is {}x{}: the parts of one image have one size",
                            quoted(part.path), part.width, part.height, quoted(first.path),
                            first.width, first.height));
        }
        const PixelRegion& r = part.region;
        if (r.x < 0 || r.y < 0 || r.width < 1 || r.height < 1 ||
            long(r.x) + r.width > first.width || long(r.y) + r.height > first.height) {
            throw std::invalid_argument(fmt::format(
                "{} has its region ({}x{} at {}, {}) outside its {}x{} image", quoted(part.path),
                r.width, r.height, r.x, r.y, first.width, first.height));
        }
        if (part.samples < 1 || part.samples > kMaxSamples) {
            throw std::invalid_argument(fmt::format("{} has {} samples per pixel, not 1 to {}",
                                                    quoted(part.path), part.samples, kMaxSamples));
        }
        if (part.layers != first.layers) {
            throw std::invalid_argument(fmt::format(
                "{} {} the layers' planes but {} {}: parts of one image have the same layers",
                quoted(part.path), part.layers ? "has" : "lacks", quoted(first.path),
                first.layers ? "has" : "lacks"));
        }
        if (part.display.exposure != first.display.exposure ||
            part.display.tone_map != first.display.tone_map) {
            throw std::invalid_argument(fmt::format(
                "{} and {} differ in their display transform (exposure {:.9g} tone map {} and "
                "exposure {:.9g} tone map {})",
                quoted(first.path), quoted(part.path), first.display.exposure,
                static_cast<int>(first.display.tone_map), part.display.exposure,
                static_cast<int>(part.display.tone_map)));
        }
    }
}

// Parts grouped by region, top to bottom and left to right; two parts of a region must be
// different samples (different seeds of the path tracer).
std::vector<PartGroup> group_by_region(const std::vector<PartInfo>& parts) {
    std::map<std::tuple<int, int, int, int>, PartGroup> groups;
    for (size_t i = 0; i < parts.size(); ++i) {
        const PixelRegion& r = parts[i].region;
        PartGroup& group = groups[{r.y, r.x, r.height, r.width}];
        group.region = r;
        for (size_t other : group.parts) {
            if (parts[other].seed != parts[i].seed) continue;
            if (!seeded_samples(parts[i].mode)) {
                throw std::invalid_argument(fmt::format(
                    "{} and {} render the same pixels in the {} mode, which repeats its "
                    "samples: only --mode path renders independent samples (--seed S)",
                    named(parts[other]), quoted(parts[i].path), parts[i].mode));
            }
            throw std::invalid_argument(fmt::format(
                "{} and {} are the same samples (seed {}): give each part of a region its own "
                "--seed",
                named(parts[other]), quoted(parts[i].path), parts[i].seed));
        }
        if (group.samples > std::numeric_limits<int>::max() - parts[i].samples) {
            throw std::invalid_argument(
                fmt::format("{} and its region's other parts have more samples per pixel than "
                            "fgr counts",
                            named(parts[i])));
        }
        group.parts.push_back(i);
        group.samples += parts[i].samples;
    }
    std::vector<PartGroup> ordered;
    for (auto& [key, group] : groups) ordered.push_back(std::move(group));
    return ordered;
}

bool overlap(const PixelRegion& a, const PixelRegion& b) {
    return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height &&
           b.y < a.y + a.height;
}

void check_no_overlap(const std::vector<PartInfo>& parts, const std::vector<PartGroup>& groups) {
    for (size_t i = 0; i < groups.size(); ++i) {
        for (size_t j = i + 1; j < groups.size(); ++j) {
            // Sorted by first row: none further down can reach into group i.
            if (groups[j].region.y >= groups[i].region.y + groups[i].region.height) break;
            if (overlap(groups[i].region, groups[j].region)) {
                throw std::invalid_argument(fmt::format(
                    "{} and {} overlap: each pixel must come from one region (parts of the same "
                    "region are merged as samples)",
                    named(parts[groups[i].parts.front()]), named(parts[groups[j].parts.front()])));
            }
        }
    }
}

// With no overlaps, the image is covered when every row is covered across its width.
void check_coverage(const MergePlan& plan) {
    std::set<int> cuts{0, plan.height};
    for (const PartGroup& group : plan.groups) {
        cuts.insert(group.region.y);
        cuts.insert(group.region.y + group.region.height);
    }
    int missing_from = -1;
    bool partly = false;
    for (auto cut = cuts.begin(); std::next(cut) != cuts.end(); ++cut) {
        const int y0 = *cut, y1 = *std::next(cut);
        long covered = 0;
        for (const PartGroup& group : plan.groups) {
            if (group.region.y <= y0 && y1 <= group.region.y + group.region.height) {
                covered += group.region.width;
            }
        }
        if (covered < plan.width) {
            if (missing_from < 0) missing_from = y0;
            partly = partly || covered > 0;
            continue;
        }
        if (missing_from >= 0) {
            throw std::invalid_argument(fmt::format(
                "no part covers {}rows {}..{} of the {}x{} image: a part is missing",
                partly ? "all of " : "", missing_from, y0 - 1, plan.width, plan.height));
        }
    }
    if (missing_from >= 0) {
        throw std::invalid_argument(fmt::format(
            "no part covers {}rows {}..{} of the {}x{} image: a part is missing",
            partly ? "all of " : "", missing_from, plan.height - 1, plan.width, plan.height));
    }
}

void check_same_samples(const MergePlan& plan) {
    const PartGroup& first = plan.groups.front();
    for (const PartGroup& group : plan.groups) {
        if (group.samples == first.samples) continue;
        throw std::invalid_argument(fmt::format(
            "{} has {} samples per pixel and {} {}: every region of the image needs the same "
            "samples (the same --spp and as many seeds)",
            named(plan.parts[first.parts.front()]), first.samples,
            named(plan.parts[group.parts.front()]), group.samples));
    }
}

// The 8-bit display image of merged linear colour, as the renderer makes it (display_image).
Image8 display_of(const Frame& frame, const DisplayTransform& display) {
    Image8 image{frame.image.width, frame.image.height, std::vector<uint8_t>(frame.linear.size())};
    for (size_t i = 0; i < frame.linear.size(); ++i) {
        image.rgb[i] = encode_srgb(tone_map(frame.linear[i] * display.exposure, display.tone_map));
    }
    return image;
}

void check_layers(const MergePlan& plan, const TiledOutput& output) {
    if (plan.layers) return;
    const bool needs =
        output.alpha || output.aovs.alpha || output.aovs.albedo || output.aovs.normal;
    if (needs) {
        throw std::invalid_argument(fmt::format(
            "{} needs the layers' planes, which the parts lack: render them with --alpha or "
            "--aov albedo,normal,alpha",
            output.alpha || output.aovs.alpha ? "alpha" : "--aov"));
    }
}

}  // namespace

MergePlan plan_merge(std::vector<PartInfo> parts) {
    if (parts.empty()) throw std::invalid_argument("no parts to merge");
    check_same_render(parts);
    check_same_numbers(parts);
    MergePlan plan;
    plan.width = parts.front().width;
    plan.height = parts.front().height;
    plan.display = parts.front().display;
    plan.layers = parts.front().layers;
    plan.groups = group_by_region(parts);
    plan.parts = std::move(parts);
    check_no_overlap(plan.parts, plan.groups);
    check_coverage(plan);
    check_same_samples(plan);
    plan.samples = plan.groups.front().samples;
    return plan;
}

MergeResult merge_parts(const MergePlan& plan, TiledOutput output, size_t band_budget_bytes) {
    output.display = plan.display;
    check_layers(plan, output);
    const RowLayout layout = output_row_layout(output);
    const size_t pixel_bytes = layout.pixel_bytes();
    // Per pixel of a band: the output's samples, a group's merged planes and one part's, and the
    // merged display colour.
    const size_t plane_bytes = part_channels(plan.layers).size() * sizeof(float);
    const size_t band_pixel_bytes = pixel_bytes + 2 * plane_bytes + 3;
    MergeResult result;
    result.band_rows = static_cast<int>(std::clamp<size_t>(
        band_budget_bytes / (size_t(plan.width) * band_pixel_bytes), 1, size_t(plan.height)));

    auto writer = open_streaming_image(output.path, output.format, plan.width, plan.height, layout,
                                       {}, output.embedded_view);
    std::vector<std::unique_ptr<PartReader>> readers(plan.parts.size());
    std::vector<uint8_t> band;
    const size_t stride = pixel_bytes * size_t(plan.width);
    for (int band_y = 0; band_y < plan.height; band_y += result.band_rows) {
        const int rows = std::min(result.band_rows, plan.height - band_y);
        band.assign(stride * size_t(rows), 0);
        for (const PartGroup& group : plan.groups) {
            const PixelRegion& region = group.region;
            const int y0 = std::max(band_y, region.y);
            const int y1 = std::min(band_y + rows, region.y + region.height);
            if (y0 >= y1) continue;
            Frame merged;
            for (size_t p : group.parts) {
                if (!readers[p]) readers[p] = std::make_unique<PartReader>(plan.parts[p]);
                add_samples(merged, readers[p]->read_rows(y0, y1 - y0));
            }
            merged.image = display_of(merged, plan.display);
            RowEncoder encoder(merged, output, layout);
            for (int y = y0; y < y1; ++y) {
                encoder.encode(
                    y - y0, 0, region.width,
                    band.data() + size_t(y - band_y) * stride + size_t(region.x) * pixel_bytes);
            }
            if (y1 == region.y + region.height) {
                for (size_t p : group.parts) readers[p].reset();  // done with these files
            }
        }
        writer->write_rows(band.data(), rows);
        ++result.bands;
        hold_for_test("merge");
    }
    writer->finish();
    return result;
}

}  // namespace fgr
