// SPDX-License-Identifier: Apache-2.0
// fgr merge: parts rendered apart (fgr render --part, --tile I/N, --seed S; on a farm) joined into
// one image file, or a directory of frames (fgr video --frames DIR --frame-range A:B, on many
// machines) encoded into one video.
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "commands.hpp"
#include "image/image_io.hpp"
#include "output/parts/render_parts.hpp"
#include "output/tiled/streaming_image.hpp"
#include "output/video/video_encoder.hpp"
#include "render/sample_budget.hpp"
#include "util/files.hpp"
#include "util/interruption.hpp"
#include "view_file/view_file.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;

// --- Parts into an image -------------------------------------------------------------------------

ImageFormat checked_image_output(const MergeOptions& options) {
    ImageFormat format;
    try {
        format = image_format_of(options.output);
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    }
    check_output_directory(options.output);
    const bool exr = format == ImageFormat::Exr;
    if (!options.aovs.empty() && !exr) throw UsageError("--aov needs an .exr output");
    if (exr && options.bit_depth != 8) throw UsageError("--bit-depth is for PNG and TIFF output");
    if (!options.codec.empty() || options.crf) {
        throw UsageError("--codec and --crf are for a video merged from --frames DIR");
    }
    return format;
}

TiledOutput merge_output(const MergeOptions& options, ImageFormat format) {
    TiledOutput output;
    output.path = options.output;
    output.format = format;
    output.bit_depth = options.bit_depth;
    output.alpha = options.alpha;
    try {
        output.aovs = parse_aovs(options.aovs);
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    }
    if (output.aovs.samples || output.aovs.variance) {
        throw UsageError(
            "--aov samples and variance are not kept in parts: fgr merge cannot write them");
    }
    // As fgr render: an EXR's alpha is its A channel.
    if (format == ImageFormat::Exr) output.aovs.alpha = output.aovs.alpha || options.alpha;
    return output;
}

std::string seeds_text(const MergePlan& plan) {
    std::set<uint32_t> seeds;
    for (const PartInfo& part : plan.parts) seeds.insert(part.seed);
    std::string text;
    for (uint32_t seed : seeds) text += (text.empty() ? "" : ",") + std::to_string(seed);
    return text;
}

// The view the merged image carries: its parts' (one image's: their identities agree), with the
// samples of all of them; "" when the first part carries none or one that cannot be read.
std::string merged_view(const MergePlan& plan) {
    if (plan.parts.empty() || plan.parts.front().view.empty()) return "";
    try {
        ViewFile view = parse_view_file(plan.parts.front().view);
        view.samples = std::min(plan.samples, kMaxSamples);
        return view_file_text(view);
    } catch (const std::runtime_error& error) {
        spdlog::warn("{}: its view cannot be read ({}): the merged image carries none",
                     plan.parts.front().path.string(), error.what());
        return "";
    }
}

int merge_parts_into_image(const MergeOptions& options) {
    TiledOutput output = merge_output(options, checked_image_output(options));
    std::vector<PartInfo> parts;
    for (const std::string& path : options.parts) {
        try {
            parts.push_back(read_part_info(path));
        } catch (const std::runtime_error& error) {
            throw UsageError(error.what());
        }
    }
    MergePlan plan;
    MergeResult result;
    try {
        plan = plan_merge(std::move(parts));
        output.embedded_view = merged_view(plan);
        result = merge_parts(plan, output);
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    } catch (const std::runtime_error& error) {
        throw RuntimeFailure(error.what());
    }
    fmt::print("parts {}\n", plan.parts.size());
    fmt::print("tiles {}\n", plan.groups.size());
    fmt::print("samples_per_pixel {}\n", plan.samples);
    fmt::print("seeds {}\n", seeds_text(plan));
    fmt::print("bands {} ({} rows a band)\n", result.bands, result.band_rows);
    fmt::print("wrote {} ({}x{})\n", options.output, plan.width, plan.height);
    return 0;
}

// --- Frames into a video -------------------------------------------------------------------------

// A frame's PNG file at most: a 16384-pixel square frame of noise, compressed as badly as PNG can.
constexpr std::uintmax_t kMaxFrameBytes = std::uintmax_t{1} << 30;

// The directory's frame_NNNNN.png files by number; UsageError when there are none or one is
// missing between frame 0 and the last.
std::vector<fs::path> numbered_frames(const fs::path& directory) {
    std::error_code error;
    if (!fs::is_directory(directory, error)) {
        throw UsageError(fmt::format("--frames '{}' is not a directory", directory.string()));
    }
    const std::regex name(R"(frame_(\d{1,9})\.png)");
    std::map<long, fs::path> found;
    for (const auto& entry : fs::directory_iterator(directory, error)) {
        std::smatch match;
        const std::string file = entry.path().filename().string();
        if (!std::regex_match(file, match, name)) continue;
        // Named like a frame, so meant as one: refused here, before any frame is encoded.
        if (const std::string problem = regular_file_problem(entry.path(), kMaxFrameBytes);
            !problem.empty()) {
            throw UsageError(
                fmt::format("frame {} cannot be read: {}", quoted(entry.path()), problem));
        }
        found[std::stol(match[1])] = entry.path();
    }
    if (found.empty()) {
        throw UsageError(
            fmt::format("no frame_00000.png ... in '{}' (fgr video --frames DIR "
                        "writes them)",
                        directory.string()));
    }
    std::vector<fs::path> frames;
    for (long number = 0; number <= found.rbegin()->first; ++number) {
        const auto frame = found.find(number);
        if (frame == found.end()) {
            throw UsageError(fmt::format(
                "'{}' has frames up to frame_{:05}.png but not frame_{:05}.png: render the "
                "missing range (fgr video --frames DIR --frame-range A:B) and merge again",
                directory.string(), found.rbegin()->first, number));
        }
        frames.push_back(frame->second);
    }
    return frames;
}

Image8 read_frame(const fs::path& file) {
    // Again as it is read: the directory may have changed since it was listed.
    if (const std::string problem = regular_file_problem(file, kMaxFrameBytes); !problem.empty()) {
        throw RuntimeFailure(fmt::format("frame {} cannot be read: {}", quoted(file), problem));
    }
    try {
        return read_png(file);
    } catch (const std::runtime_error& error) {
        throw RuntimeFailure(error.what());
    }
}

int merge_frames_into_video(const MergeOptions& options) {
    if (!options.parts.empty()) throw UsageError("give PARTS or --frames DIR, not both");
    if (options.bit_depth != 8 || options.alpha || !options.aovs.empty()) {
        throw UsageError("--bit-depth, --alpha and --aov are for merging parts, not frames");
    }
    if (!(options.fps > 0.0))
        throw UsageError(fmt::format("--fps must be positive (got {})", options.fps));
    check_output_directory(options.output);
    const std::vector<fs::path> frames = numbered_frames(options.frames_directory);
    const Image8 first = read_frame(frames.front());
    const VideoSettings settings{options.codec, first.width, first.height, options.fps,
                                 options.crf};
    try {
        check_video_settings(options.output, settings);
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    }
    try {
        VideoEncoder encoder(options.output, settings);
        encoder.add_frame(first);
        hold_for_test("merge");
        for (size_t i = 1; i < frames.size(); ++i) {
            const Image8 image = read_frame(frames[i]);
            if (image.width != first.width || image.height != first.height) {
                throw UsageError(
                    fmt::format("'{}' is {}x{} but '{}' is {}x{}: the frames of a "
                                "video must have one size",
                                frames[i].string(), image.width, image.height,
                                frames.front().string(), first.width, first.height));
            }
            encoder.add_frame(image);
        }
        encoder.finish();
        fmt::print("frames {}\n", frames.size());
        fmt::print("wrote {} ({} frames, {}x{}, {:g} fps, {})\n", options.output, frames.size(),
                   first.width, first.height, options.fps, encoder.description());
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    } catch (const UsageError&) {
        throw;
    } catch (const RuntimeFailure&) {
        throw;
    } catch (const std::runtime_error& error) {
        throw RuntimeFailure(error.what());
    }
    return 0;
}

}  // namespace

void add_merge_command(CLI::App& app, MergeOptions& options) {
    CLI::App* merge = app.add_subcommand(
        "merge",
        "join parts rendered apart (fgr render --part/--tile) into one image, or a "
        "frame directory (fgr video --frames) into a video");
    merge->add_option("parts", options.parts,
                      "part files (.exr) of one image: tiles (--tile I/N) and/or seeds (--seed S)");
    merge
        ->add_option("-o,--output", options.output,
                     "merged image (.png, .tif, .exr, as fgr render writes them), or a video "
                     "(.mp4 ...) with --frames")
        ->required();
    merge
        ->add_option("--bit-depth", options.bit_depth,
                     "8: tone-mapped sRGB PNG/TIFF (default); 16: linear 16-bit (exposure only)")
        ->check(CLI::IsMember({8, 16}));
    merge->add_flag("--alpha", options.alpha,
                    "coverage as alpha (the parts need their layers: render them with --alpha)");
    merge->add_option("--aov", options.aovs,
                      "EXR layers beside the linear image: albedo,normal,depth,alpha (albedo, "
                      "normal and alpha need parts rendered with them)");
    merge->add_option("--frames", options.frames_directory,
                      "encode DIR/frame_00000.png ... (every number from 0, one size) into -o");
    merge->add_option("--fps", options.fps, "with --frames: frames per second (default 30)");
    merge->add_option("--codec", options.codec,
                      "with --frames: FFmpeg encoder (default: the container's, as fgr video)");
    merge->add_option("--crf", options.crf, "with --frames: constant quality, as fgr video");
}

int command_merge(const MergeOptions& options) {
    // A merge does not stop midway: a signal removes its temporary output and ends it at once.
    install_interrupt_handlers();
    if (!options.frames_directory.empty()) return merge_frames_into_video(options);
    if (options.parts.empty()) {
        throw UsageError(
            "merge needs PARTS (.exr files of fgr render --part or --tile) or "
            "--frames DIR");
    }
    return merge_parts_into_image(options);
}

}  // namespace fgr
