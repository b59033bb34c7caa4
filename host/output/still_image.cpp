// SPDX-License-Identifier: Apache-2.0
#include "output/still_image.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "camera/view_validation.hpp"
#include "device/kernel_assembly.hpp"
#include "image/hdr_io.hpp"
#include "image/image_io.hpp"
#include "util/lower_case.hpp"

namespace fgr {

KernelSwitches still_switches(const ComputeDevice& device, const StillSettings& settings) {
    return {settings.packet_width ? settings.packet_width : preferred_packet_width(device.info),
            settings.effects,
            settings.stats,
            false,
            settings.mode,
            settings.aovs};
}

Renderer& build_still_renderer(PrecisionRenderers& renderers, const Scene& scene,
                               const ComputeDevice& device, const StillSettings& settings,
                               bool double_precision) {
    if (Renderer* built = renderers.built(double_precision)) return *built;
    const KernelSwitches switches =
        with_precision(still_switches(device, settings), double_precision);
    spdlog::info("building '{}' for {} ({} mode, {} rays per work-item, {}, effects: {})", scene.id,
                 device.info.name, render_mode_name(switches.mode), switches.packet_width,
                 double_precision ? "double" : "float", effect_names(switches.effects));
    Renderer& built = renderers.get(double_precision);
    spdlog::info("kernel ready in {:.0f} ms", built.build_report().build_ms);
    return built;
}

Renderer& choose_still_renderer(PrecisionRenderers& renderers, const Scene& scene,
                                const FrameRequest& request, const ComputeDevice& device,
                                const StillSettings& settings) {
    // Before any kernel is built for it (Renderer::render would refuse it too).
    if (const std::string problem = computed_view_problem(request.view); !problem.empty()) {
        throw std::invalid_argument("cannot render this view: " + problem);
    }
    check_supported_effects(scene, settings.effects);
    const auto build = [&](bool double_precision) -> Renderer& {
        return build_still_renderer(renderers, scene, device, settings, double_precision);
    };
    PrecisionChooser chooser(device.info,
                             [](const std::string& warning) { spdlog::warn("{}", warning); });
    // The auto rule's DE at the camera comes from the float kernel, as in fgr view and fgr bench.
    const auto distance = [&] {
        return surface_distance(build(false), request.view, request.params);
    };
    const bool in_double =
        chooser.in_double(settings.precision, request.view, request.width, distance);
    if (in_double && settings.precision == Precision::Auto) {
        spdlog::info("a pixel of this view is finer than float resolves: rendering in double");
    }
    return build(in_double);
}

Frame render_still(const Scene& scene, const FrameRequest& request, const ComputeDevice& device,
                   ProgramCache& cache, const StillSettings& settings) {
    // One frame at known values: the kernel compiled with the scene's specialisable parameters
    // as constants (it is cached, so the next render with the same values builds nothing).
    KernelSwitches switches = still_switches(device, settings);
    switches.specialised = specialisation_for(scene, request.params);
    PrecisionRenderers renderers(device, cache, scene, switches);
    Frame frame =
        choose_still_renderer(renderers, scene, request, device, settings).render(request);
    check_finite_frame(scene, frame);
    return frame;
}

void check_finite_frame(const Scene& scene, const Frame& frame) {
    // A pixel the kernel could not compute must not reach a file as if it were an image.
    if (const long broken = non_finite_pixels(frame); broken > 0) {
        throw std::runtime_error(
            fmt::format("rendering '{}' gave non-finite colour or depth at {} of {} pixels",
                        scene.id, broken, frame.depth.size()));
    }
}

long non_finite_pixels(const Frame& frame) {
    long broken = 0;
    for (size_t pixel = 0; pixel < frame.depth.size(); ++pixel) {
        const float* colour = &frame.linear[pixel * 3];
        broken += !std::isfinite(frame.depth[pixel]) || !std::isfinite(colour[0]) ||
                  !std::isfinite(colour[1]) || !std::isfinite(colour[2]);
    }
    return broken;
}

Aovs parse_aovs(std::string_view list) {
    Aovs aovs;
    size_t start = 0;
    while (start <= list.size()) {
        const size_t comma = std::min(list.find(',', start), list.size());
        const std::string_view name = list.substr(start, comma - start);
        start = comma + 1;
        if (name.empty()) continue;
        if (name == "albedo") {
            aovs.albedo = true;
        } else if (name == "normal") {
            aovs.normal = true;
        } else if (name == "depth") {
            aovs.depth = true;
        } else if (name == "alpha") {
            aovs.alpha = true;
        } else if (name == "samples") {
            aovs.samples = true;
        } else if (name == "variance") {
            aovs.variance = true;
        } else {
            throw std::invalid_argument(fmt::format(
                "unknown --aov layer '{}' (choose from albedo,normal,depth,alpha,samples,variance)",
                name));
        }
    }
    return aovs;
}

namespace {

// The frame's linear colour, or with alpha the straight foreground, as a PNG's pixels.
void write_png_still(const std::filesystem::path& path, const Frame& frame,
                     const StillOutput& output) {
    const int width = frame.image.width, height = frame.image.height;
    const size_t pixels = static_cast<size_t>(width) * static_cast<size_t>(height);
    if (!output.alpha) {
        if (output.bit_depth == 16) {
            write_png16_linear(path, linear_image16(frame, output.display.exposure),
                               output.embedded_view);
        } else {
            write_png(path, frame.image, output.embedded_view);
        }
        return;
    }
    const auto split = [pixels](const auto& rgba, auto& image) {
        image.rgb.resize(pixels * 3);
        image.alpha.resize(pixels);
        for (size_t i = 0; i < pixels; ++i) {
            for (size_t c = 0; c < 3; ++c) image.rgb[i * 3 + c] = rgba[i * 4 + c];
            image.alpha[i] = rgba[i * 4 + 3];
        }
    };
    if (output.bit_depth == 16) {
        std::vector<uint16_t> rgba(pixels * 4);
        rgba16_linear_rows(frame, output.display.exposure, whole_frame(frame), rgba);
        Image16 image{width, height, {}, {}};
        split(rgba, image);
        write_png16_linear(path, image, output.embedded_view);
    } else {
        std::vector<uint8_t> rgba(pixels * 4);
        rgba8_rows(frame, output.display, whole_frame(frame), rgba);
        Image8 image{width, height, {}, {}};
        split(rgba, image);
        write_png(path, image, output.embedded_view);
    }
}

}  // namespace

void write_still(const std::filesystem::path& path, const Frame& frame, const StillOutput& output) {
    if (lower_extension(path) == ".exr") {
        Aovs aovs = output.aovs;
        aovs.alpha = aovs.alpha || output.alpha;
        write_exr(path, frame.image.width, frame.image.height,
                  exr_layers(frame, aovs, whole_frame(frame)), output.embedded_view);
    } else {
        write_png_still(path, frame, output);
    }
}

}  // namespace fgr
