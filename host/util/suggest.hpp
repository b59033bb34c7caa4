// SPDX-License-Identifier: Apache-2.0
#pragma once
// "Did you mean": the known name closest to a mistyped one (a scene id, an option, a mode, a
// parameter or one of its choices), so a one-line error can offer it instead of listing them all.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fgr {

// The optimal string alignment distance (restricted Damerau-Levenshtein): how many insertions,
// deletions, substitutions and swaps of two neighbouring characters turn `first` into `second`,
// compared without regard to ASCII case.
std::size_t edit_distance(std::string_view first, std::string_view second);

// The candidate closest to `typed`, when it is close enough to be what was meant: at most a third
// of typed's length in edits (at least one), and fewer edits than typed has characters. The first
// of equally close candidates wins; nullopt when none is close.
std::optional<std::string> closest_name(std::string_view typed,
                                        const std::vector<std::string>& candidates);

// "; did you mean 'NAME'?" for the closest candidate, "" when none is close: for the end of a
// "unknown ... 'typed'" message.
std::string did_you_mean(std::string_view typed, const std::vector<std::string>& candidates);

// `message` ("unknown thing 'typed'") followed by did_you_mean's suggestion, or by `otherwise`
// (such as " (`fgr list` lists them)") when no candidate is close.
std::string unknown_name_message(std::string message, std::string_view typed,
                                 const std::vector<std::string>& candidates,
                                 std::string_view otherwise);

}  // namespace fgr
