// Plugin discovery and loading from disk, using the fixture plugins in FGR_TEST_FIXTURE_DIR and,
// when built, the real mandelbulb plugin in FGR_TEST_PLUGIN_DIR.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "fgr/discovery.hpp"
#include "fgr/plugin_loader.hpp"

namespace fgr {
namespace {
namespace fs = std::filesystem;

const fs::path kFixtureDir = FGR_TEST_FIXTURE_DIR;
const fs::path kPluginDir = FGR_TEST_PLUGIN_DIR;

// Sets (or unsets) an environment variable for one test and restores the old value afterwards.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name)) old_value_ = old;
        set(value);
    }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;
    ~ScopedEnv() { set(old_value_ ? old_value_->c_str() : nullptr); }

private:
    void set(const char* value) {
        if (value != nullptr) {
            setenv(name_.c_str(), value, 1);
        } else {
            unsetenv(name_.c_str());
        }
    }
    std::string name_;
    std::optional<std::string> old_value_;
};

const SkippedPlugin* find_skipped(const Discovery& discovery, const std::string& file_name) {
    for (const SkippedPlugin& skipped : discovery.skipped) {
        if (skipped.file.filename() == file_name) return &skipped;
    }
    return nullptr;
}

void expect_skipped(const Discovery& discovery, const std::string& file_name,
                    const std::string& reason_part) {
    const SkippedPlugin* skipped = find_skipped(discovery, file_name);
    ASSERT_NE(skipped, nullptr) << file_name << " was not skipped";
    EXPECT_NE(skipped->reason.find(reason_part), std::string::npos)
        << file_name << ": reason was: " << skipped->reason
        << "\nexpected it to contain: " << reason_part;
}

TEST(Discovery, FindsTheGoodFixtureWithItsData) {
    const Discovery discovery = discover_scenes({kFixtureDir});
    ASSERT_EQ(discovery.scenes.size(), 1u);
    const Scene& scene = discovery.scenes[0];
    EXPECT_EQ(scene.id, "fixture-good");
    EXPECT_EQ(scene.name, "Fixture sphere");
    EXPECT_EQ(scene.plugin_file, kFixtureDir / "good_scene.so");
    EXPECT_EQ(scene.source_name, "fixture.cl");
    EXPECT_NE(scene.source.find("scene_de"), std::string::npos);
    ASSERT_EQ(scene.params.size(), 1u + builtin_param_count());
    EXPECT_EQ(scene.params[0].id, "scale");
    EXPECT_FLOAT_EQ(scene.params[0].default_value[0], 1.0f);
    EXPECT_NE(scene.find_param("iterations"), nullptr);
    ASSERT_EQ(scene.cameras.size(), 1u);
    EXPECT_EQ(scene.cameras[0].name, "front");
    EXPECT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.march.de_iterations, 8u);
}

TEST(Discovery, SkipsBrokenFixturesWithReasons) {
    const Discovery discovery = discover_scenes({kFixtureDir});
    EXPECT_EQ(discovery.skipped.size(), 5u);
    expect_skipped(discovery, "wrong_version.so", "ABI major version 2, host supports 1");
    expect_skipped(discovery, "no_entry.so", "no entry symbol 'fgr_scene_entry'");
    expect_skipped(discovery, "null_entry.so", "entry returned NULL");
    expect_skipped(discovery, "bad_param.so", "parameter 'scale': default 20 outside [0.5, 2]");
    expect_skipped(discovery, "garbage.so", "not a loadable shared library: ");
}

TEST(Discovery, FirstOfDuplicateIdsWins) {
    const fs::path dup_dir = kFixtureDir / "dup";
    const Discovery discovery = discover_scenes({kFixtureDir, dup_dir});
    ASSERT_EQ(discovery.scenes.size(), 1u);
    EXPECT_EQ(discovery.scenes[0].plugin_file, kFixtureDir / "good_scene.so");
    expect_skipped(discovery, "duplicate_id.so",
                   "duplicate scene id 'fixture-good' (already loaded from " +
                       (kFixtureDir / "good_scene.so").string() + ")");

    const Discovery reversed = discover_scenes({dup_dir, kFixtureDir});
    ASSERT_EQ(reversed.scenes.size(), 1u);
    EXPECT_EQ(reversed.scenes[0].plugin_file, dup_dir / "duplicate_id.so");
    expect_skipped(reversed, "good_scene.so", "duplicate scene id 'fixture-good'");
}

TEST(Discovery, ScansADirectoryListedTwiceOnce) {
    const Discovery discovery = discover_scenes({kFixtureDir, kFixtureDir / "." / ""});
    EXPECT_EQ(discovery.scenes.size(), 1u);
    EXPECT_EQ(find_skipped(discovery, "good_scene.so"), nullptr);
}

TEST(Discovery, IgnoresMissingDirectoriesAndNonDirectories) {
    const Discovery discovery = discover_scenes(
        {kFixtureDir / "no-such-directory", kFixtureDir / "good_scene.so", fs::path()});
    EXPECT_TRUE(discovery.scenes.empty());
    EXPECT_TRUE(discovery.skipped.empty());
}

TEST(LoadScenePlugin, LoadsAndRecordsTheFile) {
    const fs::path file = kFixtureDir / "good_scene.so";
    const LoadResult result = load_scene_plugin(file);
    ASSERT_TRUE(result.scene.has_value()) << result.error;
    EXPECT_EQ(result.scene->plugin_file, file);
    EXPECT_TRUE(result.error.empty());

    // Loading again works: the library was closed, nothing the first copy holds points into it.
    const LoadResult again = load_scene_plugin(file);
    ASSERT_TRUE(again.scene.has_value()) << again.error;
    EXPECT_EQ(again.scene->source, result.scene->source);
}

TEST(LoadScenePlugin, RefusesMissingFile) {
    const LoadResult result = load_scene_plugin(kFixtureDir / "missing.so");
    EXPECT_FALSE(result.scene.has_value());
    EXPECT_EQ(result.error.rfind("not a loadable shared library: ", 0), 0u) << result.error;
}

TEST(PluginSearchPath, EnvironmentThenExecutableThenHome) {
    const ScopedEnv plugin_path("FGR_PLUGIN_PATH", "/first::/second/dir:");
    const ScopedEnv home("HOME", "/home/tester");
    const std::vector<fs::path> expected = {"/first", "/second/dir", "/opt/fgr/" FGR_TEST_LIBDIR "/fgr/plugins",
                                            "/home/tester/.local/share/fgr/plugins"};
    EXPECT_EQ(plugin_search_path("/opt/fgr/bin"), expected);
}

TEST(PluginSearchPath, WithoutEnvironment) {
    const ScopedEnv plugin_path("FGR_PLUGIN_PATH", nullptr);
    const ScopedEnv home("HOME", nullptr);
    EXPECT_EQ(plugin_search_path("/opt/fgr/bin"), std::vector<fs::path>{"/opt/fgr/" FGR_TEST_LIBDIR "/fgr/plugins"});
}

TEST(PluginSearchPath, EnvironmentRestoredAfterScope) {
    const char* before = std::getenv("FGR_PLUGIN_PATH");
    const std::optional<std::string> saved =
        before ? std::optional<std::string>(before) : std::nullopt;
    { const ScopedEnv plugin_path("FGR_PLUGIN_PATH", "/changed"); }
    const char* after = std::getenv("FGR_PLUGIN_PATH");
    EXPECT_EQ(after ? std::optional<std::string>(after) : std::nullopt, saved);
}

TEST(ExecutableDir, IsTheTestBinarysDirectory) {
    const fs::path dir = executable_dir();
    EXPECT_TRUE(dir.is_absolute()) << dir;
    EXPECT_TRUE(fs::is_directory(dir)) << dir;
}

TEST(MandelbulbPlugin, LoadsFromThePluginDirectory) {
    const fs::path file = kPluginDir / "mandelbulb.so";
    if (!fs::exists(file)) GTEST_SKIP() << file << " not built yet";
    const LoadResult result = load_scene_plugin(file);
    ASSERT_TRUE(result.scene.has_value()) << result.error;
    EXPECT_FALSE(result.scene->id.empty());
    EXPECT_FALSE(result.scene->source.empty());
    EXPECT_FALSE(result.scene->cameras.empty());
    EXPECT_NE(result.scene->find_param("max_steps"), nullptr);
}

}  // namespace
}  // namespace fgr
