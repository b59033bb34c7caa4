// SPDX-License-Identifier: Apache-2.0
#pragma once
// How the user asks the viewer to render, beyond the scene and its session: set on the command
// line, then changed in the panel. Private to fgr_viewer.

#include <map>
#include <memory>
#include <optional>
#include <string>

#include "camera/projection.hpp"
#include "render/environment.hpp"
#include "render/path_settings.hpp"
#include "render/precision.hpp"
#include "scene/render_mode.hpp"
#include "scene/scene.hpp"
#include "viewer/adaptive_quality.hpp"
#include "viewer/viewer.hpp"

namespace fgr::viewer {

struct RenderChoices {
    explicit RenderChoices(const ViewerOptions& options);

    // The mode `scene` renders in: the chosen one, else the scene's own.
    RenderMode mode_for(const Scene& scene) const { return mode.value_or(scene.default_mode); }

    QualitySettings quality;
    Precision precision = Precision::Auto;
    std::optional<RenderMode> mode;  // unset: each scene's own
    Projection projection;
    PathSettings path;     // path mode's settings; the environment is prepared per scene
    bool denoise = false;  // path mode: show the accumulating image denoised
    EnvironmentChoice environment;
};

// The environment prepared for each scene (the sky's sun follows the scene's key light), kept
// until the choice changes.
class SceneEnvironments {
public:
    // What `choice` lights `scene` with (the scene's own environment when the user named none:
    // with_scene_environment). A file that stopped being readable gives the sky instead: `choice`
    // becomes the sky, and `fallback_reason` says why.
    std::shared_ptr<const PreparedEnvironment> prepare(const Scene& scene,
                                                       EnvironmentChoice& choice,
                                                       std::string* fallback_reason);
    // The choice changed: each scene's environment is made again.
    void clear() { prepared_.clear(); }

private:
    std::map<const Scene*, std::shared_ptr<const PreparedEnvironment>> prepared_;
};

}  // namespace fgr::viewer
