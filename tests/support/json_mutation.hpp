// SPDX-License-Identifier: Apache-2.0
#pragma once
// Mutations of JSON documents for the seeded fuzz tests of fgr's scene files (IFS files, formula
// files): to the text (bytes deleted, inserted, duplicated, the text cut short) or to the parsed
// value (a number, string, array or object swapped for a nasty one, a number nudged, a key removed
// or misspelt, an array grown).

#include <nlohmann/json.hpp>
#include <string>

#include "fuzz_rng.hpp"

namespace fgr::test {

// A value a reader must refuse or survive: extremes, NaN-free oddities, wrong types, huge text.
nlohmann::json nasty_value(FuzzRng& rng);
// One mutation at a random place in the parsed document.
void mutate_value(nlohmann::json& document, FuzzRng& rng);
// One mutation of the text.
void mutate_text(std::string& text, FuzzRng& rng);

}  // namespace fgr::test
