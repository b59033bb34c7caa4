// SPDX-License-Identifier: Apache-2.0
// Replay scripts: parsing of every event kind and of malformed lines (messages name FILE:LINE),
// loading from disk, and playback against a clock including wait_idle pauses.

#include <gtest/gtest.h>

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "viewer/replay.hpp"

namespace fgr::viewer {
namespace {

std::vector<ReplayEvent> parse(const std::string& text) {
    std::istringstream input(text);
    return parse_replay(input, "demo.replay");
}

// The message parse() throws for `text`, or a note that it threw nothing.
std::string parse_error(const std::string& text) {
    try {
        parse(text);
    } catch (const std::runtime_error& error) {
        return error.what();
    }
    return "(no error)";
}

// A script of the given actions with the given delays.
std::vector<ReplayEvent> script(const std::vector<std::pair<double, ReplayAction>>& steps) {
    std::vector<ReplayEvent> events;
    for (const auto& [delay, action] : steps) {
        ReplayEvent event;
        event.delay_seconds = delay;
        event.action = action;
        event.line = static_cast<int>(events.size()) + 1;
        events.push_back(event);
    }
    return events;
}

std::vector<int> lines_of(const std::vector<ReplayEvent>& events) {
    std::vector<int> lines;
    for (const ReplayEvent& event : events) {
        lines.push_back(event.line);
    }
    return lines;
}

TEST(ReplayParse, KeyEvents) {
    const auto events = parse("0.5 key_down W\n0 key_up F12\n1.25 key PageDown\n");
    ASSERT_EQ(events.size(), 3u);
    EXPECT_EQ(events[0].action, ReplayAction::KeyDown);
    EXPECT_EQ(events[0].key, "W");
    EXPECT_DOUBLE_EQ(events[0].delay_seconds, 0.5);
    EXPECT_EQ(events[0].line, 1);
    EXPECT_EQ(events[1].action, ReplayAction::KeyUp);
    EXPECT_EQ(events[1].key, "F12");
    EXPECT_DOUBLE_EQ(events[1].delay_seconds, 0.0);
    EXPECT_EQ(events[2].action, ReplayAction::KeyPress);
    EXPECT_EQ(events[2].key, "PageDown");
    EXPECT_DOUBLE_EQ(events[2].delay_seconds, 1.25);
    EXPECT_EQ(events[2].line, 3);
}

TEST(ReplayParse, UnderscoresInKeyNamesBecomeSpaces) {
    const auto events = parse("0 key_down Left_Shift\n0 key Keypad_+\n");
    ASSERT_EQ(events.size(), 2u);
    EXPECT_EQ(events[0].key, "Left Shift");
    EXPECT_EQ(events[1].key, "Keypad +");
}

TEST(ReplayParse, MouseButtonsWithAndWithoutPosition) {
    const auto events = parse(
        "0 mouse_down left\n"
        "0.1 mouse_up middle 10 20\n"
        "0.2 mouse_down right 0 16383\n");
    ASSERT_EQ(events.size(), 3u);
    EXPECT_EQ(events[0].action, ReplayAction::MouseDown);
    EXPECT_EQ(events[0].button, 1);
    EXPECT_FALSE(events[0].has_position);

    EXPECT_EQ(events[1].action, ReplayAction::MouseUp);
    EXPECT_EQ(events[1].button, 2);
    EXPECT_TRUE(events[1].has_position);
    EXPECT_EQ(events[1].x, 10);
    EXPECT_EQ(events[1].y, 20);

    EXPECT_EQ(events[2].action, ReplayAction::MouseDown);
    EXPECT_EQ(events[2].button, 3);
    EXPECT_TRUE(events[2].has_position);
    EXPECT_EQ(events[2].x, 0);
    EXPECT_EQ(events[2].y, 16383);
}

TEST(ReplayParse, MotionWheelResizeWaitAndQuit) {
    const auto events = parse(
        "0 mouse_move 15 -7\n"
        "0 wheel -3\n"
        "0 resize 800 600\n"
        "2 wait_idle\n"
        "0.5 quit\n");
    ASSERT_EQ(events.size(), 5u);
    EXPECT_EQ(events[0].action, ReplayAction::MouseMove);
    EXPECT_EQ(events[0].x, 15);
    EXPECT_EQ(events[0].y, -7);
    EXPECT_EQ(events[1].action, ReplayAction::Wheel);
    EXPECT_EQ(events[1].wheel, -3);
    EXPECT_EQ(events[2].action, ReplayAction::Resize);
    EXPECT_EQ(events[2].x, 800);
    EXPECT_EQ(events[2].y, 600);
    EXPECT_EQ(events[3].action, ReplayAction::WaitIdle);
    EXPECT_DOUBLE_EQ(events[3].delay_seconds, 2.0);
    EXPECT_EQ(events[4].action, ReplayAction::Quit);
    EXPECT_DOUBLE_EQ(events[4].delay_seconds, 0.5);
}

TEST(ReplayParse, WaitReload) {
    const auto events = parse("0.5 wait_reload\n");
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].action, ReplayAction::WaitReload);
    EXPECT_DOUBLE_EQ(events[0].delay_seconds, 0.5);
    EXPECT_EQ(parse_error("0 wait_reload now\n"),
              "demo.replay:1: wait_reload takes wait_reload, got 1 argument");
}

TEST(ReplayParse, WaitFramesCountsFrames) {
    const auto events = parse("0.2 wait_frames 6\n");
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].action, ReplayAction::WaitFrames);
    EXPECT_EQ(events[0].count, 6);
    EXPECT_TRUE(is_wait(events[0].action));
    EXPECT_EQ(parse_error("0 wait_frames 0\n"), "demo.replay:1: N 0 is out of range [1, 100000]");
    EXPECT_EQ(parse_error("0 wait_frames\n"),
              "demo.replay:1: wait_frames takes wait_frames N, got 0 arguments");
}

TEST(ReplayParse, BrowserAndHybridEditorEvents) {
    const auto events = parse(
        "0 browser_search box_julia\n0 browser_search -\n0 browser_pick 3\n0 wait_thumbnails\n"
        "0 hybrid_add amazing_box\n0 hybrid_remove 2\n0 hybrid_move 2 -1\n"
        "0 hybrid_repeat 1 4\n");
    ASSERT_EQ(events.size(), 8u);
    EXPECT_EQ(events[0].action, ReplayAction::BrowserSearch);
    EXPECT_EQ(events[0].text, "box julia") << "underscores stand for spaces";
    EXPECT_EQ(events[1].text, "") << "- clears the search";
    EXPECT_EQ(events[2].action, ReplayAction::BrowserPick);
    EXPECT_EQ(events[2].count, 2) << "N counts from 1";
    EXPECT_EQ(events[3].action, ReplayAction::WaitThumbnails);
    EXPECT_TRUE(is_wait(events[3].action));
    EXPECT_EQ(events[4].action, ReplayAction::HybridAdd);
    EXPECT_EQ(events[4].text, "amazing_box") << "formula names keep their underscores";
    EXPECT_EQ(events[5].action, ReplayAction::HybridRemove);
    EXPECT_EQ(events[5].slot, 1);
    EXPECT_EQ(events[6].action, ReplayAction::HybridMove);
    EXPECT_EQ(events[6].slot, 1);
    EXPECT_EQ(events[6].count, -1);
    EXPECT_EQ(events[7].action, ReplayAction::HybridRepeat);
    EXPECT_EQ(events[7].slot, 0);
    EXPECT_EQ(events[7].count, 4);
    EXPECT_EQ(parse_error("0 hybrid_remove 0\n"), "demo.replay:1: N 0 is out of range [1, 64]");
    EXPECT_EQ(parse_error("0 hybrid_move 1 up\n"),
              "demo.replay:1: OFFSET must be an integer, got 'up'");
    EXPECT_EQ(parse_error("0 browser_pick\n"),
              "demo.replay:1: browser_pick takes browser_pick N, got 0 arguments");
}

TEST(ReplayClock, WaitThumbnailsHoldsTheScriptUntilResumed) {
    ReplayClock clock(script({{0.0, ReplayAction::WaitThumbnails}, {0.0, ReplayAction::Quit}}));
    EXPECT_EQ(clock.due(0.0).size(), 1u);
    EXPECT_TRUE(clock.waiting());
    EXPECT_TRUE(clock.due(5.0).empty());
    clock.resume(5.0);
    EXPECT_EQ(clock.due(5.0).size(), 1u);
}

TEST(ReplayParse, CommentsBlankLinesAndSpacingAreIgnored) {
    const auto events = parse(
        "# a demo\n"
        "\n"
        "   \t \n"
        "  # indented comment\n"
        "  1e-1\tkey   W  \r\n"
        "0 quit");  // no final newline
    ASSERT_EQ(events.size(), 2u);
    EXPECT_EQ(events[0].action, ReplayAction::KeyPress);
    EXPECT_EQ(events[0].key, "W");
    EXPECT_DOUBLE_EQ(events[0].delay_seconds, 0.1);
    EXPECT_EQ(events[0].line, 5);
    EXPECT_EQ(events[1].action, ReplayAction::Quit);
    EXPECT_EQ(events[1].line, 6);
}

TEST(ReplayParse, EmptyScriptHasNoEvents) {
    EXPECT_TRUE(parse("").empty());
    EXPECT_TRUE(parse("# nothing\n\n").empty());
}

TEST(ReplayParse, SetTakesOneParameterAssignment) {
    const auto events = parse("0 set power=7.25\n0.5 set tint=0.1,0.2,0.3\n");
    ASSERT_EQ(events.size(), 2u);
    EXPECT_EQ(events[0].action, ReplayAction::SetParameter);
    EXPECT_EQ(events[0].text, "power=7.25");
    EXPECT_EQ(events[1].text, "tint=0.1,0.2,0.3");
    EXPECT_EQ(parse_error("0 set power\n"), "demo.replay:1: set needs ID=VALUE, got 'power'");
    EXPECT_EQ(parse_error("0 set =7\n"), "demo.replay:1: set needs ID=VALUE, got '=7'");
    EXPECT_EQ(parse_error("0 set power=\n"), "demo.replay:1: set needs ID=VALUE, got 'power='");
    EXPECT_EQ(parse_error("0 set power = 7\n"),
              "demo.replay:1: set takes set ID=VALUE, got 3 arguments");
}

TEST(ReplayParse, UnknownEventNamesFileAndLine) {
    EXPECT_EQ(parse_error("0 key W\n# x\n1 jump\n"), "demo.replay:3: unknown event 'jump'");
    EXPECT_EQ(parse_error("0.5\n"), "demo.replay:1: expected an event after the delay '0.5'");
}

TEST(ReplayParse, WrongArgumentCounts) {
    EXPECT_EQ(parse_error("0 key\n"), "demo.replay:1: key takes key KEY, got 0 arguments");
    EXPECT_EQ(parse_error("0 key_down A B\n"),
              "demo.replay:1: key_down takes key_down KEY, got 2 arguments");
    EXPECT_EQ(parse_error("0 mouse_down left 5\n"),
              "demo.replay:1: mouse_down takes mouse_down BUTTON [X Y], got 2 arguments");
    EXPECT_EQ(parse_error("0 mouse_up left 1 2 3\n"),
              "demo.replay:1: mouse_up takes mouse_up BUTTON [X Y], got 4 arguments");
    EXPECT_EQ(parse_error("\n0 mouse_move 1\n"),
              "demo.replay:2: mouse_move takes mouse_move DX DY, got 1 argument");
    EXPECT_EQ(parse_error("0 wheel\n"), "demo.replay:1: wheel takes wheel STEPS, got 0 arguments");
    EXPECT_EQ(parse_error("0 resize 800\n"),
              "demo.replay:1: resize takes resize WIDTH HEIGHT, got 1 argument");
    EXPECT_EQ(parse_error("0 wait_idle now\n"),
              "demo.replay:1: wait_idle takes wait_idle, got 1 argument");
    EXPECT_EQ(parse_error("0 quit 1\n"), "demo.replay:1: quit takes quit, got 1 argument");
}

TEST(ReplayParse, BadDelays) {
    const std::string expected = "demo.replay:1: delay must be a non-negative number of seconds";
    EXPECT_EQ(parse_error("-1 quit\n"), expected + ", got '-1'");
    EXPECT_EQ(parse_error("soon quit\n"), expected + ", got 'soon'");
    EXPECT_EQ(parse_error("1s quit\n"), expected + ", got '1s'");
    EXPECT_EQ(parse_error("inf quit\n"), expected + ", got 'inf'");
    EXPECT_EQ(parse_error("nan quit\n"), expected + ", got 'nan'");
    EXPECT_EQ(parse_error("1e999 quit\n"), expected + ", got '1e999'");
}

TEST(ReplayParse, BadNumbers) {
    EXPECT_EQ(parse_error("0 wheel 1.5\n"), "demo.replay:1: STEPS must be an integer, got '1.5'");
    EXPECT_EQ(parse_error("0 mouse_move x 1\n"), "demo.replay:1: DX must be an integer, got 'x'");
    EXPECT_EQ(parse_error("0 mouse_move 1 99999999999\n"),
              "demo.replay:1: DY 99999999999 is out of range [-2147483648, 2147483647]");
    EXPECT_EQ(parse_error("0 mouse_down left 10 -1\n"),
              "demo.replay:1: Y -1 is out of range [0, 16383]");
}

TEST(ReplayParse, UnknownButton) {
    EXPECT_EQ(parse_error("0 mouse_down wheel\n"),
              "demo.replay:1: unknown mouse button 'wheel' (left, middle, right)");
    EXPECT_EQ(parse_error("0 mouse_up Left 1 1\n"),
              "demo.replay:1: unknown mouse button 'Left' (left, middle, right)");
}

TEST(ReplayParse, ResizeOutOfRange) {
    EXPECT_EQ(parse_error("0 resize 0 600\n"), "demo.replay:1: WIDTH 0 is out of range [1, 16384]");
    EXPECT_EQ(parse_error("0 resize 800 16385\n"),
              "demo.replay:1: HEIGHT 16385 is out of range [1, 16384]");
    EXPECT_EQ(parse_error("0 resize -5 600\n"),
              "demo.replay:1: WIDTH -5 is out of range [1, 16384]");
    const auto largest = parse("0 resize 1 16384\n");
    ASSERT_EQ(largest.size(), 1u);
    EXPECT_EQ(largest[0].x, 1);
    EXPECT_EQ(largest[0].y, 16384);
}

TEST(ReplayParse, ErrorsAreOneLine) {
    for (const char* text : {"0 jump\n", "x quit\n", "0 resize 0 0\n", "0 key\n"}) {
        EXPECT_EQ(parse_error(text).find('\n'), std::string::npos) << text;
    }
}

class ReplayLoad : public ::testing::Test {
protected:
    void SetUp() override {
        directory_ = std::filesystem::temp_directory_path() /
                     ("fgr_test_replay_" +
                      std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
                      ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::create_directories(directory_);
    }
    void TearDown() override { std::filesystem::remove_all(directory_); }

    std::filesystem::path directory_;
};

TEST_F(ReplayLoad, ReadsAFile) {
    const std::filesystem::path file = directory_ / "ok.replay";
    std::ofstream(file) << "# demo\n0.5 key W\n1 quit\n";
    const auto events = load_replay(file);
    ASSERT_EQ(events.size(), 2u);
    EXPECT_EQ(events[0].key, "W");
    EXPECT_EQ(events[1].action, ReplayAction::Quit);
    EXPECT_EQ(events[1].line, 3);
}

TEST_F(ReplayLoad, ErrorsNameTheFile) {
    const std::filesystem::path file = directory_ / "bad.replay";
    std::ofstream(file) << "0 key W\n0 fly\n";
    try {
        load_replay(file);
        FAIL() << "no error";
    } catch (const std::runtime_error& error) {
        EXPECT_EQ(std::string(error.what()), file.string() + ":2: unknown event 'fly'");
    }
}

TEST_F(ReplayLoad, MissingFileThrowsNamingIt) {
    const std::filesystem::path file = directory_ / "missing.replay";
    try {
        load_replay(file);
        FAIL() << "no error";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos) << error.what();
    }
}

TEST_F(ReplayLoad, DirectoryThrowsNamingIt) {
    try {
        load_replay(directory_);
        FAIL() << "no error";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find(directory_.string()), std::string::npos)
            << error.what();
    }
}

TEST(ReplayClock, NothingComesOutBeforeTheFirstDueTime) {
    ReplayClock clock(script({{1.0, ReplayAction::KeyPress}}));
    EXPECT_TRUE(clock.due(100.0).empty());  // starts the script at 100
    EXPECT_TRUE(clock.due(100.5).empty());
    EXPECT_TRUE(clock.due(100.999).empty());
    EXPECT_FALSE(clock.finished());
    EXPECT_EQ(lines_of(clock.due(101.0)), std::vector<int>{1});
    EXPECT_TRUE(clock.finished());
    EXPECT_TRUE(clock.due(200.0).empty());
}

TEST(ReplayClock, ZeroDelayComesOutOnTheFirstCall) {
    ReplayClock clock(script({{0.0, ReplayAction::KeyDown}, {0.0, ReplayAction::KeyUp}}));
    EXPECT_EQ(lines_of(clock.due(5.0)), (std::vector<int>{1, 2}));
    EXPECT_TRUE(clock.finished());
}

TEST(ReplayClock, DelaysAreCumulative) {
    ReplayClock clock(script(
        {{1.0, ReplayAction::KeyDown}, {0.5, ReplayAction::KeyUp}, {2.0, ReplayAction::Quit}}));
    EXPECT_TRUE(clock.due(0.0).empty());
    EXPECT_EQ(lines_of(clock.due(1.2)), std::vector<int>{1});
    EXPECT_TRUE(clock.due(1.49).empty());
    EXPECT_EQ(lines_of(clock.due(1.5)), std::vector<int>{2});
    EXPECT_TRUE(clock.due(3.49).empty());
    EXPECT_EQ(lines_of(clock.due(3.5)), std::vector<int>{3});
    EXPECT_TRUE(clock.finished());
}

TEST(ReplayClock, SeveralEventsCanBeDueAtOnce) {
    ReplayClock clock(script({{1.0, ReplayAction::KeyDown},
                              {1.0, ReplayAction::KeyUp},
                              {1.0, ReplayAction::Wheel},
                              {5.0, ReplayAction::Quit}}));
    clock.due(10.0);
    // A slow frame: the first three were due at 11, 12 and 13, all passed by 13.5.
    const auto events = clock.due(13.5);
    ASSERT_EQ(lines_of(events), (std::vector<int>{1, 2, 3}));
    EXPECT_EQ(events[0].action, ReplayAction::KeyDown);
    EXPECT_EQ(events[2].action, ReplayAction::Wheel);
    // The last counts from when the third was due (13), not from when it came out.
    EXPECT_TRUE(clock.due(17.9).empty());
    EXPECT_EQ(lines_of(clock.due(18.0)), std::vector<int>{4});
}

TEST(ReplayClock, WaitIdleHoldsTheRestUntilResume) {
    ReplayClock clock(script({{0.0, ReplayAction::KeyDown},
                              {1.0, ReplayAction::WaitIdle},
                              {0.0, ReplayAction::KeyUp},
                              {2.0, ReplayAction::Quit}}));
    EXPECT_EQ(lines_of(clock.due(0.0)), std::vector<int>{1});
    EXPECT_FALSE(clock.waiting());

    const auto paused = clock.due(5.0);
    ASSERT_EQ(lines_of(paused), std::vector<int>{2});  // comes out, and nothing after it
    EXPECT_EQ(paused[0].action, ReplayAction::WaitIdle);
    EXPECT_TRUE(clock.waiting());
    EXPECT_FALSE(clock.finished());
    EXPECT_TRUE(clock.due(50.0).empty());
    EXPECT_TRUE(clock.due(100.0).empty());

    clock.resume(100.0);
    EXPECT_FALSE(clock.waiting());
    // Delays now count from the resume time.
    EXPECT_EQ(lines_of(clock.due(100.0)), std::vector<int>{3});
    EXPECT_TRUE(clock.due(101.9).empty());
    EXPECT_EQ(lines_of(clock.due(102.0)), std::vector<int>{4});
    EXPECT_TRUE(clock.finished());
}

TEST(ReplayClock, WaitReloadHoldsTheRestUntilResumeLikeWaitIdle) {
    ReplayClock clock(script({{0.0, ReplayAction::WaitReload}, {1.0, ReplayAction::KeyPress}}));
    const auto paused = clock.due(0.0);
    ASSERT_EQ(lines_of(paused), std::vector<int>{1});
    EXPECT_EQ(paused[0].action, ReplayAction::WaitReload);
    EXPECT_TRUE(clock.waiting());
    EXPECT_TRUE(clock.due(60.0).empty());
    clock.resume(60.0);
    EXPECT_TRUE(clock.due(60.9).empty());
    EXPECT_EQ(lines_of(clock.due(61.0)), std::vector<int>{2});
    EXPECT_TRUE(clock.finished());
}

TEST(ReplayClock, WaitIdleAtTheEndIsNotFinishedUntilResumed) {
    ReplayClock clock(script({{0.0, ReplayAction::WaitIdle}}));
    EXPECT_EQ(lines_of(clock.due(0.0)), std::vector<int>{1});
    EXPECT_FALSE(clock.finished());
    clock.resume(1.0);
    EXPECT_TRUE(clock.finished());
}

TEST(ReplayClock, ResumeWithoutWaitDoesNotShiftTheSchedule) {
    ReplayClock clock(script({{1.0, ReplayAction::KeyDown}, {1.0, ReplayAction::KeyUp}}));
    clock.due(0.0);
    clock.resume(0.9);
    EXPECT_EQ(lines_of(clock.due(1.0)), std::vector<int>{1});
    clock.resume(1.5);
    EXPECT_EQ(lines_of(clock.due(2.0)), std::vector<int>{2});
}

TEST(ReplayClock, EmptyScriptIsFinished) {
    ReplayClock clock({});
    EXPECT_TRUE(clock.finished());
    EXPECT_TRUE(clock.due(0.0).empty());
    EXPECT_TRUE(clock.finished());
}

}  // namespace
}  // namespace fgr::viewer
