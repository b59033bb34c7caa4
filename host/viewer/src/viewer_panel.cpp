// The viewer's Dear ImGui panel: status line, scenes, cameras and paths, a widget per
// parameter, effects, adaptive quality, messages, key bindings and build errors (the formula
// browser and the sequence editor are in viewer_formulas.cpp).
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "fgr/kernel_assembly.hpp"
#include "fgr/parameters.hpp"
#include "fgr/plugin.h"
#include "fgr/precision.hpp"
#include "fgr/projection.hpp"
#include "fgr/render_mode.hpp"
#include "viewer_app.hpp"

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
    {"Ctrl+S", "save the recorded path as JSON"},
    {"F12", "screenshot at full resolution and quality"},
    {"Tab", "show / hide the panel"},
    {"F11", "fullscreen"},
    {"B", "formula browser: thumbnails of the scenes, search"},
    {"H or F1", "this help"},
    {"Escape", "quit"}};

}  // namespace

// --- The panel -------------------------------------------------------------------------------

void ViewerApp::draw_ui() {
    ImGui_ImplOpenGL2_NewFrame();
    ImGui_ImplSDL2_NewFrame();
    ImGui::NewFrame();
    draw_image();
    draw_status_overlay();
    if (show_panel_) {
        draw_panel();
    } else {
        panel_min_ = panel_max_ = ImVec2(0, 0);
    }
    browser_.draw_window();
    draw_build_error();
    if (show_help_) draw_help();
    ImGui::Render();
    const auto [width, height] = window_.drawable_size();
    glViewport(0, 0, width, height);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
    window_.swap();
}

void ViewerApp::draw_image() {
    if (texture_->empty()) return;
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    ImGui::GetBackgroundDrawList()->AddImage(texture_->id(), ImVec2(0, 0), size);
}

void ViewerApp::draw_status_overlay() {
    ImGui::SetNextWindowPos(ImVec2(8, 8));
    ImGui::SetNextWindowBgAlpha(0.55f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoInputs |
                                   ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoSavedSettings |
                                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
    ImGui::Begin("##status", nullptr, flags);
    ImGui::Text("%s  %dx%d", scene().id.c_str(), view_.last().width, view_.last().height);
    if (shown_) {
        const bool path = view_.last().mode == RenderMode::Path;
        ImGui::Text("resolution %.0f%%  samples %d/%d  frame %.0f ms  %s", shown_->scale * 100.0f,
                    shown_->samples,
                    mode_sample_cap(view_.last().mode) > 0 ? mode_sample_cap(view_.last().mode)
                                                           : choices_.quality.sample_cap,
                    shown_->render_ms,
                    precision_label(choices_.precision, shown_->double_precision));
        if (path) {
            ImGui::Text("path tracing: %d samples/pixel, %.2f M samples/s", shown_->samples,
                        shown_->samples_per_second / 1e6);
        }
        if (scene().ifs && shown_->ifs_depth_reached >= 0) {
            // The slider caps the depth; the pixel footprint stops it sooner where detail
            // would be smaller than a pixel.
            ImGui::Text("IFS depth reached %d (slider %d)", shown_->ifs_depth_reached,
                        static_cast<int>(param_value(scene(), view_.last().params, "ifs_depth")));
        }
    }
    if (status_.compiling) {
        ImGui::TextColored(ImVec4(1, 0.8f, 0.2f, 1), "compiling %s%s...",
                           status_.compiling_scene.c_str(),
                           status_.compiling_double ? " in double" : "");
    }
    if (status_.pending_screenshots > 0) {
        ImGui::TextColored(ImVec4(0.6f, 0.9f, 1, 1), "screenshot in progress (%d)",
                           status_.pending_screenshots);
    }
    if (paths_.playing()) ImGui::Text("playing path  t = %.1f s", paths_.playback_time());
    ImGui::TextDisabled("H: help");
    ImGui::End();
}

void ViewerApp::draw_panel() {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float width = std::min(kPanelWidth, display.x * 0.4f);
    ImGui::SetNextWindowPos(ImVec2(display.x - width - 8, 8), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(width, display.y - 16), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.8f);
    ImGui::Begin("fgr", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize);
    panel_min_ = ImGui::GetWindowPos();
    panel_max_ =
        ImVec2(panel_min_.x + ImGui::GetWindowSize().x, panel_min_.y + ImGui::GetWindowSize().y);
    ImGui::Text("frame %.0f ms  ui %.0f fps", shown_ ? shown_->render_ms : 0.0,
                ImGui::GetIO().Framerate);
    ImGui::PushItemWidth(-150);
    draw_scene_section();
    hybrid_.draw_section();
    draw_camera_section();
    draw_projection_section();
    draw_params_section();
    draw_effects_section();
    draw_mode_section();
    draw_quality_section();
    ImGui::PopItemWidth();
    draw_messages();
    ImGui::End();
}

void ViewerApp::draw_scene_section() {
    if (!ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen)) return;
    if (ImGui::Button(browser_.shown() ? "Hide the formula browser (B)" : "Formula browser (B)")) {
        browser_.toggle();
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
            switch_scene(static_cast<int>(i));
        }
        if (selected && scene_list_follows_) ImGui::SetScrollHereY();
    }
    scene_list_follows_ = false;
    ImGui::EndChild();
    ImGui::TextWrapped("%s", scene().description.c_str());
}

void ViewerApp::draw_camera_section() {
    if (!ImGui::CollapsingHeader("Camera and paths", ImGuiTreeNodeFlags_DefaultOpen)) return;
    SceneSession& current = session();
    const auto& cameras = scene().cameras;
    if (ImGui::BeginCombo("camera", cameras[size_t(current.camera_index)].name.c_str())) {
        for (size_t i = 0; i < cameras.size(); ++i) {
            if (ImGui::Selectable(cameras[i].name.c_str(), int(i) == current.camera_index)) {
                reset_camera(static_cast<int>(i));
            }
        }
        ImGui::EndCombo();
    }
    ImGui::SliderFloat("fov", &current.camera.fov_degrees, 5.0f, 150.0f, "%.0f deg");
    float speed = input_.speed_factor();
    if (ImGui::SliderFloat("speed", &speed, 1e-3f, 1e3f, "%.3g x DE/s",
                           ImGuiSliderFlags_Logarithmic)) {
        input_.set_speed_factor(speed);
    }
    if (status_.de_at_camera >= 0.0f) {
        ImGui::Text("distance to surface %.3g", double(status_.de_at_camera));
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
    if (ImGui::Button("Save (Ctrl+S)")) paths_.save_recorded();
    ImGui::SameLine();
    if (ImGui::Button("Clear")) current.recorded.keyframes.clear();
    float spacing = paths_.keyframe_interval();
    if (ImGui::SliderFloat("keyframe spacing", &spacing, 0.25f, 10.0f, "%.2f s")) {
        paths_.set_keyframe_interval(spacing);
    }
    if (ImGui::Button("Screenshot (F12)")) take_screenshot();
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

void ViewerApp::draw_projection_section() {
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
    const double distance = session().camera.target_distance;
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

void ViewerApp::draw_params_section() {
    const Scene& current = scene();
    const std::vector<int> offsets = param_offsets(current);
    std::vector<std::string> groups;  // in order of first appearance
    for (const ParamInfo& param : current.params) {
        if (std::find(groups.begin(), groups.end(), param.group) == groups.end()) {
            groups.push_back(param.group);
        }
    }
    for (const std::string& group : groups) {
        const bool open_by_default = group != "Effects";
        const std::string header = group.empty() ? "Parameters" : group;
        if (!ImGui::CollapsingHeader(header.c_str(),
                                     open_by_default ? ImGuiTreeNodeFlags_DefaultOpen : 0)) {
            continue;
        }
        for (size_t i = 0; i < current.params.size(); ++i) {
            const ParamInfo& param = current.params[i];
            if (param.group != group) continue;
            ImGui::PushID(param.id.c_str());
            edit_param(param, &session().params[static_cast<size_t>(offsets[i])]);
            ImGui::PopID();
        }
        if (group == "Quality" && ImGui::Button("Reset parameters")) {
            session().params = default_param_values(current);
        }
    }
}

void ViewerApp::draw_effects_section() {
    if (!ImGui::CollapsingHeader("Effects (compiled in)", ImGuiTreeNodeFlags_DefaultOpen)) return;
    uint64_t& effects = session().effects;
    // An IFS scene offers only the effects exact tracing supports (kIfsEffects).
    const uint64_t offered = FGR_EFFECT_ALL_V1 & supported_effects(scene());
    for (uint64_t bit = 1; bit != 0 && bit <= FGR_EFFECT_ALL_V1; bit <<= 1) {
        if ((offered & bit) == 0) continue;
        bool on = (effects & bit) != 0;
        if (ImGui::Checkbox(effect_names(bit).c_str(), &on)) effects ^= bit;
    }
    if (status_.compiling) ImGui::TextColored(ImVec4(1, 0.8f, 0.2f, 1), "compiling...");
}

void ViewerApp::draw_quality_section() {
    if (!ImGui::CollapsingHeader("Adaptive quality", ImGuiTreeNodeFlags_DefaultOpen)) return;
    float target = static_cast<float>(choices_.quality.target_ms);
    bool changed = ImGui::SliderFloat("target frame", &target, 5.0f, 200.0f, "%.0f ms");
    changed |= ImGui::SliderInt("sample cap", &choices_.quality.sample_cap, 1, 256, "%d",
                                ImGuiSliderFlags_Logarithmic);
    if (changed) {
        choices_.quality.target_ms = target;
        worker_->set_quality(choices_.quality);
    }
    draw_precision_combo();
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
    ImGui::TextDisabled("device: %s", worker_->device_info().name.c_str());
}

void ViewerApp::draw_mode_section() {
    if (!ImGui::CollapsingHeader("Render mode", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const RenderMode current = choices_.mode_for(scene());
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
    if (draw_environment_controls()) environments_.clear();
    ImGui::SliderInt("bounces", &choices_.path.max_bounces, 0, 32);
    ImGui::Checkbox("light sampling", &choices_.path.light_sampling);
    ImGui::SameLine();
    ImGui::Checkbox("MIS", &choices_.path.mis);
    ImGui::Checkbox("scene lights", &choices_.path.scene_lights);
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("the scene's own lights shine besides the environment");
    }
}

// The environment's controls; true when the choice changed (its maps are then made again).
bool ViewerApp::draw_environment_controls() {
    static constexpr std::pair<EnvironmentKind, const char*> kinds[] = {
        {EnvironmentKind::Sky, "sky"},
        {EnvironmentKind::Studio, "studio"},
        {EnvironmentKind::Uniform, "uniform"},
        {EnvironmentKind::File, "file"},
    };
    bool changed = false;
    const char* shown = "sky";
    for (const auto& [kind, name] : kinds) {
        if (kind == choices_.environment.kind) shown = name;
    }
    if (ImGui::BeginCombo("environment", shown)) {
        for (const auto& [kind, name] : kinds) {
            // A file comes from --environment FILE; without one there is none to pick.
            const bool unavailable =
                kind == EnvironmentKind::File && choices_.environment.file.empty();
            if (ImGui::Selectable(name, kind == choices_.environment.kind,
                                  unavailable ? ImGuiSelectableFlags_Disabled : 0)) {
                changed |= kind != choices_.environment.kind;
                choices_.environment.kind = kind;
            }
        }
        ImGui::EndCombo();
    }
    if (choices_.environment.kind == EnvironmentKind::File) {
        ImGui::TextDisabled("%s", choices_.environment.file.filename().string().c_str());
    }
    // Sliders change the maps when let go: making a sky takes a few milliseconds, not a frame's.
    ImGui::SliderFloat("intensity", &choices_.environment.intensity, 0.0f, 10.0f, "%.2f",
                       ImGuiSliderFlags_Logarithmic);
    changed |= ImGui::IsItemDeactivatedAfterEdit();
    ImGui::SliderFloat("rotation", &choices_.environment.rotation_degrees, -180.0f, 180.0f,
                       "%.0f deg");
    changed |= ImGui::IsItemDeactivatedAfterEdit();
    if (choices_.environment.kind == EnvironmentKind::Sky) {
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

void ViewerApp::draw_precision_combo() {
    const bool has_fp64 = worker_->device_info().has_fp64;
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
    if (shown_) {
        ImGui::TextDisabled("rendered in %s",
                            precision_label(choices_.precision, shown_->double_precision));
    }
}

void ViewerApp::draw_messages() {
    if (messages_.empty()) return;
    ImGui::Separator();
    for (const std::string& message : messages_) ImGui::TextWrapped("%s", message.c_str());
}

void ViewerApp::draw_help() {
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

void ViewerApp::draw_build_error() {
    if (!reload_error_.first.empty()) {
        const ImVec2 display = ImGui::GetIO().DisplaySize;
        ImGui::SetNextWindowPos(ImVec2(16, display.y * 0.25f), ImGuiCond_Appearing);
        ImGui::SetNextWindowSize(ImVec2(std::min(640.0f, display.x * 0.6f), display.y * 0.45f),
                                 ImGuiCond_Appearing);
        bool open = true;
        ImGui::Begin("Update refused", &open);
        ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", reload_error_.first.c_str());
        ImGui::BeginChild("log", ImVec2(0, 0), true, ImGuiWindowFlags_HorizontalScrollbar);
        ImGui::TextUnformatted(reload_error_.second.c_str());
        ImGui::EndChild();
        ImGui::End();
        if (!open) reload_error_ = {};
    }
    if (status_.error.empty()) return;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(16, display.y * 0.3f), ImGuiCond_Appearing);
    ImGui::SetNextWindowSize(ImVec2(std::min(640.0f, display.x * 0.6f), display.y * 0.5f),
                             ImGuiCond_Appearing);
    ImGui::Begin("Kernel build failed");
    ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", status_.error.c_str());
    ImGui::TextWrapped("The previous image stays; fix the scene, or switch scenes or effects.");
    ImGui::BeginChild("log", ImVec2(0, 0), true, ImGuiWindowFlags_HorizontalScrollbar);
    ImGui::TextUnformatted(status_.error_log.c_str());
    ImGui::EndChild();
    ImGui::End();
}

}  // namespace fgr::viewer
