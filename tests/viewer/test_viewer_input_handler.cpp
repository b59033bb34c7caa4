// SPDX-License-Identifier: Apache-2.0
// The viewer's key bindings without a window: each key the help window lists runs its command,
// Ctrl matters only to S (Ctrl+S saves the view, S alone flies backwards) and K (Ctrl+K saves the
// recorded path, K alone records a keyframe), and the flying keys, which act while held, run
// none.
#include <gtest/gtest.h>

#include <optional>
#include <utility>

#include "viewer/input_handler.hpp"

namespace fgr::viewer {
namespace {

TEST(ViewerKeyBindings, EachListedKeyRunsItsCommandWithOrWithoutCtrl) {
    const std::pair<SDL_Scancode, ViewerCommand> bindings[] = {
        {SDL_SCANCODE_ESCAPE, ViewerCommand::Quit},
        {SDL_SCANCODE_R, ViewerCommand::ResetCamera},
        {SDL_SCANCODE_C, ViewerCommand::NextCamera},
        {SDL_SCANCODE_PAGEUP, ViewerCommand::PreviousScene},
        {SDL_SCANCODE_PAGEDOWN, ViewerCommand::NextScene},
        {SDL_SCANCODE_P, ViewerCommand::TogglePlayback},
        {SDL_SCANCODE_F12, ViewerCommand::Screenshot},
        {SDL_SCANCODE_H, ViewerCommand::ToggleHelp},
        {SDL_SCANCODE_F1, ViewerCommand::ToggleHelp},
        {SDL_SCANCODE_TAB, ViewerCommand::TogglePanel},
        {SDL_SCANCODE_F11, ViewerCommand::ToggleFullscreen},
        {SDL_SCANCODE_B, ViewerCommand::ToggleBrowser},
    };
    for (const auto& [key, command] : bindings) {
        for (const bool ctrl : {false, true}) {
            EXPECT_EQ(command_for_key(key, ctrl), command)
                << SDL_GetScancodeName(key) << (ctrl ? " with Ctrl" : "");
        }
    }
}

TEST(ViewerKeyBindings, CtrlSSavesTheViewAndSAloneRunsNothing) {
    EXPECT_EQ(command_for_key(SDL_SCANCODE_S, true), ViewerCommand::SaveView);
    EXPECT_EQ(command_for_key(SDL_SCANCODE_S, false), std::nullopt);
}

TEST(ViewerKeyBindings, CtrlKSavesThePathAndKAloneRecordsAKeyframe) {
    EXPECT_EQ(command_for_key(SDL_SCANCODE_K, true), ViewerCommand::SaveRecordedPath);
    EXPECT_EQ(command_for_key(SDL_SCANCODE_K, false), ViewerCommand::RecordKeyframe);
}

TEST(ViewerKeyBindings, FlyingKeysRunNoCommand) {
    for (const SDL_Scancode key : {SDL_SCANCODE_W, SDL_SCANCODE_A, SDL_SCANCODE_D, SDL_SCANCODE_Q,
                                   SDL_SCANCODE_E, SDL_SCANCODE_LSHIFT, SDL_SCANCODE_RSHIFT}) {
        EXPECT_EQ(command_for_key(key, false), std::nullopt) << SDL_GetScancodeName(key);
    }
}

}  // namespace
}  // namespace fgr::viewer
