// SPDX-License-Identifier: Apache-2.0
// fgr under MPI (host/distributed). In process: results that arrive out of order are handed on
// in task order, a farm of one process runs every task, frames and tiles cross the wire intact.
// Then `mpirun -np 3` on this machine (loopback, oversubscribed).
// A shaded still shared out in tiles equals the single-process render byte for byte, whichever
// ranks render; a path-traced still over 3 ranks is the mean of the three seeds' renders with 3x
// the samples, the same file run to run, and agrees with one process taking all the samples
// within 3 standard errors; a video over 3 ranks has every frame once and in order; a rank that
// cannot open its device, or that is killed, ends the job at once with one message naming it,
// nothing written.
#include <gtest/gtest.h>
#include <signal.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "distributed/frame_wire.hpp"
#include "distributed/task_farm.hpp"
#include "image/hdr_io.hpp"
#include "test_files.hpp"
#include "video_decoding.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;

#ifdef FGR_TEST_MPIEXEC
constexpr const char* kMpiexec = FGR_TEST_MPIEXEC;
#else
constexpr const char* kMpiexec = nullptr;
#endif

// The options every run gets: as many ranks as asked on 2 cores, shared memory between them and
// nothing else (no network), and root allowed (CI runs as root).
std::vector<std::string> mpirun_options() {
    return {"--oversubscribe",
            "--mca",
            "btl",
            "self,vader",
            "--mca",
            "btl_vader_single_copy_mechanism",
            "none"};
}

// Runs mpirun with the programs of `ranks` (MPMD: one fgr command line per rank), in `dir`; a
// command line that starts with "env" runs fgr under /usr/bin/env (for a variable of that rank
// alone: "env", "NAME=VALUE", fgr's arguments...). `watch` as ChildOptions::watch.
test::RunResult run_mpi(const std::vector<std::vector<std::string>>& ranks, const fs::path& dir,
                        bool rank0_renders = true,
                        std::function<bool(pid_t, const std::string&)> watch = {}) {
    std::vector<std::string> args = mpirun_options();
    for (size_t r = 0; r < ranks.size(); ++r) {
        if (r > 0) args.push_back(":");
        args.insert(args.end(), {"-np", "1"});
        auto rest = ranks[r].begin();
        if (rest != ranks[r].end() && *rest == "env") {
            args.insert(args.end(), {"/usr/bin/env", *++rest});
            ++rest;
        }
        args.push_back(FGR_TEST_FGR_EXE);
        args.insert(args.end(), rest, ranks[r].end());
    }
    test::ChildOptions options;
    options.working_dir = dir;
    options.watch = std::move(watch);
    options.environment["FGR_PLUGIN_PATH"] = std::nullopt;
    options.environment["OMPI_ALLOW_RUN_AS_ROOT"] = "1";
    options.environment["OMPI_ALLOW_RUN_AS_ROOT_CONFIRM"] = "1";
    options.environment["FGR_MPI_RANK0_RENDERS"] = rank0_renders ? "1" : "0";
    options.timeout = std::chrono::seconds(180);
    return test::run_child(kMpiexec, args, options);
}

test::RunResult run_mpi_same(int ranks, const std::vector<std::string>& args, const fs::path& dir,
                             bool rank0_renders = true) {
    return run_mpi(std::vector<std::vector<std::string>>(size_t(ranks), args), dir, rank0_renders);
}

// The numbers after "mpi_tasks_by_rank": rank -> tasks.
std::map<int, long> tasks_by_rank(const std::string& out) {
    std::map<int, long> tasks;
    std::smatch line;
    if (!std::regex_search(out, line, std::regex("mpi_tasks_by_rank ([0-9: ]+)"))) return tasks;
    const std::string text = line[1];
    const std::regex pair("([0-9]+):([0-9]+)");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), pair);
         it != std::sregex_iterator(); ++it) {
        tasks[std::stoi((*it)[1])] = std::stol((*it)[2]);
    }
    return tasks;
}

long printed_number(const std::string& out, const std::string& key) {
    std::smatch match;
    if (!std::regex_search(out, match, std::regex(key + " ([0-9]+)"))) return -1;
    return std::stol(match[1]);
}

TEST(InTaskOrder, HandsResultsOnInTaskOrderWhateverOrderTheyArriveIn) {
    std::vector<int64_t> handed;
    InTaskOrder in_order(
        [&](int64_t task, std::vector<uint8_t>&& result) {
            EXPECT_EQ(result, std::vector<uint8_t>{uint8_t(task)});
            handed.push_back(task);
        },
        3);
    for (int64_t task : {5, 3, 7, 4, 6}) in_order.add(task, {uint8_t(task)});
    EXPECT_EQ(handed, (std::vector<int64_t>{3, 4, 5, 6, 7}));
    EXPECT_EQ(in_order.held(), 0u);
    EXPECT_THROW(in_order.add(4, {}), std::logic_error);  // a task delivered twice
}

TEST(TaskFarm, AloneItRunsEveryTaskInTheOrderGiven) {
    std::vector<int64_t> done;
    const FarmOutcome outcome = run_farm(
        Cluster::current(), {4, 1, 9},
        [](int64_t task) { return std::vector<uint8_t>(size_t(task), 7); },
        [&](int64_t task, std::vector<uint8_t>&& bytes) {
            EXPECT_EQ(bytes.size(), size_t(task));
            done.push_back(task);
        });
    EXPECT_TRUE(outcome.finished);
    EXPECT_EQ(done, (std::vector<int64_t>{4, 1, 9}));
    EXPECT_EQ(outcome.tasks_by_rank, std::vector<long>{3});
}

TEST(FrameWire, FramesAndTilesCrossIntact) {
    Frame frame;
    frame.image = {3, 2, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18}};
    frame.linear = {0.5f, 1.5f, -2.0f};
    frame.depth = {1.0f, -1.0f};
    frame.alpha = {0.25f};
    frame.samples = 7;
    frame.hits = 5;
    const Frame back = frame_from_bytes(frame_to_bytes(frame));
    EXPECT_EQ(back.image.width, 3);
    EXPECT_EQ(back.image.height, 2);
    EXPECT_EQ(back.image.rgb, frame.image.rgb);
    EXPECT_EQ(back.linear, frame.linear);
    EXPECT_EQ(back.depth, frame.depth);
    EXPECT_EQ(back.alpha, frame.alpha);
    EXPECT_TRUE(back.albedo.empty());
    EXPECT_EQ(back.samples, 7);
    EXPECT_EQ(back.hits, 5);
    std::vector<uint8_t> bytes = frame_to_bytes(frame);
    bytes.pop_back();
    EXPECT_THROW(frame_from_bytes(bytes), std::runtime_error);  // cut short

    const EncodedTile tile{{9, 8, 7}, 2};
    const EncodedTile tile_back = tile_from_bytes(tile_to_bytes(tile));
    EXPECT_EQ(tile_back.rows, tile.rows);
    EXPECT_EQ(tile_back.hits, 2);
}

class MpiTest : public ::testing::Test {
protected:
    void SetUp() override {
        if (!kMpiexec) GTEST_SKIP() << "fgr was built without MPI";
    }
    test::TempDir temp{"fgr_mpi"};
    const fs::path& dir() const { return temp.path(); }
};

TEST_F(MpiTest, AShadedStillOverThreeRanksEqualsTheSingleProcessRender) {
    const std::vector<std::string> base = {"render", "mandelbulb", "--width",
                                           "200",    "--height",   "150"};
    auto with = [&](std::vector<std::string> extra) {
        std::vector<std::string> args = base;
        args.insert(args.end(), extra.begin(), extra.end());
        return args;
    };
    ASSERT_EQ(test::run_fgr(with({"-o", "one.png"}), dir()).exit_code, 0);
    // The workers alone render: every tile crossed the wire and was placed by rank 0.
    const test::RunResult shared = run_mpi_same(3, with({"-o", "three.png"}), dir(), false);
    ASSERT_EQ(shared.exit_code, 0) << shared;
    EXPECT_EQ(test::read_file(dir() / "three.png"), test::read_file(dir() / "one.png"));
    const std::map<int, long> tasks = tasks_by_rank(shared.out);
    ASSERT_EQ(tasks.size(), 3u) << shared.out;
    EXPECT_EQ(tasks.at(0), 0);
    EXPECT_EQ(tasks.at(1) + tasks.at(2), printed_number(shared.out, "tiles")) << shared.out;
    EXPECT_FALSE(fs::exists(dir() / "three.png.fgr-tiles"));

    // Float layers too, with rank 0 rendering beside the workers.
    const std::vector<std::string> layers = {"--alpha", "--aov", "albedo,normal,depth"};
    std::vector<std::string> single = with({"-o", "one.exr"}), mpi = with({"-o", "three.exr"});
    single.insert(single.end(), layers.begin(), layers.end());
    mpi.insert(mpi.end(), layers.begin(), layers.end());
    ASSERT_EQ(test::run_fgr(single, dir()).exit_code, 0);
    const test::RunResult exr = run_mpi_same(3, mpi, dir());
    ASSERT_EQ(exr.exit_code, 0) << exr;
    EXPECT_EQ(test::read_file(dir() / "three.exr"), test::read_file(dir() / "one.exr"));
}

std::vector<std::string> path_args(int spp, int seed, const std::string& output) {
    return {"render", "mandelbulb",         "--mode", "path",  "--width",
            "96",     "--height",           "72",     "--spp", std::to_string(spp),
            "--seed", std::to_string(seed), "-o",     output};
}

TEST_F(MpiTest, APathTracedStillOverThreeRanksHasTheirSamplesAdded) {
    const test::RunResult shared = run_mpi_same(3, path_args(4, 10, "three.exr"), dir());
    ASSERT_EQ(shared.exit_code, 0) << shared;
    EXPECT_EQ(printed_number(shared.out, "samples_per_pixel"), 12) << shared.out;
    const HdrImage three = read_hdr_image(dir() / "three.exr");

    // Bit-identical run to run: the frames are added in seed order, whoever rendered them.
    ASSERT_EQ(run_mpi_same(3, path_args(4, 10, "again.exr"), dir()).exit_code, 0);
    EXPECT_EQ(test::read_file(dir() / "again.exr"), test::read_file(dir() / "three.exr"));

    // The same estimator as the three seeds rendered apart and averaged: rank r took seed 10 + r.
    // They are rendered as parts (fgr render --part), which fgr merge sums the way the ranks'
    // frames are summed: the farm's file and the merged one hold the same floats.
    std::vector<HdrImage> seeds;
    std::vector<std::string> merge = {"merge"};
    for (int seed : {10, 11, 12}) {
        const std::string name = "seed" + std::to_string(seed) + ".exr";
        std::vector<std::string> part = path_args(4, seed, name);
        part.push_back("--part");
        ASSERT_EQ(test::run_fgr(part, dir()).exit_code, 0);
        seeds.push_back(read_hdr_image(dir() / name));
        merge.push_back(name);
    }
    merge.insert(merge.end(), {"-o", "merged.exr"});
    const test::RunResult merged = test::run_fgr(merge, dir());
    ASSERT_EQ(merged.exit_code, 0) << merged;
    EXPECT_EQ(read_hdr_image(dir() / "merged.exr").rgb, three.rgb);
    ASSERT_EQ(three.rgb.size(), seeds[0].rgb.size());
    long off = 0;
    for (size_t i = 0; i < three.rgb.size(); ++i) {
        const float mean = (seeds[0].rgb[i] + seeds[1].rgb[i] + seeds[2].rgb[i]) / 3.0f;
        // The farm weighs in double, one frame at a time: a few float roundings apart.
        off += std::abs(three.rgb[i] - mean) > 1e-6f * std::abs(mean) + 1e-7f;
    }
    EXPECT_EQ(off, 0) << "samples of the three seeds not averaged as one render of 12";

    // And unbiased against one process taking all 12 samples with another seed: per channel, the
    // image mean of the per-pixel differences within 3 of its standard errors (the pixels'
    // estimates are independent, so the spread of the differences gives the error).
    ASSERT_EQ(test::run_fgr(path_args(12, 100, "one.exr"), dir()).exit_code, 0);
    const HdrImage one = read_hdr_image(dir() / "one.exr");
    for (size_t c = 0; c < 3; ++c) {
        double sum = 0.0, squares = 0.0;
        const size_t pixels = three.rgb.size() / 3;
        for (size_t p = 0; p < pixels; ++p) {
            const double d = double(three.rgb[p * 3 + c]) - double(one.rgb[p * 3 + c]);
            sum += d;
            squares += d * d;
        }
        const double mean = sum / double(pixels);
        const double variance = squares / double(pixels) - mean * mean;
        const double standard_error = std::sqrt(variance / double(pixels));
        ASSERT_GT(standard_error, 0.0);
        EXPECT_LT(std::abs(mean) / standard_error, 3.0)
            << "channel " << c << ": mean difference " << mean << ", standard error "
            << standard_error;
    }
}

TEST_F(MpiTest, AVideoOverThreeRanksHasEveryFrameOnceInOrder) {
    const std::vector<std::string> video = {"video",      "mandelbulb", "--camera-path", "orbit",
                                            "--duration", "1",          "--fps",         "8",
                                            "--width",    "96",         "--height",      "72"};
    auto with = [&](std::vector<std::string> extra) {
        std::vector<std::string> args = video;
        args.insert(args.end(), extra.begin(), extra.end());
        return args;
    };
    ASSERT_EQ(test::run_fgr(with({"--frames", "one", "-o", "one.mp4"}), dir()).exit_code, 0);
    const test::RunResult shared =
        run_mpi_same(3, with({"--frames", "three", "-o", "three.mp4"}), dir(), false);
    ASSERT_EQ(shared.exit_code, 0) << shared;
    const std::map<int, long> tasks = tasks_by_rank(shared.out);
    ASSERT_EQ(tasks.size(), 3u) << shared.out;
    EXPECT_EQ(tasks.at(1) + tasks.at(2), 8);
    long files = 0;
    for (const auto& entry : fs::directory_iterator(dir() / "three")) {
        ++files;
        EXPECT_EQ(test::read_file(entry.path()),
                  test::read_file(dir() / "one" / entry.path().filename()))
            << entry.path().filename();
    }
    EXPECT_EQ(files, 8);
    // The videos hold those frames in that order. Not byte for byte: x264 here encodes the same
    // YUV frames into different packets from run to run, one thread or many (measured), so each
    // decoded frame of the shared video is compared with the one-process video's: the same
    // picture up to coding noise (35-40 dB apart here, where the next frame is 11-17 dB away).
    const test::DecodedVideo one = test::decode_video(dir() / "one.mp4");
    const test::DecodedVideo three = test::decode_video(dir() / "three.mp4");
    ASSERT_EQ(one.frames.size(), 8u);
    ASSERT_EQ(three.frames.size(), one.frames.size());
    for (size_t i = 0; i < one.frames.size(); ++i) {
        double squared = 0.0;
        const std::vector<uint8_t>& a = one.frames[i].rgb;
        const std::vector<uint8_t>& b = three.frames[i].rgb;
        ASSERT_EQ(a.size(), b.size());
        for (size_t k = 0; k < a.size(); ++k)
            squared += (double(a[k]) - b[k]) * (double(a[k]) - b[k]);
        const double psnr =
            10.0 * std::log10(255.0 * 255.0 * double(a.size()) / std::max(squared, 1e-9));
        EXPECT_GT(psnr, 25.0) << "frame " << i;
    }
}

TEST_F(MpiTest, ARankThatFailsEndsTheJobWithOneMessageNamingIt) {
    const std::vector<std::string> render = {"render",   "mandelbulb", "--width", "96",
                                             "--height", "72",         "-o",      "out.png"};
    std::vector<std::string> bad_device = render;
    bad_device.insert(bad_device.end(), {"--device", "7"});
    const test::RunResult failed = run_mpi({render, bad_device, render}, dir());
    EXPECT_FALSE(failed.timed_out);
    EXPECT_NE(failed.exit_code, 0);
    EXPECT_NE(failed.err.find("fgr: error: rank 1 ("), std::string::npos) << failed.err;
    EXPECT_NE(failed.err.find("no OpenCL device 7"), std::string::npos) << failed.err;
    size_t errors = 0;
    for (size_t at = failed.err.find("fgr: error:"); at != std::string::npos;
         at = failed.err.find("fgr: error:", at + 1)) {
        ++errors;
    }
    EXPECT_EQ(errors, 1u) << failed.err;
    EXPECT_FALSE(fs::exists(dir() / "out.png"));
    EXPECT_FALSE(fs::exists(dir() / "out.png.fgr-tiles"));
}

// A rank killed outright says nothing; rank 0, which watches the workers on its node, ends the
// job with one line naming it, and leaves no temporary file. Ranks 1 and 2 hold after their first
// tile (FGR_TEST_HOLD=task; rank 0 only schedules), so the job cannot finish first; the first of
// them to say so is killed with SIGKILL once it has.
TEST_F(MpiTest, ARankThatIsKilledEndsTheJobWithOneLineNamingIt) {
    const std::vector<std::string> render = {"render", "menger",      "--width", "64", "--height",
                                             "48",     "--tile-size", "16",      "-o", "out.png"};
    std::vector<std::string> held = {"env", "FGR_TEST_HOLD=task"};
    held.insert(held.end(), render.begin(), render.end());
    const auto kill_first_holder = [](pid_t, const std::string& err) {
        std::smatch match;
        const std::regex holding("holding after the first task [^\\n]*pid ([0-9]+)");
        if (!std::regex_search(err, match, holding)) return false;
        ::kill(static_cast<pid_t>(std::stol(match[1])), SIGKILL);
        return true;
    };
    const test::RunResult run = run_mpi({render, held, held}, dir(), false, kill_first_holder);
    EXPECT_FALSE(run.timed_out) << run;
    EXPECT_FALSE(run.exited && run.exit_code == 0) << run;
    EXPECT_TRUE(std::regex_search(run.err, std::regex("fgr: error: rank [12] \\([^)]+\\): its "
                                                      "process ended without a word")))
        << run.err;
    size_t errors = 0;
    for (size_t at = run.err.find("fgr: error:"); at != std::string::npos;
         at = run.err.find("fgr: error:", at + 1)) {
        ++errors;
    }
    EXPECT_EQ(errors, 1u) << run.err;
    for (const std::string& name : test::directory_listing(dir())) {
        EXPECT_TRUE(name == "out.png.fgr-tiles") << "left behind: " << name;
    }
}

TEST_F(MpiTest, CommandsThatDoNotShareWorkAreRefusedUnderMpirun) {
    const test::RunResult listed = run_mpi_same(2, {"list"}, dir());
    EXPECT_NE(listed.exit_code, 0);
    EXPECT_NE(listed.err.find("only `fgr render` and `fgr video` run across MPI ranks"),
              std::string::npos)
        << listed.err;
}

}  // namespace
}  // namespace fgr
