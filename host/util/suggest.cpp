// SPDX-License-Identifier: Apache-2.0
#include "util/suggest.hpp"

#include <algorithm>

#include "util/lower_case.hpp"

namespace fgr {

std::size_t edit_distance(std::string_view first, std::string_view second) {
    // Case does not count: both in lower case once, not a character at a time.
    const std::string a = lower_case(first);
    const std::string b = lower_case(second);
    // Three rows of the dynamic programme: the swap of two neighbours looks two rows back.
    const std::size_t columns = b.size() + 1;
    std::vector<std::size_t> before(columns), previous(columns), row(columns);
    for (std::size_t j = 0; j < columns; ++j) previous[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        row[0] = i;
        for (std::size_t j = 1; j < columns; ++j) {
            const bool same = a[i - 1] == b[j - 1];
            row[j] = std::min({previous[j] + 1, row[j - 1] + 1, previous[j - 1] + (same ? 0 : 1)});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
                row[j] = std::min(row[j], before[j - 2] + 1);
            }
        }
        std::swap(before, previous);
        std::swap(previous, row);
    }
    return previous[b.size()];
}

std::optional<std::string> closest_name(std::string_view typed,
                                        const std::vector<std::string>& candidates) {
    std::optional<std::string> best;
    std::size_t best_distance = 0;
    for (const std::string& candidate : candidates) {
        const std::size_t distance = edit_distance(typed, candidate);
        const std::size_t allowed = std::max<std::size_t>(1, typed.size() / 3);
        // A name as far from `typed` as `typed` is long shares nothing worth suggesting.
        if (candidate == typed || distance > allowed || distance >= typed.size()) continue;
        if (!best || distance < best_distance) {
            best = candidate;
            best_distance = distance;
        }
    }
    return best;
}

std::string did_you_mean(std::string_view typed, const std::vector<std::string>& candidates) {
    const std::optional<std::string> name = closest_name(typed, candidates);
    return name ? "; did you mean '" + *name + "'?" : std::string();
}

std::string unknown_name_message(std::string message, std::string_view typed,
                                 const std::vector<std::string>& candidates,
                                 std::string_view otherwise) {
    const std::string suggestion = did_you_mean(typed, candidates);
    message += suggestion.empty() ? std::string(otherwise) : suggestion;
    return message;
}

}  // namespace fgr
