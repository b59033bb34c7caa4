// SPDX-License-Identifier: Apache-2.0
// `fgr view` end to end, in a virtual X server (xvfb-run, SDL's X11 driver): replayed input moves
// the camera and switches scenes, F12 writes a full-resolution PNG equal to `fgr render`'s image
// of the same view, Ctrl+S saves the view and `fgr render` renders it to the screenshot's bytes,
// `fgr view VIEW` opens it again, recorded paths are saved and render from the command line, a
// scene whose kernel fails to compile is survived, and the viewer exits cleanly with its
// statistics.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <glm/geometric.hpp>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "camera/camera_path_file.hpp"
#include "camera/view_override.hpp"
#include "child_process.hpp"
#include "hermetic_caches.hpp"
#include "image/embedded_view.hpp"
#include "image/image_io.hpp"
#include "image_compare.hpp"
#include "scene/formulas/formulas.hpp"
#include "test_files.hpp"
#include "view_file/view_file.hpp"
#include "viewer/thumbnails.hpp"
#include "viewer/view_still.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;

using test::kFgrExe;
using test::mean_abs_difference;
using test::pixels_over_one_level;

const fs::path kXvfbRun = "/usr/bin/xvfb-run";
constexpr int kWindowWidth = 400;  // wide enough that the window centre is clear of the panel
constexpr int kWindowHeight = 300;

// The value of `key` in a --stats line of the viewer's output (defined below).
std::string stat_text(const std::string& out, const std::string& key);

struct ViewerRun {
    test::RunResult result;
    std::vector<fs::path> screenshots;  // in the order they were written
    std::vector<fs::path> views;        // saved with Ctrl+S (NAME.fgrview.json), by name
};

// Whether `file` is a saved view's thumbnail (NAME.fgrview.png), not a screenshot.
bool is_view_thumbnail(const fs::path& file) {
    return file.filename().string().ends_with(viewer::kViewThumbnailSuffix);
}

class ViewerTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_FALSE(dir_.path().empty());
        ASSERT_TRUE(fs::exists(kXvfbRun))
            << "the viewer tests need xvfb-run (Debian packages xvfb and xauth)";
    }

    // Runs `fgr view` under a fresh virtual X server with `script` as its replay file.
    // The window is kWindowWidth x kWindowHeight and F12 renders 1 sample unless the test sets
    // these first (samples_ 0: no --samples).
    int window_width_ = kWindowWidth;
    int window_height_ = kWindowHeight;
    int samples_ = 1;

    ViewerRun view(const std::string& script, std::vector<std::string> extra = {},
                   const std::optional<fs::path>& plugin_path = std::nullopt,
                   int exit_after_seconds = 150) {
        std::ofstream(dir_.path() / "replay.txt") << script;
        // Distinct start displays keep parallel test processes from racing for the same one.
        std::vector<std::string> args = {"-a",
                                         "-n",
                                         std::to_string(100 + getpid() % 800),
                                         "-s",
                                         "-screen 0 1024x768x24",
                                         kFgrExe.string(),
                                         "view",
                                         "--width",
                                         std::to_string(window_width_),
                                         "--height",
                                         std::to_string(window_height_),
                                         "--replay",
                                         "replay.txt",
                                         "--exit-after",
                                         std::to_string(exit_after_seconds),
                                         "--stats"};
        if (samples_ > 0) args.insert(args.end(), {"--samples", std::to_string(samples_)});
        args.insert(args.end(), extra.begin(), extra.end());
        test::ChildOptions options;
        options.working_dir = dir_.path();
        options.timeout = std::chrono::seconds(200);
        options.environment["FGR_PLUGIN_PATH"] =
            plugin_path ? std::optional<std::string>(plugin_path->string()) : std::nullopt;
        ViewerRun run{test::run_child(kXvfbRun, args, options), {}, {}};
        EXPECT_FALSE(run.result.timed_out) << run.result;
        for (const auto& entry : fs::directory_iterator(dir_.path())) {
            if (entry.path().extension() == ".png" && !is_view_thumbnail(entry.path())) {
                run.screenshots.push_back(entry.path());
            }
            if (is_view_file_name(entry.path())) run.views.push_back(entry.path());
        }
        std::sort(run.views.begin(), run.views.end());
        // In the order taken. Not by name: names carry the scene and a time in whole seconds, and
        // a second shot within the same second gets "-2" appended, which sorts before ".png".
        std::sort(run.screenshots.begin(), run.screenshots.end(),
                  [](const fs::path& a, const fs::path& b) {
                      return std::pair(fs::last_write_time(a), a) <
                             std::pair(fs::last_write_time(b), b);
                  });
        return run;
    }

    // Renders once (`warm`: fgr render's arguments after the subcommand) so the kernel is
    // cached, then opens the viewer (`extra`) on a still view until the frame on screen is full
    // size and three samples (passes) deep (wait_samples; the kernel's build, however slow, only
    // delays it), and checks that the last frame is.
    void expect_still_view_accumulates(std::vector<std::string> warm,
                                       const std::vector<std::string>& extra) {
        warm.insert(warm.begin(), "render");
        warm.insert(warm.end(),
                    {"--spp", "1", "--width", "16", "--height", "12", "-o", "warm.png"});
        const test::RunResult warmed = test::run_fgr(warm, dir());
        ASSERT_EQ(warmed.exit_code, 0) << warmed;
        fs::remove(dir() / "warm.png");
        const ViewerRun run = view("0 wait_samples 3\n0 quit\n", extra);
        ASSERT_EQ(run.result.exit_code, 0) << run.result;
        const std::string last = stat_text(run.result.out, "last_frame");
        ASSERT_FALSE(last.empty()) << run.result;
        int samples = 0;
        float scale = 0.0f;
        ASSERT_EQ(std::sscanf(last.c_str(), "scale %f samples %d", &scale, &samples), 2) << last;
        EXPECT_EQ(scale, 1.0f) << last;
        EXPECT_GT(samples, 2) << last;
    }

    void expect_saved_view_renders_to_the_screenshot(const std::string& script,
                                                     const std::vector<std::string>& extra,
                                                     fs::path* saved);

    const fs::path& dir() const { return dir_.path(); }

private:
    test::TempDir dir_{"fgr_viewer_test"};
};

// The numbers after `key ` on the line starting with it.
std::vector<double> stat_values(const std::string& out, const std::string& key) {
    std::istringstream lines(out);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.rfind(key + " ", 0) != 0) continue;
        std::istringstream values(line.substr(key.size() + 1));
        std::vector<double> numbers;
        double number = 0.0;
        while (values >> number) numbers.push_back(number);
        return numbers;
    }
    return {};
}

std::string stat_text(const std::string& out, const std::string& key) {
    std::istringstream lines(out);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.rfind(key + " ", 0) == 0) return line.substr(key.size() + 1);
    }
    return {};
}

// The camera the viewer reports on exit (--stats): the line `camera --eye X,Y,Z --target X,Y,Z
// --up X,Y,Z --fov DEG`, read as `fgr render` reads those options; none when it is missing or
// incomplete.
std::optional<CameraView> stat_camera(const std::string& out) {
    std::istringstream words(stat_text(out, "camera"));
    ViewOverrideText text;
    for (std::string option, value; words >> option >> value;) {
        if (option == "--eye") text.eye = value;
        if (option == "--target") text.target = value;
        if (option == "--up") text.up = value;
        if (option == "--fov") text.fov = value;
    }
    const ViewOverride parsed = parse_view_override(text);
    if (!parsed.eye || !parsed.target || !parsed.up || !parsed.fov_degrees) return std::nullopt;
    return CameraView{*parsed.eye, *parsed.target, *parsed.up, *parsed.fov_degrees};
}

// Runs actions[i] once `directory` holds i + 1 PNG files (the viewer's screenshots), on a thread
// beside the blocking viewer run: how a test changes files while the viewer watches them.
class AfterEachScreenshot {
public:
    AfterEachScreenshot(fs::path directory, std::vector<std::function<void()>> actions)
        : thread_([this, directory, actions] { run(directory, actions); }) {}
    ~AfterEachScreenshot() {
        stop_ = true;
        thread_.join();
    }
    AfterEachScreenshot(const AfterEachScreenshot&) = delete;
    AfterEachScreenshot& operator=(const AfterEachScreenshot&) = delete;

private:
    void run(const fs::path& directory, const std::vector<std::function<void()>>& actions) {
        size_t done = 0;
        while (!stop_ && done < actions.size()) {
            size_t shots = 0;
            for (const auto& entry : fs::directory_iterator(directory)) {
                shots += entry.path().extension() == ".png";
            }
            if (shots > done) {
                actions[done++]();
            } else {
                std::this_thread::sleep_for(std::chrono::milliseconds(50));
            }
        }
    }
    std::atomic<bool> stop_{false};
    std::thread thread_;
};

// Copies over the target in place, as `cp` does when a user drops in a rebuilt plugin.
void drop_in(const fs::path& from, const fs::path& to) {
    fs::copy_file(from, to, fs::copy_options::overwrite_existing);
}

// Replay lines that record two keyframes where the camera is and save them as a camera path
// (fgr-path-SCENE-TIME.json in the output folder, Ctrl+K): `fgr render --camera-path FILE --time
// 0` then renders exactly the view the viewer had, with no rounding of a camera typed in again.
const char* const kSaveViewAsPath = R"(0 key K
0 key K
0 key_down Left_Ctrl
0 key K
0 key_up Left_Ctrl
)";

// Replay lines that save the view (Ctrl+S) `delay` seconds after the line before.
std::string save_view_after(const std::string& delay) {
    return delay + " key_down Left_Ctrl\n0 key S\n0 key_up Left_Ctrl\n";
}

// The one camera path the viewer saved in `directory`.
fs::path saved_path(const fs::path& directory) {
    std::vector<fs::path> paths;
    for (const auto& entry : fs::directory_iterator(directory)) {
        if (entry.path().extension() == ".json") paths.push_back(entry.path());
    }
    return paths.size() == 1 ? paths[0] : fs::path();
}

TEST_F(ViewerTest, FlyingAndLookingMoveTheCamera) {
    const ViewerRun run =
        view(R"(# wait for the refined first view, shoot, fly forward, look right, shoot
0 wait_idle
0 key F12
0.3 key_down W
# a second's flight, and six frames of it however slowly this machine renders them
1.0 wait_frames 6
0 key_up W
0.1 mouse_down right
0.1 mouse_move 120 0
0.1 mouse_up right
0 wait_idle
0 key F12
0.2 quit
)",
             {"--target-ms", "5"});
    ASSERT_EQ(run.result.exit_code, 0) << run.result;
    ASSERT_EQ(run.screenshots.size(), 2u) << run.result;
    EXPECT_GT(stat_values(run.result.out, "frames_shown").at(0), 3) << run.result;
    const Image8 before = read_png(run.screenshots[0]);
    const Image8 after = read_png(run.screenshots[1]);
    EXPECT_GT(mean_abs_difference(before, after), 10.0) << "the view did not change";

    // The canonical camera sits at (2, -2, 1) looking at the origin: flying forward brings it
    // closer, and looking right turns the view direction clockwise seen from +z.
    const std::optional<CameraView> camera = stat_camera(run.result.out);
    ASSERT_TRUE(camera) << run.result;
    const glm::dvec3 forward = glm::normalize(camera->target - camera->position);
    EXPECT_LT(glm::length(camera->position), 3.0 * 0.95) << "did not fly towards the fractal";
    EXPECT_GT(glm::length(camera->position), 1.0) << "flew through the surface";
    const double initial_forward[3] = {-2.0 / 3.0, 2.0 / 3.0, -1.0 / 3.0};
    const double cross_z = initial_forward[0] * forward[1] - initial_forward[1] * forward[0];
    EXPECT_LT(cross_z, -0.1) << "looking right did not turn the camera clockwise";
    // A full frame takes longer than the 5 ms target asked for here, so the flight was shown in
    // previews at reduced resolution.
    const std::vector<double> previews = stat_values(run.result.out, "preview_frames");
    ASSERT_EQ(previews.size(), 1u) << run.result;
    EXPECT_GT(previews[0], 3) << run.result;
}

// F12 writes the full-resolution image `fgr render` gives for the same view: the viewer saves its
// view as a camera path, `fgr render` renders that, and every pixel agrees within one level. The
// view is the scene's default camera.
TEST_F(ViewerTest, ScreenshotIsTheFullResolutionImageFgrRenderGives) {
    const ViewerRun run =
        view(std::string("0 wait_idle\n0 key F12\n") + kSaveViewAsPath + "0.2 quit\n");
    ASSERT_EQ(run.result.exit_code, 0) << run.result;
    ASSERT_EQ(run.screenshots.size(), 1u) << run.result;
    EXPECT_NE(run.result.err.find("screenshot: wrote"), std::string::npos) << run.result;
    const Image8 shot = read_png(run.screenshots[0]);
    EXPECT_EQ(shot.width, kWindowWidth);
    EXPECT_EQ(shot.height, kWindowHeight);
    const fs::path path = saved_path(dir());
    ASSERT_FALSE(path.empty()) << run.result;
    const CameraView saved = read_camera_path_file(path).path.keyframes.at(0).view;
    EXPECT_EQ(saved.position, glm::dvec3(2.0, -2.0, 1.0)) << "the default camera";
    EXPECT_LT(glm::length(saved.target), 1e-6);

    const test::RunResult rendered =
        test::run_fgr({"render", "mandelbulb", "--camera-path", path.string(), "--time", "0", "-o",
                       "reference.png", "--width", std::to_string(kWindowWidth), "--height",
                       std::to_string(kWindowHeight)},
                      dir());
    ASSERT_EQ(rendered.exit_code, 0) << rendered;
    EXPECT_EQ(pixels_over_one_level(shot, read_png(dir() / "reference.png")), 0);
}

TEST_F(ViewerTest, SwitchingScenesChangesTheImageAndKeepsEachScenesCamera) {
    const ViewerRun run = view(R"(0 wait_idle
0 key F12
0 key_down W
0.6 key_up W
0 key PageDown
0 wait_idle
0 key F12
0 key PageUp
0 wait_idle
0.2 quit
)");
    ASSERT_EQ(run.result.exit_code, 0) << run.result;
    ASSERT_EQ(run.screenshots.size(), 2u) << run.result;
    EXPECT_GT(mean_abs_difference(read_png(run.screenshots[0]), read_png(run.screenshots[1])),
              10.0);
    // Back in the Mandelbulb, the camera is where the flight left it, not the default.
    EXPECT_EQ(stat_text(run.result.out, "scene"), "mandelbulb") << run.result;
    const std::optional<CameraView> camera = stat_camera(run.result.out);
    ASSERT_TRUE(camera) << run.result;
    EXPECT_LT(glm::length(camera->position), 3.0 * 0.97) << run.result;
}

// The formula browser: a search finds the Bulb-Box hybrid, its thumbnail is rendered and kept in
// the kernel cache's folder, picking it switches the view to it, and the next start reads the
// thumbnail instead of rendering it.
TEST_F(ViewerTest, FormulaBrowserFindsAScenePicksItAndCachesItsThumbnail) {
    const std::string script = R"(0 wait_idle
0 browser_search BULB_box
0 wait_thumbnails
0 browser_pick 1
0 wait_idle
0 key F12
0.2 quit
)";
    const fs::path file = fs::path(FGR_TEST_FORMULA_DIR) / "bulb-box.formula.json";
    const std::string key =
        viewer::thumbnail_key(formula_scene_to_scene(read_formula_file(file), file));
    const fs::path thumbnail = test::test_kernel_cache() / "thumbnails" / (key + ".png");
    fs::remove(thumbnail);

    const ViewerRun first = view(script);
    ASSERT_EQ(first.result.exit_code, 0) << first.result;
    EXPECT_EQ(stat_text(first.result.out, "scene"), "bulb-box") << first.result;
    EXPECT_EQ(stat_text(first.result.out, "sequence"), "mandelbulb*1 amazing_box*1")
        << first.result;
    EXPECT_NE(first.result.err.find("thumbnail of 'bulb-box' rendered"), std::string::npos)
        << first.result;
    ASSERT_TRUE(fs::exists(thumbnail)) << "the thumbnail is cached on disk" << first.result;
    const Image8 cached = read_png(thumbnail);
    EXPECT_EQ(cached.width, viewer::kThumbnailWidth);
    EXPECT_EQ(cached.height, viewer::kThumbnailHeight);
    long lit = 0;
    for (const uint8_t channel : cached.rgb) lit += channel > 40;
    EXPECT_GT(lit, long(cached.rgb.size() / 20)) << "the thumbnail shows the fractal";
    ASSERT_EQ(first.screenshots.size(), 1u) << first.result;
    EXPECT_EQ(read_png(first.screenshots[0]).width, kWindowWidth);

    const ViewerRun second = view(script);
    ASSERT_EQ(second.result.exit_code, 0) << second.result;
    EXPECT_EQ(second.result.err.find("thumbnail of 'bulb-box' rendered"), std::string::npos)
        << "the second start reads the thumbnail" << second.result;
    EXPECT_NE(second.result.err.find("thumbnail of 'bulb-box' read from"), std::string::npos)
        << second.result;
    EXPECT_EQ(stat_text(second.result.out, "scene"), "bulb-box") << second.result;
}

// The hybrid editor: an edit is built on the render thread and then replaces the scene (the log
// says so in that order; a screenshot asked for in the edit's frame is still the old image), the
// new sequence shows; an edit the sequence cannot take is refused in one line and changes nothing.
// (That the old scene stays in view for the whole build is not timed here: with the kernel caches
// warm the build can end within a frame.)
TEST_F(ViewerTest, HybridEditRebuildsTheSceneAndKeepsTheOldImageWhileCompiling) {
    const ViewerRun run = view(R"(0 wait_idle
0 key F12
0 hybrid_repeat 2 3
0 key F12
0 wait_reload
0 wait_idle
0 key F12
0 hybrid_remove 3
0 hybrid_save bulb-box-edited
0 wait_idle
0.2 quit
)",
                               {"bulb-box"});
    ASSERT_EQ(run.result.exit_code, 0) << run.result;
    ASSERT_EQ(run.screenshots.size(), 3u) << run.result;
    const Image8 before = read_png(run.screenshots[0]);
    const Image8 while_compiling = read_png(run.screenshots[1]);
    const Image8 after = read_png(run.screenshots[2]);
    EXPECT_EQ(while_compiling.rgb, before.rgb) << "the old scene stays until the new one builds";
    EXPECT_GT(mean_abs_difference(before, after), 2.0) << "the new sequence shows" << run.result;
    const std::string& err = run.result.err;
    const size_t building = err.find("building the edited 'bulb-box': mandelbulb, amazing_box x3");
    const size_t adopted = err.find("'bulb-box' now iterates mandelbulb, amazing_box x3");
    ASSERT_NE(building, std::string::npos) << run.result;
    ASSERT_NE(adopted, std::string::npos) << run.result;
    EXPECT_LT(building, adopted);
    EXPECT_NE(err.find("edit of 'bulb-box' refused: no formula 3 in a sequence of 2"),
              std::string::npos)
        << run.result;
    EXPECT_EQ(stat_text(run.result.out, "sequence"), "mandelbulb*1 amazing_box*3") << run.result;
    EXPECT_EQ(stat_text(run.result.out, "hybrid_edits"), "1") << run.result;
    // Saved as a file that loads as the edited scene under its new id.
    const FormulaScene saved = read_formula_file(dir() / "bulb-box-edited.formula.json");
    EXPECT_EQ(saved.id, "bulb-box-edited");
    ASSERT_EQ(saved.sequence.size(), 2u);
    EXPECT_EQ(saved.sequence[1].formula->name, "amazing_box");
    EXPECT_EQ(saved.sequence[1].repeat, 3);
}

TEST_F(ViewerTest, RecordedPathIsSavedAndRendersFromTheCommandLine) {
    const ViewerRun run = view(R"(0 wait_idle
0 key K
0 key_down W
0.5 key_up W
0 key K
0 key_down Left_Ctrl
0 key K
0 key_up Left_Ctrl
0 key P
0.5 quit
)");
    ASSERT_EQ(run.result.exit_code, 0) << run.result;
    std::vector<fs::path> paths;
    for (const auto& entry : fs::directory_iterator(dir())) {
        if (entry.path().extension() == ".json") paths.push_back(entry.path());
    }
    ASSERT_EQ(paths.size(), 1u) << run.result;
    const CameraPathFile saved = read_camera_path_file(paths[0]);
    EXPECT_EQ(saved.scene, "mandelbulb");
    ASSERT_EQ(saved.path.keyframes.size(), 2u);
    EXPECT_EQ(saved.path.keyframes[0].time, 0.0f);
    EXPECT_EQ(saved.path.keyframes[1].time, 2.0f);  // the default keyframe spacing
    EXPECT_NE(saved.path.keyframes[0].view.position, saved.path.keyframes[1].view.position);

    const test::RunResult rendered =
        test::run_fgr({"render", "mandelbulb", "--camera-path", paths[0].string(), "--time", "1",
                       "-o", "path.png", "--width", "64", "--height", "48"},
                      dir());
    EXPECT_EQ(rendered.exit_code, 0) << rendered;
    EXPECT_TRUE(fs::exists(dir() / "path.png"));
}

TEST_F(ViewerTest, ResizingRendersAtTheNewSizeAndPPlaysTheScenesPath) {
    const ViewerRun run = view(R"(0 wait_idle
0 resize 320 200
0 wait_idle
0 key F12
0 key P
1.5 quit
)");
    ASSERT_EQ(run.result.exit_code, 0) << run.result;
    ASSERT_EQ(run.screenshots.size(), 1u) << run.result;
    const Image8 shot = read_png(run.screenshots[0]);
    EXPECT_EQ(shot.width, 320);
    EXPECT_EQ(shot.height, 200);
    // No movement keys: only the camera path moved the camera off its default (2, -2, 1).
    const std::optional<CameraView> camera = stat_camera(run.result.out);
    ASSERT_TRUE(camera) << run.result;
    EXPECT_GT(glm::length(camera->position - glm::dvec3(2.0, -2.0, 1.0)), 0.05) << run.result;
}

TEST_F(ViewerTest, SurvivesASceneWhoseKernelDoesNotCompile) {
    // The fixture folder comes first in the search path, so the broken scene opens first.
    const ViewerRun run = view(R"(0 wait_idle
0 key F12
0 key PageDown
0 wait_idle
0 key F12
0.2 quit
)",
                               {"fixture-broken"}, fs::path(FGR_TEST_FIXTURE_DIR) / "broken");
    ASSERT_EQ(run.result.exit_code, 0) << run.result;
    EXPECT_NE(run.result.err.find("fixture-broken"), std::string::npos) << run.result;
    EXPECT_NE(run.result.err.find("undeclared_radius"), std::string::npos)
        << "the compiler's message is shown" << run.result;
    EXPECT_NE(run.result.err.find("screenshot not taken"), std::string::npos) << run.result;
    // The next scene renders and its screenshot is written.
    ASSERT_EQ(run.screenshots.size(), 1u) << run.result;
    EXPECT_EQ(read_png(run.screenshots[0]).width, kWindowWidth);
    EXPECT_NE(stat_text(run.result.out, "scene"), "fixture-broken");
}

TEST_F(ViewerTest, RebuiltPluginsAreReloadedAndBrokenUpdatesKeepTheWorkingVersion) {
    const fs::path fixtures = FGR_TEST_FIXTURE_DIR;
    const fs::path plugins = dir() / "plugins";
    fs::create_directory(plugins);
    fs::copy_file(fixtures / "good_scene.so", plugins / "fixture.so");
    // Each screenshot triggers the next change; the script waits until the viewer has dealt
    // with it (wait_reload), then until the view is refined.
    const std::string script = R"(0 wait_idle
0 key F12
0 wait_reload
0 wait_idle
0 key F12
0 wait_reload
0 wait_idle
0 key F12
0 wait_reload
0 wait_idle
0 key F12
0 wait_reload
0 key PageUp
0 wait_idle
0 key F12
0.2 quit
)";
    ViewerRun run;
    {
        AfterEachScreenshot changes(
            dir(),
            {[&] { drop_in(fixtures / "reload" / "reload_bigger.so", plugins / "fixture.so"); },
             [&] { drop_in(fixtures / "reload" / "reload_broken.so", plugins / "fixture.so"); },
             [&] { drop_in(fixtures / "bad_param.so", plugins / "fixture.so"); },
             [&] { drop_in(fixtures / "reload" / "reload_other.so", plugins / "other.so"); }});
        run = view(script, {"fixture-good"}, plugins);
    }
    ASSERT_EQ(run.result.exit_code, 0) << run.result;
    ASSERT_EQ(run.screenshots.size(), 5u) << run.result;
    const Image8 original = read_png(run.screenshots[0]);
    const Image8 rebuilt = read_png(run.screenshots[1]);
    const Image8 after_broken = read_png(run.screenshots[2]);
    const Image8 after_invalid = read_png(run.screenshots[3]);
    EXPECT_GT(mean_abs_difference(original, rebuilt), 5.0)
        << "the bigger sphere did not show" << run.result;
    EXPECT_EQ(after_broken.rgb, rebuilt.rgb)
        << "a broken update replaced the working version" << run.result;
    EXPECT_EQ(after_invalid.rgb, rebuilt.rgb)
        << "an invalid plugin replaced the working version" << run.result;
    const std::string& err = run.result.err;
    EXPECT_NE(err.find("reloaded 'fixture-good'"), std::string::npos) << run.result;
    EXPECT_NE(err.find("update of 'fixture-good' refused"), std::string::npos) << run.result;
    EXPECT_NE(err.find("undeclared_radius"), std::string::npos) << run.result;
    EXPECT_NE(err.find("keeping the version loaded before"), std::string::npos)
        << "an invalid description is reported" << run.result;
    // A plugin dropped in while running appears as a new scene (last in the list: PageUp from
    // the first scene reaches it).
    EXPECT_NE(err.find("new scene 'fixture-other'"), std::string::npos) << run.result;
    EXPECT_EQ(stat_text(run.result.out, "scene"), "fixture-other") << run.result;
}

// A plugin that stays loaded once opened (linked -z nodelete, as a C++ plugin pinned by a unique
// symbol is), rebuilt as a new file renamed over the old: dlopen of its path would hand back the
// image it still holds, so the viewer must load the new version from a copy.
TEST_F(ViewerTest, RebuiltPluginThatStaysLoadedIsReloadedAsRebuilt) {
    const fs::path fixtures = fs::path(FGR_TEST_FIXTURE_DIR) / "nodelete";
    const fs::path plugins = dir() / "plugins";
    fs::create_directory(plugins);
    fs::copy_file(fixtures / "nodelete_v1.so", plugins / "fixture.so");
    // After the first screenshot the new version is renamed over the old: wait until the viewer
    // has dealt with it, then until the view is refined.
    const std::string script = R"(0 wait_idle
0 key F12
0 wait_reload
0 wait_idle
0 key F12
0.2 quit
)";
    ViewerRun run;
    {
        const auto rebuild = [&] {
            fs::copy_file(fixtures / "nodelete_v2.so", plugins / "fixture.so.new");
            fs::rename(plugins / "fixture.so.new", plugins / "fixture.so");
        };
        AfterEachScreenshot changes(dir(), {rebuild});
        run = view(script, {"fixture-nodelete"}, plugins);
    }
    ASSERT_EQ(run.result.exit_code, 0) << run.result;
    ASSERT_EQ(run.screenshots.size(), 2u) << run.result;
    EXPECT_NE(run.result.err.find("reloaded 'fixture-nodelete'"), std::string::npos) << run.result;
    EXPECT_GT(mean_abs_difference(read_png(run.screenshots[0]), read_png(run.screenshots[1])), 5.0)
        << "the old image of the plugin came back: the bigger sphere did not show" << run.result;
}

TEST_F(ViewerTest, DevModeReloadsAnEditedSourceAndKeepsTheLastOneThatCompiles) {
    const fs::path fixtures = FGR_TEST_FIXTURE_DIR;
    const fs::path source = fixtures / "dev" / "dev_scene.cl";  // the path the plugin names
    std::ofstream(source)
        << "real scene_de(vec3 p, PARAMS) { return v3_length(p) - param_scale; }\n";
    const fs::path plugins = dir() / "plugins";
    fs::create_directory(plugins);
    fs::copy_file(fixtures / "dev" / "dev_scene.so", plugins / "dev_scene.so");
    const std::string script = R"(0 wait_idle
0 key F12
0 wait_reload
0 wait_idle
0 key F12
0 wait_reload
0 wait_idle
0 key F12
0.2 quit
)";
    ViewerRun run;
    {
        AfterEachScreenshot edits(
            dir(), {[&] {
                        std::ofstream(source)
                            << "real scene_de(vec3 p, PARAMS) {\n"
                               "    return v3_length(p) - 1.5f * param_scale;\n}\n";
                    },
                    [&] {
                        std::ofstream(source) << "real scene_de(vec3 p, PARAMS) {\n"
                                                 "    return v3_length(p) - typo_radius;\n}\n";
                    }});
        run = view(script, {"fixture-dev", "--dev"}, plugins);
    }
    ASSERT_EQ(run.result.exit_code, 0) << run.result;
    ASSERT_EQ(run.screenshots.size(), 3u) << run.result;
    const Image8 original = read_png(run.screenshots[0]);
    const Image8 edited = read_png(run.screenshots[1]);
    EXPECT_GT(mean_abs_difference(original, edited), 5.0) << "the edit did not show" << run.result;
    EXPECT_EQ(read_png(run.screenshots[2]).rgb, edited.rgb)
        << "a broken edit replaced the scene" << run.result;
    // The compiler's message names the edited file and the line of the typo.
    EXPECT_NE(run.result.err.find("dev_scene.cl:2:"), std::string::npos) << run.result;
    EXPECT_NE(run.result.err.find("typo_radius"), std::string::npos) << run.result;
}

// A text scene opened by path, outside the plugin folders, is reloaded when it is saved; a version
// that does not compile, or whose header is refused, leaves the last good one on screen and says
// why, naming the file (and the line).
TEST_F(ViewerTest, ATextSceneOpenedByPathIsReloadedOnSaveAndBrokenVersionsKeepTheLastGoodOne) {
    const fs::path scene = dir() / "ball.cl";
    const std::string header =
        "/* fgr-scene\n{\"id\": \"fixture-text\", \"name\": \"Text\", \"effects\": [],\n"
        " \"parameters\": [{\"id\": \"scale\", \"min\": 0.1, \"max\": 2, \"default\": 1}]}\n"
        "*/\n";
    test::write_text(scene, header +
                                "real scene_de(vec3 p, PARAMS) {\n"
                                "    return v3_length(p) - param_scale;\n}\n");
    const fs::path plugins = dir() / "plugins";  // empty: the scene is the file alone
    fs::create_directory(plugins);
    const std::string script = R"(0 wait_idle
0 key F12
0 wait_reload
0 wait_idle
0 key F12
0 wait_reload
0 wait_idle
0 key F12
0 wait_reload
0 wait_idle
0 key F12
0.2 quit
)";
    ViewerRun run;
    {
        AfterEachScreenshot edits(
            dir(), {[&] {
                        test::write_text(scene, header +
                                                    "real scene_de(vec3 p, PARAMS) {\n"
                                                    "    return v3_length(p) - 1.5f;\n}\n");
                    },
                    [&] {
                        test::write_text(scene, header +
                                                    "real scene_de(vec3 p, PARAMS) {\n"
                                                    "    return v3_length(p) - typo_radius;\n}\n");
                    },
                    [&] {
                        test::write_text(scene,
                                         "/* fgr-scene {\"id\": \"fixture-text\", "
                                         "\"name\": 7} */\n");
                    }});
        run = view(script, {"ball.cl"}, plugins);
    }
    ASSERT_EQ(run.result.exit_code, 0) << run.result;
    ASSERT_EQ(run.screenshots.size(), 4u) << run.result;
    const Image8 original = read_png(run.screenshots[0]);
    const Image8 edited = read_png(run.screenshots[1]);
    EXPECT_GT(mean_abs_difference(original, edited), 5.0) << "the edit did not show" << run.result;
    EXPECT_EQ(read_png(run.screenshots[2]).rgb, edited.rgb)
        << "a version that does not compile replaced the scene" << run.result;
    EXPECT_EQ(read_png(run.screenshots[3]).rgb, edited.rgb)
        << "a refused header replaced the scene" << run.result;
    const std::string& err = run.result.err;
    EXPECT_NE(err.find("reloaded 'fixture-text'"), std::string::npos) << run.result;
    // The header has 4 lines: the typo is on the file's line 6.
    EXPECT_NE(err.find("OpenCL program failed to compile: ball.cl:6:"), std::string::npos)
        << run.result;
    EXPECT_NE(err.find(R"(ball.cl: header "name": must be a string (keeping the version loaded)"),
              std::string::npos)
        << run.result;
}

// A plugin whose recorded .cl file was edited after it was built: the viewer shows the embedded
// source and says so in one line; with --dev it starts from the file on disk (a ball of half the
// radius: a different picture) and says nothing.
TEST_F(ViewerTest, AChangedSourceIsWarnedAboutAndDevStartsFromTheFile) {
    const fs::path fixtures = FGR_TEST_FIXTURE_DIR;
    const fs::path plugins = dir() / "plugins";
    fs::create_directory(plugins);
    fs::copy_file(fixtures / "stale_view" / "stale_view.so", plugins / "stale_view.so");
    const auto now = fs::file_time_type::clock::now();
    fs::last_write_time(plugins / "stale_view.so", now - std::chrono::hours(1));
    std::ofstream(fixtures / "stale_view" / "stale_view.cl")
        << "real scene_de(vec3 p, PARAMS) { return v3_length(p) - 0.5f * param_scale; }\n";
    const std::string script = "0 wait_idle\n0 key F12\n0.2 quit\n";
    const ViewerRun embedded = view(script, {"fixture-stale-view"}, plugins);
    ASSERT_EQ(embedded.result.exit_code, 0) << embedded.result;
    EXPECT_NE(embedded.result.err.find("stale_view.cl changed after stale_view.so was built"),
              std::string::npos)
        << embedded.result;
    ASSERT_EQ(embedded.screenshots.size(), 1u) << embedded.result;
    const Image8 embedded_image = read_png(embedded.screenshots[0]);
    fs::remove(embedded.screenshots[0]);  // the next run's screenshot is then the only one
    const ViewerRun dev = view(script, {"fixture-stale-view", "--dev"}, plugins);
    ASSERT_EQ(dev.result.exit_code, 0) << dev.result;
    EXPECT_EQ(dev.result.err.find("changed after"), std::string::npos) << dev.result;
    ASSERT_EQ(dev.screenshots.size(), 1u) << dev.result;
    EXPECT_GT(mean_abs_difference(embedded_image, read_png(dev.screenshots[0])), 5.0)
        << "--dev did not start from the edited file";
}

TEST_F(ViewerTest, ExitAfterEndsCleanlyWithFrameStatistics) {
    // The kernel is built first (into this test's kernel cache, which the viewer shares), so the
    // 4 s are the window's: it must show frames in them, not merely print a count.
    const test::RunResult warm = test::run_fgr(
        {"render", "mandelbulb", "--width", "16", "--height", "12", "-o", "warm.png"}, dir());
    ASSERT_EQ(warm.exit_code, 0) << warm;
    fs::remove(dir() / "warm.png");
    const ViewerRun run = view("", {}, std::nullopt, 4);
    ASSERT_EQ(run.result.exit_code, 0) << run.result;
    const std::vector<double> ui = stat_values(run.result.out, "ui_frame_ms count");
    ASSERT_FALSE(ui.empty()) << run.result;
    EXPECT_GT(ui[0], 10) << "the window loop ran";
    const std::vector<double> rendered = stat_values(run.result.out, "render_ms count");
    ASSERT_FALSE(rendered.empty()) << run.result;
    EXPECT_GE(rendered[0], 1) << run.result;
    const std::vector<double> shown = stat_values(run.result.out, "frames_shown");
    ASSERT_FALSE(shown.empty()) << run.result;
    EXPECT_GE(shown[0], 1) << "no frame reached the window in 4 s" << run.result;
    EXPECT_FALSE(stat_text(run.result.out, "last_frame").empty()) << run.result;
    EXPECT_TRUE(run.screenshots.empty());
}

// --eye, --target and --fov set the view the viewer opens at: with no input,
// the camera it reports on exit stands where --eye put it and looks at --target.
TEST_F(ViewerTest, EyeAndTargetSetTheStartView) {
    const ViewerRun run =
        view("", {"mandelbulb", "--eye", "1.5,-2.5,0.5", "--target", "0,0,0.25", "--fov", "40"},
             std::nullopt, 2);
    ASSERT_EQ(run.result.exit_code, 0) << run.result;
    const std::optional<CameraView> camera = stat_camera(run.result.out);
    ASSERT_TRUE(camera) << run.result;
    // The position is kept (and printed) to the last bit; the viewer flies a float forward
    // direction, so the target comes back to float's precision.
    EXPECT_EQ(camera->position, glm::dvec3(1.5, -2.5, 0.5));
    EXPECT_LT(glm::length(camera->target - glm::dvec3(0.0, 0.0, 0.25)), 1e-6);
    EXPECT_EQ(camera->fov_degrees, 40.0f);
}

// Path mode refines a still view progressively past the shaded mode's sample cap (the viewer
// runs with --samples 1): after 8 s standing still the last frame shown averages several samples
// per pixel, all at full resolution.
TEST_F(ViewerTest, PathModeAccumulatesSamplesWhileTheViewStandsStill) {
    expect_still_view_accumulates({"mandelbulb", "--mode", "path"},
                                  {"--mode", "path", "--environment", "uniform"});
}

// A scene with no DE opens in the brute mode, whose passes accumulate while the view stands
// still: the frame shown is full size and several passes deep.
TEST_F(ViewerTest, BruteModeAddsPassesWhileTheViewStandsStill) {
    expect_still_view_accumulates({"stereographic-julia"}, {"stereographic-julia"});
}

// --precision double renders in double: not just the label, the pixels. With a fine hit
// threshold (0.001) float and double images of the default view differ (about 1% of pixels by
// more than a level at 400x300); the screenshot must be the double one, pixel for pixel, as
// `fgr render --precision double` renders the viewer's own view (saved as a camera path).
TEST_F(ViewerTest, PrecisionDoubleRendersTheViewInDouble) {
    const std::vector<std::string> fine = {"--set", "hit_threshold=0.001"};
    std::vector<std::string> options = {"--precision", "double"};
    options.insert(options.end(), fine.begin(), fine.end());
    const ViewerRun run =
        view(std::string("0 wait_idle\n0 key F12\n") + kSaveViewAsPath + "0.2 quit\n", options);
    ASSERT_EQ(run.result.exit_code, 0) << run.result;
    EXPECT_NE(stat_text(run.result.out, "last_frame").find("precision double"), std::string::npos)
        << run.result;
    ASSERT_EQ(run.screenshots.size(), 1u) << run.result;
    const fs::path path = saved_path(dir());
    ASSERT_FALSE(path.empty()) << run.result;
    std::map<std::string, Image8> references;
    for (const std::string precision : {"double", "float"}) {
        std::vector<std::string> args = {"render",
                                         "mandelbulb",
                                         "--camera-path",
                                         path.string(),
                                         "--time",
                                         "0",
                                         "--precision",
                                         precision,
                                         "--width",
                                         std::to_string(kWindowWidth),
                                         "--height",
                                         std::to_string(kWindowHeight),
                                         "-o",
                                         precision + ".png"};
        args.insert(args.end(), fine.begin(), fine.end());
        const test::RunResult rendered = test::run_fgr(args, dir());
        ASSERT_EQ(rendered.exit_code, 0) << rendered;
        references[precision] = read_png(dir() / (precision + ".png"));
    }
    ASSERT_GT(pixels_over_one_level(references["double"], references["float"]), 100)
        << "this view cannot tell float from double";
    EXPECT_EQ(pixels_over_one_level(read_png(run.screenshots[0]), references["double"]), 0);
}

// In a 64 x 64 window at 2 samples: runs `script`, which saves one view (Ctrl+S) and takes one
// screenshot (F12) of it, which carries the view, then `fgr render SAVED.fgrview.json` at the size
// the view was saved at: its PNG must be the screenshot's, byte for byte. Fills `saved` with the
// view file.
void ViewerTest::expect_saved_view_renders_to_the_screenshot(const std::string& script,
                                                             const std::vector<std::string>& extra,
                                                             fs::path* saved) {
    window_width_ = 64;
    window_height_ = 64;
    samples_ = 2;
    const ViewerRun run = view(script, extra);
    ASSERT_EQ(run.result.exit_code, 0) << run.result;
    ASSERT_EQ(run.views.size(), 1u) << run.result;
    ASSERT_EQ(run.screenshots.size(), 1u) << run.result;
    *saved = run.views[0];
    EXPECT_NE(run.result.err.find("view saved: ./" + saved->filename().string()), std::string::npos)
        << run.result;
    const test::RunResult rendered =
        test::run_fgr({"render", saved->string(), "-o", "rendered.png"}, dir());
    ASSERT_EQ(rendered.exit_code, 0) << rendered;
    EXPECT_EQ(read_embedded_view(run.screenshots[0]), view_file_text(read_view_file(*saved)))
        << "the screenshot carries the view Ctrl+S saved";
    const std::vector<uint8_t> shot = test::read_bytes(run.screenshots[0]);
    ASSERT_FALSE(shot.empty());
    EXPECT_TRUE(shot == test::read_bytes(dir() / "rendered.png"))
        << "`fgr render` of the saved view gave other bytes than the viewer's screenshot";
}

// The viewer's view, saved and rendered again: a flight and a parameter set by replayed input
// are saved with Ctrl+S beside a thumbnail, F12 shoots the view, and `fgr render SAVED` gives
// the screenshot's bytes. Then `fgr view SAVED` opens the view again under an option typed over
// it and a warning that its scene changed: Ctrl+S there saves the same view, the option's value
// in place of the view's.
TEST_F(ViewerTest, SavedViewRendersToTheScreenshotsBytesAndOpensAgain) {
    fs::path saved;
    expect_saved_view_renders_to_the_screenshot(R"(0 wait_idle
0 key_down W
0.3 key_up W
0 set power=7.25
0 wait_idle
)" + save_view_after("0") + "0 key F12\n0.2 quit\n",
                                                {}, &saved);
    ASSERT_FALSE(saved.empty());
    const ViewFile first = read_view_file(saved);
    EXPECT_EQ(first.scene_id, "mandelbulb");
    EXPECT_EQ(first.width, 64);
    EXPECT_EQ(first.samples, 2) << "the view's still is F12's: the sample cap";
    EXPECT_EQ(first.mode, RenderMode::Shaded);
    ASSERT_EQ(first.parameters.size(), 1u);
    EXPECT_EQ(parameter_assignment(first.parameters[0]), "power=7.25");
    EXPECT_LT(glm::length(first.camera.position), 3.0 * 0.99) << "the flight is not in the view";
    const fs::path thumbnail = viewer::view_thumbnail_file(saved);
    ASSERT_TRUE(fs::exists(thumbnail));
    EXPECT_EQ(read_png(thumbnail).width, 64) << "a window narrower than the thumbnail keeps its";

    // Opened again with a fingerprint from another version of the scene.
    std::vector<uint8_t> bytes = test::read_bytes(saved);
    std::string text(bytes.begin(), bytes.end());
    const size_t fingerprint = text.find(first.scene_fingerprint);
    ASSERT_NE(fingerprint, std::string::npos);
    text.replace(fingerprint, first.scene_fingerprint.size(), "0123456789abcdef");
    const fs::path opened = dir() / "opened.fgrview.json";
    std::ofstream(opened) << text;
    for (const fs::path& file : {saved, thumbnail}) fs::remove(file);
    samples_ = 0;  // the view's
    const ViewerRun again =
        view(save_view_after("0.2") + "0.2 quit\n", {opened.string(), "--set", "power=6.5"});
    ASSERT_EQ(again.result.exit_code, 0) << again.result;
    EXPECT_NE(again.result.err.find("scene 'mandelbulb' changed since this view was saved"),
              std::string::npos)
        << again.result;
    ASSERT_EQ(again.views.size(), 2u) << again.result;  // opened.fgrview.json and the new one
    const fs::path resaved = again.views[0] == opened ? again.views[1] : again.views[0];
    ViewFile expected = first;
    expected.parameters[0].text = "6.5";
    ViewFile reopened = read_view_file(resaved);
    EXPECT_EQ(reopened.camera.position, first.camera.position);
    EXPECT_LT(glm::length(reopened.camera.target - first.camera.target), 1e-6);
    reopened.camera = expected.camera;  // the viewer flies a float forward direction
    EXPECT_EQ(reopened, expected);
}

// The same in the path tracer's mode, with its settings away from the defaults.
TEST_F(ViewerTest, SavedPathTracedViewRendersToTheScreenshotsBytes) {
    fs::path saved;
    expect_saved_view_renders_to_the_screenshot(R"(0.1 key_down W
0.2 key_up W
0 set power=7.25
)" + save_view_after("0.1") + "0 key F12\n0.2 quit\n",
                                                {"--mode", "path", "--environment", "studio",
                                                 "--environment-rotation", "30", "--bounces", "3"},
                                                &saved);
    ASSERT_FALSE(saved.empty());
    const ViewFile view_file = read_view_file(saved);
    EXPECT_EQ(view_file.mode, RenderMode::Path);
    ASSERT_TRUE(view_file.path);
    EXPECT_EQ(view_file.path->environment, "studio");
    EXPECT_EQ(view_file.path->environment_rotation, 30.0f);
    EXPECT_EQ(view_file.path->bounces, 3);
    ASSERT_EQ(view_file.parameters.size(), 1u);
}

TEST_F(ViewerTest, BadReplayScriptsAreRefusedBeforeAWindowOpens) {
    const ViewerRun typo = view("0 key NoSuchKey\n");
    EXPECT_EQ(typo.result.exit_code, 2) << typo.result;
    EXPECT_NE(typo.result.err.find("replay.txt:1: unknown key 'NoSuchKey'"), std::string::npos)
        << typo.result;
    const ViewerRun event = view("0 jump\n");
    EXPECT_EQ(event.result.exit_code, 2) << event.result;
    EXPECT_NE(event.result.err.find("replay.txt:1:"), std::string::npos) << event.result;
}

TEST(ViewerWithoutDisplay, FailsWithOneLineAndExitCodeOne) {
    test::TempDir dir("fgr_viewer_test");
    test::ChildOptions options;
    options.working_dir = dir.path();
    options.environment["DISPLAY"] = std::nullopt;
    options.environment["WAYLAND_DISPLAY"] = std::nullopt;
    options.environment["SDL_VIDEODRIVER"] = std::nullopt;
    const test::RunResult run = test::run_child(kFgrExe, {"view", "--exit-after", "1"}, options);
    EXPECT_EQ(run.exit_code, 1) << run;
    EXPECT_NE(run.err.find("fgr: error: cannot open a window"), std::string::npos) << run;
}

// --projection reaches the viewer's frames: the F12 screenshot of a stereo pair (eye separation
// and convergence left to follow the view) and of a panorama are the images `fgr render` gives
// for the viewer's own view with the same projection, within a level per pixel.
TEST_F(ViewerTest, ProjectionFromTheCommandLineShapesTheViewersFrames) {
    for (const std::vector<std::string>& projection :
         {std::vector<std::string>{"--stereo", "sbs"},
          std::vector<std::string>{"--projection", "panorama"}}) {
        SCOPED_TRACE(projection.back());
        for (const fs::path& old : fs::directory_iterator(dir())) fs::remove_all(old);
        const ViewerRun run = view(
            std::string("0 wait_idle\n0 key F12\n") + kSaveViewAsPath + "0.2 quit\n", projection);
        ASSERT_EQ(run.result.exit_code, 0) << run.result;
        ASSERT_EQ(run.screenshots.size(), 1u) << run.result;
        const fs::path path = saved_path(dir());
        ASSERT_FALSE(path.empty()) << run.result;
        std::vector<std::string> args = {"render",
                                         "mandelbulb",
                                         "--camera-path",
                                         path.string(),
                                         "--time",
                                         "0",
                                         "--width",
                                         std::to_string(kWindowWidth),
                                         "--height",
                                         std::to_string(kWindowHeight),
                                         "-o",
                                         "reference.png"};
        args.insert(args.end(), projection.begin(), projection.end());
        const test::RunResult rendered = test::run_fgr(args, dir());
        ASSERT_EQ(rendered.exit_code, 0) << rendered;
        const Image8 reference = read_png(dir() / "reference.png");
        EXPECT_EQ(pixels_over_one_level(read_png(run.screenshots[0]), reference), 0);
        // And it is not the pinhole's image.
        args.resize(args.size() - projection.size());
        args.back() = "pinhole.png";
        ASSERT_EQ(test::run_fgr(args, dir()).exit_code, 0);
        EXPECT_GT(pixels_over_one_level(read_png(dir() / "pinhole.png"), reference), 1000);
    }
}

}  // namespace
}  // namespace fgr
