// SPDX-License-Identifier: Apache-2.0
#pragma once
// Rendering the frames of a video as `fgr render` renders stills (the same kernel switches, the
// same non-finite check), but with the kernel built once for the whole video instead of per
// frame, and float or double decided once for the whole video.

#include <cstdint>
#include <functional>
#include <vector>

#include "camera/camera.hpp"
#include "output/still_image.hpp"
#include "render/precision.hpp"

namespace fgr {

class VideoFrameRenderer {
public:
    // Keeps references to all four; builds nothing yet.
    VideoFrameRenderer(const Scene& scene, const ComputeDevice& device, ProgramCache& cache,
                       const StillSettings& settings);

    // Float or double for every frame: as settings.precision says, and for Auto, double when the
    // auto rule (PrecisionChooser, as render_still applies it to one view) wants double for the
    // view of any of the `frames` (`view` gives frame i's, one at a time) at `width` pixels (the DE
    // at each camera with `params`): a video never switches precision mid-way (no visible jump in
    // detail) and no frame is rendered coarser than its still would be. Builds the chosen kernel
    // (and, for Auto, the float kernel the rule reads the DE from). Returns true for double.
    bool choose_precision(std::int64_t frames, const std::function<CameraView(std::int64_t)>& view,
                          int width, const std::vector<float>& params);

    // One frame in the chosen precision; throws std::runtime_error when a pixel came out
    // non-finite (check_finite_frame) and std::invalid_argument for a view that cannot be rendered.
    Frame render(const FrameRequest& request);

private:
    Renderer& build(bool double_precision);

    const Scene& scene_;
    const ComputeDevice& device_;
    StillSettings settings_;
    PrecisionRenderers renderers_;
    bool in_double_ = false;
};

}  // namespace fgr
