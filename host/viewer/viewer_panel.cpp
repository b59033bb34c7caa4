// SPDX-License-Identifier: Apache-2.0
#include "viewer/viewer_panel.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "camera/projection.hpp"
#include "device/kernel_assembly.hpp"
#include "fgr/plugin.h"
#include "render/precision.hpp"
#include "render/sample_budget.hpp"
#include "scene/parameters.hpp"
#include "scene/render_mode.hpp"
#include "scene/scene.hpp"
#include "viewer/viewer_util.hpp"

namespace fgr::viewer {
namespace {

constexpr float kPanelWidth = 340.0f;
constexpr size_t kSceneListRows = 8;  // the scene list's height; it scrolls beyond

const std::pair<const char*, std::pair<int, int>> kWindowPresets[] = {{"1366x768", {1366, 768}},
                                                                      {"1920x1080", {1920, 1080}},
                                                                      {"2560x1440", {2560, 1440}},
                                                                      {"3840x2160", {3840, 2160}}};

const std::pair<const char*, const char*> kKeyBindings[] = {
    {"W A S D", "move forward, left, back, right"},
    {"Q / E", "move down / up"},
    {"Shift", "move 4x faster"},
    {"right mouse + drag", "look around"},
    {"mouse wheel", "movement speed (it also scales with the distance to the surface)"},
    {"R", "reset to the scene's default camera"},
    {"C", "next named camera of the scene"},
    {"PageUp / PageDown", "previous / next scene"},
    {"P", "play / stop the selected camera path"},
    {"K", "record the current view as a keyframe"},
    {"Ctrl+K", "save the recorded path as JSON"},
    {"Ctrl+S", "save the view (.fgrview.json, with a thumbnail): `fgr render FILE` renders it"},
    {"F12", "screenshot at full resolution and quality"},
    {"Tab", "show / hide the panel"},
    {"F11", "fullscreen"},
    {"B", "formula browser: thumbnails of the scenes, search"},
    {"N", "path mode: denoise the accumulating image on or off"},
    {"H or F1", "this help"},
    {"Escape", "quit"}};

}  // namespace

ViewerPanel::ViewerPanel(SceneSet& scenes, RenderChoices& choices, CameraPaths& paths,
                         ViewerWindow& window, PanelHost host)
    : scenes_(scenes), choices_(choices), paths_(paths), window_(window), host_(std::move(host)) {}

void ViewerPanel::draw_dialogs(const WorkerStatus& status) {
    draw_build_errors(status);
    if (show_help_) draw_help();
}

bool ViewerPanel::covers(int x, int y) const {
    const auto fx = static_cast<float>(x), fy = static_cast<float>(y);
    return visible_ && fx >= min_.x && fx < max_.x && fy >= min_.y && fy < max_.y;
}

void ViewerPanel::show_refused_update(std::string summary, std::string log) {
    refused_update_ = {std::move(summary), std::move(log)};
}

void ViewerPanel::draw_overlay(const ViewReport& report) {
    ImGui::SetNextWindowPos(ImVec2(8, 8));
    ImGui::SetNextWindowBgAlpha(0.55f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoInputs |
                                   ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoSavedSettings |
                                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
    ImGui::Begin("##status", nullptr, flags);
    ImGui::Text("%s  %dx%d", scenes_.current().id.c_str(), report.view.width, report.view.height);
    if (report.shown) {
        const bool path = report.view.mode == RenderMode::Path;
        const int standing_view = sample_budget(report.view.mode).standing_view;
        ImGui::Text("resolution %.0f%%  samples %d/%d  frame %.0f ms  %s",
                    report.shown->scale * 100.0f, report.shown->samples,
                    standing_view > 0 ? standing_view : choices_.quality.sample_cap,
                    report.shown->render_ms,
                    precision_label(choices_.precision, report.shown->double_precision));
        if (path) {
            ImGui::Text("path tracing: %d samples/pixel, %.2f M samples/s", report.shown->samples,
                        report.shown->samples_per_second / 1e6);
        }
        if (scenes_.current().ifs && report.shown->ifs_depth_reached >= 0) {
            // The slider caps the depth; the pixel footprint stops it sooner where detail
            // would be smaller than a pixel.
            ImGui::Text(
                "IFS depth reached %d (slider %d)", report.shown->ifs_depth_reached,
                static_cast<int>(param_value(scenes_.current(), report.view.params, "ifs_depth")));
        }
    }
    if (report.status.compiling) {
        ImGui::TextColored(ImVec4(1, 0.8f, 0.2f, 1), "compiling %s%s...",
                           report.status.compiling_scene.c_str(),
                           report.status.compiling_double ? " in double" : "");
    }
    if (report.status.pending_screenshots > 0) {
        ImGui::TextColored(ImVec4(0.6f, 0.9f, 1, 1), "screenshot in progress (%d)",
                           report.status.pending_screenshots);
    }
    if (paths_.playing()) ImGui::Text("playing path  t = %.1f s", paths_.playback_time());
    ImGui::TextDisabled("H: help");
    ImGui::End();
}

void ViewerPanel::draw_panel(const ViewReport& report) {
    if (!visible_) {
        min_ = max_ = ImVec2(0, 0);
        return;
    }
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float width = std::min(kPanelWidth, display.x * 0.4f);
    ImGui::SetNextWindowPos(ImVec2(display.x - width - 8, 8), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(width, display.y - 16), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.8f);
    ImGui::Begin("fgr", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize);
    min_ = ImGui::GetWindowPos();
    max_ = ImVec2(min_.x + ImGui::GetWindowSize().x, min_.y + ImGui::GetWindowSize().y);
    ImGui::Text("frame %.0f ms  ui %.0f fps", report.shown ? report.shown->render_ms : 0.0,
                ImGui::GetIO().Framerate);
    ImGui::PushItemWidth(-150);
    draw_scene_section();
    host_.draw_formula_sequence();
    draw_camera_section(report.status);
    draw_projection_section();
    draw_params_section();
    draw_effects_section(report.status);
    draw_mode_section();
    draw_quality_section(report);
    ImGui::PopItemWidth();
    draw_messages(report.messages);
    ImGui::End();
}

void ViewerPanel::draw_scene_section() {
    if (!ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen)) return;
    if (ImGui::Button(host_.browser_shown() ? "Hide the formula browser (B)"
                                            : "Formula browser (B)")) {
        host_.toggle_browser();
    }
    // A list of its own that scrolls: with the formula scenes there are fifty, and the sections
    // below must stay in reach.
    const float list_height = ImGui::GetTextLineHeightWithSpacing() *
                              static_cast<float>(std::min<size_t>(scenes_.size(), kSceneListRows));
    ImGui::BeginChild("scenes", ImVec2(0, list_height + 4), false);
    for (size_t i = 0; i < scenes_.size(); ++i) {
        const bool selected = static_cast<int>(i) == scenes_.current_index();
        const Scene& listed = *scenes_.at(i);
        if (ImGui::Selectable(fmt::format("{}  ({})", listed.name, listed.id).c_str(), selected) &&
            !selected) {
            host_.switch_scene(static_cast<int>(i));
        }
        if (selected && scene_list_follows_) ImGui::SetScrollHereY();
    }
    scene_list_follows_ = false;
    ImGui::EndChild();
    ImGui::TextWrapped("%s", scenes_.current().description.c_str());
}

void ViewerPanel::draw_camera_section(const WorkerStatus& status) {
    if (!ImGui::CollapsingHeader("Camera and paths", ImGuiTreeNodeFlags_DefaultOpen)) return;
    SceneSession& current = scenes_.session();
    const auto& cameras = scenes_.current().cameras;
    if (ImGui::BeginCombo("camera", cameras[size_t(current.camera_index)].name.c_str())) {
        for (size_t i = 0; i < cameras.size(); ++i) {
            if (ImGui::Selectable(cameras[i].name.c_str(), int(i) == current.camera_index)) {
                host_.reset_camera(static_cast<int>(i));
            }
        }
        ImGui::EndCombo();
    }
    ImGui::SliderFloat("fov", &current.camera.fov_degrees, 5.0f, 150.0f, "%.0f deg");
    float speed = host_.fly_speed();
    if (ImGui::SliderFloat("speed", &speed, 1e-3f, 1e3f, "%.3g x DE/s",
                           ImGuiSliderFlags_Logarithmic)) {
        host_.set_fly_speed(speed);
    }
    if (status.de_at_camera >= 0.0f) {
        ImGui::Text("distance to surface %.3g", double(status.de_at_camera));
    } else {
        ImGui::TextDisabled("distance to surface unknown");
    }

    const std::vector<CameraPath> paths = paths_.playable();
    if (!paths.empty()) {
        current.path_index = std::clamp(current.path_index, 0, int(paths.size()) - 1);
        if (ImGui::BeginCombo("path", paths[size_t(current.path_index)].name.c_str())) {
            for (size_t i = 0; i < paths.size(); ++i) {
                if (ImGui::Selectable(paths[i].name.c_str(), int(i) == current.path_index)) {
                    current.path_index = static_cast<int>(i);
                    paths_.stop();
                }
            }
            ImGui::EndCombo();
        }
        if (ImGui::Button(paths_.playing() ? "Stop (P)" : "Play (P)")) paths_.toggle_playback();
        ImGui::SameLine();
        bool loop = paths_.loop();
        if (ImGui::Checkbox("loop", &loop)) paths_.set_loop(loop);
    }
    ImGui::Text("recorded: %zu keyframes", current.recorded.keyframes.size());
    if (ImGui::Button("Add keyframe (K)")) paths_.record_keyframe();
    ImGui::SameLine();
    if (ImGui::Button("Save (Ctrl+K)")) paths_.save_recorded();
    ImGui::SameLine();
    if (ImGui::Button("Clear")) current.recorded.keyframes.clear();
    float spacing = paths_.keyframe_interval();
    if (ImGui::SliderFloat("keyframe spacing", &spacing, 0.25f, 10.0f, "%.2f s")) {
        paths_.set_keyframe_interval(spacing);
    }
    if (ImGui::Button("Screenshot (F12)")) host_.take_screenshot();
    ImGui::SameLine();
    if (ImGui::Button("Save view (Ctrl+S)")) host_.save_view();
}

namespace {

// A distance that is either automatic (unset: `automatic` follows the view) or the user's own,
// dragged on a logarithmic scale from its last value; at least `minimum`.
void draw_optional_distance(const char* label, std::optional<double>* value, double automatic,
                            double minimum) {
    bool automatic_on = !value->has_value();
    if (ImGui::Checkbox(fmt::format("auto {}", label).c_str(), &automatic_on)) {
        *value = automatic_on ? std::nullopt : std::optional<double>(automatic);
    }
    if (automatic_on) {
        ImGui::TextDisabled("%s %.3g (follows the target distance)", label, automatic);
        return;
    }
    auto shown = static_cast<float>(**value);
    const auto low = static_cast<float>(std::max(minimum, 1e-4 * automatic));
    if (ImGui::SliderFloat(label, &shown, low,
                           static_cast<float>(std::max(automatic, 1e-30) * 10.0), "%.4g",
                           ImGuiSliderFlags_Logarithmic)) {
        *value = std::max(double(shown), minimum);
    }
}

}  // namespace

void ViewerPanel::draw_projection_section() {
    if (!ImGui::CollapsingHeader("Projection", ImGuiTreeNodeFlags_DefaultOpen)) return;
    constexpr std::array kKinds{ProjectionKind::Pinhole, ProjectionKind::Equirectangular,
                                ProjectionKind::Fisheye, ProjectionKind::StereoSideBySide,
                                ProjectionKind::StereoTopBottom};
    if (ImGui::BeginCombo("projection", projection_name(choices_.projection.kind))) {
        for (const ProjectionKind kind : kKinds) {
            if (ImGui::Selectable(projection_name(kind), kind == choices_.projection.kind)) {
                choices_.projection.kind = kind;
            }
        }
        ImGui::EndCombo();
    }
    if (choices_.projection.kind == ProjectionKind::Fisheye) {
        ImGui::SliderFloat("fisheye fov", &choices_.projection.fisheye_fov_degrees, 10.0f, 360.0f,
                           "%.0f deg");
    }
    if (!is_stereo(choices_.projection.kind)) return;
    // Unset values follow the view: 1/30 of the distance to the target, converging there.
    const double distance = scenes_.session().camera.target_distance;
    draw_optional_distance("eye separation", &choices_.projection.eye_separation,
                           distance * kDefaultSeparationFraction, 0.0);
    draw_optional_distance("convergence", &choices_.projection.convergence, distance,
                           1e-6 * distance);
}

namespace {

// One widget of the parameter's type and range; returns whether it changed.
bool edit_param(const ParamInfo& param, float* value) {
    const char* label = param.label.empty() ? param.id.c_str() : param.label.c_str();
    bool changed = false;
    const ImGuiSliderFlags clamp = ImGuiSliderFlags_AlwaysClamp;
    switch (param.type) {
        case ParamType::Float: {
            const bool wide = param.min_value > 0.0f && param.max_value >= 100.0f * param.min_value;
            changed = ImGui::SliderFloat(label, value, param.min_value, param.max_value, "%.4g",
                                         clamp | (wide ? ImGuiSliderFlags_Logarithmic : 0));
            break;
        }
        case ParamType::Int: {
            int current = static_cast<int>(std::lround(*value));
            const int low = static_cast<int>(param.min_value);
            if (!param.choices.empty()) {
                int index = std::clamp(current - low, 0, int(param.choices.size()) - 1);
                if (ImGui::BeginCombo(label, param.choices[size_t(index)].c_str())) {
                    for (size_t i = 0; i < param.choices.size(); ++i) {
                        // Only what the scene offers (ABI 1.4 colour_modes).
                        if (!choice_offered(param, i)) continue;
                        if (ImGui::Selectable(param.choices[i].c_str(), int(i) == index)) {
                            index = static_cast<int>(i);
                            changed = true;
                        }
                    }
                    ImGui::EndCombo();
                }
                current = low + index;
            } else {
                changed = ImGui::SliderInt(label, &current, low, static_cast<int>(param.max_value),
                                           "%d", clamp);
            }
            *value = static_cast<float>(current);
            break;
        }
        case ParamType::Bool: {
            bool on = *value != 0.0f;
            changed = ImGui::Checkbox(label, &on);
            *value = on ? 1.0f : 0.0f;
            break;
        }
        case ParamType::Vec3:
            changed =
                ImGui::SliderFloat3(label, value, param.min_value, param.max_value, "%.3g", clamp);
            break;
        case ParamType::Colour:
            changed = ImGui::ColorEdit3(label, value, ImGuiColorEditFlags_Float);
            break;
    }
    if (ImGui::IsItemHovered() && !param.description.empty()) {
        ImGui::SetTooltip("%s: %s%s", param.id.c_str(), param.description.c_str(),
                          param.scene_default ? " (the scene gives its own default)" : "");
    }
    return changed;
}

}  // namespace

void ViewerPanel::draw_params_section() {
    const Scene& current = scenes_.current();
    const std::vector<int> offsets = param_offsets(current);
    std::vector<std::string> groups;  // in order of first appearance
    for (const ParamInfo& param : current.params) {
        if (!param_applies(current, param)) continue;
        if (std::find(groups.begin(), groups.end(), param.group) == groups.end()) {
            groups.push_back(param.group);
        }
    }
    for (const std::string& group : groups) {
        const bool open_by_default = group != "Effects";
        // The built-in "Effects" group holds the effects' settings; the switches that compile
        // them in have the "Effects" header of their own (draw_effects_section).
        const std::string header = group.empty()        ? "Parameters"
                                   : group == "Effects" ? "Effect settings"
                                                        : group;
        if (!ImGui::CollapsingHeader(header.c_str(),
                                     open_by_default ? ImGuiTreeNodeFlags_DefaultOpen : 0)) {
            continue;
        }
        for (size_t i = 0; i < current.params.size(); ++i) {
            const ParamInfo& param = current.params[i];
            if (param.group != group || !param_applies(current, param)) continue;
            ImGui::PushID(param.id.c_str());
            edit_param(param, &scenes_.session().params[static_cast<size_t>(offsets[i])]);
            ImGui::PopID();
        }
        if (group == "Quality" && ImGui::Button("Reset parameters")) {
            scenes_.session().params = default_param_values(current);
        }
    }
}

void ViewerPanel::draw_effects_section(const WorkerStatus& status) {
    if (!ImGui::CollapsingHeader("Effects", ImGuiTreeNodeFlags_DefaultOpen)) return;
    uint64_t& effects = scenes_.session().effects;
    // An IFS scene offers only the effects exact tracing supports (kIfsEffects).
    const uint64_t offered = FGR_EFFECT_ALL_V1 & supported_effects(scenes_.current());
    for (uint64_t bit = 1; bit != 0 && bit <= FGR_EFFECT_ALL_V1; bit <<= 1) {
        if ((offered & bit) == 0) continue;
        bool on = (effects & bit) != 0;
        if (ImGui::Checkbox(effect_names(bit).c_str(), &on)) effects ^= bit;
    }
    if (status.compiling) ImGui::TextColored(ImVec4(1, 0.8f, 0.2f, 1), "compiling...");
}

void ViewerPanel::draw_quality_section(const ViewReport& report) {
    if (!ImGui::CollapsingHeader("Adaptive quality", ImGuiTreeNodeFlags_DefaultOpen)) return;
    float target = static_cast<float>(choices_.quality.target_ms);
    bool changed = ImGui::SliderFloat("target frame", &target, 5.0f, 200.0f, "%.0f ms");
    changed |= ImGui::SliderInt("sample cap", &choices_.quality.sample_cap, 1, 256, "%d",
                                ImGuiSliderFlags_Logarithmic);
    if (changed) {
        choices_.quality.target_ms = target;
        host_.quality_changed();
    }
    draw_precision_combo(report);
    int preset = -1;
    const char* preview = "window size";
    if (ImGui::BeginCombo("window", preview)) {
        for (size_t i = 0; i < std::size(kWindowPresets); ++i) {
            if (ImGui::Selectable(kWindowPresets[i].first)) preset = static_cast<int>(i);
        }
        ImGui::EndCombo();
    }
    if (preset >= 0) {
        window_.set_size(kWindowPresets[preset].second.first, kWindowPresets[preset].second.second);
    }
    bool fullscreen = window_.fullscreen();
    if (ImGui::Checkbox("fullscreen (F11)", &fullscreen)) window_.toggle_fullscreen();
    ImGui::TextDisabled("device: %s", report.device.name.c_str());
}

void ViewerPanel::draw_mode_section() {
    if (!ImGui::CollapsingHeader("Render mode", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const RenderMode current = choices_.mode_for(scenes_.current());
    if (ImGui::BeginCombo("mode", std::string(render_mode_name(current)).c_str())) {
        for (const RenderModeInfo& info : render_modes()) {
            if (ImGui::Selectable(std::string(info.name).c_str(), info.mode == current)) {
                choices_.mode = info.mode;
            }
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", std::string(info.summary).c_str());
        }
        ImGui::EndCombo();
    }
    if (current != RenderMode::Path) return;
    ImGui::TextDisabled("accumulates while the camera stands still");
    if (draw_environment_controls()) host_.environment_changed();
    ImGui::SliderInt("bounces", &choices_.path.max_bounces, 0, 32);
    if (ImGui::SliderFloat("noise threshold", &choices_.path.noise_threshold, 0.0f, 0.1f, "%.3f")) {
        choices_.path.noise_threshold = std::clamp(choices_.path.noise_threshold, 0.0f, 1.0f);
    }
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip(
            "adaptive sampling: each pixel stops once the relative standard error of its "
            "estimate is about this (0.01: 1%%), in rounds up to the sample cap; 0: off");
    }
    ImGui::Checkbox("light sampling", &choices_.path.light_sampling);
    ImGui::SameLine();
    ImGui::Checkbox("MIS", &choices_.path.mis);
    ImGui::Checkbox("scene lights", &choices_.path.scene_lights);
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip(
            "the scene's own lights shine besides the environment (under the sky its sun takes "
            "the key light's place); off: the environment alone, as a furnace test wants");
    }
    ImGui::Checkbox("denoise (N)", &choices_.denoise);
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip(
            "show the accumulating image denoised, guided by its albedo, normal and depth (an "
            "a-trous filter; F12 and saved views denoise with --denoise's filter)");
    }
}

bool ViewerPanel::draw_environment_controls() {
    static constexpr std::pair<EnvironmentKind, const char*> kinds[] = {
        {EnvironmentKind::Sky, "sky"},
        {EnvironmentKind::Studio, "studio"},
        {EnvironmentKind::Uniform, "uniform"},
        {EnvironmentKind::File, "file"},
    };
    bool changed = false;
    // What lights the scene: the user's choice, else the scene's own environment.
    const EnvironmentKind current =
        with_scene_environment(choices_.environment, scenes_.current()).kind;
    const char* shown = "sky";
    for (const auto& [kind, name] : kinds) {
        if (kind == current) shown = name;
    }
    if (ImGui::BeginCombo("environment", shown)) {
        for (const auto& [kind, name] : kinds) {
            // A file comes from --environment FILE; without one there is none to pick.
            const bool unavailable =
                kind == EnvironmentKind::File && choices_.environment.file.empty();
            if (ImGui::Selectable(name, kind == current,
                                  unavailable ? ImGuiSelectableFlags_Disabled : 0)) {
                changed |= kind != current;
                choices_.environment.kind = kind;
                choices_.environment.given = true;
            }
        }
        ImGui::EndCombo();
    }
    if (!choices_.environment.given && current != choices_.environment.kind) {
        ImGui::TextDisabled("the scene's own");
    }
    if (current == EnvironmentKind::File) {
        ImGui::TextDisabled("%s", choices_.environment.file.filename().string().c_str());
    }
    // Sliders change the maps when let go: making a sky takes a few milliseconds, not a frame's.
    ImGui::SliderFloat("intensity", &choices_.environment.intensity, 0.0f, 10.0f, "%.2f",
                       ImGuiSliderFlags_Logarithmic);
    changed |= ImGui::IsItemDeactivatedAfterEdit();
    ImGui::SliderFloat("rotation", &choices_.environment.rotation_degrees, -180.0f, 180.0f,
                       "%.0f deg");
    changed |= ImGui::IsItemDeactivatedAfterEdit();
    if (current == EnvironmentKind::Sky) {
        ImGui::SliderFloat("turbidity", &choices_.environment.sky.turbidity, 1.7f, 10.0f, "%.1f");
        changed |= ImGui::IsItemDeactivatedAfterEdit();
        bool own_sun = !choices_.environment.sun_from_scene;
        if (ImGui::Checkbox("place the sun", &own_sun)) {
            choices_.environment.sun_from_scene = !own_sun;
            changed = true;
        }
        if (ImGui::IsItemHovered()) {
            ImGui::SetTooltip("off: the sun stands where the scene's key light is");
        }
        if (own_sun) {
            ImGui::SliderFloat("sun elevation", &choices_.environment.sky.sun_elevation_degrees,
                               -5.0f, 90.0f, "%.0f deg");
            changed |= ImGui::IsItemDeactivatedAfterEdit();
            ImGui::SliderFloat("sun azimuth", &choices_.environment.sky.sun_azimuth_degrees,
                               -180.0f, 180.0f, "%.0f deg");
            changed |= ImGui::IsItemDeactivatedAfterEdit();
        }
    }
    return changed;
}

void ViewerPanel::draw_precision_combo(const ViewReport& report) {
    const bool has_fp64 = report.device.has_fp64;
    if (ImGui::BeginCombo("precision", std::string(precision_name(choices_.precision)).c_str())) {
        for (Precision choice : {Precision::Auto, Precision::Float, Precision::Double}) {
            // Without cl_khr_fp64 double cannot be chosen; auto then stays in float.
            const ImGuiSelectableFlags flags =
                choice == Precision::Double && !has_fp64 ? ImGuiSelectableFlags_Disabled : 0;
            if (ImGui::Selectable(std::string(precision_name(choice)).c_str(),
                                  choice == choices_.precision, flags)) {
                choices_.precision = choice;
            }
        }
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip(
            "auto: double where a pixel is finer than float resolves (deep "
            "zooms); double costs ~2.3x on a CPU");
    }
    if (report.shown) {
        ImGui::TextDisabled("rendered in %s",
                            precision_label(choices_.precision, report.shown->double_precision));
    }
}

void ViewerPanel::draw_messages(const std::deque<std::string>& messages) {
    if (messages.empty()) return;
    ImGui::Separator();
    for (const std::string& message : messages) ImGui::TextWrapped("%s", message.c_str());
}

void ViewerPanel::draw_help() {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Always,
                            ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowBgAlpha(0.95f);
    ImGui::SetNextWindowFocus();
    ImGui::Begin("Key bindings", &show_help_,
                 ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse);
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg)) {
        for (const auto& [keys, action] : kKeyBindings) {
            ImGui::TableNextRow();
            ImGui::TableSetColumnIndex(0);
            ImGui::TextUnformatted(keys);
            ImGui::TableSetColumnIndex(1);
            ImGui::TextUnformatted(action);
        }
        ImGui::EndTable();
    }
    ImGui::TextDisabled("While the view moves fgr renders at reduced resolution to hold the");
    ImGui::TextDisabled("target frame time; when it is still, it refines up to the sample cap.");
    ImGui::End();
}

void ViewerPanel::draw_build_errors(const WorkerStatus& status) {
    if (!refused_update_.first.empty()) {
        const ImVec2 display = ImGui::GetIO().DisplaySize;
        ImGui::SetNextWindowPos(ImVec2(16, display.y * 0.25f), ImGuiCond_Appearing);
        ImGui::SetNextWindowSize(ImVec2(std::min(640.0f, display.x * 0.6f), display.y * 0.45f),
                                 ImGuiCond_Appearing);
        bool open = true;
        ImGui::Begin("Update refused", &open);
        ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", refused_update_.first.c_str());
        ImGui::BeginChild("log", ImVec2(0, 0), true, ImGuiWindowFlags_HorizontalScrollbar);
        ImGui::TextUnformatted(refused_update_.second.c_str());
        ImGui::EndChild();
        ImGui::End();
        if (!open) refused_update_ = {};
    }
    if (status.error.empty()) return;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(16, display.y * 0.3f), ImGuiCond_Appearing);
    ImGui::SetNextWindowSize(ImVec2(std::min(640.0f, display.x * 0.6f), display.y * 0.5f),
                             ImGuiCond_Appearing);
    ImGui::Begin("Kernel build failed");
    ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", status.error.c_str());
    ImGui::TextWrapped("The previous image stays; fix the scene, or switch scenes or effects.");
    ImGui::BeginChild("log", ImVec2(0, 0), true, ImGuiWindowFlags_HorizontalScrollbar);
    ImGui::TextUnformatted(status.error_log.c_str());
    ImGui::EndChild();
    ImGui::End();
}

}  // namespace fgr::viewer
