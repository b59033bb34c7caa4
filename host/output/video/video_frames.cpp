// SPDX-License-Identifier: Apache-2.0
#include "output/video/video_frames.hpp"

#include <spdlog/spdlog.h>

#include <stdexcept>

#include "camera/view_validation.hpp"
#include "device/kernel_assembly.hpp"

namespace fgr {

VideoFrameRenderer::VideoFrameRenderer(const Scene& scene, const ComputeDevice& device,
                                       ProgramCache& cache, const StillSettings& settings)
    : scene_(scene),
      device_(device),
      settings_(settings),
      renderers_(device, cache, scene, still_switches(device, settings)) {
    check_supported_effects(scene, settings.effects);
}

Renderer& VideoFrameRenderer::build(bool double_precision) {
    return build_still_renderer(renderers_, scene_, device_, settings_, double_precision);
}

bool VideoFrameRenderer::choose_precision(std::int64_t frames,
                                          const std::function<CameraView(std::int64_t)>& view_of,
                                          int width, const std::vector<float>& params) {
    PrecisionChooser chooser(device_.info,
                             [](const std::string& warning) { spdlog::warn("{}", warning); });
    in_double_ = false;
    for (std::int64_t i = 0; i < frames; ++i) {
        const CameraView view = view_of(i);
        const auto distance = [&] { return surface_distance(build(false), view, params); };
        if (chooser.in_double(settings_.precision, view, width, distance)) {
            in_double_ = true;
            break;
        }
    }
    if (in_double_ && settings_.precision == Precision::Auto) {
        spdlog::info(
            "a pixel of some frame is finer than float resolves: the whole video renders "
            "in double");
    }
    build(in_double_);
    return in_double_;
}

Frame VideoFrameRenderer::render(const FrameRequest& request) {
    if (const std::string problem = computed_view_problem(request.view); !problem.empty()) {
        throw std::invalid_argument("cannot render this view: " + problem);
    }
    Frame frame = build(in_double_).render(request);
    if (!frame.cancelled) check_finite_frame(scene_, frame);
    return frame;
}

}  // namespace fgr
