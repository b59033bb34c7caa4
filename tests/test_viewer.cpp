// `fgr view` end to end, in a virtual X server (xvfb-run, SDL's X11 driver): replayed input moves
// the camera and switches scenes, F12 writes a full-resolution PNG equal to `fgr render`'s image
// of the same view, recorded paths are saved and render from the command line, a scene whose
// kernel fails to compile is survived, and the viewer exits cleanly with its statistics.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <functional>
#include <thread>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "fgr/camera_path_file.hpp"
#include "fgr/image_io.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;

const fs::path kFgrExe = FGR_TEST_FGR_EXE;
const fs::path kXvfbRun = "/usr/bin/xvfb-run";
constexpr int kWidth = 400;  // wide enough that the window centre is clear of the panel
constexpr int kHeight = 300;

struct ViewerRun {
    test::RunResult result;
    std::vector<fs::path> screenshots;  // sorted by name, i.e. by time taken
};

class ViewerTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_FALSE(dir_.path().empty());
        ASSERT_TRUE(fs::exists(kXvfbRun))
            << "the viewer tests need xvfb-run (Debian packages xvfb and xauth)";
    }

    // Runs `fgr view` under a fresh virtual X server with `script` as its replay file.
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
                                         std::to_string(kWidth),
                                         "--height",
                                         std::to_string(kHeight),
                                         "--samples",
                                         "1",
                                         "--replay",
                                         "replay.txt",
                                         "--exit-after",
                                         std::to_string(exit_after_seconds),
                                         "--stats"};
        args.insert(args.end(), extra.begin(), extra.end());
        test::ChildOptions options;
        options.working_dir = dir_.path();
        options.timeout = std::chrono::seconds(200);
        options.environment["FGR_PLUGIN_PATH"] =
            plugin_path ? std::optional<std::string>(plugin_path->string()) : std::nullopt;
        ViewerRun run{test::run_child(kXvfbRun, args, options), {}};
        EXPECT_FALSE(run.result.timed_out) << run.result;
        for (const auto& entry : fs::directory_iterator(dir_.path())) {
            if (entry.path().extension() == ".png") run.screenshots.push_back(entry.path());
        }
        std::sort(run.screenshots.begin(), run.screenshots.end());
        return run;
    }

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

double mean_abs_difference(const Image8& a, const Image8& b) {
    double sum = 0.0;
    for (size_t i = 0; i < a.rgb.size(); ++i) sum += std::abs(int(a.rgb[i]) - int(b.rgb[i]));
    return sum / static_cast<double>(a.rgb.size());
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

double length(const std::vector<double>& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

TEST_F(ViewerTest, FlyingAndLookingMoveTheCamera) {
    const ViewerRun run = view(R"(# wait for the refined first view, shoot, fly forward, look right, shoot
0 wait_idle
0 key F12
0.3 key_down W
1.0 key_up W
0.1 mouse_down right
0.1 mouse_move 120 0
0.1 mouse_up right
0 wait_idle
0 key F12
0.2 quit
)");
    ASSERT_EQ(run.result.exit_code, 0) << run.result;
    ASSERT_EQ(run.screenshots.size(), 2u) << run.result;
    EXPECT_GT(stat_values(run.result.out, "frames_shown").at(0), 3) << run.result;
    const Image8 before = read_png(run.screenshots[0]);
    const Image8 after = read_png(run.screenshots[1]);
    EXPECT_GT(mean_abs_difference(before, after), 10.0) << "the view did not change";

    // The canonical camera sits at (2, -2, 1) looking at the origin: flying forward brings it
    // closer, and looking right turns the view direction clockwise seen from +z.
    const std::vector<double> position = stat_values(run.result.out, "camera_position");
    const std::vector<double> forward = stat_values(run.result.out, "camera_forward");
    ASSERT_EQ(position.size(), 3u) << run.result;
    ASSERT_EQ(forward.size(), 3u) << run.result;
    EXPECT_LT(length(position), 3.0 * 0.95) << "did not fly towards the fractal";
    EXPECT_GT(length(position), 1.0) << "flew through the surface";
    const double initial_forward[3] = {-2.0 / 3.0, 2.0 / 3.0, -1.0 / 3.0};
    const double cross_z = initial_forward[0] * forward[1] - initial_forward[1] * forward[0];
    EXPECT_LT(cross_z, -0.1) << "looking right did not turn the camera clockwise";
    // A full frame takes longer than the 33 ms target here, so the flight was shown in previews
    // at reduced resolution.
    const std::vector<double> previews = stat_values(run.result.out, "preview_frames");
    ASSERT_EQ(previews.size(), 1u) << run.result;
    EXPECT_GT(previews[0], 3) << run.result;
}

TEST_F(ViewerTest, ScreenshotIsTheFullResolutionImageFgrRenderGives) {
    const ViewerRun run = view(R"(0 wait_idle
0 key F12
0.2 quit
)");
    ASSERT_EQ(run.result.exit_code, 0) << run.result;
    ASSERT_EQ(run.screenshots.size(), 1u) << run.result;
    EXPECT_NE(run.result.err.find("screenshot: wrote"), std::string::npos) << run.result;
    const Image8 shot = read_png(run.screenshots[0]);
    EXPECT_EQ(shot.width, kWidth);
    EXPECT_EQ(shot.height, kHeight);

    const test::RunResult rendered = test::run_fgr(
        {"render", "mandelbulb", "-o", "reference.png", "--width", std::to_string(kWidth),
         "--height", std::to_string(kHeight)},
        dir());
    ASSERT_EQ(rendered.exit_code, 0) << rendered;
    const Image8 reference = read_png(dir() / "reference.png");
    // The same view and one sample each: equal but for rounding in the camera's target.
    EXPECT_LT(mean_abs_difference(shot, reference), 0.5);
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
    const std::vector<double> position = stat_values(run.result.out, "camera_position");
    ASSERT_EQ(position.size(), 3u);
    EXPECT_LT(length(position), 3.0 * 0.97) << run.result;
}

TEST_F(ViewerTest, RecordedPathIsSavedAndRendersFromTheCommandLine) {
    const ViewerRun run = view(R"(0 wait_idle
0 key K
0 key_down W
0.5 key_up W
0 key K
0 key_down Left_Ctrl
0 key S
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

    const test::RunResult rendered = test::run_fgr(
        {"render", "mandelbulb", "--camera-path", paths[0].string(), "--time", "1", "-o",
         "path.png", "--width", "64", "--height", "48"},
        dir());
    EXPECT_EQ(rendered.exit_code, 0) << rendered;
    EXPECT_TRUE(fs::exists(dir() / "path.png"));
}

TEST_F(ViewerTest, ResizingRendersAtTheNewSizeAndPPlaysTheScenesPath) {
    const ViewerRun run = view(R"(0 wait_idle
0 resize 320 200
0.5 wait_idle
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
    const std::vector<double> position = stat_values(run.result.out, "camera_position");
    ASSERT_EQ(position.size(), 3u) << run.result;
    EXPECT_GT(std::abs(position[0] - 2.0) + std::abs(position[1] + 2.0) + std::abs(position[2] - 1.0),
              0.05)
        << run.result;
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
    EXPECT_EQ(read_png(run.screenshots[0]).width, kWidth);
    EXPECT_NE(stat_text(run.result.out, "scene"), "fixture-broken");
}

TEST_F(ViewerTest, RebuiltPluginsAreReloadedAndBrokenUpdatesKeepTheWorkingVersion) {
    const fs::path fixtures = FGR_TEST_FIXTURE_DIR;
    const fs::path plugins = dir() / "plugins";
    fs::create_directory(plugins);
    fs::copy_file(fixtures / "good_scene.so", plugins / "fixture.so");
    // Each phase waits long enough for the watcher (two polls, 1 s) to see the change.
    const std::string script = R"(0 wait_idle
0 key F12
3 wait_idle
0 key F12
3 wait_idle
0 key F12
3 wait_idle
0 key PageUp
0 wait_idle
0 key F12
0.2 quit
)";
    ViewerRun run;
    {
        AfterEachScreenshot changes(
            dir(), {[&] { drop_in(fixtures / "reload" / "reload_bigger.so", plugins / "fixture.so"); },
                    [&] { drop_in(fixtures / "reload" / "reload_broken.so", plugins / "fixture.so"); },
                    [&] {
                        drop_in(fixtures / "bad_param.so", plugins / "fixture.so");
                        drop_in(fixtures / "reload" / "reload_other.so", plugins / "other.so");
                    }});
        run = view(script, {"fixture-good"}, plugins);
    }
    ASSERT_EQ(run.result.exit_code, 0) << run.result;
    ASSERT_EQ(run.screenshots.size(), 4u) << run.result;
    const Image8 original = read_png(run.screenshots[0]);
    const Image8 rebuilt = read_png(run.screenshots[1]);
    const Image8 after_broken = read_png(run.screenshots[2]);
    EXPECT_GT(mean_abs_difference(original, rebuilt), 5.0)
        << "the bigger sphere did not show" << run.result;
    EXPECT_EQ(after_broken.rgb, rebuilt.rgb)
        << "a broken update replaced the working version" << run.result;
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
    const std::string script = R"(0 wait_idle
0 key F12
3 wait_idle
0 key F12
0.2 quit
)";
    ViewerRun run;
    {
        AfterEachScreenshot changes(dir(), {[&] {
                                        fs::copy_file(fixtures / "nodelete_v2.so",
                                                      plugins / "fixture.so.new");
                                        fs::rename(plugins / "fixture.so.new", plugins / "fixture.so");
                                    }});
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
    std::ofstream(source) << "real scene_de(vec3 p, PARAMS) { return v3_length(p) - param_scale; }\n";
    const fs::path plugins = dir() / "plugins";
    fs::create_directory(plugins);
    fs::copy_file(fixtures / "dev" / "dev_scene.so", plugins / "dev_scene.so");
    const std::string script = R"(0 wait_idle
0 key F12
3 wait_idle
0 key F12
3 wait_idle
0 key F12
0.2 quit
)";
    ViewerRun run;
    {
        AfterEachScreenshot edits(
            dir(), {[&] {
                        std::ofstream(source) << "real scene_de(vec3 p, PARAMS) {\n"
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

TEST_F(ViewerTest, ExitAfterEndsCleanlyWithFrameStatistics) {
    const ViewerRun run = view("", {}, std::nullopt, 4);
    ASSERT_EQ(run.result.exit_code, 0) << run.result;
    const std::vector<double> ui = stat_values(run.result.out, "ui_frame_ms count");
    ASSERT_FALSE(ui.empty()) << run.result;
    EXPECT_GT(ui[0], 10) << "the window loop ran";
    EXPECT_FALSE(stat_values(run.result.out, "render_ms count").empty()) << run.result;
    // Frames may or may not have arrived in 4 s (a cold kernel cache compiles for longer), but the
    // counts are printed either way.
    EXPECT_FALSE(stat_values(run.result.out, "frames_shown").empty()) << run.result;
    EXPECT_TRUE(run.screenshots.empty());
}

TEST_F(ViewerTest, PrecisionDoubleRendersTheViewInDouble) {
    const ViewerRun run = view("0 wait_idle\n0 quit\n", {"--precision", "double"});
    ASSERT_EQ(run.result.exit_code, 0) << run.result;
    EXPECT_NE(stat_text(run.result.out, "last_frame").find("precision double"), std::string::npos)
        << run.result;
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

}  // namespace
}  // namespace fgr
