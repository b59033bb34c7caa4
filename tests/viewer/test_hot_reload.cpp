// SPDX-License-Identifier: Apache-2.0
// Pieces of the viewer's hot reload: the file watcher reports new and changed plugins (and
// watched sources) once they hold still, never what was there at the start, and a new version of a
// scene keeps the user's values of the parameters it still has. (The viewer reloading a rebuilt
// plugin or an edited .cl file is tested end to end in test_viewer.cpp.)
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "child_process.hpp"
#include "scene/parameters.hpp"
#include "scene/plugin_loader.hpp"
#include "scoped_env.hpp"
#include "test_scenes.hpp"
#include "viewer/file_watcher.hpp"

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

// IFS scene files (NAME.ifs.json) in a plugin folder are watched like plugins; other JSON is not.
TEST_F(FileWatcherTest, ReportsChangedIfsFiles) {
    write(dir_.path() / "tree.ifs.json", "v1");
    FileWatcher watcher;
    watcher.watch_directory(dir_.path());
    EXPECT_EQ(watcher.poll(), Files{});
    write(dir_.path() / "tree.ifs.json", "v2");
    write(dir_.path() / "path.json", "a camera path");
    EXPECT_EQ(watcher.poll(), Files{});
    EXPECT_EQ(watcher.poll(), Files{dir_.path() / "tree.ifs.json"});
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

// --- Reloading a plugin that stays loaded --------------------------------------------------------

// The temporary directory set to one of the test's own while alive, so the copies
// reload_scene_plugin makes (and must remove) can be counted.
class OwnTemporaryDirectory {
public:
    const fs::path& path() const { return dir_.path(); }

private:
    test::TempDir dir_{"fgr_reload_tmp"};
    test::ScopedEnv tmpdir_{"TMPDIR", dir_.path().c_str()};
};

float scale_default(const LoadResult& loaded) {
    const ParamInfo* scale = loaded.scene ? loaded.scene->find_param("scale") : nullptr;
    return scale ? scale->default_value[0] : -1.0f;
}

// nodelete_v1 and nodelete_v2 are linked with -z nodelete: once dlopen'ed they stay loaded after
// dlclose, as a C++ plugin pinned by a unique symbol does. v2 has scale 1.5 where v1 has 1.
TEST(ReloadScenePlugin, ARebuiltPluginThatStaysLoadedIsReadAfresh) {
    const fs::path fixtures = fs::path(FGR_TEST_FIXTURE_DIR) / "nodelete";
    const test::TempDir plugins("fgr_reload_plugins");
    const fs::path file = plugins.path() / "plugin.so";
    fs::copy_file(fixtures / "nodelete_v1.so", file);
    const LoadResult first = load_scene_plugin(file);  // as discovery at start-up
    ASSERT_TRUE(first.scene) << first.error;
    EXPECT_EQ(scale_default(first), 1.0f);

    // Rebuilt: the new file renamed over the old, as linkers and package managers do (the old
    // image stays intact in its unlinked file).
    fs::copy_file(fixtures / "nodelete_v2.so", plugins.path() / "plugin.so.new");
    fs::rename(plugins.path() / "plugin.so.new", file);
    // Why reloading needs a copy: dlopen of the same path returns the image still loaded.
    ASSERT_EQ(scale_default(load_scene_plugin(file)), 1.0f)
        << "dlopen no longer returns a library still loaded for its path: this test cannot fail";

    const OwnTemporaryDirectory tmp;
    const LoadResult reloaded = reload_scene_plugin(file);
    ASSERT_TRUE(reloaded.scene) << reloaded.error;
    EXPECT_EQ(scale_default(reloaded), 1.5f) << "the old image came back";
    EXPECT_EQ(reloaded.scene->plugin_file, file);
    EXPECT_TRUE(fs::is_empty(tmp.path())) << "the temporary copy was left behind";

    // Overwritten in place this time (`cp`): each reload reads the file as it is now. (No image
    // was loaded from this file itself, only from copies, so nothing mapped changes under it.)
    fs::copy_file(fixtures / "nodelete_v1.so", file, fs::copy_options::overwrite_existing);
    EXPECT_EQ(scale_default(reload_scene_plugin(file)), 1.0f);
    EXPECT_TRUE(fs::is_empty(tmp.path()));
}

TEST(ReloadScenePlugin, FailuresNameTheReasonAndLeaveNoCopy) {
    const test::TempDir plugins("fgr_reload_plugins");
    const OwnTemporaryDirectory tmp;
    const LoadResult missing = reload_scene_plugin(plugins.path() / "missing.so");
    EXPECT_FALSE(missing.scene);
    EXPECT_NE(missing.error.find("cannot read the plugin file"), std::string::npos)
        << missing.error;
    std::ofstream(plugins.path() / "text.so") << "not a library";
    const LoadResult text = reload_scene_plugin(plugins.path() / "text.so");
    EXPECT_FALSE(text.scene);
    EXPECT_NE(text.error.find("not a loadable shared library"), std::string::npos) << text.error;
    EXPECT_EQ(text.error.find("fgr-plugin-"), std::string::npos)
        << "the reason names the copy: " << text.error;
    EXPECT_TRUE(fs::is_empty(tmp.path()));
}

}  // namespace
}  // namespace fgr::viewer
