// SPDX-License-Identifier: Apache-2.0
#include "viewer/render_choices.hpp"

#include <fmt/format.h>

#include <exception>

namespace fgr::viewer {

RenderChoices::RenderChoices(const ViewerOptions& options)
    : precision(options.precision),
      mode(options.mode),
      projection(options.projection),
      path(options.path),
      denoise(options.denoise),
      environment(options.environment) {
    quality.target_ms = options.target_ms;
    quality.sample_cap = options.sample_cap;
}

std::shared_ptr<const PreparedEnvironment> SceneEnvironments::prepare(
    const Scene& scene, EnvironmentChoice& choice, std::string* fallback_reason) {
    const auto found = prepared_.find(&scene);
    if (found != prepared_.end()) return found->second;
    std::shared_ptr<const PreparedEnvironment> prepared;
    try {
        prepared = prepare_environment(with_scene_environment(choice, scene), scene);
    } catch (const std::exception& error) {
        *fallback_reason = fmt::format("environment: {}; using the sky", error.what());
        choice = EnvironmentChoice{};
        choice.given = true;
        prepared = prepare_environment(choice, scene);
    }
    return prepared_[&scene] = prepared;
}

}  // namespace fgr::viewer
