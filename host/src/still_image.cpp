#include "fgr/still_image.hpp"

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "fgr/image_io.hpp"
#include "fgr/kernel_assembly.hpp"
#include "fgr/view_validation.hpp"

namespace fgr {

Frame render_still(const Scene& scene, const FrameRequest& request, const ComputeDevice& device,
                   ProgramCache& cache, const StillSettings& settings) {
    // Before any kernel is built for it (Renderer::render would refuse it too).
    if (const std::string problem = computed_view_problem(request.view); !problem.empty()) {
        throw std::invalid_argument("cannot render this view: " + problem);
    }
    const KernelSwitches in_float{
        settings.packet_width ? settings.packet_width : preferred_packet_width(device.info),
        settings.effects, settings.stats};
    PrecisionRenderers renderers(device, cache, scene, in_float);
    const auto build = [&](bool double_precision) -> Renderer& {
        if (Renderer* built = renderers.built(double_precision)) return *built;
        const KernelSwitches switches = with_precision(in_float, double_precision);
        spdlog::info("building '{}' for {} ({} rays per work-item, {}, effects: {})", scene.id,
                     device.info.name, switches.packet_width,
                     double_precision ? "double" : "float", effect_names(switches.effects));
        Renderer& built = renderers.get(double_precision);
        spdlog::info("kernel ready in {:.0f} ms", built.build_report().build_ms);
        return built;
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
    Frame frame = build(in_double).render(request);
    // A pixel the kernel could not compute must not reach a file as if it were an image.
    if (const long broken = non_finite_pixels(frame); broken > 0) {
        throw std::runtime_error(fmt::format(
            "rendering '{}' gave non-finite colour or depth at {} of {} pixels", scene.id, broken,
            frame.depth.size()));
    }
    return frame;
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

void write_still(const std::filesystem::path& path, const Frame& frame, int bit_depth,
                 float exposure) {
    if (bit_depth == 16) {
        write_png16_linear(path, linear_image16(frame, exposure));
    } else {
        write_png(path, frame.image);
    }
}

}  // namespace fgr
