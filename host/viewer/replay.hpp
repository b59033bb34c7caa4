// SPDX-License-Identifier: Apache-2.0
#pragma once
// Scripted input for the viewer (`fgr view --replay FILE`): a text file of timed events that the
// viewer feeds through the same handlers as real input, for tests and demos. A user-facing format:
// docs/file-formats.md ("Viewer scripts") documents it; keep the two in step.
//
// One event a line: DELAY EVENT [ARGS...], DELAY being seconds after the previous event (after
// the start for the first). Blank lines and lines starting with '#' are ignored.
//
//   key_down KEY          key_up KEY          key KEY (down, then up)
//   mouse_down BUTTON [X Y]   mouse_up BUTTON [X Y]   (BUTTON: left, middle, right; X Y pixels,
//                                                      default: the window centre)
//   mouse_move DX DY      relative motion in pixels
//   wheel STEPS           scroll (positive: away from the user)
//   resize WIDTH HEIGHT   resize the window
//   wait_idle             pause the script until the view is fully refined (no compile pending)
//                         and, after a replayed resize, rendered at the size it asked for
//   wait_reload           pause the script until the viewer has dealt with the next change to a
//                         watched file: a scene reloaded or its update refused, a new scene
//                         added, a plugin that failed to load
//   quit                  close the viewer
//   browser_search TEXT   open the formula browser and search for TEXT (underscores stand for
//                         spaces; "-" clears the search)
//   browser_pick N        switch to the browser's Nth scene (1 is the first found)
//   wait_thumbnails       pause the script until the browser's thumbnails are all made
//   hybrid_add NAME       append formula NAME to the current formula scene's sequence
//   hybrid_remove N       remove its Nth formula (1 is the first)
//   hybrid_move N OFFSET  move its Nth formula OFFSET places (-1: up, 1: down)
//   hybrid_repeat N COUNT repeat its Nth formula COUNT times
//   hybrid_save ID        save the current formula scene as ID.formula.json in the output folder
//                         (a hybrid edit rebuilds the scene like a reload: wait_reload waits
//                         for it)
//   set ID=VALUE          set a parameter of the scene shown, as --set does (the panel's sliders)
//
// KEY is an SDL key name: W, A, F12, PageDown, Escape, "Left Shift" is written Left_Shift
// (underscores stand for spaces).

#include <filesystem>
#include <istream>
#include <string>
#include <vector>

namespace fgr::viewer {

enum class ReplayAction {
    KeyDown,
    KeyUp,
    KeyPress,
    MouseDown,
    MouseUp,
    MouseMove,
    Wheel,
    Resize,
    WaitIdle,
    WaitReload,
    Quit,
    BrowserSearch,
    BrowserPick,
    WaitThumbnails,
    HybridAdd,
    HybridRemove,
    HybridMove,
    HybridRepeat,
    HybridSave,
    SetParameter,
    WaitSamples,
    WaitFrames
};

struct ReplayEvent {
    double delay_seconds = 0.0;  // after the previous event
    ReplayAction action = ReplayAction::Quit;
    std::string key;            // key events: the SDL key name, underscores turned to spaces
    int button = 0;             // mouse buttons: 1 left, 2 middle, 3 right (SDL numbering)
    bool has_position = false;  // mouse_down / mouse_up with X Y
    int x = 0, y = 0;           // mouse_down / mouse_up position; mouse_move: DX DY; resize: W H
    int wheel = 0;              // wheel steps
    std::string text;           // browser_search: the text; hybrid_add: the formula's name;
                                // hybrid_save: the new scene's id; set: ID=VALUE
    int slot = 0;               // hybrid edits: the formula's place, 0 the first
    int count = 0;              // browser_pick: the scene, 0 the first; hybrid_move: the offset;
                                // hybrid_repeat: the repeat count; wait_samples, wait_frames: N
    int line = 0;               // line number in the file, for messages
};

// Parses a replay script. `source_name` prefixes error messages ("FILE:LINE: reason"), which are
// thrown as std::runtime_error: unknown event, wrong argument count, a negative, non-finite or
// non-numeric delay, an unknown button, non-integer or out-of-range numbers (resize sides in
// [1, 16384], hybrid places and counts in [1, 64], offsets in [-16, 16]).
std::vector<ReplayEvent> parse_replay(std::istream& input, const std::string& source_name);

// Reads and parses FILE; a missing or unreadable file is a std::runtime_error naming it.
std::vector<ReplayEvent> load_replay(const std::filesystem::path& file);

// Whether the script waits at this event until the viewer says it may go on.
bool is_wait(ReplayAction action);

// Plays a script against a clock: due events come out in order, and a wait (WaitIdle, WaitReload,
// WaitThumbnails, WaitSamples, WaitFrames) holds everything after it until resume() is called
// (the viewer calls it once what the wait names has happened).
class ReplayClock {
public:
    explicit ReplayClock(std::vector<ReplayEvent> events);

    // Events due at `now_seconds` (a monotonic clock; the first call starts the script). A wait
    // event is returned too, and stops the stream until resume(now).
    std::vector<ReplayEvent> due(double now_seconds);

    // Continues after a wait: the following delays count from `now_seconds`.
    void resume(double now_seconds);

    bool waiting() const { return waiting_; }
    bool finished() const { return next_ >= events_.size() && !waiting_; }

private:
    std::vector<ReplayEvent> events_;
    std::size_t next_ = 0;
    bool started_ = false;
    bool waiting_ = false;
    double last_event_time_ = 0.0;  // when the previous event came out (or the script resumed)
};

}  // namespace fgr::viewer
