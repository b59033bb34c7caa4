// The viewer's window thread: SDL2 window and input, the Dear ImGui panel, the fly camera and the
// hand-over of view states to the render thread (render_worker.cpp).
#include "fgr/viewer/viewer.hpp"

#include <SDL2/SDL.h>
#include <SDL2/SDL_opengl.h>
#include <backends/imgui_impl_opengl2.h>
#include <backends/imgui_impl_sdl.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <deque>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "fgr/camera.hpp"
#include "fgr/camera_path_file.hpp"
#include "fgr/discovery.hpp"
#include "fgr/kernel_assembly.hpp"
#include "fgr/parameters.hpp"
#include "fgr/plugin.h"
#include "fgr/plugin_loader.hpp"
#include "fgr/viewer/file_watcher.hpp"
#include "fgr/viewer/fly_camera.hpp"
#include "fgr/viewer/frame_stats.hpp"
#include "fgr/viewer/render_worker.hpp"
#include "fgr/viewer/replay.hpp"

namespace fgr::viewer {
namespace {

// How long the view counts as moving after its last change: mouse look arrives in bursts, and
// refining between two bursts would only be cancelled again.
constexpr double kSettleSeconds = 0.15;
// The window thread's pace: input and the panel stay smooth without taking a core from rendering.
constexpr double kUiFrameSeconds = 1.0 / 60.0;
constexpr float kLookRadiansPerPixel = 0.0035f;
constexpr float kShiftSpeedUp = 4.0f;
constexpr float kWheelSpeedStep = 1.25f;
constexpr float kPanelWidth = 340.0f;
constexpr size_t kMessagesKept = 6;
// How often plugin folders (and in --dev mode scene sources) are checked for changes.
constexpr double kWatchSeconds = 0.5;

const std::pair<const char*, std::pair<int, int>> kWindowPresets[] = {
    {"1366x768", {1366, 768}},
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
    {"H or F1", "this help"},
    {"Escape", "quit"}};

// --- RAII over SDL and ImGui handles --------------------------------------------------------

struct SdlSession {
    SdlSession() {
        if (SDL_Init(SDL_INIT_VIDEO | SDL_INIT_EVENTS) != 0) {
            throw std::runtime_error(fmt::format(
                "cannot open a window: {} (no display? run under xvfb-run for headless use)",
                SDL_GetError()));
        }
        // With no display SDL falls back to drivers that show nothing; a viewer nobody can see
        // is an error unless that is what the user asked for.
        const std::string driver = SDL_GetCurrentVideoDriver();
        if ((driver == "offscreen" || driver == "dummy") && !SDL_getenv("SDL_VIDEODRIVER")) {
            SDL_Quit();
            throw std::runtime_error(
                "cannot open a window: no display found (set DISPLAY, run under xvfb-run, or set "
                "SDL_VIDEODRIVER=offscreen to run without showing anything)");
        }
    }
    ~SdlSession() { SDL_Quit(); }
    SdlSession(const SdlSession&) = delete;
    SdlSession& operator=(const SdlSession&) = delete;
};

struct WindowDeleter {
    void operator()(SDL_Window* window) const { SDL_DestroyWindow(window); }
};
using WindowHandle = std::unique_ptr<SDL_Window, WindowDeleter>;

struct GlContextDeleter {
    void operator()(void* context) const { SDL_GL_DeleteContext(context); }
};
using GlContextHandle = std::unique_ptr<void, GlContextDeleter>;

class ImGuiSession {
public:
    ImGuiSession(SDL_Window* window, void* gl_context) {
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini in the user's directory
        ImGui::StyleColorsDark();
        ImGui_ImplSDL2_InitForOpenGL(window, gl_context);
        ImGui_ImplOpenGL2_Init();
    }
    ~ImGuiSession() {
        ImGui_ImplOpenGL2_Shutdown();
        ImGui_ImplSDL2_Shutdown();
        ImGui::DestroyContext();
    }
    ImGuiSession(const ImGuiSession&) = delete;
    ImGuiSession& operator=(const ImGuiSession&) = delete;
};

// The texture the rendered image is drawn from.
class ImageTexture {
public:
    ImageTexture() {
        glGenTextures(1, &id_);
        glBindTexture(GL_TEXTURE_2D, id_);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP);
    }
    ~ImageTexture() { glDeleteTextures(1, &id_); }
    ImageTexture(const ImageTexture&) = delete;
    ImageTexture& operator=(const ImageTexture&) = delete;

    void upload(const Image8& image) {
        glBindTexture(GL_TEXTURE_2D, id_);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        if (image.width != width_ || image.height != height_) {
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, image.width, image.height, 0, GL_RGB,
                         GL_UNSIGNED_BYTE, image.rgb.data());
            width_ = image.width;
            height_ = image.height;
        } else {
            glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width_, height_, GL_RGB, GL_UNSIGNED_BYTE,
                            image.rgb.data());
        }
    }
    bool empty() const { return width_ == 0; }
    ImTextureID id() const { return reinterpret_cast<ImTextureID>(static_cast<intptr_t>(id_)); }

private:
    GLuint id_ = 0;
    int width_ = 0;
    int height_ = 0;
};

// --- Per-scene state, remembered while the viewer runs ---------------------------------------

struct SceneSession {
    FlyCamera camera;
    std::vector<float> params;
    uint64_t effects = 0;
    int camera_index = 0;
    int path_index = 0;  // into ViewerApp::playable_paths()
    CameraPath recorded{"recorded", {}};
};

SceneSession default_session(const Scene& scene) {
    SceneSession session;
    session.camera = FlyCamera::from_view(scene.cameras.front().view);
    session.params = default_param_values(scene);
    session.effects = scene.effects;
    return session;
}

bool same_image_inputs(const ViewState& a, const ViewState& b) {
    return a.scene == b.scene && a.effects == b.effects && a.width == b.width &&
           a.height == b.height && a.view.position == b.view.position &&
           a.view.target == b.view.target && a.view.up == b.view.up &&
           a.view.fov_degrees == b.view.fov_degrees && a.params == b.params;
}

std::string timestamp() {
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    char text[32];
    std::strftime(text, sizeof text, "%Y%m%d-%H%M%S", &local);
    return text;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

SDL_Scancode scancode_named(const std::string& name) { return SDL_GetScancodeFromName(name.c_str()); }

// Replay scripts are checked before the window opens, so a typo fails fast.
void check_replay_keys(const std::vector<ReplayEvent>& events, const std::string& file) {
    for (const ReplayEvent& event : events) {
        const bool is_key = event.action == ReplayAction::KeyDown ||
                            event.action == ReplayAction::KeyUp ||
                            event.action == ReplayAction::KeyPress;
        if (is_key && scancode_named(event.key) == SDL_SCANCODE_UNKNOWN) {
            throw UsageError(fmt::format("{}:{}: unknown key '{}' (SDL key names: W, F12, "
                                         "PageDown, Left_Shift...)",
                                         file, event.line, event.key));
        }
    }
}

// --- The application ---------------------------------------------------------------------

class ViewerApp {
public:
    ViewerApp(const ViewerOptions& options, std::vector<Scene> scenes);
    int run();

private:
    // Setup.
    void prepare_first_scene();
    void open_window();

    // Input.
    void pump_events();
    void handle_event(const SDL_Event& event);
    void handle_key_down(SDL_Scancode key, bool repeat);
    void handle_mouse_button(const SDL_MouseButtonEvent& button, bool down);
    void feed_replay();
    void push_replay_event(const ReplayEvent& event);
    bool over_ui(int x, int y) const;

    // Per-frame updates.
    void update_camera(double dt);
    void update_playback(double dt);
    void submit_view();
    void receive_frame();
    bool view_idle() const;
    void log_refined_view();  // once each time the view becomes fully refined (debug level)

    // Hot reload.
    void watch_sources();
    void poll_sources();
    void reload_plugin(const std::filesystem::path& file);
    void reload_source(const std::filesystem::path& file);
    void apply_reloads();
    void adopt_scene(size_t index, const std::shared_ptr<const Scene>& scene);

    // Actions.
    void switch_scene(int index);
    void reset_camera(int camera_index);
    void toggle_playback();
    void record_keyframe();
    void save_recorded_path();
    void take_screenshot();
    void toggle_fullscreen();
    void set_window_size(int width, int height);
    void add_message(std::string message);

    // The panel.
    void draw_ui();
    void draw_image();
    void draw_status_overlay();
    void draw_panel();
    void draw_scene_section();
    void draw_camera_section();
    void draw_params_section();
    void draw_effects_section();
    void draw_quality_section();
    void draw_messages();
    void draw_help();
    void draw_build_error();

    std::vector<CameraPath> playable_paths() const;
    const Scene& scene() const { return *scenes_[static_cast<size_t>(scene_index_)]; }
    SceneSession& session() { return sessions_.at(scene_index_); }
    const SceneSession& session() const { return sessions_.at(scene_index_); }
    void print_stats() const;

    ViewerOptions options_;
    std::vector<std::shared_ptr<const Scene>> scenes_;
    std::optional<CameraPathFile> loaded_path_;
    std::vector<ReplayEvent> replay_events_;

    int scene_index_ = 0;
    std::map<int, SceneSession> sessions_;

    // Created in run(), in this order, destroyed in reverse.
    std::unique_ptr<SdlSession> sdl_;
    WindowHandle window_;
    GlContextHandle gl_context_;
    std::unique_ptr<ImGuiSession> imgui_;
    std::unique_ptr<ImageTexture> texture_;
    std::unique_ptr<RenderWorker> worker_;
    std::unique_ptr<ReplayClock> replay_;

    std::chrono::steady_clock::time_point start_;
    bool quit_ = false;
    std::set<SDL_Scancode> held_keys_;
    bool looking_ = false;
    float speed_factor_ = 1.0f;
    bool show_panel_ = true;
    bool show_help_ = false;
    bool fullscreen_ = false;
    bool playing_ = false;
    bool loop_playback_ = true;
    double playback_time_ = 0.0;
    float keyframe_interval_ = 2.0f;
    QualitySettings quality_;

    ViewState last_state_;
    bool submitted_ = false;
    double last_change_ = -1e9;
    uint64_t generation_ = 0;
    WorkerStatus status_;
    bool was_idle_ = false;
    std::optional<DisplayFrame> shown_;  // image data lives in the texture; this keeps its facts
    ImVec2 panel_min_{0, 0}, panel_max_{0, 0};
    std::deque<std::string> messages_;
    std::set<std::filesystem::path> screenshot_files_;
    FileWatcher watcher_;
    double next_watch_ = 0.0;
    std::pair<std::string, std::string> reload_error_;  // a refused update: summary, log

    FrameStats render_stats_;
    FrameStats ui_stats_;
    int frames_shown_ = 0;
    int preview_frames_ = 0;  // shown at reduced resolution
    double preview_scale_sum_ = 0.0;
};

ViewerApp::ViewerApp(const ViewerOptions& options, std::vector<Scene> scenes)
    : options_(options) {
    for (Scene& scene : scenes) scenes_.push_back(std::make_shared<const Scene>(std::move(scene)));
    quality_.target_ms = options.target_ms;
    quality_.sample_cap = options.sample_cap;
    fullscreen_ = options.fullscreen;
    if (options.camera_path_file) {
        try {
            loaded_path_ = read_camera_path_file(*options.camera_path_file);
        } catch (const std::runtime_error& error) {
            throw UsageError(error.what());
        }
    }
    if (options.replay) {
        try {
            replay_events_ = load_replay(*options.replay);
        } catch (const std::runtime_error& error) {
            throw UsageError(error.what());
        }
        check_replay_keys(replay_events_, options.replay->string());
    }
    prepare_first_scene();
}

void ViewerApp::prepare_first_scene() {
    // Without a choice, the Mandelbulb (fgr's default scene) if it is installed.
    const std::string wanted = options_.scene.empty() ? "mandelbulb" : options_.scene;
    const auto default_scene = std::find_if(scenes_.begin(), scenes_.end(),
                                            [&](const auto& s) { return s->id == wanted; });
    if (options_.scene.empty() && default_scene != scenes_.end()) {
        scene_index_ = static_cast<int>(default_scene - scenes_.begin());
    }
    if (!options_.scene.empty()) {
        const auto found = std::find_if(scenes_.begin(), scenes_.end(),
                                        [&](const auto& s) { return s->id == options_.scene; });
        if (found == scenes_.end()) {
            std::string ids;
            for (const auto& s : scenes_) ids += (ids.empty() ? "" : ", ") + s->id;
            throw UsageError(
                fmt::format("unknown scene '{}' (available: {})", options_.scene, ids));
        }
        scene_index_ = static_cast<int>(found - scenes_.begin());
    }
    SceneSession first = default_session(scene());
    for (const std::string& assignment : options_.assignments) {
        set_param_from_text(scene(), first.params, assignment);
    }
    try {
        first.effects = apply_effect_changes(first.effects, options_.effect_changes);
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    }
    sessions_[scene_index_] = std::move(first);
}

void ViewerApp::open_window() {
    sdl_ = std::make_unique<SdlSession>();
    SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
    Uint32 flags = SDL_WINDOW_OPENGL | SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI;
    if (fullscreen_) flags |= SDL_WINDOW_FULLSCREEN_DESKTOP;
    window_.reset(SDL_CreateWindow("fgr", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                                   options_.width, options_.height, flags));
    if (!window_) throw std::runtime_error(fmt::format("cannot open a window: {}", SDL_GetError()));
    gl_context_.reset(SDL_GL_CreateContext(window_.get()));
    if (!gl_context_) {
        throw std::runtime_error(fmt::format("cannot create an OpenGL context: {}", SDL_GetError()));
    }
    SDL_GL_SetSwapInterval(1);
    imgui_ = std::make_unique<ImGuiSession>(window_.get(), gl_context_.get());
    texture_ = std::make_unique<ImageTexture>();
}

int ViewerApp::run() {
    open_window();
    worker_ = std::make_unique<RenderWorker>(options_.device, options_.packet_width, quality_);
    watch_sources();
    spdlog::info("viewer on {}; press H for the key bindings", worker_->device_info().name);
    if (!replay_events_.empty()) replay_ = std::make_unique<ReplayClock>(replay_events_);
    start_ = std::chrono::steady_clock::now();
    auto previous = start_;
    while (!quit_) {
        const auto frame_start = std::chrono::steady_clock::now();
        const double dt = std::chrono::duration<double>(frame_start - previous).count();
        previous = frame_start;
        ui_stats_.add(dt * 1000.0);

        status_ = worker_->status();
        log_refined_view();
        feed_replay();
        pump_events();
        update_playback(dt);
        update_camera(dt);
        submit_view();
        receive_frame();
        for (std::string& message : worker_->take_messages()) add_message(std::move(message));
        poll_sources();
        apply_reloads();
        draw_ui();
        if (options_.exit_after_seconds && seconds_since(start_) >= *options_.exit_after_seconds) {
            quit_ = true;
        }
        const double spent = seconds_since(frame_start);
        if (spent < kUiFrameSeconds) {
            SDL_Delay(static_cast<Uint32>((kUiFrameSeconds - spent) * 1000.0));
        }
    }
    if (const int pending = worker_->status().pending_screenshots; pending > 0) {
        spdlog::info("finishing {} screenshot(s) before exit", pending);
    }
    worker_->stop();
    for (std::string& message : worker_->take_messages()) add_message(std::move(message));
    if (options_.print_stats) print_stats();
    return 0;
}

// --- Input -------------------------------------------------------------------------------------

void ViewerApp::pump_events() {
    SDL_Event event;
    while (SDL_PollEvent(&event)) {
        ImGui_ImplSDL2_ProcessEvent(&event);
        handle_event(event);
    }
}

bool ViewerApp::over_ui(int x, int y) const {
    const auto fx = static_cast<float>(x), fy = static_cast<float>(y);
    return show_panel_ && fx >= panel_min_.x && fx < panel_max_.x && fy >= panel_min_.y &&
           fy < panel_max_.y;
}

void ViewerApp::handle_event(const SDL_Event& event) {
    switch (event.type) {
        case SDL_QUIT: quit_ = true; break;
        case SDL_KEYDOWN:
            if (ImGui::GetIO().WantTextInput) break;  // typing a value into the panel
            held_keys_.insert(event.key.keysym.scancode);
            handle_key_down(event.key.keysym.scancode, event.key.repeat != 0);
            break;
        case SDL_KEYUP: held_keys_.erase(event.key.keysym.scancode); break;
        case SDL_MOUSEBUTTONDOWN: handle_mouse_button(event.button, true); break;
        case SDL_MOUSEBUTTONUP: handle_mouse_button(event.button, false); break;
        case SDL_MOUSEMOTION:
            if (looking_) {
                const float fov_scale = session().camera.fov_degrees / 60.0f;
                session().camera.turn(static_cast<float>(event.motion.xrel) *
                                          kLookRadiansPerPixel * fov_scale,
                                      -static_cast<float>(event.motion.yrel) *
                                          kLookRadiansPerPixel * fov_scale);
                playing_ = false;
            }
            break;
        case SDL_MOUSEWHEEL: {
            int x = 0, y = 0;
            SDL_GetMouseState(&x, &y);
            if (!looking_ && over_ui(x, y)) break;
            speed_factor_ = std::clamp(
                speed_factor_ * std::pow(kWheelSpeedStep, static_cast<float>(event.wheel.y)),
                1e-3f, 1e3f);
            break;
        }
        default: break;
    }
}

void ViewerApp::handle_mouse_button(const SDL_MouseButtonEvent& button, bool down) {
    if (button.button != SDL_BUTTON_RIGHT) return;
    if (down && over_ui(button.x, button.y)) return;
    looking_ = down;
    // Relative mode hides the pointer and reports unbounded motion; some X servers refuse it,
    // and motion still arrives then, only bounded by the window.
    SDL_SetRelativeMouseMode(down ? SDL_TRUE : SDL_FALSE);
}

void ViewerApp::handle_key_down(SDL_Scancode key, bool repeat) {
    if (repeat) return;
    const bool ctrl = held_keys_.count(SDL_SCANCODE_LCTRL) || held_keys_.count(SDL_SCANCODE_RCTRL);
    switch (key) {
        case SDL_SCANCODE_ESCAPE: quit_ = true; break;
        case SDL_SCANCODE_R: reset_camera(0); break;
        case SDL_SCANCODE_C:
            reset_camera((session().camera_index + 1) % static_cast<int>(scene().cameras.size()));
            break;
        case SDL_SCANCODE_PAGEUP:
            switch_scene((scene_index_ + static_cast<int>(scenes_.size()) - 1) %
                         static_cast<int>(scenes_.size()));
            break;
        case SDL_SCANCODE_PAGEDOWN:
            switch_scene((scene_index_ + 1) % static_cast<int>(scenes_.size()));
            break;
        case SDL_SCANCODE_P: toggle_playback(); break;
        case SDL_SCANCODE_K: record_keyframe(); break;
        case SDL_SCANCODE_S:
            if (ctrl) save_recorded_path();
            break;
        case SDL_SCANCODE_F12: take_screenshot(); break;
        case SDL_SCANCODE_H:
        case SDL_SCANCODE_F1: show_help_ = !show_help_; break;
        case SDL_SCANCODE_TAB: show_panel_ = !show_panel_; break;
        case SDL_SCANCODE_F11: toggle_fullscreen(); break;
        default: break;
    }
}

void ViewerApp::feed_replay() {
    if (!replay_) return;
    const double now = seconds_since(start_);
    if (replay_->waiting()) {
        if (!view_idle()) return;
        replay_->resume(now);
    }
    for (const ReplayEvent& event : replay_->due(now)) push_replay_event(event);
}

void ViewerApp::push_replay_event(const ReplayEvent& event) {
    int width = 0, height = 0;
    SDL_GetWindowSize(window_.get(), &width, &height);
    SDL_Event sdl{};
    const Uint32 window_id = SDL_GetWindowID(window_.get());
    switch (event.action) {
        case ReplayAction::KeyDown:
        case ReplayAction::KeyUp:
        case ReplayAction::KeyPress: {
            const SDL_Scancode code = scancode_named(event.key);
            sdl.key.windowID = window_id;
            sdl.key.keysym.scancode = code;
            sdl.key.keysym.sym = SDL_GetKeyFromScancode(code);
            if (event.action != ReplayAction::KeyUp) {
                sdl.type = SDL_KEYDOWN;
                sdl.key.state = SDL_PRESSED;
                SDL_PushEvent(&sdl);
            }
            if (event.action != ReplayAction::KeyDown) {
                sdl.type = SDL_KEYUP;
                sdl.key.state = SDL_RELEASED;
                SDL_PushEvent(&sdl);
            }
            break;
        }
        case ReplayAction::MouseDown:
        case ReplayAction::MouseUp:
            sdl.type = event.action == ReplayAction::MouseDown ? SDL_MOUSEBUTTONDOWN
                                                               : SDL_MOUSEBUTTONUP;
            sdl.button.windowID = window_id;
            sdl.button.button = static_cast<Uint8>(event.button);
            sdl.button.state = event.action == ReplayAction::MouseDown ? SDL_PRESSED : SDL_RELEASED;
            sdl.button.clicks = 1;
            sdl.button.x = event.has_position ? event.x : width / 2;
            sdl.button.y = event.has_position ? event.y : height / 2;
            SDL_PushEvent(&sdl);
            break;
        case ReplayAction::MouseMove:
            sdl.type = SDL_MOUSEMOTION;
            sdl.motion.windowID = window_id;
            sdl.motion.x = width / 2;
            sdl.motion.y = height / 2;
            sdl.motion.xrel = event.x;
            sdl.motion.yrel = event.y;
            SDL_PushEvent(&sdl);
            break;
        case ReplayAction::Wheel:
            sdl.type = SDL_MOUSEWHEEL;
            sdl.wheel.windowID = window_id;
            sdl.wheel.y = event.wheel;
            sdl.wheel.direction = SDL_MOUSEWHEEL_NORMAL;
            SDL_PushEvent(&sdl);
            break;
        case ReplayAction::Resize: set_window_size(event.x, event.y); break;
        case ReplayAction::WaitIdle: break;  // the clock holds the script until view_idle()
        case ReplayAction::Quit: quit_ = true; break;
    }
}

// --- Per-frame updates -----------------------------------------------------------------------

void ViewerApp::update_camera(double dt) {
    const auto held = [&](SDL_Scancode key) { return held_keys_.count(key) ? 1.0f : 0.0f; };
    const glm::vec3 local(held(SDL_SCANCODE_D) - held(SDL_SCANCODE_A),
                          held(SDL_SCANCODE_W) - held(SDL_SCANCODE_S),
                          held(SDL_SCANCODE_E) - held(SDL_SCANCODE_Q));
    if (local == glm::vec3(0.0f)) return;
    playing_ = false;
    FlyCamera& camera = session().camera;
    // Until the render thread has measured the distance to the surface, move relative to the
    // distance to the target.
    const float de = status_.de_at_camera >= 0.0f ? status_.de_at_camera
                                                  : 0.25f * camera.target_distance;
    const bool shift = held(SDL_SCANCODE_LSHIFT) + held(SDL_SCANCODE_RSHIFT) > 0.0f;
    const float speed = travel_speed(de, speed_factor_ * (shift ? kShiftSpeedUp : 1.0f));
    camera.move(local, limit_step(speed * static_cast<float>(dt), de));
}

void ViewerApp::update_playback(double dt) {
    if (!playing_) return;
    const std::vector<CameraPath> paths = playable_paths();
    if (paths.empty()) {
        playing_ = false;
        return;
    }
    const CameraPath& path =
        paths[static_cast<size_t>(std::clamp(session().path_index, 0, int(paths.size()) - 1))];
    playback_time_ += dt;
    if (playback_time_ > path.duration()) {
        if (!loop_playback_) playing_ = false;
        playback_time_ = loop_playback_ ? std::fmod(playback_time_, double(path.duration()))
                                        : double(path.duration());
    }
    const CameraView view =
        evaluate_camera_path(path, path.keyframes.front().time + float(playback_time_));
    session().camera = FlyCamera::from_view(view);
}

void ViewerApp::submit_view() {
    int width = 0, height = 0;
    SDL_GL_GetDrawableSize(window_.get(), &width, &height);
    ViewState state;
    state.scene = scenes_[static_cast<size_t>(scene_index_)];
    state.effects = session().effects;
    state.view = session().camera.to_view();
    state.params = session().params;
    state.width = std::clamp(width, 1, kMaxImageSide);
    state.height = std::clamp(height, 1, kMaxImageSide);
    const double now = seconds_since(start_);
    if (!submitted_ || !same_image_inputs(state, last_state_)) {
        ++generation_;
        last_change_ = now;
    }
    state.generation = generation_;
    state.interactive = playing_ || now - last_change_ < kSettleSeconds;
    last_state_ = state;
    submitted_ = true;
    worker_->submit(std::move(state));
}

void ViewerApp::receive_frame() {
    std::optional<DisplayFrame> frame = worker_->take_frame();
    if (!frame) return;
    texture_->upload(frame->image);
    render_stats_.add(frame->render_ms);
    if (frame->scale < 1.0f) {
        ++preview_frames_;
        preview_scale_sum_ += frame->scale;
    }
    ++frames_shown_;
    frame->image.rgb.clear();  // the texture has it
    shown_ = std::move(frame);
}

void ViewerApp::log_refined_view() {
    const bool idle = view_idle();
    if (idle && !was_idle_ && shown_) {
        spdlog::debug("view refined: {}x{}, {} samples per pixel", last_state_.width,
                      last_state_.height, shown_->samples);
    }
    was_idle_ = idle;
}

bool ViewerApp::view_idle() const {
    return status_.idle && status_.idle_generation == generation_ && !status_.compiling &&
           status_.pending_screenshots == 0 && status_.pending_reloads == 0 &&
           !last_state_.interactive;
}

// --- Hot reload --------------------------------------------------------------------------------

void ViewerApp::watch_sources() {
    for (const auto& directory : plugin_search_path(executable_dir())) {
        watcher_.watch_directory(directory);
    }
    if (options_.dev) {
        // A scene built with fgr_add_scene_plugin names its .cl file by absolute path.
        for (const auto& scene : scenes_) {
            const std::filesystem::path source = scene->source_name;
            if (source.is_absolute() && std::filesystem::exists(source)) {
                watcher_.watch_file(source);
                spdlog::info("watching {} for '{}'", source.string(), scene->id);
            }
        }
    }
    watcher_.poll();  // what is there now is what was loaded
}

void ViewerApp::poll_sources() {
    const double now = seconds_since(start_);
    if (now < next_watch_) return;
    next_watch_ = now + kWatchSeconds;
    for (const std::filesystem::path& file : watcher_.poll()) {
        if (file.extension() == ".so") {
            reload_plugin(file);
        } else {
            reload_source(file);
        }
    }
}

void ViewerApp::reload_plugin(const std::filesystem::path& file) {
    LoadResult loaded = load_scene_plugin(file);
    if (!loaded.scene) {
        const std::string message =
            fmt::format("{}: {} (keeping the version loaded before)", file.string(), loaded.error);
        spdlog::error("{}", message);
        add_message(message);
        reload_error_ = {message, ""};
        return;
    }
    auto candidate = std::make_shared<const Scene>(std::move(*loaded.scene));
    const auto same_id = std::find_if(scenes_.begin(), scenes_.end(),
                                      [&](const auto& s) { return s->id == candidate->id; });
    if (same_id == scenes_.end()) {
        spdlog::info("new scene '{}' from {}", candidate->id, file.string());
        add_message(fmt::format("new scene '{}'", candidate->id));
        scenes_.push_back(candidate);
        if (options_.dev) watcher_.watch_file(candidate->source_name);
        return;
    }
    if ((*same_id)->plugin_file != candidate->plugin_file) {
        spdlog::warn("{}: scene '{}' is already loaded from {}; ignored", file.string(),
                     candidate->id, (*same_id)->plugin_file.string());
        return;
    }
    const int index = static_cast<int>(same_id - scenes_.begin());
    const uint64_t effects =
        sessions_.count(index) ? sessions_.at(index).effects : candidate->effects;
    spdlog::info("{} changed: building the new '{}'", file.string(), candidate->id);
    worker_->request_reload({candidate, *same_id, effects});
}

void ViewerApp::reload_source(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in && !in.eof()) {
        add_message(fmt::format("cannot read {}", file.string()));
        return;
    }
    for (size_t i = 0; i < scenes_.size(); ++i) {
        if (scenes_[i]->source_name != file.string()) continue;
        Scene edited = *scenes_[i];
        edited.source = text.str();
        const uint64_t effects =
            sessions_.count(int(i)) ? sessions_.at(int(i)).effects : edited.effects;
        spdlog::info("{} changed: building the new '{}'", file.string(), edited.id);
        worker_->request_reload({std::make_shared<const Scene>(std::move(edited)), scenes_[i],
                                 effects});
    }
}

void ViewerApp::apply_reloads() {
    for (const ReloadResult& result : worker_->take_reloads()) {
        const auto running = std::find(scenes_.begin(), scenes_.end(), result.request.replaces);
        if (running == scenes_.end()) continue;  // replaced again meanwhile
        const std::string& id = result.request.candidate->id;
        if (!result.ok) {
            const std::string message =
                fmt::format("update of '{}' refused, keeping the previous version: {}", id,
                            result.error);
            spdlog::error("{}", message);
            add_message(message);
            reload_error_ = {message, result.error_log};
            continue;
        }
        adopt_scene(static_cast<size_t>(running - scenes_.begin()), result.request.candidate);
        reload_error_ = {};
        spdlog::info("reloaded '{}'", id);
        add_message(fmt::format("reloaded '{}'", id));
    }
}

// The new version takes the old one's place; its session keeps the camera and every parameter
// that still exists, and follows the scene's effects unless the user had changed them.
void ViewerApp::adopt_scene(size_t index, const std::shared_ptr<const Scene>& scene) {
    const std::shared_ptr<const Scene> old = scenes_[index];
    scenes_[index] = scene;
    const auto session = sessions_.find(static_cast<int>(index));
    if (session == sessions_.end()) return;
    session->second.params = carry_param_values(*old, session->second.params, *scene);
    if (session->second.effects == old->effects) session->second.effects = scene->effects;
    const int cameras = static_cast<int>(scene->cameras.size());
    session->second.camera_index = std::min(session->second.camera_index, cameras - 1);
}

// --- Actions ---------------------------------------------------------------------------------

void ViewerApp::add_message(std::string message) {
    messages_.push_back(std::move(message));
    while (messages_.size() > kMessagesKept) messages_.pop_front();
}

void ViewerApp::switch_scene(int index) {
    playing_ = false;
    scene_index_ = index;
    if (!sessions_.count(index)) sessions_[index] = default_session(scene());
    spdlog::info("scene '{}'", scene().id);
}

void ViewerApp::reset_camera(int camera_index) {
    playing_ = false;
    session().camera_index = camera_index;
    session().camera =
        FlyCamera::from_view(scene().cameras[static_cast<size_t>(camera_index)].view);
}

std::vector<CameraPath> ViewerApp::playable_paths() const {
    std::vector<CameraPath> paths = scene().camera_paths;
    if (session().recorded.keyframes.size() >= 2) paths.push_back(session().recorded);
    if (loaded_path_) {
        paths.push_back(loaded_path_->path);
        paths.back().name = "file: " + loaded_path_->path.name;
    }
    return paths;
}

void ViewerApp::toggle_playback() {
    if (playing_) {
        playing_ = false;
        return;
    }
    if (playable_paths().empty()) {
        add_message("no camera path to play: record one with K");
        return;
    }
    playing_ = true;
    playback_time_ = 0.0;
}

void ViewerApp::record_keyframe() {
    CameraPath& recorded = session().recorded;
    const float time = recorded.keyframes.empty()
                           ? 0.0f
                           : recorded.keyframes.back().time + keyframe_interval_;
    recorded.keyframes.push_back({time, session().camera.to_view()});
    add_message(fmt::format("keyframe {} at {:.1f} s", recorded.keyframes.size(), time));
}

void ViewerApp::save_recorded_path() {
    const CameraPath& recorded = session().recorded;
    if (recorded.keyframes.size() < 2) {
        add_message("record at least two keyframes (K) before saving");
        return;
    }
    const auto file =
        options_.output_dir / fmt::format("fgr-path-{}-{}.json", scene().id, timestamp());
    try {
        write_camera_path_file(file, {scene().id, recorded});
    } catch (const std::runtime_error& error) {
        spdlog::error("{}", error.what());
        add_message(error.what());
        return;
    }
    spdlog::info("saved camera path {} ({} keyframes, {:.1f} s); render it with `fgr render {} "
                 "--camera-path {} --time T`",
                 file.string(), recorded.keyframes.size(), recorded.duration(), scene().id,
                 file.string());
    add_message(fmt::format("saved {}", file.string()));
}

void ViewerApp::take_screenshot() {
    ScreenshotRequest request;
    request.state = last_state_;
    request.state.interactive = false;
    request.samples = quality_.sample_cap;
    const std::string stem = fmt::format("fgr-{}-{}", scene().id, timestamp());
    std::filesystem::path file = options_.output_dir / (stem + ".png");
    // Two screenshots within a second (the first may not be written yet) must not collide.
    for (int n = 2; std::filesystem::exists(file) || screenshot_files_.count(file); ++n) {
        file = options_.output_dir / fmt::format("{}-{}.png", stem, n);
    }
    screenshot_files_.insert(file);
    request.file = file;
    spdlog::info("screenshot requested: {}", file.string());
    add_message(fmt::format("rendering {} ...", file.filename().string()));
    worker_->request_screenshot(std::move(request));
}

void ViewerApp::toggle_fullscreen() {
    fullscreen_ = !fullscreen_;
    SDL_SetWindowFullscreen(window_.get(), fullscreen_ ? SDL_WINDOW_FULLSCREEN_DESKTOP : 0);
}

void ViewerApp::set_window_size(int width, int height) {
    if (fullscreen_) toggle_fullscreen();
    SDL_SetWindowSize(window_.get(), width, height);
}

void ViewerApp::print_stats() const {
    const FlyCamera& camera = session().camera;
    fmt::print("scene {}\n", scene().id);
    fmt::print("frames_shown {}\n", frames_shown_);
    fmt::print("{}\n", format_summary("render_ms", render_stats_.summary()));
    fmt::print("{}\n", format_summary("ui_frame_ms", ui_stats_.summary()));
    fmt::print("preview_frames {} mean_scale {:.3f}\n", preview_frames_,
               preview_frames_ ? preview_scale_sum_ / preview_frames_ : 1.0);
    fmt::print("camera_position {:.6g} {:.6g} {:.6g}\n", camera.position.x, camera.position.y,
               camera.position.z);
    fmt::print("camera_forward {:.6g} {:.6g} {:.6g}\n", camera.forward.x, camera.forward.y,
               camera.forward.z);
    if (shown_) fmt::print("last_frame scale {:.3f} samples {}\n", shown_->scale, shown_->samples);
}

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
    draw_build_error();
    if (show_help_) draw_help();
    ImGui::Render();
    int width = 0, height = 0;
    SDL_GL_GetDrawableSize(window_.get(), &width, &height);
    glViewport(0, 0, width, height);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
    SDL_GL_SwapWindow(window_.get());
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
    ImGui::Text("%s  %dx%d", scene().id.c_str(), last_state_.width, last_state_.height);
    if (shown_) {
        ImGui::Text("resolution %.0f%%  samples %d/%d  frame %.0f ms", shown_->scale * 100.0f,
                    shown_->samples, quality_.sample_cap, shown_->render_ms);
    }
    if (status_.compiling) {
        ImGui::TextColored(ImVec4(1, 0.8f, 0.2f, 1), "compiling %s...",
                           status_.compiling_scene.c_str());
    }
    if (status_.pending_screenshots > 0) {
        ImGui::TextColored(ImVec4(0.6f, 0.9f, 1, 1), "screenshot in progress (%d)",
                           status_.pending_screenshots);
    }
    if (playing_) ImGui::Text("playing path  t = %.1f s", playback_time_);
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
    panel_max_ = ImVec2(panel_min_.x + ImGui::GetWindowSize().x,
                        panel_min_.y + ImGui::GetWindowSize().y);
    ImGui::Text("frame %.0f ms  ui %.0f fps", shown_ ? shown_->render_ms : 0.0,
                ImGui::GetIO().Framerate);
    ImGui::PushItemWidth(-150);
    draw_scene_section();
    draw_camera_section();
    draw_params_section();
    draw_effects_section();
    draw_quality_section();
    ImGui::PopItemWidth();
    draw_messages();
    ImGui::End();
}

void ViewerApp::draw_scene_section() {
    if (!ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen)) return;
    for (size_t i = 0; i < scenes_.size(); ++i) {
        const bool selected = static_cast<int>(i) == scene_index_;
        if (ImGui::Selectable(fmt::format("{}  ({})", scenes_[i]->name, scenes_[i]->id).c_str(),
                              selected) &&
            !selected) {
            switch_scene(static_cast<int>(i));
        }
    }
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
    ImGui::SliderFloat("speed", &speed_factor_, 1e-3f, 1e3f, "%.3g x DE/s",
                       ImGuiSliderFlags_Logarithmic);
    if (status_.de_at_camera >= 0.0f) {
        ImGui::Text("distance to surface %.3g", double(status_.de_at_camera));
    } else {
        ImGui::TextDisabled("distance to surface unknown");
    }

    const std::vector<CameraPath> paths = playable_paths();
    if (!paths.empty()) {
        current.path_index = std::clamp(current.path_index, 0, int(paths.size()) - 1);
        if (ImGui::BeginCombo("path", paths[size_t(current.path_index)].name.c_str())) {
            for (size_t i = 0; i < paths.size(); ++i) {
                if (ImGui::Selectable(paths[i].name.c_str(), int(i) == current.path_index)) {
                    current.path_index = static_cast<int>(i);
                    playing_ = false;
                }
            }
            ImGui::EndCombo();
        }
        if (ImGui::Button(playing_ ? "Stop (P)" : "Play (P)")) toggle_playback();
        ImGui::SameLine();
        ImGui::Checkbox("loop", &loop_playback_);
    }
    ImGui::Text("recorded: %zu keyframes", current.recorded.keyframes.size());
    if (ImGui::Button("Add keyframe (K)")) record_keyframe();
    ImGui::SameLine();
    if (ImGui::Button("Save (Ctrl+S)")) save_recorded_path();
    ImGui::SameLine();
    if (ImGui::Button("Clear")) current.recorded.keyframes.clear();
    ImGui::SliderFloat("keyframe spacing", &keyframe_interval_, 0.25f, 10.0f, "%.2f s");
    if (ImGui::Button("Screenshot (F12)")) take_screenshot();
}

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
                        if (ImGui::Selectable(param.choices[i].c_str(), int(i) == index)) {
                            index = static_cast<int>(i);
                            changed = true;
                        }
                    }
                    ImGui::EndCombo();
                }
                current = low + index;
            } else {
                changed = ImGui::SliderInt(label, &current, low,
                                           static_cast<int>(param.max_value), "%d", clamp);
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
            changed = ImGui::SliderFloat3(label, value, param.min_value, param.max_value, "%.3g",
                                          clamp);
            break;
        case ParamType::Colour: changed = ImGui::ColorEdit3(label, value, ImGuiColorEditFlags_Float);
            break;
    }
    if (ImGui::IsItemHovered() && !param.description.empty()) {
        ImGui::SetTooltip("%s: %s", param.id.c_str(), param.description.c_str());
    }
    return changed;
}

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
    for (uint64_t bit = 1; bit != 0 && bit <= FGR_EFFECT_ALL_V1; bit <<= 1) {
        if ((FGR_EFFECT_ALL_V1 & bit) == 0) continue;
        bool on = (effects & bit) != 0;
        if (ImGui::Checkbox(effect_names(bit).c_str(), &on)) effects ^= bit;
    }
    if (status_.compiling) ImGui::TextColored(ImVec4(1, 0.8f, 0.2f, 1), "compiling...");
}

void ViewerApp::draw_quality_section() {
    if (!ImGui::CollapsingHeader("Adaptive quality", ImGuiTreeNodeFlags_DefaultOpen)) return;
    float target = static_cast<float>(quality_.target_ms);
    bool changed = ImGui::SliderFloat("target frame", &target, 5.0f, 200.0f, "%.0f ms");
    changed |= ImGui::SliderInt("sample cap", &quality_.sample_cap, 1, 256, "%d",
                                ImGuiSliderFlags_Logarithmic);
    if (changed) {
        quality_.target_ms = target;
        worker_->set_quality(quality_);
    }
    int preset = -1;
    const char* preview = "window size";
    if (ImGui::BeginCombo("window", preview)) {
        for (size_t i = 0; i < std::size(kWindowPresets); ++i) {
            if (ImGui::Selectable(kWindowPresets[i].first)) preset = static_cast<int>(i);
        }
        ImGui::EndCombo();
    }
    if (preset >= 0) {
        set_window_size(kWindowPresets[preset].second.first, kWindowPresets[preset].second.second);
    }
    if (ImGui::Checkbox("fullscreen (F11)", &fullscreen_)) {
        fullscreen_ = !fullscreen_;
        toggle_fullscreen();
    }
    ImGui::TextDisabled("device: %s", worker_->device_info().name.c_str());
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

}  // namespace

int run_viewer(const ViewerOptions& options) {
    Discovery found = discover_scenes(plugin_search_path(executable_dir()));
    if (found.scenes.empty()) {
        throw std::runtime_error("no scenes found (see `fgr list` for the folders searched)");
    }
    ViewerApp app(options, std::move(found.scenes));
    return app.run();
}

}  // namespace fgr::viewer
