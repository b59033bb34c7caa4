// SPDX-License-Identifier: Apache-2.0
// `fgr new-scene`: names derived from the id, placeholders filled, the project written all at
// once into a new or empty directory and never over anything else. (Building the result against
// an installed fgr is tests/sdk_end_to_end.sh.)
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "child_process.hpp"
#include "cli/scaffold.hpp"
#include "scene/parameters.hpp"
#include "test_files.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;

TEST(Scaffold, NamesFollowFromTheId) {
    const ScaffoldNames names = scaffold_names("my-kifs_2");
    EXPECT_EQ(names.id, "my-kifs_2");
    EXPECT_EQ(names.symbol, "my_kifs_2");
    EXPECT_EQ(names.display_name, "My Kifs 2");
}

TEST(Scaffold, RefusesIdsThePluginLoaderWouldRefuse) {
    const std::vector<std::string> bad_ids = {
        "", "My-scene", "2d", "-x", "a b", "a.b", "caf\xc3\xa9", std::string(64, 'a')};
    for (const std::string& bad : bad_ids) {
        EXPECT_THROW(scaffold_names(bad), UsageError) << "'" << bad << "'";
    }
    EXPECT_NO_THROW(scaffold_names(std::string(63, 'a')));
    try {
        scaffold_names("2d");
        ADD_FAILURE() << "'2d' was taken for a scene id";
    } catch (const UsageError& error) {
        EXPECT_STREQ(error.what(),
                     "scene name '2d' must be a scene id: a lowercase letter, then lowercase "
                     "letters, digits, '-' or '_' (at most 63)");
    }
}

TEST(Scaffold, FillsEveryPlaceholderAndLeavesOtherAtSignsAlone) {
    EXPECT_EQ(fill_template("@A@-@B@ @A@ user@example @C@", {{"A", "x"}, {"B", "@A@"}}),
              "x-@A@ x user@example @C@");
}

class ScaffoldProject : public ::testing::Test {
protected:
    test::TempDir dir_{"fgr_scaffold_test"};
};

TEST_F(ScaffoldProject, WritesTheFourFilesWithNamesFilledIn) {
    const fs::path project = dir_.path() / "my-kifs";
    const auto files = scaffold_scene("my-kifs", project, "/opt/fgr");
    ASSERT_EQ(files.size(), 4u);
    for (const char* name : {"CMakeLists.txt", "my_kifs.c", "my_kifs.cl", "README.md"}) {
        ASSERT_TRUE(fs::exists(project / name)) << name;
        const std::string text = test::read_file(project / name);
        EXPECT_EQ(text.find("@SCENE_"), std::string::npos) << name;
        EXPECT_EQ(text.find("@FGR_PREFIX@"), std::string::npos) << name;
    }
    const std::string cmake = test::read_file(project / "CMakeLists.txt");
    EXPECT_NE(cmake.find("find_package(fgr 0.1 REQUIRED HINTS \"/opt/fgr\")"), std::string::npos);
    EXPECT_NE(cmake.find("fgr_add_scene_plugin(my-kifs SOURCES my_kifs.c CL_SOURCES my_kifs.cl)"),
              std::string::npos);
    const std::string description = test::read_file(project / "my_kifs.c");
    EXPECT_NE(description.find("\"my-kifs\", \"My Kifs\""), std::string::npos);
    EXPECT_NE(description.find("#include \"my_kifs_cl.h\""), std::string::npos);
    EXPECT_NE(test::read_file(project / "my_kifs.cl").find("real scene_de(vec3 p, PARAMS)"),
              std::string::npos);
    // Nothing else was left beside it (no staging directory).
    EXPECT_EQ(std::distance(fs::directory_iterator(dir_.path()), fs::directory_iterator()), 1);
}

TEST_F(ScaffoldProject, UsesAnEmptyDirectoryButNeverOverwrites) {
    const fs::path empty = dir_.path() / "empty";
    fs::create_directory(empty);
    EXPECT_EQ(scaffold_scene("ok", empty, "/p").size(), 4u);

    const fs::path busy = dir_.path() / "busy";
    fs::create_directory(busy);
    std::ofstream(busy / "mine.txt") << "keep me";
    EXPECT_THROW(scaffold_scene("ok", busy, "/p"), UsageError);
    EXPECT_EQ(test::read_file(busy / "mine.txt"), "keep me");
    EXPECT_FALSE(fs::exists(busy / "CMakeLists.txt"));

    std::ofstream(dir_.path() / "file") << "x";
    EXPECT_THROW(scaffold_scene("ok", dir_.path() / "file", "/p"), UsageError);
}

TEST_F(ScaffoldProject, CommandLineReportsBadNamesOnOneLine) {
    test::ChildOptions options;
    options.working_dir = dir_.path();
    const test::RunResult bad =
        test::run_child(FGR_TEST_FGR_EXE, {"new-scene", "Bad Name"}, options);
    EXPECT_EQ(bad.exit_code, 2) << bad;
    EXPECT_NE(bad.err.find("fgr: error: scene name 'Bad Name' must be a scene id"),
              std::string::npos)
        << bad;
    EXPECT_FALSE(fs::exists(dir_.path() / "Bad Name"));
    const test::RunResult good =
        test::run_child(FGR_TEST_FGR_EXE, {"new-scene", "nice", "--dir", "projects/nice"}, options);
    EXPECT_EQ(good.exit_code, 0) << good;
    EXPECT_TRUE(fs::exists(dir_.path() / "projects/nice/nice.cl"));
    EXPECT_NE(good.out.find("cmake -S projects/nice -B projects/nice/build"), std::string::npos)
        << good;
}

// `fgr new-scene --text NAME`: one file, NAME.cl, that fgr opens as it is (test_cli.cpp's
// TextScenesPassFgrCheck renders and checks it).
TEST_F(ScaffoldProject, TextSceneIsOneFileFgrOpensAsItIs) {
    test::ChildOptions options;
    options.working_dir = dir_.path();
    const test::RunResult made =
        test::run_child(FGR_TEST_FGR_EXE, {"new-scene", "--text", "my-scene"}, options);
    ASSERT_EQ(made.exit_code, 0) << made;
    EXPECT_EQ(test::directory_listing(dir_.path()), std::vector<std::string>{"my-scene.cl"});
    EXPECT_NE(made.out.find("fgr render ./my-scene.cl -o my-scene.png"), std::string::npos) << made;
    const test::RunResult listed =
        test::run_child(FGR_TEST_FGR_EXE, {"list", "my-scene.cl"}, options);
    ASSERT_EQ(listed.exit_code, 0) << listed;
    EXPECT_EQ(listed.out.rfind("my-scene  My Scene - ", 0), 0u) << listed;
    EXPECT_NE(listed.out.find("text scene: my-scene.cl"), std::string::npos) << listed;
    // Never over a file that is there.
    const test::RunResult again =
        test::run_child(FGR_TEST_FGR_EXE, {"new-scene", "--text", "my-scene"}, options);
    EXPECT_EQ(again.exit_code, 2) << again;
    EXPECT_EQ(again.err, "fgr: error: './my-scene.cl' already exists\n") << again;
}

}  // namespace
}  // namespace fgr
