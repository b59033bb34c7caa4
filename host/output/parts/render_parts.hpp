// SPDX-License-Identifier: Apache-2.0
#pragma once
// Renders split for schedulers (Slurm job arrays, GNU parallel over ssh, a studio farm) and
// merged again, with no protocol of fgr's own: each job writes a file, one merge reads them all.
//
// A part is an OpenEXR file (32-bit float) whose display window is the whole image and whose data
// window is the region it rendered, holding the Frame's raw planes: R, G, B the linear colour as
// rendered (not premultiplied), depth.Z (-1 where the camera ray missed), and, when the render
// had the layers' planes (--alpha, --aov), albedo.R/G/B, normal.X/Y/Z, alpha.A and
// foreground.R/G/B. Its header attribute "fgr.part" (JSON) records what the render was, field by
// field (scene, kernel, size, view, parameters, mode, effects, precision, projection, path
// tracing but the seed, display transform, layers), its region, samples per pixel and seed.
//
// Merging checks that the parts belong together (the same identity), groups them by region (a
// group's parts are independent sample sets of the same pixels, merged with add_samples), that
// the groups tile the image exactly with the same samples everywhere, and streams the result a
// band of rows at a time through the writers tiled stills use: tile parts merge into exactly the
// whole render's file, seed parts into the render of all their samples.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "image/display.hpp"
#include "output/tiled/tiled_still.hpp"
#include "render/renderer.hpp"

namespace fgr {

// Tile `index` (1-based) of `count` of a width x height image: rows
// floor((index - 1) * height / count) .. floor(index * height / count) - 1, full width. Throws
// std::invalid_argument unless 1 <= index <= count <= height.
PixelRegion tile_region(int width, int height, int index, int count);

struct PartSettings {
    int tile_size = kDefaultTileSize;  // launches of about this side (as a tiled still's tiles)
    // Polled between launches: true stops the render, leaving no file.
    std::function<bool()> interrupted{};
    std::function<void(long done, long total)> on_progress{};  // launches
    // The view the part carries (image/embedded_view.hpp), for the merged image; "": none.
    std::string embedded_view{};
};

struct PartResult {
    bool interrupted = false;
    PixelRegion region;  // of the whole image
    long hits = 0;       // pixels of the region whose camera ray met the surface
    int samples = 0;     // per pixel
    long launches = 0;
    double render_ms = 0.0;  // rendering and writing
};

// Renders the region of `request` (request.region; whole: the whole image) with `renderer` into
// the part file `path`, a band of rows at a time in launches of at most kMaxImageSide a side
// (with the padding a brute-mode tile needs, region_padding), so memory is bounded by a band.
// `display` is recorded for the merge (the 8-bit output's exposure and tone map). Throws
// std::invalid_argument for a path that is not .exr or a region outside the image,
// std::runtime_error for a file that cannot be written or non-finite pixels.
PartResult render_part(Renderer& renderer, const FrameRequest& request,
                       const DisplayTransform& display, const std::filesystem::path& path,
                       const PartSettings& settings);

// What a part's header says.
struct PartInfo {
    std::filesystem::path path;
    std::vector<std::pair<std::string, std::string>> identity;  // in image_identity's order
    // The whole image.
    int width = 0;
    int height = 0;
    PixelRegion region;
    int samples = 0;  // per pixel
    uint32_t seed = 0;
    std::string mode;  // the render mode's name
    DisplayTransform display;
    bool layers = false;  // albedo, normal, alpha and foreground planes
    std::string view;     // the view it carries ("": none), as the part was rendered
};

// Throws std::runtime_error, one line naming the file: "cannot read '<path>': ..." (not a regular
// file, not OpenEXR), "'<path>' is not an fgr part (...)", or "'<path>' is a damaged fgr part:
// its header's "FIELD" ..." (a field of the wrong type or outside its range, or numbers that
// disagree with the identity: parse_part_header in part_file.hpp).
PartInfo read_part_info(const std::filesystem::path& path);

// Parts of the same region: independent samples of the same pixels.
struct PartGroup {
    PixelRegion region;
    std::vector<size_t> parts;  // indices into MergePlan::parts
    int samples = 0;            // per pixel, all of them
};

struct MergePlan {
    int width = 0;
    int height = 0;
    std::vector<PartInfo> parts;
    std::vector<PartGroup> groups;  // top to bottom, left to right
    int samples = 0;                // per pixel, every group's
    DisplayTransform display;
    bool layers = false;
};

// Checks that `parts` make one image and how, before anything is allocated for them: throws
// std::invalid_argument (one line, naming the files) for parts of different renders (the first
// differing field), of different sizes, layers or display transforms, a region outside the image,
// two parts of a region with the same seed, regions that overlap, pixels no part covers (the
// first missing rows), or regions with different samples per pixel.
MergePlan plan_merge(std::vector<PartInfo> parts);

struct MergeResult {
    int band_rows = 0;  // rows merged and written at a time
    int bands = 0;
};

// Merges the parts into `output` (output.display is taken from the parts), band by band: memory
// is bounded by `band_budget_bytes` (at least a row), not the image. Atomic: on an error no file
// is left. Throws std::invalid_argument for an output that needs layers the parts lack (alpha,
// albedo, normal), std::runtime_error for a file that cannot be read or written.
MergeResult merge_parts(const MergePlan& plan, TiledOutput output,
                        size_t band_budget_bytes = kBandBudgetBytes);

}  // namespace fgr
