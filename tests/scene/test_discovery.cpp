// SPDX-License-Identifier: Apache-2.0
// Plugin discovery and loading from disk, using the fixture plugins in FGR_TEST_FIXTURE_DIR and,
// when built, the real mandelbulb plugin in FGR_TEST_PLUGIN_DIR.

#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "fuzz_rng.hpp"
#include "json_mutation.hpp"
#include "scene/discovery.hpp"
#include "scene/plugin_loader.hpp"
#include "scene/scene_index.hpp"
#include "scoped_env.hpp"
#include "test_files.hpp"

namespace fgr {
namespace {
namespace fs = std::filesystem;

using test::kFixtureDir;
using test::kPluginDir;

const SkippedPlugin* find_skipped_named(const Discovery& discovery, const std::string& file_name) {
    for (const SkippedPlugin& skipped : discovery.skipped) {
        if (skipped.file.filename() == file_name) return &skipped;
    }
    return nullptr;
}

void expect_skipped(const Discovery& discovery, const std::string& file_name,
                    const std::string& reason_part) {
    const SkippedPlugin* skipped = find_skipped_named(discovery, file_name);
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
    EXPECT_EQ(find_skipped_named(discovery, "good_scene.so"), nullptr);
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
    const test::ScopedEnv plugin_path("FGR_PLUGIN_PATH", "/first::/second/dir:");
    const test::ScopedEnv home("HOME", "/home/tester");
    const std::vector<fs::path> expected = {"/first", "/second/dir",
                                            "/opt/fgr/" FGR_TEST_LIBDIR "/fgr/plugins",
                                            "/home/tester/.local/share/fgr/plugins"};
    EXPECT_EQ(plugin_search_path("/opt/fgr/bin"), expected);
}

TEST(PluginSearchPath, WithoutEnvironment) {
    const test::ScopedEnv plugin_path("FGR_PLUGIN_PATH", nullptr);
    const test::ScopedEnv home("HOME", nullptr);
    EXPECT_EQ(plugin_search_path("/opt/fgr/bin"),
              std::vector<fs::path>{"/opt/fgr/" FGR_TEST_LIBDIR "/fgr/plugins"});
}

TEST(PluginSearchPath, EnvironmentRestoredAfterScope) {
    const char* before = std::getenv("FGR_PLUGIN_PATH");
    const std::optional<std::string> saved =
        before ? std::optional<std::string>(before) : std::nullopt;
    { const test::ScopedEnv plugin_path("FGR_PLUGIN_PATH", "/changed"); }
    const char* after = std::getenv("FGR_PLUGIN_PATH");
    EXPECT_EQ(after ? std::optional<std::string>(after) : std::nullopt, saved);
}

TEST(ExecutableDir, IsTheTestBinarysDirectory) {
    const fs::path dir = executable_dir();
    EXPECT_TRUE(dir.is_absolute()) << dir;
    EXPECT_TRUE(fs::is_directory(dir)) << dir;
}

// --- Finding one scene by id: discover_scene and the scene index --------------------------------

// An IFS scene file `name` in `directory` holding scene `id`, padded with `padding` spaces (to
// give two versions of a file different sizes).
fs::path write_ifs_scene(const fs::path& directory, const std::string& name, const std::string& id,
                         std::size_t padding = 0) {
    const fs::path file = directory / name;
    std::ofstream(file) << R"({"format": "fgr-ifs", "version": 1, "id": ")" << id
                        << R"(", "name": "Test", "maps": [{"scale": 0.5},)"
                        << R"( {"scale": 0.5, "translate": [1, 0, 0]}]})"
                        << std::string(padding, ' ');
    return file;
}

// Rewrites `file` in place (same inode) with contents every load refuses, of the same size and
// modification time: a file the index vouches for that would be refused if it were loaded.
void make_refused_keeping_stamp(const fs::path& file) {
    const std::uintmax_t size = fs::file_size(file);
    const fs::file_time_type modified = fs::last_write_time(file);
    std::ofstream(file, std::ios::in | std::ios::out) << "{" << std::string(size - 2, ' ') << "}";
    fs::last_write_time(file, modified);
    ASSERT_EQ(fs::file_size(file), size);
}

struct SceneDirectories {
    test::TempDir root{"fgr_scene_index"};
    fs::path first = root.path() / "first";
    fs::path second = root.path() / "second";
    fs::path index = root.path() / "cache" / kSceneIndexName;
    SceneDirectories() {
        fs::create_directories(first);
        fs::create_directories(second);
    }
    std::vector<fs::path> search_path() const { return {first, second}; }
};

TEST(DiscoverScene, FindsTheFileDiscoveryWouldPickWithOrWithoutTheIndex) {
    SceneDirectories dirs;
    write_ifs_scene(dirs.first, "a.ifs.json", "other");
    const fs::path winner = write_ifs_scene(dirs.first, "b.ifs.json", "target");
    write_ifs_scene(dirs.first, "c.ifs.json", "target");   // a duplicate later in the folder
    write_ifs_scene(dirs.second, "a.ifs.json", "target");  // and one in a later folder
    const Discovery all = discover_scenes(dirs.search_path());
    ASSERT_EQ(all.scenes.size(), 2u);
    ASSERT_EQ(all.scenes[1].id, "target");
    ASSERT_EQ(all.scenes[1].plugin_file, winner);
    // Without an index, building it, then through it.
    for (const fs::path& index : {fs::path(), dirs.index, dirs.index}) {
        const Discovery found = discover_scene(dirs.search_path(), "target", index);
        ASSERT_EQ(found.scenes.size(), 1u) << index;
        EXPECT_EQ(found.scenes[0].plugin_file, winner) << index;
        EXPECT_TRUE(found.skipped.empty()) << index;
    }
    EXPECT_EQ(SceneIndex::read(dirs.index).size(), 2u);  // a and b: the files up to the winner
}

TEST(DiscoverScene, TheIndexSparesLoadingTheFilesOfOtherScenes) {
    SceneDirectories dirs;
    const fs::path other = write_ifs_scene(dirs.first, "a.ifs.json", "other");
    write_ifs_scene(dirs.first, "b.ifs.json", "target");
    ASSERT_EQ(discover_scene(dirs.search_path(), "target", dirs.index).scenes.size(), 1u);
    make_refused_keeping_stamp(other);
    // Loading a.ifs.json now would refuse it: without the index it is tried and refused...
    const Discovery unindexed = discover_scene(dirs.search_path(), "target", {});
    ASSERT_EQ(unindexed.skipped.size(), 1u);
    EXPECT_EQ(unindexed.skipped[0].file, other);
    // ...with it, it is never opened.
    const Discovery indexed = discover_scene(dirs.search_path(), "target", dirs.index);
    ASSERT_EQ(indexed.scenes.size(), 1u);
    EXPECT_EQ(indexed.scenes[0].id, "target");
    EXPECT_TRUE(indexed.skipped.empty());
}

TEST(DiscoverScene, AFileChangedSinceItWasIndexedIsLoadedAgain) {
    SceneDirectories dirs;
    const fs::path first = write_ifs_scene(dirs.first, "a.ifs.json", "other");
    write_ifs_scene(dirs.first, "b.ifs.json", "target");
    ASSERT_EQ(discover_scene(dirs.search_path(), "target", dirs.index).scenes.size(), 1u);
    // a.ifs.json now holds the scene: it comes first, so it is the one discovery picks.
    write_ifs_scene(dirs.first, "a.ifs.json", "target", 7);
    fs::last_write_time(first, fs::last_write_time(first) + std::chrono::seconds(2));
    const Discovery found = discover_scene(dirs.search_path(), "target", dirs.index);
    ASSERT_EQ(found.scenes.size(), 1u);
    EXPECT_EQ(found.scenes[0].plugin_file, first);
    const std::optional<FileStamp> stamp = file_stamp(first);
    ASSERT_TRUE(stamp);
    EXPECT_EQ(SceneIndex::read(dirs.index).id_of(first, *stamp), "target");
}

TEST(DiscoverScene, AnUnknownIdGivesEverySceneForTheError) {
    SceneDirectories dirs;
    write_ifs_scene(dirs.first, "a.ifs.json", "one");
    write_ifs_scene(dirs.second, "b.ifs.json", "two");
    std::ofstream(dirs.second / "c.ifs.json") << "{}";
    const Discovery found = discover_scene(dirs.search_path(), "three", dirs.index);
    ASSERT_EQ(found.scenes.size(), 2u);
    EXPECT_EQ(found.skipped.size(), 1u);
    // The nearest id when one is near, else where to find them; and the file refused.
    EXPECT_EQ(unknown_scene_message(found, "three"),
              "unknown scene 'three' (`fgr list` lists the scenes; refused: " +
                  (dirs.second / "c.ifs.json").string() + " (" + found.skipped[0].reason + "))");
    EXPECT_EQ(unknown_scene_message(found, "tow"),
              "unknown scene 'tow' (refused: " + (dirs.second / "c.ifs.json").string() + " (" +
                  found.skipped[0].reason + ")); did you mean 'two'?");
}

TEST(DiscoverScene, FilesRefusedBeforeTheSceneAreReported) {
    SceneDirectories dirs;
    std::ofstream(dirs.first / "a.ifs.json") << "{}";
    write_ifs_scene(dirs.first, "b.ifs.json", "target");
    for (int run = 0; run < 2; ++run) {  // refused files are not indexed: tried again each time
        const Discovery found = discover_scene(dirs.search_path(), "target", dirs.index);
        ASSERT_EQ(found.scenes.size(), 1u);
        ASSERT_EQ(found.skipped.size(), 1u);
        EXPECT_EQ(found.skipped[0].file, dirs.first / "a.ifs.json");
    }
}

TEST(DiscoverScene, ADamagedIndexIsRebuiltAndRemovedFilesLeaveIt) {
    SceneDirectories dirs;
    const fs::path gone = write_ifs_scene(dirs.first, "a.ifs.json", "other");
    write_ifs_scene(dirs.first, "b.ifs.json", "target");
    fs::create_directories(dirs.index.parent_path());
    for (const char* damage : {"not json", "[]", R"({"format": "fgr-scene-index", "version": 1,
                                                    "files": [{"path": 3}]})"}) {
        std::ofstream(dirs.index) << damage;
        EXPECT_EQ(SceneIndex::read(dirs.index).size(), 0u) << damage;
        ASSERT_EQ(discover_scene(dirs.search_path(), "target", dirs.index).scenes.size(), 1u);
        EXPECT_EQ(SceneIndex::read(dirs.index).size(), 2u) << damage;
    }
    fs::remove(gone);
    ASSERT_EQ(discover_scene(dirs.search_path(), "target", dirs.index).scenes.size(), 1u);
    EXPECT_EQ(SceneIndex::read(dirs.index).size(), 1u);
}

// 10^4 seeded damaged indexes (FGR_FUZZ_CASES, FGR_FUZZ_SEED; a failure prints its seed): a valid
// index with its text, structure or values mutated. Parsing one never throws or crashes, and a
// search through it, written to its file, still finds the scene (every 500th case, as that writes
// and loads files).
TEST(FuzzSceneIndex, ADamagedIndexIsReadOrDroppedNeverACrash) {
    SceneDirectories dirs;
    write_ifs_scene(dirs.first, "a.ifs.json", "other");
    write_ifs_scene(dirs.first, "b.ifs.json", "target");
    ASSERT_EQ(discover_scene(dirs.search_path(), "target", dirs.index).scenes.size(), 1u);
    const std::string valid = test::read_file(dirs.index);
    ASSERT_EQ(SceneIndex::read(dirs.index).size(), 2u);
    const std::uint64_t base = test::fuzz_base_seed(0x5363656e65496478);  // "SceneIdx"
    const std::uint64_t cases = test::fuzz_case_count();
    for (std::uint64_t i = 0; i < cases; ++i) {
        const std::uint64_t seed = base + i;
        test::FuzzRng rng(seed);
        std::string text = valid;
        test::mutate_document(text, rng, rng.range(1, 3));
        std::string problem;
        ASSERT_NO_THROW((void)SceneIndex::parse(text, problem)) << "seed " << seed;
        ASSERT_EQ(problem.find('\n'), std::string::npos) << "seed " << seed << ": " << problem;
        if (i % 500 != 0) continue;
        test::write_text(dirs.index, text);
        ASSERT_NO_THROW((void)SceneIndex::read(dirs.index)) << "seed " << seed;
        // An index that names another id for the file is stale data, not a crash: the search then
        // scans everything, and still finds it.
        const Discovery found = discover_scene(dirs.search_path(), "target", dirs.index);
        ASSERT_TRUE(std::any_of(found.scenes.begin(), found.scenes.end(),
                                [](const Scene& scene) { return scene.id == "target"; }))
            << "seed " << seed;
    }
}

// --- Entries named like scene files that are no file to read -------------------------------------

// A Unix socket bound at `file` (closed at once: the entry stays).
void make_socket(const fs::path& file) {
    const int handle = socket(AF_UNIX, SOCK_STREAM, 0);
    ASSERT_GE(handle, 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    ASSERT_LT(file.native().size(), sizeof(address.sun_path));
    std::copy(file.native().begin(), file.native().end(), address.sun_path);
    ASSERT_EQ(bind(handle, reinterpret_cast<const sockaddr*>(&address), sizeof(address)), 0);
    close(handle);
}

// A plugin folder whose scene-named entries are a FIFO, a directory, a socket, a loop of links
// and a dangling link, beside one good scene: each odd entry is skipped with its own reason, never
// opened (a FIFO opened for reading would wait for a writer forever), by the full scan and by the
// search for one id alike.
TEST(Discovery, EntriesThatAreNoRegularFileAreSkippedEachWithWhy) {
    SceneDirectories dirs;
    write_ifs_scene(dirs.first, "z.ifs.json", "target");
    ASSERT_EQ(mkfifo((dirs.first / "fifo.ifs.json").c_str(), 0600), 0);
    fs::create_directories(dirs.first / "folder.so");
    fs::create_symlink("loop_b.formula.json", dirs.first / "loop_a.formula.json");
    fs::create_symlink("loop_a.formula.json", dirs.first / "loop_b.formula.json");
    fs::create_symlink("missing.ifs.json", dirs.first / "dangling.ifs.json");
    // Short: a socket's path has a limit of about 100 bytes.
    test::TempDir short_root{"fgr_sock"};
    make_socket(short_root.path() / "s.cl");
    // First, so that the search for one id passes it on its way to the scene.
    const std::vector<fs::path> search_path = {short_root.path(), dirs.first};

    const auto expect_all_skipped = [&](const Discovery& found) {
        ASSERT_EQ(found.scenes.size(), 1u);
        EXPECT_EQ(found.scenes[0].id, "target");
        EXPECT_EQ(found.skipped.size(), 6u);
        expect_skipped(found, "fifo.ifs.json", "not a regular file: a FIFO");
        expect_skipped(found, "folder.so", "not a regular file: a directory");
        expect_skipped(found, "s.cl", "not a regular file: a socket");
        expect_skipped(found, "loop_a.formula.json",
                       "not a regular file: a symbolic link that cannot be followed (");
        expect_skipped(found, "loop_b.formula.json", "a symbolic link that cannot be followed");
        expect_skipped(found, "dangling.ifs.json", "a symbolic link that cannot be followed");
    };
    expect_all_skipped(discover_scenes(search_path));
    for (int run = 0; run < 2; ++run) {
        expect_all_skipped(discover_scene(search_path, "target", dirs.index));
    }
}

// A file name with a newline and a terminal escape in it is shown escaped in the refusal, which
// stays one line.
TEST(Discovery, ControlCharactersInAFileNameAreShownEscaped) {
    SceneDirectories dirs;
    std::ofstream(dirs.first / "bad\n\x1b[31mname.ifs.json") << "{}";
    const Discovery found = discover_scenes(dirs.search_path());
    ASSERT_EQ(found.skipped.size(), 1u);
    const std::string message = unknown_scene_message(found, "bad");
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.find('\x1b'), std::string::npos) << message;
    EXPECT_NE(message.find("bad\\n\\x1b[31mname.ifs.json"), std::string::npos) << message;
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
