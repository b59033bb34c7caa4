// SPDX-License-Identifier: Apache-2.0
#pragma once
// Small renders the tests ask of a scene: its default view at a test's size, and whether a point
// is in its solid.

#include "render/renderer.hpp"
#include "scene/parameters.hpp"

namespace fgr::test {

// The scene's default view at 96x72 with its default parameters.
inline FrameRequest default_view_request(const Scene& scene) {
    FrameRequest request;
    request.width = 96;
    request.height = 72;
    request.view = scene.cameras.front().view;
    request.params = default_param_values(scene);
    return request;
}

// Whether the camera's eye is inside the solid of the set: with the set solid and sampling from
// the eye, a 1x1 brute-force render then hits at depth 0 exactly (the cut at near).
inline bool eye_inside(Renderer& brute, const Scene& scene, const CameraView& view) {
    FrameRequest probe = {1, 1, view, default_param_values(scene)};
    set_param_from_text(scene, probe.params, "brute_solid=set");
    set_param_from_text(scene, probe.params, "brute_samples=1");
    return brute.render(probe).depth[0] == 0.0f;
}

}  // namespace fgr::test
