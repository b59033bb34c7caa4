// Pieces of the viewer's hot reload: the file watcher reports new and changed plugins (and
// watched sources) once they hold still, never what was there at the start, and a new version of a
// scene keeps the user's values of the parameters it still has. (The viewer reloading a rebuilt
// plugin or an edited .cl file is tested end to end in test_viewer.cpp.)
#include <chrono>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "child_process.hpp"
#include "fgr/parameters.hpp"
#include "fgr/viewer/file_watcher.hpp"
#include "test_scenes.hpp"

namespace fgr::viewer {
namespace {

namespace fs = std::filesystem;
using Files = std::vector<fs::path>;

class FileWatcherTest : public ::testing::Test {
protected:
    // Writes `text` and moves the file's time on by `tick` seconds, so a change is visible even
    // on file systems with coarse timestamps.
    void write(const fs::path& file, const std::string& text) {
        std::ofstream(file, std::ios::binary) << text;
        fs::last_write_time(file, start_ + std::chrono::seconds(++tick_));
    }
    test::TempDir dir_{"fgr_watch_test"};
    fs::file_time_type start_ = fs::file_time_type::clock::now();
    int tick_ = 0;
};

TEST_F(FileWatcherTest, ReportsNewAndChangedPluginsOnceTheyHoldStill) {
    write(dir_.path() / "old.so", "v1");
    FileWatcher watcher;
    watcher.watch_directory(dir_.path());
    EXPECT_EQ(watcher.poll(), Files{}) << "what was there at the start is not news";

    write(dir_.path() / "new.so", "v1");
    write(dir_.path() / "notes.txt", "not a plugin");
    EXPECT_EQ(watcher.poll(), Files{}) << "a file seen once may still be being written";
    EXPECT_EQ(watcher.poll(), Files{dir_.path() / "new.so"});
    EXPECT_EQ(watcher.poll(), Files{}) << "reported once";

    write(dir_.path() / "old.so", "version 2");
    EXPECT_EQ(watcher.poll(), Files{});
    write(dir_.path() / "old.so", "version 2, still copying");
    EXPECT_EQ(watcher.poll(), Files{}) << "changed again: not stable yet";
    EXPECT_EQ(watcher.poll(), Files{dir_.path() / "old.so"});
    EXPECT_EQ(watcher.poll(), Files{});
}

TEST_F(FileWatcherTest, WatchesSingleFilesAndDirectoriesThatAppearLater) {
    const fs::path later = dir_.path() / "later";
    const fs::path source = dir_.path() / "scene.cl";
    FileWatcher watcher;
    watcher.watch_directory(later);
    watcher.watch_file(source);
    EXPECT_EQ(watcher.poll(), Files{});
    fs::create_directory(later);
    write(later / "a.so", "x");
    write(source, "real scene_de(vec3 p, PARAMS) { return v3_length(p) - 1.0f; }");
    watcher.poll();
    Files changed = watcher.poll();
    std::sort(changed.begin(), changed.end());
    EXPECT_EQ(changed, (Files{later / "a.so", source}));
    fs::remove(source);
    EXPECT_EQ(watcher.poll(), Files{}) << "a removed file is not a change to load";
    write(source, "again");
    watcher.poll();
    EXPECT_EQ(watcher.poll(), Files{source}) << "a file that comes back is new again";
}

TEST(CarryParamValues, KeepsValuesOfParametersThatStillExist) {
    Scene before = test::sphere_scene();
    ParamInfo twist;
    twist.id = "twist";
    twist.type = ParamType::Float;
    twist.min_value = -1.0f;
    twist.max_value = 1.0f;
    before.params.insert(before.params.begin(), twist);
    std::vector<float> values = default_param_values(before);
    set_param_from_text(before, values, "radius=1.5");
    set_param_from_text(before, values, "twist=0.5");
    set_param_from_text(before, values, "max_steps=99");

    Scene after = test::sphere_scene();  // twist gone; radius now limited to [0.1, 1]
    after.params.front().max_value = 1.0f;
    // An untouched parameter follows the new version's default.
    after.params.back().default_value[0] = 7.0f;  // the last built-in, left at its default
    const std::string untouched = after.params.back().id;
    ParamInfo tint;
    tint.id = "tint";
    tint.type = ParamType::Colour;
    tint.default_value = {0.25f, 0.5f, 0.75f};
    after.params.push_back(tint);
    const std::vector<float> carried = carry_param_values(before, values, after);
    ASSERT_EQ(carried.size(), default_param_values(after).size());
    EXPECT_EQ(param_value(after, carried, "radius"), 1.0f) << "kept, clamped to the new range";
    EXPECT_EQ(param_value(after, carried, "max_steps"), 99.0f);
    EXPECT_EQ(param_value(after, carried, "tint"), 0.25f) << "new parameter: its default";
    EXPECT_EQ(param_value(after, carried, untouched), 7.0f) << "untouched: the new default";

    ParamInfo retyped = after.params.front();
    retyped.type = ParamType::Vec3;
    after.params.front() = retyped;
    after.params.front().default_value = {0.2f, 0.3f, 0.4f};
    const std::vector<float> reset = carry_param_values(before, values, after);
    EXPECT_EQ(param_value(after, reset, "radius"), 0.2f) << "a changed type starts from default";
}

}  // namespace
}  // namespace fgr::viewer
