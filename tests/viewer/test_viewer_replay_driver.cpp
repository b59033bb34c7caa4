// SPDX-License-Identifier: Apache-2.0
// A replay script fed into the viewer without a window: input events reach SDL's queue addressed
// to the viewer's window (a mouse button without a position at its centre), a wait holds the rest
// of the script until what it waits for has happened, a resize keeps the view from counting as
// idle until the window has the size, the browser's and the editor's events go to them, and a
// parameter set goes to the viewer.
#include <SDL2/SDL.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "viewer/replay.hpp"
#include "viewer/replay_driver.hpp"

namespace fgr::viewer {
namespace {

constexpr uint32_t kWindowId = 7;

// A viewer whose state the test sets, and which records what the script did to it.
struct FakeViewer {
    std::pair<int, int> window_size{400, 300};
    bool view_idle = false;
    bool thumbnails_done = false;
    int full_size_samples = 0;
    long frames_shown = 0;
    uint64_t changes_handled = 0;
    bool quit = false;
    std::vector<std::pair<int, int>> resizes;
    std::vector<ReplayAction> browser_events;
    std::vector<ReplayAction> editor_events;
    std::vector<std::string> assignments;

    ReplayHost host() {
        return {
            .window_size = [this] { return window_size; },
            .window_id = [] { return kWindowId; },
            .resize_window = [this](int w, int h) { resizes.emplace_back(w, h); },
            .view_idle = [this] { return view_idle; },
            .thumbnails_done = [this] { return thumbnails_done; },
            .full_size_samples = [this] { return full_size_samples; },
            .frames_shown = [this] { return frames_shown; },
            .changes_handled = [this] { return changes_handled; },
            .quit = [this] { quit = true; },
            .browser_event = [this](const ReplayEvent& e) { browser_events.push_back(e.action); },
            .editor_event = [this](const ReplayEvent& e) { editor_events.push_back(e.action); },
            .set_parameter = [this](const std::string& text) { assignments.push_back(text); },
        };
    }
};

std::vector<ReplayEvent> script(const std::string& text) {
    std::istringstream input(text);
    return parse_replay(input, "test");
}

class ViewerReplayDriver : public ::testing::Test {
protected:
    void SetUp() override { ASSERT_EQ(SDL_Init(SDL_INIT_EVENTS), 0) << SDL_GetError(); }
    void TearDown() override { SDL_Quit(); }

    static std::vector<SDL_Event> pushed() {
        std::vector<SDL_Event> events;
        SDL_Event event;
        while (SDL_PollEvent(&event)) {
            if (event.type == SDL_KEYDOWN || event.type == SDL_KEYUP ||
                event.type == SDL_MOUSEBUTTONDOWN || event.type == SDL_MOUSEBUTTONUP) {
                events.push_back(event);
            }
        }
        return events;
    }
};

TEST_F(ViewerReplayDriver, AKeyIsPressedAndReleasedInTheViewersWindow) {
    FakeViewer viewer;
    ReplayDriver driver(script("0 key W\n"), viewer.host());
    driver.feed(0.0);
    const std::vector<SDL_Event> events = pushed();
    ASSERT_EQ(events.size(), 2u);
    EXPECT_EQ(events[0].type, SDL_KEYDOWN);
    EXPECT_EQ(events[1].type, SDL_KEYUP);
    for (const SDL_Event& event : events) {
        EXPECT_EQ(event.key.keysym.scancode, SDL_SCANCODE_W);
        EXPECT_EQ(event.key.windowID, kWindowId);
    }
}

TEST_F(ViewerReplayDriver, AMouseButtonWithoutAPositionIsAtTheWindowsCentre) {
    FakeViewer viewer;
    ReplayDriver driver(script("0 mouse_down right\n0 mouse_up right 10 20\n"), viewer.host());
    driver.feed(0.0);
    const std::vector<SDL_Event> events = pushed();
    ASSERT_EQ(events.size(), 2u);
    EXPECT_EQ(events[0].type, SDL_MOUSEBUTTONDOWN);
    EXPECT_EQ(events[0].button.button, SDL_BUTTON_RIGHT);
    EXPECT_EQ(std::pair(events[0].button.x, events[0].button.y), std::pair(200, 150));
    EXPECT_EQ(events[1].type, SDL_MOUSEBUTTONUP);
    EXPECT_EQ(std::pair(events[1].button.x, events[1].button.y), std::pair(10, 20));
}

TEST_F(ViewerReplayDriver, WaitIdleHoldsTheScriptUntilTheViewIsIdle) {
    FakeViewer viewer;
    ReplayDriver driver(script("0 wait_idle\n0 quit\n"), viewer.host());
    driver.feed(0.0);
    driver.feed(1.0);
    EXPECT_FALSE(viewer.quit);
    viewer.view_idle = true;
    driver.feed(2.0);
    EXPECT_TRUE(viewer.quit);
}

TEST_F(ViewerReplayDriver, WaitSamplesHoldsTheScriptUntilTheFullSizeFrameHasThem) {
    FakeViewer viewer;
    viewer.view_idle = true;  // not what wait_samples waits for
    ReplayDriver driver(script("0 wait_samples 3\n0 quit\n"), viewer.host());
    driver.feed(0.0);
    viewer.full_size_samples = 2;
    driver.feed(1.0);
    EXPECT_FALSE(viewer.quit);
    viewer.full_size_samples = 3;
    driver.feed(2.0);
    EXPECT_TRUE(viewer.quit);
}

TEST_F(ViewerReplayDriver, WaitFramesHoldsTheScriptUntilThatManyMoreFramesAreShown) {
    FakeViewer viewer;
    viewer.view_idle = true;   // not what wait_frames waits for
    viewer.frames_shown = 10;  // shown before the wait: they do not count
    ReplayDriver driver(script("0 key_down W\n0 wait_frames 3\n0 key_up W\n0 quit\n"),
                        viewer.host());
    driver.feed(0.0);
    viewer.frames_shown = 12;
    driver.feed(5.0);  // however long it takes
    EXPECT_FALSE(viewer.quit);
    viewer.frames_shown = 13;
    driver.feed(5.1);
    EXPECT_TRUE(viewer.quit);
}

TEST_F(ViewerReplayDriver, WaitReloadHoldsTheScriptUntilAnotherChangeIsDealtWith) {
    FakeViewer viewer;
    viewer.changes_handled = 3;
    viewer.view_idle = true;  // not what wait_reload waits for
    ReplayDriver driver(script("0 wait_reload\n0 quit\n"), viewer.host());
    driver.feed(0.0);
    driver.feed(1.0);
    EXPECT_FALSE(viewer.quit);
    viewer.changes_handled = 4;
    driver.feed(2.0);
    EXPECT_TRUE(viewer.quit);
}

TEST_F(ViewerReplayDriver, WaitThumbnailsHoldsTheScriptUntilTheyAreDone) {
    FakeViewer viewer;
    viewer.view_idle = true;  // not what wait_thumbnails waits for
    ReplayDriver driver(script("0 wait_thumbnails\n0 quit\n"), viewer.host());
    driver.feed(0.0);
    driver.feed(1.0);
    EXPECT_FALSE(viewer.quit);
    viewer.thumbnails_done = true;
    driver.feed(2.0);
    EXPECT_TRUE(viewer.quit);
}

TEST_F(ViewerReplayDriver, AResizeIsPendingUntilTheWindowHasTheSize) {
    FakeViewer viewer;
    ReplayDriver driver(script("0 resize 320 240\n0 wait_idle\n0 quit\n"), viewer.host());
    EXPECT_FALSE(driver.window_size_pending());
    driver.feed(0.0);
    ASSERT_EQ(viewer.resizes.size(), 1u);
    EXPECT_EQ(viewer.resizes[0], std::pair(320, 240));
    EXPECT_TRUE(driver.window_size_pending());
    viewer.window_size = {320, 240};
    EXPECT_FALSE(driver.window_size_pending());
    viewer.view_idle = true;
    driver.feed(1.0);
    EXPECT_TRUE(viewer.quit);
    viewer.window_size = {500, 500};  // resized by the user after the wait: none asked for now
    EXPECT_FALSE(driver.window_size_pending());
}

TEST_F(ViewerReplayDriver, BrowserAndEditorEventsGoToThem) {
    FakeViewer viewer;
    ReplayDriver driver(script("0 browser_search julia\n0 browser_pick 1\n0 hybrid_add "
                               "mandelbulb\n0 hybrid_remove 2\n0 hybrid_save mine\n"),
                        viewer.host());
    driver.feed(0.0);
    EXPECT_EQ(viewer.browser_events,
              (std::vector{ReplayAction::BrowserSearch, ReplayAction::BrowserPick}));
    EXPECT_EQ(viewer.editor_events,
              (std::vector{ReplayAction::HybridAdd, ReplayAction::HybridRemove,
                           ReplayAction::HybridSave}));
}

TEST_F(ViewerReplayDriver, SetGivesTheViewerTheAssignment) {
    FakeViewer viewer;
    ReplayDriver driver(script("0 set power=7.25\n"), viewer.host());
    driver.feed(0.0);
    EXPECT_EQ(viewer.assignments, std::vector<std::string>{"power=7.25"});
    EXPECT_TRUE(pushed().empty()) << "no input event";
}

}  // namespace
}  // namespace fgr::viewer
