// SPDX-License-Identifier: Apache-2.0
// View files on the command line: `fgr render … --save-view V` then `fgr render V`, or
// `fgr render --view IMAGE`, gives the same bytes in every mode; a view names the environment that
// lit the render; options typed override the view; a scene changed since the view was saved is
// reported; a bad view file is one error line naming the file and the key (`fgr view` too).

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "cli/commands.hpp"
#include "cli/view_options.hpp"
#include "image/image_io.hpp"
#include "test_files.hpp"
#include "test_scenes.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::RunResult;

class ViewFileCli : public ::testing::Test {
protected:
    RunResult run(const std::vector<std::string>& args) {
        RunResult result = test::run_fgr(args, dir());
        EXPECT_FALSE(result.timed_out) << test::describe("fgr", args) << ": " << result;
        EXPECT_EQ(result.term_signal, 0) << test::describe("fgr", args) << ": " << result;
        return result;
    }
    // Runs a command that must succeed.
    RunResult succeed(const std::vector<std::string>& args) {
        RunResult result = run(args);
        EXPECT_TRUE(result.exited && result.exit_code == 0)
            << test::describe("fgr", args) << ": " << result;
        return result;
    }
    const fs::path& dir() const { return dir_.path(); }
    json read_json(const fs::path& file) const {
        const std::vector<uint8_t> bytes = test::read_bytes(file);
        return json::parse(std::string(bytes.begin(), bytes.end()));
    }

private:
    test::TempDir dir_{"fgr_view_cli"};
};

struct ModeCase {
    const char* name;
    std::vector<std::string> args;  // after `render`, before -o and the size
};

void PrintTo(const ModeCase& mode, std::ostream* os) { *os << mode.name; }

// Each with settings away from the defaults, so a setting the view lost shows as other bytes.
const ModeCase kModes[] = {
    {"Shaded",
     {"mandelbulb", "--set", "power=7.25", "--effects", "+shadows", "--eye", "0.3,-2.2,0.9",
      "--target", "0,0,0.1", "--fov", "50.5", "--spp", "2"}},
    {"Path",
     {"mandelbulb", "--mode", "path", "--spp", "2", "--seed", "3", "--environment", "studio",
      "--environment-rotation", "30", "--bounces", "2", "--clamp", "4"}},
    {"Brute", {"mandelbulb", "--mode", "brute", "--spp", "2", "--set", "power=6"}},
};

class ViewFileRoundTrip : public ViewFileCli, public ::testing::WithParamInterface<ModeCase> {};

TEST_P(ViewFileRoundTrip, RenderingTheSavedViewGivesTheSameBytes) {
    std::vector<std::string> first{"render"};
    first.insert(first.end(), GetParam().args.begin(), GetParam().args.end());
    for (const char* arg : {"--width", "24", "--height", "16", "-o", "first.png", "--save-view",
                            "saved.fgrview.json"}) {
        first.emplace_back(arg);
    }
    succeed(first);
    succeed({"render", "saved.fgrview.json", "-o", "again.png"});
    succeed({"render", "--view", "first.png", "-o", "from-image.png"});
    const std::vector<uint8_t> original = test::read_bytes(dir() / "first.png");
    ASSERT_FALSE(original.empty());
    EXPECT_TRUE(original == test::read_bytes(dir() / "again.png"))
        << "the view file rendered other bytes than the command that saved it";
    EXPECT_TRUE(original == test::read_bytes(dir() / "from-image.png"))
        << "the view the image carries rendered other bytes than the image";
}

INSTANTIATE_TEST_SUITE_P(Modes, ViewFileRoundTrip, ::testing::ValuesIn(kModes),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

TEST_F(ViewFileCli, OptionsTypedOverrideTheViewAndTheRestIsKept) {
    succeed({"render", "mandelbulb", "--width", "24", "--height", "16", "--set", "power=7.25",
             "--eye", "0.3,-2.2,0.9", "--effects", "+shadows", "-o", "a.png", "--save-view",
             "a.fgrview.json"});
    succeed({"render", "--view", "a.fgrview.json", "--width", "20", "--set", "power=6", "--effects",
             "-shadows,+fog", "-o", "b.png", "--save-view", "b.fgrview.json"});
    const json a = read_json(dir() / "a.fgrview.json");
    const json b = read_json(dir() / "b.fgrview.json");
    EXPECT_EQ(b["image"]["width"], 20);
    EXPECT_EQ(b["image"]["height"], a["image"]["height"]);
    EXPECT_EQ(b["parameters"]["power"], 6);
    EXPECT_EQ(b["camera"], a["camera"]);
    EXPECT_EQ(a["camera"]["eye"], json::parse("[0.3, -2.2, 0.9]"));
    std::vector<std::string> effects = a["render"]["effects"];
    EXPECT_NE(std::find(effects.begin(), effects.end(), "shadows"), effects.end());
    effects = b["render"]["effects"].get<std::vector<std::string>>();
    EXPECT_EQ(std::find(effects.begin(), effects.end(), "shadows"), effects.end());
    EXPECT_NE(std::find(effects.begin(), effects.end(), "fog"), effects.end());
    // A named camera typed replaces the view's camera.
    succeed({"render", "a.fgrview.json", "--camera", "canonical", "-o", "c.png", "--save-view",
             "c.fgrview.json"});
    EXPECT_NE(read_json(dir() / "c.fgrview.json")["camera"]["eye"], a["camera"]["eye"]);
}

TEST_F(ViewFileCli, AChangedSceneIsReported) {
    succeed({"render", "mandelbulb", "--width", "16", "--height", "12", "-o", "a.png",
             "--save-view", "a.fgrview.json"});
    json view = read_json(dir() / "a.fgrview.json");
    const RunResult same = succeed({"render", "a.fgrview.json", "-o", "b.png"});
    EXPECT_EQ(same.err.find("changed since"), std::string::npos) << same;
    view["scene"]["fingerprint"] = "0000000000000000";
    test::write_text(dir() / "old.fgrview.json", view.dump(2));
    const RunResult changed = succeed({"render", "old.fgrview.json", "-o", "c.png"});
    EXPECT_NE(changed.err.find("scene 'mandelbulb' changed since this view was saved"),
              std::string::npos)
        << changed;
}

TEST_F(ViewFileCli, BadViewFilesAreOneErrorLineNamingFileAndKey) {
    json view = json::parse(R"({"format": "fgr-view", "version": 1,
        "scene": {"id": "mandelbulb"},
        "camera": {"eye": [0, -3, 0], "target": [0, 0, 0], "fov": 500}})");
    test::write_text(dir() / "bad.fgrview.json", view.dump());
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"render", "bad.fgrview.json", "-o", "x.png"},
          std::vector<std::string>{"render", "--view", "bad.fgrview.json", "-o", "x.png"},
          std::vector<std::string>{"video", "bad.fgrview.json", "-o", "x.mp4"},
          // Refused before a window would open: no display is needed.
          std::vector<std::string>{"view", "bad.fgrview.json"},
          std::vector<std::string>{"view", "--view", "bad.fgrview.json"}}) {
        const RunResult result = run(args);
        EXPECT_EQ(result.exit_code, 2) << result;
        EXPECT_EQ(result.err.find('\n'), result.err.size() - 1) << result;
        EXPECT_NE(result.err.find("bad.fgrview.json"), std::string::npos) << result;
        EXPECT_NE(result.err.find("\"camera.fov\""), std::string::npos) << result;
    }
    const RunResult missing = run({"render", "--view", "none.fgrview.json", "-o", "x.png"});
    EXPECT_EQ(missing.exit_code, 2) << missing;
    const RunResult misnamed =
        run({"render", "mandelbulb", "-o", "x.png", "--save-view", "view.json"});
    EXPECT_EQ(misnamed.exit_code, 2) << misnamed;
    EXPECT_NE(misnamed.err.find(".fgrview.json"), std::string::npos) << misnamed;
    EXPECT_EQ(test::directory_listing(dir()), std::vector<std::string>{"bad.fgrview.json"});
}

// `fgr video VIEW` turns around the view's target with the view's settings, and each frame file
// carries its own view: rendering it again gives the frame's bytes.
TEST_F(ViewFileCli, VideoFromAViewAndItsFramesRenderAgainFromTheirViews) {
    succeed({"render", "mandelbulb", "--width", "24", "--height", "16", "--set", "power=7", "-o",
             "a.png", "--save-view", "a.fgrview.json"});
    succeed({"video", "a.fgrview.json", "--frames", "frames", "--fps", "1", "--duration", "2"});
    EXPECT_EQ(test::directory_listing(dir() / "frames"),
              (std::vector<std::string>{"frame_00000.png", "frame_00001.png"}));
    // The same pixels (the files differ in the view they carry: a frame's precision is the
    // video's).
    EXPECT_TRUE(read_png(dir() / "a.png").rgb == read_png(dir() / "frames" / "frame_00000.png").rgb)
        << "the turn starts at the view";
    succeed({"render", "--view", "frames/frame_00001.png", "-o", "again.png"});
    EXPECT_TRUE(test::read_bytes(dir() / "frames" / "frame_00001.png") ==
                test::read_bytes(dir() / "again.png"));
}

// A view of a scene opened by path names the file, so the view renders from anywhere: here a
// text scene as `fgr new-scene --text` writes it, with no compiler involved.
TEST_F(ViewFileCli, AViewOfASceneOpenedByPathRendersFromAnotherDirectory) {
    succeed({"new-scene", "--text", "blob"});
    succeed({"render", "blob.cl", "--width", "24", "--height", "16", "-o", "blob.png",
             "--save-view", "blob.fgrview.json"});
    const json view = read_json(dir() / "blob.fgrview.json");
    EXPECT_EQ(view["scene"]["file"], (dir() / "blob.cl").lexically_normal().string());
    fs::create_directory(dir() / "elsewhere");
    const RunResult again =
        test::run_fgr({"render", "../blob.fgrview.json", "-o", "again.png"}, dir() / "elsewhere");
    ASSERT_EQ(again.exit_code, 0) << again;
    EXPECT_TRUE(test::read_bytes(dir() / "blob.png") ==
                test::read_bytes(dir() / "elsewhere" / "again.png"));
}

// A view names the environment that lit the render, so that it renders the same: the one typed,
// else the sky when the sky's settings are typed, else the scene's own, else the sky; and
// apply_view gives it back as --environment.
TEST(ViewOfRender, RecordsTheEnvironmentThatLitTheRender) {
    Scene scene = test::inline_scene("real scene_de(vec3 p, PARAMS) { return v3_length(p) - 1; }");
    scene.environment = "uniform:0.5";
    const auto recorded = [&scene](const ModeOptions& mode) {
        RenderOptions options;
        options.mode = mode;
        options.mode.mode = "path";
        const ViewFile view = view_of_render(scene, scene_request(scene, options), options);
        EXPECT_TRUE(view.path.has_value());
        RenderOptions again;
        apply_view(again, view);
        EXPECT_EQ(chosen_path_settings(again.mode, scene).environment->description,
                  chosen_path_settings(options.mode, scene).environment->description)
            << "the view renders under another environment";
        return view.path ? view.path->environment : std::string();
    };
    EXPECT_EQ(recorded(ModeOptions{}), "uniform:0.5");
    ModeOptions typed;
    typed.environment = "sky";
    EXPECT_EQ(recorded(typed), "sky");
    ModeOptions hazy;
    hazy.turbidity = 6.0f;
    EXPECT_EQ(recorded(hazy), "sky");
    scene.environment.clear();
    EXPECT_EQ(recorded(ModeOptions{}), "sky");
}

// A text scene that names its own environment, rendered without --environment, renders again
// from its view to the same bytes.
TEST_F(ViewFileCli, AViewOfASceneWithItsOwnEnvironmentRendersUnderIt) {
    test::write_text(dir() / "grey.cl",
                     "/* fgr-scene {\"id\": \"grey\", \"name\": \"Grey\", "
                     "\"environment\": \"uniform:0.25,0.5,1\"} */\n"
                     "real scene_de(vec3 p, PARAMS) { return v3_length(p) - 1.0f; }\n");
    succeed({"render", "grey.cl", "--mode", "path", "--spp", "1", "--bounces", "1", "--width", "16",
             "--height", "12", "-o", "grey.png", "--save-view", "grey.fgrview.json"});
    EXPECT_EQ(read_json(dir() / "grey.fgrview.json")["path"]["environment"], "uniform:0.25,0.5,1");
    succeed({"render", "grey.fgrview.json", "-o", "again.png"});
    EXPECT_TRUE(test::read_bytes(dir() / "grey.png") == test::read_bytes(dir() / "again.png"));
}

// Parts carry the view, and `fgr merge` passes it on: the merged image renders again as one.
TEST_F(ViewFileCli, AMergedImageCarriesTheViewOfItsParts) {
    for (const char* tile : {"1/2", "2/2"}) {
        succeed({"render", "mandelbulb", "--width", "24", "--height", "16", "--set", "power=6.5",
                 "--tile", tile, "-o", std::string("part") + tile[0] + ".exr"});
    }
    succeed({"merge", "part1.exr", "part2.exr", "-o", "merged.png"});
    succeed({"render", "--view", "merged.png", "-o", "again.png"});
    EXPECT_TRUE(read_png(dir() / "merged.png").rgb == read_png(dir() / "again.png").rgb);
}

}  // namespace
}  // namespace fgr
