// SPDX-License-Identifier: Apache-2.0
#pragma once
// Mutations of JSON documents for the seeded fuzz tests of fgr's JSON files (camera paths, IFS and
// formula files, views, text scenes' headers, the scene index): to the text (bytes deleted,
// inserted, duplicated, the text cut short), to its structure (nesting far too deep, a key
// given twice, a number no double holds, a NUL byte, bytes after the document) or to the parsed
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
// One mutation of the text that no parsed value can hold, at a random place: a value replaced by
// arrays or objects nested 63 to 100000 deep (closed or not), a key of an object given again, a
// number past double's range or with up to thousands of digits, a NUL byte, bytes after the
// document, an escaped NUL or terminal escape inside a string.
void mutate_structure(std::string& text, FuzzRng& rng);
// mutate_value (through a parse and a dump), mutate_text or mutate_structure, `count` times, the
// kind chosen at random; a text that no longer parses gets only text mutations.
void mutate_document(std::string& text, FuzzRng& rng, int count);

}  // namespace fgr::test
