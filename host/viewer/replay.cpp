// SPDX-License-Identifier: Apache-2.0
#include "viewer/replay.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <utility>

#include "render/sample_budget.hpp"
#include "util/files.hpp"
#include "util/strings.hpp"

namespace fgr::viewer {
namespace {

// The largest window side a script may ask for; mouse positions must lie inside such a window.
constexpr int kMaxWindowSide = 16384;
constexpr int kIntMin = std::numeric_limits<int>::min();
constexpr int kIntMax = std::numeric_limits<int>::max();

// What an event name stands for and the argument counts it accepts: its short form and its long
// form (the same for all but mouse_down / mouse_up, whose X Y come as a pair or not at all).
struct EventSyntax {
    std::string_view name;
    ReplayAction action;
    int short_form_args;
    int long_form_args;
    std::string_view usage;  // for argument-count messages

    bool accepts(int arg_count) const {
        return arg_count == short_form_args || arg_count == long_form_args;
    }
};

constexpr std::array kEventSyntax{
    EventSyntax{"key_down", ReplayAction::KeyDown, 1, 1, "key_down KEY"},
    EventSyntax{"key_up", ReplayAction::KeyUp, 1, 1, "key_up KEY"},
    EventSyntax{"key", ReplayAction::KeyPress, 1, 1, "key KEY"},
    EventSyntax{"mouse_down", ReplayAction::MouseDown, 1, 3, "mouse_down BUTTON [X Y]"},
    EventSyntax{"mouse_up", ReplayAction::MouseUp, 1, 3, "mouse_up BUTTON [X Y]"},
    EventSyntax{"mouse_move", ReplayAction::MouseMove, 2, 2, "mouse_move DX DY"},
    EventSyntax{"wheel", ReplayAction::Wheel, 1, 1, "wheel STEPS"},
    EventSyntax{"resize", ReplayAction::Resize, 2, 2, "resize WIDTH HEIGHT"},
    EventSyntax{"wait_idle", ReplayAction::WaitIdle, 0, 0, "wait_idle"},
    EventSyntax{"wait_reload", ReplayAction::WaitReload, 0, 0, "wait_reload"},
    EventSyntax{"quit", ReplayAction::Quit, 0, 0, "quit"},
    EventSyntax{"browser_search", ReplayAction::BrowserSearch, 1, 1, "browser_search TEXT"},
    EventSyntax{"browser_pick", ReplayAction::BrowserPick, 1, 1, "browser_pick N"},
    EventSyntax{"wait_thumbnails", ReplayAction::WaitThumbnails, 0, 0, "wait_thumbnails"},
    EventSyntax{"wait_samples", ReplayAction::WaitSamples, 1, 1, "wait_samples N"},
    EventSyntax{"wait_frames", ReplayAction::WaitFrames, 1, 1, "wait_frames N"},
    EventSyntax{"hybrid_add", ReplayAction::HybridAdd, 1, 1, "hybrid_add NAME"},
    EventSyntax{"hybrid_remove", ReplayAction::HybridRemove, 1, 1, "hybrid_remove N"},
    EventSyntax{"hybrid_move", ReplayAction::HybridMove, 2, 2, "hybrid_move N OFFSET"},
    EventSyntax{"hybrid_repeat", ReplayAction::HybridRepeat, 2, 2, "hybrid_repeat N COUNT"},
    EventSyntax{"hybrid_save", ReplayAction::HybridSave, 1, 1, "hybrid_save ID"},
    EventSyntax{"set", ReplayAction::SetParameter, 1, 1, "set ID=VALUE"},
};

// Places in a hybrid's sequence and repeat counts a script may name (kFormulaMaxSlots and
// kFormulaMaxRepeat are smaller; the viewer says so in one line), and scenes in the browser.
constexpr int kMaxSlotNumber = 64;
constexpr int kMaxMove = 16;
constexpr int kMaxPick = 100000;
// Frames wait_frames may hold a script for: minutes of frames at any rate a viewer reaches.
constexpr int kMaxWaitFrames = 100000;

// SDL's button numbering.
constexpr std::array<std::pair<std::string_view, int>, 3> kButtons{{
    {"left", 1},
    {"middle", 2},
    {"right", 3},
}};

// One line being parsed: knows where it came from, so every error names the file and line.
class LineParser {
public:
    LineParser(const std::string& source_name, int line) : source_name_(source_name), line_(line) {}

    [[noreturn]] void fail(const std::string& reason) const {
        throw std::runtime_error(fmt::format("{}:{}: {}", source_name_, line_, reason));
    }

    double delay(const std::string& token) const {
        double value = 0.0;
        const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
        const bool whole_token = error == std::errc{} && end == token.data() + token.size();
        if (!whole_token || !std::isfinite(value) || value < 0.0) {
            fail(fmt::format("delay must be a non-negative number of seconds, got '{}'", token));
        }
        return value;
    }

    int integer(const std::string& token, std::string_view what, int lowest, int highest) const {
        int value = 0;
        const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (error == std::errc::result_out_of_range) {
            fail(fmt::format("{} {} is out of range [{}, {}]", what, token, lowest, highest));
        }
        if (error != std::errc{} || end != token.data() + token.size()) {
            fail(fmt::format("{} must be an integer, got '{}'", what, token));
        }
        if (value < lowest || value > highest) {
            fail(fmt::format("{} {} is out of range [{}, {}]", what, value, lowest, highest));
        }
        return value;
    }

    int button(const std::string& token) const {
        const auto* found = std::find_if(kButtons.begin(), kButtons.end(),
                                         [&](const auto& entry) { return entry.first == token; });
        if (found == kButtons.end()) {
            fail(fmt::format("unknown mouse button '{}' (left, middle, right)", token));
        }
        return found->second;
    }

    const EventSyntax& syntax(const std::string& name) const {
        const auto* found =
            std::find_if(kEventSyntax.begin(), kEventSyntax.end(),
                         [&](const EventSyntax& entry) { return entry.name == name; });
        if (found == kEventSyntax.end()) {
            fail(fmt::format("unknown event '{}'", name));
        }
        return *found;
    }

private:
    const std::string& source_name_;
    int line_;
};

std::vector<std::string> split_words(const std::string& text) {
    std::istringstream stream(text);
    std::vector<std::string> words;
    for (std::string word; stream >> word;) {
        words.push_back(word);
    }
    return words;
}

// SDL key names contain spaces ("Left Shift"); scripts write them with underscores.
std::string key_name(std::string word) {
    std::replace(word.begin(), word.end(), '_', ' ');
    return word;
}

// Fills the event's fields from its arguments (already checked to be a valid count).
void read_arguments(const LineParser& parser, const std::vector<std::string>& args,
                    ReplayEvent& event) {
    switch (event.action) {
        case ReplayAction::KeyDown:
        case ReplayAction::KeyUp:
        case ReplayAction::KeyPress:
            event.key = key_name(args[0]);
            break;
        case ReplayAction::MouseDown:
        case ReplayAction::MouseUp:
            event.button = parser.button(args[0]);
            event.has_position = args.size() == 3;
            if (event.has_position) {
                event.x = parser.integer(args[1], "X", 0, kMaxWindowSide - 1);
                event.y = parser.integer(args[2], "Y", 0, kMaxWindowSide - 1);
            }
            break;
        case ReplayAction::MouseMove:
            event.x = parser.integer(args[0], "DX", kIntMin, kIntMax);
            event.y = parser.integer(args[1], "DY", kIntMin, kIntMax);
            break;
        case ReplayAction::Wheel:
            event.wheel = parser.integer(args[0], "STEPS", kIntMin, kIntMax);
            break;
        case ReplayAction::Resize:
            event.x = parser.integer(args[0], "WIDTH", 1, kMaxWindowSide);
            event.y = parser.integer(args[1], "HEIGHT", 1, kMaxWindowSide);
            break;
        case ReplayAction::BrowserSearch:
            event.text = args[0] == "-" ? std::string() : key_name(args[0]);
            break;
        case ReplayAction::HybridAdd:
        case ReplayAction::HybridSave:
            event.text = args[0];
            break;
        case ReplayAction::SetParameter: {
            const size_t equals = args[0].find('=');
            if (equals == 0 || equals == std::string::npos || equals + 1 == args[0].size()) {
                parser.fail(fmt::format("set needs ID=VALUE, got '{}'", args[0]));
            }
            event.text = args[0];
            break;
        }
        case ReplayAction::BrowserPick:
            event.count = parser.integer(args[0], "N", 1, kMaxPick) - 1;
            break;
        case ReplayAction::WaitSamples:
            event.count = parser.integer(args[0], "N", 1, kMaxSamples);
            break;
        case ReplayAction::WaitFrames:
            event.count = parser.integer(args[0], "N", 1, kMaxWaitFrames);
            break;
        case ReplayAction::HybridRemove:
            event.slot = parser.integer(args[0], "N", 1, kMaxSlotNumber) - 1;
            break;
        case ReplayAction::HybridMove:
            event.slot = parser.integer(args[0], "N", 1, kMaxSlotNumber) - 1;
            event.count = parser.integer(args[1], "OFFSET", -kMaxMove, kMaxMove);
            break;
        case ReplayAction::HybridRepeat:
            event.slot = parser.integer(args[0], "N", 1, kMaxSlotNumber) - 1;
            event.count = parser.integer(args[1], "COUNT", 1, kMaxSlotNumber);
            break;
        case ReplayAction::WaitIdle:
        case ReplayAction::WaitReload:
        case ReplayAction::WaitThumbnails:
        case ReplayAction::Quit:
            break;
    }
}

ReplayEvent parse_event(const std::vector<std::string>& words, const LineParser& parser) {
    if (words.size() < 2) {
        parser.fail(fmt::format("expected an event after the delay '{}'", words[0]));
    }
    ReplayEvent event;
    event.delay_seconds = parser.delay(words[0]);
    const EventSyntax& syntax = parser.syntax(words[1]);
    event.action = syntax.action;

    const std::vector<std::string> args(words.begin() + 2, words.end());
    const auto count = static_cast<int>(args.size());
    if (!syntax.accepts(count)) {
        parser.fail(fmt::format("{} takes {}, got {} argument{}", syntax.name, syntax.usage, count,
                                count == 1 ? "" : "s"));
    }
    read_arguments(parser, args, event);
    return event;
}

}  // namespace

std::vector<ReplayEvent> parse_replay(std::istream& input, const std::string& source_name) {
    std::vector<ReplayEvent> events;
    int line_number = 0;
    for (std::string line; std::getline(input, line);) {
        ++line_number;
        const std::vector<std::string> words = split_words(line);
        if (words.empty() || words[0].starts_with('#')) {
            continue;
        }
        ReplayEvent event = parse_event(words, LineParser(source_name, line_number));
        event.line = line_number;
        events.push_back(std::move(event));
    }
    if (input.bad()) {
        throw std::runtime_error(
            fmt::format("{}: read error after line {}", source_name, line_number));
    }
    return events;
}

std::vector<ReplayEvent> load_replay(const std::filesystem::path& file) {
    const std::string name = printable_path(file);
    std::error_code error;
    if (std::filesystem::is_directory(file, error)) {
        throw std::runtime_error(
            fmt::format("cannot read replay file '{}': it is a directory", name));
    }
    // A script of a few hundred lines; bounded, and read whole (a FIFO is refused, not waited on).
    constexpr std::uintmax_t kMaxReplayBytes = std::uintmax_t{16} << 20;
    std::string text;
    if (const std::string failure = read_file_bytes(file, text, kMaxReplayBytes);
        !failure.empty()) {
        throw std::runtime_error(fmt::format("cannot read replay file '{}': {}", name, failure));
    }
    std::istringstream input(text);
    return parse_replay(input, name);
}

bool is_wait(ReplayAction action) {
    return action == ReplayAction::WaitIdle || action == ReplayAction::WaitReload ||
           action == ReplayAction::WaitThumbnails || action == ReplayAction::WaitSamples ||
           action == ReplayAction::WaitFrames;
}

ReplayClock::ReplayClock(std::vector<ReplayEvent> events) : events_(std::move(events)) {}

std::vector<ReplayEvent> ReplayClock::due(double now_seconds) {
    if (!started_) {
        started_ = true;
        last_event_time_ = now_seconds;
    }
    std::vector<ReplayEvent> ready;
    while (!waiting_ && next_ < events_.size()) {
        const ReplayEvent& event = events_[next_];
        const double due_time = last_event_time_ + event.delay_seconds;
        if (now_seconds < due_time) {
            break;
        }
        // Count the next delay from when this event was due, not from when due() noticed it, so
        // a slow frame does not stretch the rest of the script.
        last_event_time_ = due_time;
        waiting_ = is_wait(event.action);
        ready.push_back(event);
        ++next_;
    }
    return ready;
}

void ReplayClock::resume(double now_seconds) {
    if (!waiting_) {
        return;
    }
    waiting_ = false;
    last_event_time_ = now_seconds;
}

}  // namespace fgr::viewer
