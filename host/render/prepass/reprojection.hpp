// SPDX-License-Identifier: Apache-2.0
#pragma once
// Temporal reprojection of a frame's depths into the next view: where the previous frame saw the
// surface, seen from the new camera, gives each new pixel a hint of how far its camera ray can
// start (FrameRequest::start_hints). The viewer uses it for previews while the camera moves; the
// kernel takes a hint only where the DE there says the point is clear of the surface by more
// than the hit footprint (kernels/geometry/fgr_prepass.cl, march_start_with_hint).

#include <vector>

#include "camera/camera.hpp"
#include "camera/projection.hpp"

namespace fgr {

// A rendered frame's depths and the view they were seen from.
struct DepthView {
    CameraView view;
    Projection projection;
    int width = 0;
    int height = 0;
    std::vector<float> depth;  // row-major distance along each pixel's centre ray; < 0: missed
};

// Start hints for a width x height frame of `view` (row-major; 0: no hint), pinhole views only
// (others get no hints). Each previous hit is moved into the new view and splatted, nearest
// first, over the new pixels its own pixel covers there. A new pixel gets a hint only where
// every pixel of its 3x3 neighbourhood received a point (no hole: a surface the old view did
// not see may show through a hole) and their depths agree within `max_spread` (a depth edge
// may hide a surface the old view's rays passed beside); the hint is the neighbourhood's
// nearest depth, less `margin` of it.
std::vector<float> reproject_start_hints(const DepthView& previous, const CameraView& view,
                                         const Projection& projection, int width, int height,
                                         float margin = 0.02f, float max_spread = 0.1f);

}  // namespace fgr
