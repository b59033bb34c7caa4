// SPDX-License-Identifier: Apache-2.0
#pragma once
// The camera as the kernels receive it: shared by the renderer and the cone prepass, which both
// launch kernels that take it.

#include "camera/camera.hpp"
#include "camera/projection.hpp"
#include "device/kernel_layout.hpp"
#include "render/renderer.hpp"

namespace fgr {

// `camera_frame` of kernels/shared/fgr_layout_camera.h, the one the kernels declare.
using CameraFrame = layout::camera_frame;

// The eye goes as a hi/lo split of its double value: hi the nearest float, lo the rest rounded to
// float (in the w components); double lanes add them, float lanes use hi alone.
CameraFrame camera_frame(const CameraView& view, const Projection& projection, int width,
                         int height, PixelRegion region);

}  // namespace fgr
