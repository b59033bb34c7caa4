// SPDX-License-Identifier: Apache-2.0
#include "viewer/view_still.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstddef>
#include <vector>

#include "render/sample_budget.hpp"
#include "scene/effects.hpp"
#include "scene/parameters.hpp"
#include "util/version.hpp"

namespace fgr::viewer {
namespace {

// The settings `fgr render` reads of a projection are those of its kind (chosen_projection
// refuses the others), so a view keeps only those.
Projection projection_as_read(const Projection& projection) {
    Projection read;
    read.kind = projection.kind;
    if (projection.kind == ProjectionKind::Fisheye) {
        read.fisheye_fov_degrees = projection.fisheye_fov_degrees;
    }
    if (is_stereo(projection.kind)) {
        read.eye_separation = projection.eye_separation;
        read.convergence = projection.convergence;
    }
    return read;
}

}  // namespace

ViewFile view_of_state(const ViewState& state, const EnvironmentChoice& environment, int samples) {
    const Scene& scene = *state.scene;
    ViewFile view;
    view.scene_id = scene.id;
    view.scene_fingerprint = scene_fingerprint(scene);
    view.fgr_version = fgr_version();
    view.width = state.width;
    view.height = state.height;
    view.camera = state.view;
    view.projection = projection_as_read(state.projection);
    view.parameters = changed_parameters(scene, state.params);
    view.mode = state.mode;
    view.samples = samples;
    for (const EffectSwitch& effect : effect_switches()) {
        if (state.effects & effect.bit) view.effects.emplace_back(effect.name);
    }
    view.precision = state.precision;
    // The viewer's frames always start from the prepass, as FrameRequest does by default.
    view.prepass = PrepassSettings{}.enabled;
    // What lit the frames: the scene's own environment when the user chose none.
    if (state.mode == RenderMode::Path) {
        view.path = path_choices_of(state.path, with_scene_environment(environment, scene));
        view.path->denoise = state.denoise;
    }
    return view;
}

ViewStill still_of_view(const Scene& scene, const ViewFile& view, int packet_width) {
    ViewStill still;
    FrameRequest& request = still.request;
    request.width = view.width;
    request.height = view.height;
    request.view = view.camera;
    request.params = default_param_values(scene);
    for (const ViewParameter& parameter : view.parameters) {
        set_param_from_text(scene, request.params, parameter_assignment(parameter));
    }
    request.projection = view.projection;
    check_projection(request.projection);
    request.prepass.enabled = view.prepass;
    request.samples = still_samples(view.mode, view.samples);
    check_mode_supported(scene, view.mode);
    if (view.mode == RenderMode::Path) {
        const ViewPathChoices choices = view.path.value_or(ViewPathChoices{});
        request.path = path_settings_of(choices);
        request.path.environment = prepare_environment(environment_choice_of(choices), scene);
    }

    StillSettings& settings = still.settings;
    settings.packet_width = packet_width;
    // The view's effects are the whole set: none, then each of them.
    std::string effects = "none";
    for (const std::string& name : view.effects) effects += ",+" + name;
    settings.effects = apply_effect_changes(scene.effects, effects);
    settings.precision = view.precision;
    settings.mode = view.mode;
    const Aovs aovs = parse_aovs(view.layers);
    settings.aovs = view.alpha || aovs.need_aov_planes();

    still.output = StillOutput{view.bit_depth, display_transform(scene, request.params), view.alpha,
                               aovs, view_file_text(view)};
    return still;
}

Image8 shrunk_image(const Image8& image, int width) {
    if (image.width <= width || image.width <= 0 || image.height <= 0) return image;
    Image8 small;
    small.width = width;
    small.height = std::max(1, static_cast<int>(int64_t{image.height} * width / image.width));
    small.rgb.resize(static_cast<size_t>(small.width) * small.height * 3);
    // Source rows [y0, y1) and columns [x0, x1) make each pixel, at least one of each.
    const auto span = [](int i, int from, int to) {
        const int first = static_cast<int>(int64_t{i} * from / to);
        const int last = std::max(first + 1, static_cast<int>(int64_t{i + 1} * from / to));
        return std::pair(first, std::min(last, from));
    };
    for (int y = 0; y < small.height; ++y) {
        const auto [y0, y1] = span(y, image.height, small.height);
        for (int x = 0; x < small.width; ++x) {
            const auto [x0, x1] = span(x, image.width, small.width);
            for (int c = 0; c < 3; ++c) {
                unsigned sum = 0;
                for (int sy = y0; sy < y1; ++sy) {
                    for (int sx = x0; sx < x1; ++sx) {
                        sum += image.rgb[(static_cast<size_t>(sy) * image.width + sx) * 3 + c];
                    }
                }
                const unsigned count = static_cast<unsigned>((y1 - y0) * (x1 - x0));
                small.rgb[(static_cast<size_t>(y) * small.width + x) * 3 + c] =
                    static_cast<uint8_t>((sum + count / 2) / count);
            }
        }
    }
    return small;
}

std::filesystem::path unused_file(const std::filesystem::path& directory, const std::string& stem,
                                  const std::string& suffix,
                                  const std::set<std::filesystem::path>& taken) {
    std::filesystem::path file = directory / (stem + suffix);
    for (int n = 2; std::filesystem::exists(file) || taken.count(file); ++n) {
        file = directory / fmt::format("{}-{}{}", stem, n, suffix);
    }
    return file;
}

std::filesystem::path view_thumbnail_file(const std::filesystem::path& view_file) {
    std::string name = view_file.filename().string();
    const std::string suffix = kViewFileSuffix;
    if (name.size() >= suffix.size() && name.ends_with(suffix)) {
        name.resize(name.size() - suffix.size());
    }
    return view_file.parent_path() / (name + kViewThumbnailSuffix);
}

}  // namespace fgr::viewer
