// SPDX-License-Identifier: Apache-2.0
#include "viewer/viewer_app.hpp"

#include <SDL2/SDL.h>
#include <fmt/format.h>
#include <imgui.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "camera/view_override.hpp"
#include "device/kernel_assembly.hpp"
#include "render/precision.hpp"
#include "render/renderer.hpp"
#include "scene/discovery.hpp"
#include "scene/parameters.hpp"
#include "scene/scene_argument.hpp"
#include "scene/scene_source.hpp"
#include "util/timing.hpp"
#include "view_file/view_file.hpp"
#include "viewer/view_still.hpp"
#include "viewer/viewer_util.hpp"

namespace fgr::viewer {
namespace {

// The window thread's pace: input and the panel stay smooth without taking a core from rendering.
constexpr double kUiFrameSeconds = 1.0 / 60.0;

// The longest the window goes without being drawn (the status line's frame time and messages).
constexpr double kMaxUndrawnSeconds = 0.1;
constexpr size_t kMessagesKept = 6;

}  // namespace

ViewerApp::ViewerApp(const ViewerOptions& options, std::vector<Scene> scenes)
    : options_(options),
      scenes_(std::move(scenes)),
      choices_(options),
      paths_(scenes_, options.camera_path_file, options.output_dir,
             [this](std::string message) { add_message(std::move(message)); }),
      input_(input_host()),
      reloader_(scenes_, options.dev, reload_host()),
      hybrid_(scenes_, options.output_dir, hybrid_host()),
      browser_(scenes_, browser_host()),
      panel_(scenes_, choices_, paths_, window_, panel_host()) {
    if (options.replay) {
        std::vector<ReplayEvent> events = ReplayDriver::load(*options.replay);
        if (!events.empty()) replay_.emplace(std::move(events), replay_host());
    }
    prepare_first_scene();
}

void ViewerApp::prepare_first_scene() {
    // Without a choice, the Mandelbulb (fgr's default scene) if it is installed.
    std::optional<size_t> index =
        scenes_.find(options_.scene.empty() ? "mandelbulb" : options_.scene);
    if (!index && !options_.scene.empty()) {
        std::string ids;
        for (size_t i = 0; i < scenes_.size(); ++i) {
            ids += (ids.empty() ? "" : ", ") + scenes_.at(i)->id;
        }
        throw UsageError(fmt::format("unknown scene '{}' (available: {})", options_.scene, ids));
    }
    const Scene& scene = *scenes_.at(index.value_or(0));
    if (options_.opened_view) {
        const ViewFile& view = *options_.opened_view;
        if (view.scene_id != scene.id) {
            spdlog::warn("the view was saved in scene '{}': showing it in '{}'", view.scene_id,
                         scene.id);
        } else if (const std::string warning = scene_change_warning(view, scene);
                   !warning.empty()) {
            spdlog::warn("{}", warning);
        }
    }
    SceneSession first = default_session(scene);
    if (options_.start_view) {
        try {
            first.camera = FlyCamera::from_view(
                apply_view_override(scene.cameras.front().view, *options_.start_view));
        } catch (const std::invalid_argument& error) {
            throw UsageError(error.what());
        }
    }
    for (const std::string& assignment : options_.assignments) {
        set_param_from_text(scene, first.params, assignment);
    }
    try {
        first.effects = apply_effect_changes(first.effects, options_.effect_changes);
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    }
    scenes_.select(static_cast<int>(index.value_or(0)), std::move(first));
    if (!options_.path_name.empty()) paths_.select(options_.path_name);
}

int ViewerApp::run() {
    start();
    auto previous = start_;
    while (!quit_) {
        const auto frame_start = std::chrono::steady_clock::now();
        update(std::chrono::duration<double>(frame_start - previous).count());
        previous = frame_start;
        if (options_.exit_after_seconds && seconds_since(start_) >= *options_.exit_after_seconds) {
            quit_ = true;
        }
        const double spent = seconds_since(frame_start);
        if (spent < kUiFrameSeconds) {
            SDL_Delay(static_cast<Uint32>((kUiFrameSeconds - spent) * 1000.0));
        }
    }
    finish();
    return 0;
}

void ViewerApp::start() {
    window_.open(options_.width, options_.height, options_.fullscreen);
    texture_ = std::make_unique<ImageTexture>();
    worker_ =
        std::make_unique<RenderWorker>(options_.device, options_.packet_width, choices_.quality);
    // --precision double on a device without it fails here, as `fgr render` does.
    use_double_precision(choices_.precision, scenes_.session().camera.to_view(), options_.width,
                         worker_->device_info());
    browser_.start_thumbnails(options_.device, options_.packet_width);
    reloader_.watch();
    spdlog::info("viewer on {}; press H for the key bindings", worker_->device_info().name);
    start_ = std::chrono::steady_clock::now();
}

void ViewerApp::update(double dt) {
    stats_.add_window_frame(dt * 1000.0);
    status_ = worker_->status();
    // Before the idle check: a swapped-in scene is not refined yet.
    reloader_.apply(worker_->take_reloads());
    log_refined_view();
    if (replay_) replay_->feed(seconds_since(start_));
    if (input_.pump_events()) redraws_pending_ = 2;  // ImGui settles a change over two frames
    paths_.advance(dt);
    input_.fly(dt, status_.de_at_camera);
    submit_view();
    receive_frame();
    if (browser_.receive_thumbnails(view_idle())) redraws_pending_ = std::max(redraws_pending_, 1);
    for (std::string& message : worker_->take_messages()) add_message(std::move(message));
    reloader_.poll(seconds_since(start_));
    if (redraws_pending_ > 0 || seconds_since(last_draw_) >= kMaxUndrawnSeconds) {
        draw_frame();
        redraws_pending_ = std::max(redraws_pending_ - 1, 0);
        last_draw_ = std::chrono::steady_clock::now();
    }
}

void ViewerApp::draw_frame() {
    window_.begin_frame();
    if (!texture_->empty()) {
        ImGui::GetBackgroundDrawList()->AddImage(texture_->id(), ImVec2(0, 0),
                                                 ImGui::GetIO().DisplaySize);
    }
    const ViewReport report{view_.last(), shown_, status_, worker_->device_info(), messages_};
    panel_.draw_overlay(report);
    panel_.draw_panel(report);
    browser_.draw_window();
    panel_.draw_dialogs(status_);
    window_.end_frame();
}

void ViewerApp::finish() {
    if (const int pending = worker_->status().pending_screenshots; pending > 0) {
        spdlog::info("finishing {} screenshot(s) before exit", pending);
    }
    browser_.stop_thumbnails();
    worker_->stop();
    for (std::string& message : worker_->take_messages()) add_message(std::move(message));
    if (options_.print_stats) print_stats();
}

// --- The view ---------------------------------------------------------------------------------

ViewState ViewerApp::current_state() {
    const auto [width, height] = window_.drawable_size();
    ViewState state;
    state.scene = scenes_.current_ptr();
    state.effects = scenes_.session().effects;
    state.view = scenes_.session().camera.to_view();
    state.projection = choices_.projection;
    state.params = scenes_.session().params;
    state.precision = choices_.precision;
    state.mode = choices_.mode_for(scenes_.current());
    if (state.mode == RenderMode::Path) {
        state.path = choices_.path;
        state.denoise = choices_.denoise;
        std::string fallback_reason;
        state.path.environment =
            environments_.prepare(scenes_.current(), choices_.environment, &fallback_reason);
        if (!fallback_reason.empty()) add_message(std::move(fallback_reason));
    }
    state.width = std::clamp(width, 1, kMaxImageSide);
    state.height = std::clamp(height, 1, kMaxImageSide);
    return state;
}

void ViewerApp::submit_view() {
    worker_->submit(view_.track(current_state(), seconds_since(start_), paths_.playing()));
}

void ViewerApp::receive_frame() {
    std::optional<DisplayFrame> frame = worker_->take_frame();
    if (!frame) return;
    texture_->upload(frame->image);
    redraws_pending_ = std::max(redraws_pending_, 1);
    stats_.add_shown_frame(*frame);
    shown_ = std::move(frame);
}

void ViewerApp::log_refined_view() {
    const bool idle = view_idle();
    if (idle && !was_idle_ && shown_) {
        spdlog::debug("view refined: {}x{}, {} samples per pixel", view_.last().width,
                      view_.last().height, shown_->samples);
    }
    was_idle_ = idle;
}

bool ViewerApp::view_idle() const {
    if (replay_ && replay_->window_size_pending()) return false;
    return view_.refined(status_);
}

// --- What the parts ask of the viewer ---------------------------------------------------------

InputHost ViewerApp::input_host() {
    return {
        .run = [this](ViewerCommand command) { run_command(command); },
        .over_panel = [this](int x, int y) { return panel_.covers(x, y); },
        .camera = [this]() -> FlyCamera& { return scenes_.session().camera; },
        .took_camera = [this] { paths_.stop(); },
    };
}

ReloadHost ViewerApp::reload_host() {
    return {
        .build = [this](ReloadRequest request) { worker_->request_reload(std::move(request)); },
        .claim_edit = [this](const ReloadResult& result) { return hybrid_.adopt_edit(result); },
        .adopt_scene = [this](size_t index,
                              std::shared_ptr<const Scene> scene) { adopt_scene(index, scene); },
        .show_refused =
            [this](std::string summary, std::string log) {
                panel_.show_refused_update(std::move(summary), std::move(log));
            },
        .clear_refused = [this] { panel_.clear_refused_update(); },
        .add_message = [this](std::string message) { add_message(std::move(message)); },
    };
}

HybridHost ViewerApp::hybrid_host() {
    return {
        .build = [this](ReloadRequest request) { worker_->request_reload(std::move(request)); },
        .adopt_scene = [this](size_t index,
                              std::shared_ptr<const Scene> scene) { adopt_scene(index, scene); },
        .show_refused =
            [this](std::string summary, std::string log) {
                panel_.show_refused_update(std::move(summary), std::move(log));
            },
        .add_message = [this](std::string message) { add_message(std::move(message)); },
    };
}

BrowserHost ViewerApp::browser_host() {
    return {
        .formula_of = [this](size_t index) { return hybrid_.formula_of(index); },
        .switch_scene = [this](int index) { switch_scene(index); },
        .add_message = [this](std::string message) { add_message(std::move(message)); },
    };
}

PanelHost ViewerApp::panel_host() {
    return {
        .switch_scene = [this](int index) { switch_scene(index); },
        .reset_camera = [this](int camera_index) { reset_camera(camera_index); },
        .take_screenshot = [this] { take_screenshot(); },
        .save_view = [this] { save_view(); },
        .quality_changed = [this] { worker_->set_quality(choices_.quality); },
        .environment_changed = [this] { environments_.clear(); },
        .fly_speed = [this] { return input_.speed_factor(); },
        .set_fly_speed = [this](float factor) { input_.set_speed_factor(factor); },
        .browser_shown = [this] { return browser_.shown(); },
        .toggle_browser = [this] { browser_.toggle(); },
        .draw_formula_sequence = [this] { hybrid_.draw_section(); },
    };
}

ReplayHost ViewerApp::replay_host() {
    return {
        .window_size = [this] { return window_.size(); },
        .window_id = [this] { return window_.id(); },
        .resize_window = [this](int width, int height) { window_.set_size(width, height); },
        .view_idle = [this] { return view_idle(); },
        .thumbnails_done = [this] { return browser_.thumbnails_done(); },
        .full_size_samples =
            [this] { return shown_ && shown_->scale >= 1.0f ? shown_->samples : 0; },
        .frames_shown = [this] { return stats_.frames_shown(); },
        .changes_handled = [this] { return reloader_.changes_handled(); },
        .quit = [this] { quit_ = true; },
        .browser_event = [this](const ReplayEvent& event) { browser_.apply_replay_event(event); },
        .editor_event = [this](const ReplayEvent& event) { hybrid_.apply_replay_event(event); },
        .set_parameter = [this](const std::string& assignment) { set_parameter(assignment); },
    };
}

void ViewerApp::run_command(ViewerCommand command) {
    switch (command) {
        case ViewerCommand::Quit:
            quit_ = true;
            break;
        case ViewerCommand::ResetCamera:
            reset_camera(0);
            break;
        case ViewerCommand::NextCamera:
            reset_camera((scenes_.session().camera_index + 1) %
                         static_cast<int>(scenes_.current().cameras.size()));
            break;
        case ViewerCommand::PreviousScene:
            switch_scene((scenes_.current_index() + static_cast<int>(scenes_.size()) - 1) %
                         static_cast<int>(scenes_.size()));
            break;
        case ViewerCommand::NextScene:
            switch_scene((scenes_.current_index() + 1) % static_cast<int>(scenes_.size()));
            break;
        case ViewerCommand::TogglePlayback:
            paths_.toggle_playback();
            break;
        case ViewerCommand::RecordKeyframe:
            paths_.record_keyframe();
            break;
        case ViewerCommand::SaveRecordedPath:
            paths_.save_recorded();
            break;
        case ViewerCommand::Screenshot:
            take_screenshot();
            break;
        case ViewerCommand::SaveView:
            save_view();
            break;
        case ViewerCommand::ToggleHelp:
            panel_.toggle_help();
            break;
        case ViewerCommand::TogglePanel:
            panel_.toggle_panel();
            break;
        case ViewerCommand::ToggleFullscreen:
            window_.toggle_fullscreen();
            break;
        case ViewerCommand::ToggleBrowser:
            browser_.toggle();
            break;
        case ViewerCommand::ToggleDenoise:
            choices_.denoise = !choices_.denoise;
            break;
    }
}

void ViewerApp::switch_scene(int index) {
    paths_.stop();
    scenes_.select(index);
    panel_.follow_current_scene();
    spdlog::info("scene '{}'", scenes_.current().id);
}

void ViewerApp::reset_camera(int camera_index) {
    paths_.stop();
    scenes_.session().camera_index = camera_index;
    scenes_.session().camera =
        FlyCamera::from_view(scenes_.current().cameras[static_cast<size_t>(camera_index)].view);
}

void ViewerApp::take_screenshot() {
    // The still of the view Ctrl+S would save, rendered as `fgr render` renders that view.
    const ViewState state = current_state();
    ScreenshotRequest request;
    request.scene = state.scene;
    request.view = current_view(state);
    request.file = unused_file(options_.output_dir,
                               fmt::format("fgr-{}-{}", state.scene->id, file_timestamp()), ".png",
                               written_files_);
    written_files_.insert(request.file);
    spdlog::info("screenshot requested: {}", request.file.string());
    add_message(fmt::format("rendering {} ...", request.file.filename().string()));
    worker_->request_screenshot(std::move(request));
}

ViewFile ViewerApp::current_view(const ViewState& state) const {
    ViewFile view = view_of_state(state, choices_.environment, choices_.quality.sample_cap);
    if (!options_.opened_scene_file.empty() && view.scene_id == options_.scene) {
        view.scene_file = options_.opened_scene_file;
    }
    return view;
}

void ViewerApp::save_view() {
    const ViewState state = current_state();
    const ViewFile view = current_view(state);
    const std::filesystem::path file =
        unused_file(options_.output_dir, fmt::format("fgr-{}-{}", view.scene_id, file_timestamp()),
                    kViewFileSuffix, written_files_);
    written_files_.insert(file);
    try {
        write_view_file(file, view);
    } catch (const std::exception& error) {
        spdlog::error("view not saved: {}", error.what());
        add_message(fmt::format("view not saved: {}", error.what()));
        return;
    }
    // The thumbnail shows the frame on screen, whatever its refinement; without one there is none.
    std::string thumbnail;
    if (shown_ && !shown_->image.rgb.empty()) {
        const std::filesystem::path image = view_thumbnail_file(file);
        try {
            write_png(image, shrunk_image(shown_->image, kViewThumbnailWidth));
            thumbnail = fmt::format(" and {}", image.filename().string());
        } catch (const std::exception& error) {
            spdlog::warn("view thumbnail not written: {}", error.what());
        }
    }
    spdlog::info("view saved: {}{}", file.string(), thumbnail);
    add_message(fmt::format("saved view {}{}", file.filename().string(), thumbnail));
}

void ViewerApp::set_parameter(const std::string& assignment) {
    try {
        set_param_from_text(scenes_.current(), scenes_.session().params, assignment);
    } catch (const std::exception& error) {
        spdlog::error("{}", error.what());
        add_message(error.what());
    }
}

void ViewerApp::adopt_scene(size_t index, const std::shared_ptr<const Scene>& scene) {
    scenes_.replace(index, scene);
    view_.scene_replaced();
}

void ViewerApp::add_message(std::string message) {
    messages_.push_back(std::move(message));
    while (messages_.size() > kMessagesKept) messages_.pop_front();
    redraws_pending_ = std::max(redraws_pending_, 1);
}

void ViewerApp::print_stats() {
    const FlyCamera& camera = scenes_.session().camera;
    fmt::print("scene {}\n", scenes_.current().id);
    if (const FormulaScene* formula =
            hybrid_.formula_of(static_cast<size_t>(scenes_.current_index()))) {
        std::string sequence;
        for (const FormulaSlot& slot : formula->sequence) {
            sequence += fmt::format("{}{}*{}", sequence.empty() ? "" : " ", slot.formula->name,
                                    slot.repeat);
        }
        fmt::print("sequence {}\n", sequence);
        fmt::print("hybrid_edits {}\n", hybrid_.edits_adopted());
    }
    stats_.print();
    // As `fgr render` takes it, every number read back to the same bits.
    const CameraView view = camera.to_view();
    fmt::print("camera --eye {},{},{} --target {},{},{} --up {},{},{} --fov {}\n", view.position.x,
               view.position.y, view.position.z, view.target.x, view.target.y, view.target.z,
               view.up.x, view.up.y, view.up.z, view.fov_degrees);
    if (shown_) {
        fmt::print("last_frame scale {:.3f} samples {} precision {}\n", shown_->scale,
                   shown_->samples, precision_label(choices_.precision, shown_->double_precision));
    }
}

int run_viewer(const ViewerOptions& options) {
    ViewerOptions chosen = options;
    // A scene file by path opens first, before the plugin folders' scenes (which it replaces when
    // one has its id); a bad one is refused before anything else is loaded.
    std::optional<Scene> opened;
    if (const SceneArgumentKind kind = scene_argument_kind(options.scene);
        kind != SceneArgumentKind::Id) {
        opened = load_scene_argument_file(options.scene, kind);
        chosen.scene = opened->id;
        std::error_code error;
        const std::filesystem::path absolute = std::filesystem::absolute(options.scene, error);
        chosen.opened_scene_file = error ? options.scene : absolute.lexically_normal().string();
    }
    Discovery found = discover_scenes(plugin_search_path(executable_dir()));
    if (opened) {
        std::erase_if(found.scenes, [&](const Scene& scene) { return scene.id == opened->id; });
        found.scenes.insert(found.scenes.begin(), std::move(*opened));
    }
    if (found.scenes.empty()) {
        throw std::runtime_error("no scenes found (see `fgr list` for the folders searched)");
    }
    const auto has_id = [&](const Scene& scene) { return scene.id == chosen.scene; };
    if (!chosen.scene.empty() && std::none_of(found.scenes.begin(), found.scenes.end(), has_id)) {
        throw UsageError(unknown_scene_message(found, chosen.scene));
    }
    for (Scene& scene : found.scenes) {
        // --dev starts from the .cl files as they are on disk, not as the plugins embed them.
        if (options.dev && recorded_source_file(scene)) {
            scene = with_source_from_disk(scene);
        } else if (const std::string stale = stale_source_warning(scene); !stale.empty()) {
            spdlog::warn("{}", stale);
        }
    }
    ViewerApp app(chosen, std::move(found.scenes));
    return app.run();
}

}  // namespace fgr::viewer
