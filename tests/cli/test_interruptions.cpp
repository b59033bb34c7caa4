// SPDX-License-Identifier: Apache-2.0
// A signal during a command that writes leaves no file behind: neither the output nor a temporary
// or partial file (util/interruption.hpp). Each case signals fgr at a moment it observed: with
// FGR_TEST_HOLD set, fgr waits at that moment (a video's first frame encoded, a merge's first band
// or frame written) until the signal arrives, so the command can never finish first. Tiled
// renders are tested beside the tile store (output/test_tiled_still.cpp).
#include <gtest/gtest.h>
#include <signal.h>

#include <filesystem>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "image/image_io.hpp"
#include "test_files.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;

class InterruptedCommand : public ::testing::Test {
protected:
    // fgr `args` held at `event`; sent `signal` once it says it holds there.
    test::RunResult signalled(const std::vector<std::string>& args, const std::string& event,
                              int signal) {
        test::ChildOptions options;
        options.working_dir = dir();
        options.environment["FGR_TEST_HOLD"] = event;
        options.watch = [signal, event](pid_t pid, const std::string& err) {
            if (err.find("holding after the first " + event) == std::string::npos) return false;
            ::kill(pid, signal);
            return true;
        };
        return test::run_fgr(args, options);
    }

    const fs::path& dir() const { return dir_.path(); }

private:
    test::TempDir dir_{"fgr_interrupted"};
};

// SIGTERM once was not caught by fgr video, which left its .v.mp4.partial.
TEST_F(InterruptedCommand, SigtermDuringAVideoLeavesNoFile) {
    const test::RunResult run =
        signalled({"video", "mandelbulb", "--camera-path", "orbit", "--width", "32", "--height",
                   "24", "--fps", "4", "--duration", "1", "-o", "v.mp4"},
                  "frame", SIGTERM);
    ASSERT_TRUE(run.exited) << run;
    EXPECT_EQ(run.exit_code, 128 + SIGTERM) << run;
    EXPECT_NE(run.err.find("interrupted: no video written to 'v.mp4'"), std::string::npos) << run;
    EXPECT_TRUE(test::directory_listing(dir()).empty())
        << ::testing::PrintToString(test::directory_listing(dir()));
}

// fgr merge once caught no signal, and its temporary output stayed. A merge does not stop
// midway: the signal removes the temporary and ends it as the signal does.
TEST_F(InterruptedCommand, SigtermDuringAMergeLeavesNoFile) {
    const test::RunResult part = test::run_fgr(
        {"render", "menger", "--width", "32", "--height", "24", "--part", "-o", "p.exr"}, dir());
    ASSERT_EQ(part.exit_code, 0) << part;
    const test::RunResult run = signalled({"merge", "p.exr", "-o", "m.png"}, "merge", SIGTERM);
    EXPECT_EQ(run.term_signal, SIGTERM) << run;
    EXPECT_EQ(test::directory_listing(dir()), std::vector<std::string>{"p.exr"});
}

TEST_F(InterruptedCommand, CtrlCDuringAMergeOfFramesLeavesNoFile) {
    fs::create_directory(dir() / "frames");
    for (int i = 0; i < 3; ++i) {
        const Image8 frame{32, 24, std::vector<uint8_t>(32 * 24 * 3, uint8_t(40 * i))};
        write_png(dir() / "frames" / ("frame_0000" + std::to_string(i) + ".png"), frame);
    }
    const test::RunResult run =
        signalled({"merge", "--frames", "frames", "-o", "v.mp4"}, "merge", SIGINT);
    EXPECT_EQ(run.term_signal, SIGINT) << run;
    EXPECT_EQ(test::directory_listing(dir()), std::vector<std::string>{"frames"});
    EXPECT_EQ(test::directory_listing(dir() / "frames").size(), 3u);
}

}  // namespace
}  // namespace fgr
