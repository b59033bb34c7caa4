// SPDX-License-Identifier: Apache-2.0
#pragma once
// Whether a camera view can be rendered: the one check behind a plugin's cameras and keyframes
// (description_validation.cpp), camera path files (camera_path_file.cpp) and every view a
// Renderer is asked to draw, so a view whose camera basis would be NaN or infinite is refused
// with a reason instead of becoming an image of NaN rays.

#include <string>

#include "camera/view.hpp"

namespace fgr {

// Why the view a user or a plugin gave cannot be rendered, or "" when it can. One phrase, without
// saying which camera or keyframe it is (callers put that in front):
//   - a number is not finite, or the fov is outside (0, 180) degrees;
//   - position equals target, or they are so close together or so far apart that the view
//     direction cannot be normalised in float (its squared length under- or overflows): 1e-30
//     apart, or coordinates of ±1e30;
//   - up is zero, or too close to parallel to the view direction to define the roll
//     (up_defines_roll): the camera would not look the way it was written down.
std::string view_problem(const CameraView& view);

// Why a view fgr computed (a moment of a camera path, the viewer's fly camera) cannot be rendered,
// or "": as view_problem, except that its up is only a hint. camera_basis replaces an up that is
// parallel to the view by a world axis (a path may pass through that roll), so only a basis that
// would not be finite and orthonormal is refused.
std::string computed_view_problem(const CameraView& view);

}  // namespace fgr
