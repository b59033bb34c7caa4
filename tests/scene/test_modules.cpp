// SPDX-License-Identifier: Apache-2.0
// fgr's modules (scene/modules.hpp): the viewer, video encoding and the MPI transport are shared
// objects fgr loads when a command needs them. fgr itself must not link what they link (that was
// the point: FFmpeg's, SDL's and Open MPI's libraries cost every process start-up time); without a
// module the commands that need it fail with one clear line while the others work; a module from
// another build is refused, not called. The module-less trees are copies of the built layout
// (bin/fgr, lib/fgr/plugins) in a temporary directory.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "child_process.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;

// A copy of the built fgr in `root`/bin with the built plugins beside it, and no modules unless
// `module_file` is given: then that file is installed under each of `module_names`.
fs::path install_fgr_without_modules(const fs::path& root, const fs::path& module_file = {},
                                     const std::vector<std::string>& module_names = {}) {
    const fs::path bin = root / "bin";
    const fs::path modules = root / FGR_TEST_LIBDIR / "fgr";
    fs::create_directories(bin);
    fs::create_directories(modules);
    fs::copy_file(FGR_TEST_FGR_EXE, bin / "fgr");
    fs::create_directory_symlink(FGR_TEST_PLUGIN_DIR, modules / "plugins");
    for (const std::string& name : module_names) fs::copy_file(module_file, modules / name);
    return bin / "fgr";
}

test::RunResult run(const fs::path& fgr, const std::vector<std::string>& args, const fs::path& dir,
                    const std::map<std::string, std::optional<std::string>>& environment = {}) {
    test::ChildOptions options;
    options.working_dir = dir;
    options.environment = environment;
    options.environment["FGR_PLUGIN_PATH"] = std::nullopt;
    return test::run_child(fgr, args, options);
}

size_t lines_in(const std::string& text) {
    return static_cast<size_t>(std::count(text.begin(), text.end(), '\n'));
}

const std::vector<std::string> kVideo = {"video",   "mandelbulb", "--camera-path", "dive",
                                         "--width", "32",         "--height",      "24",
                                         "-o",      "out.mp4"};
const std::vector<std::string> kView = {"view", "mandelbulb", "--exit-after", "1"};
const std::vector<std::string> kRender = {"render",   "mandelbulb", "--width", "32",
                                          "--height", "24",         "-o",      "out.png"};

TEST(Modules, FgrItselfLoadsNeitherFfmpegNorSdlNorMpi) {
    // The dynamic loader lists what a program needs and exits (what ldd does).
    test::ChildOptions options;
    options.environment.emplace("LD_TRACE_LOADED_OBJECTS", std::string("1"));
    const test::RunResult listed = test::run_child(FGR_TEST_FGR_EXE, {}, options);
    ASSERT_TRUE(listed.exited && listed.exit_code == 0) << listed;
    ASSERT_NE(listed.out.find("libOpenCL"), std::string::npos) << "no library list:\n" << listed;
    for (const char* library : {"libavcodec", "libavformat", "libSDL2", "libOpenGL", "libmpi"}) {
        EXPECT_EQ(listed.out.find(library), std::string::npos)
            << "fgr links " << library << " again:\n"
            << listed.out;
    }
}

TEST(Modules, WithoutThemTheCommandsNeedingThemFailInOneLineAndRenderingWorks) {
    const test::TempDir dir("fgr_modules");
    const fs::path fgr = install_fgr_without_modules(dir.path());

    const test::RunResult video = run(fgr, kVideo, dir.path());
    EXPECT_TRUE(video.exited && video.exit_code != 0) << video;
    // Missing from the install, or (FGR_BUILD_VIDEO off) from the build: either way the line says
    // which package and which build option bring it.
    EXPECT_NE(video.err.find("video encoding is not"), std::string::npos) << video;
    for (const char* how : {"fgr-video", "-DFGR_BUILD_VIDEO=ON"}) {
        EXPECT_NE(video.err.find(how), std::string::npos) << video;
    }
    EXPECT_EQ(lines_in(video.err), 1u) << video;
    EXPECT_FALSE(fs::exists(dir.path() / "out.mp4"));

    const test::RunResult view = run(fgr, kView, dir.path());
    EXPECT_TRUE(view.exited && view.exit_code != 0) << view;
    EXPECT_NE(view.err.find("the viewer is not"), std::string::npos) << view;
    for (const char* how : {"fgr-viewer", "-DFGR_BUILD_VIEWER=ON"}) {
        EXPECT_NE(view.err.find(how), std::string::npos) << view;
    }
    EXPECT_EQ(lines_in(view.err), 1u) << view;

    const test::RunResult render = run(fgr, kRender, dir.path());
    EXPECT_TRUE(render.exited && render.exit_code == 0) << render;
    EXPECT_TRUE(fs::exists(dir.path() / "out.png"));
}

TEST(Modules, AModuleFromAnotherBuildIsRefusedNotCalled) {
    const test::TempDir dir("fgr_modules_stale");
    const fs::path fgr = install_fgr_without_modules(
        dir.path(), fs::path(FGR_TEST_FIXTURE_DIR) / "modules" / "stale_module.so",
        {"libfgr_video_ffmpeg.so", "libfgr_viewer.so", "libfgr_mpi.so"});
    // The stale tables hold null functions: calling one would crash, not fail in one line.
    for (const auto& args : {kVideo, kView}) {
        const test::RunResult refused = run(fgr, args, dir.path());
        EXPECT_TRUE(refused.exited && refused.exit_code != 0) << refused;
        EXPECT_NE(refused.err.find("belongs to another build of fgr (interface version 0"),
                  std::string::npos)
            << refused;
        EXPECT_EQ(lines_in(refused.err), 1u) << refused;
    }
#ifdef FGR_HAVE_MPI
    // As if mpirun had started this process as rank 0 of two: the transport is the stale module.
    const test::RunResult mpi = run(fgr, kRender, dir.path(),
                                    {{"OMPI_COMM_WORLD_SIZE", "2"}, {"OMPI_COMM_WORLD_RANK", "0"}});
    EXPECT_TRUE(mpi.exited && mpi.exit_code != 0) << mpi;
    EXPECT_NE(mpi.err.find("libfgr_mpi.so"), std::string::npos) << mpi;
    EXPECT_NE(mpi.err.find("another build"), std::string::npos) << mpi;
    EXPECT_FALSE(fs::exists(dir.path() / "out.png"));
#endif
}

}  // namespace
}  // namespace fgr
