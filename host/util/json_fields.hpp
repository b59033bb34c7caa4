// SPDX-License-Identifier: Apache-2.0
#pragma once
// Reading fgr's JSON files (camera path files, IFS and formula scene files): the checks their
// fields share, so a number or a version is read and refused the same way in every file. Each
// throws std::runtime_error with a one-line reason that starts with `what` or `where` (callers add
// the file's name in front).

#include <fmt/format.h>

#include <cstdint>
#include <filesystem>
#include <glm/vec3.hpp>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace fgr::json_fields {

// Stops reading with a one-line reason (std::runtime_error): every reader here, and the files'
// own checks, fail this way.
[[noreturn]] inline void fail(const std::string& reason) { throw std::runtime_error(reason); }

template <typename... Args>
[[noreturn]] void fail(fmt::format_string<Args...> format, Args&&... args) {
    fail(fmt::format(format, std::forward<Args>(args)...));
}

// A number, finite and at most `limit` in magnitude.
double finite_double(const nlohmann::json& value, const std::string& what, double limit = 1e30);

// object[key], required: an array of three numbers as finite_double reads them.
glm::dvec3 dvec3_from(const nlohmann::json& object, const char* key, const std::string& where,
                      double limit = 1e30);

// Whether `value` is an integer in [low, high], compared as the integer JSON holds, never converted
// first (4294967297 is not 1, and 1.0 or "1" are not integers). Sets `out` when it is.
bool integer_in(const nlohmann::json& value, std::int64_t low, std::int64_t high,
                std::int64_t& out);

// "version" must be the integer `version`.
void check_version(const nlohmann::json& document, int version);

// What dvec3_from reads, written: three numbers (a double round-trips exactly).
nlohmann::json vec3_json(glm::dvec3 v);
// Refuses any key of `object` not in `known`: a misspelt key must not pass silently.
void check_keys(const nlohmann::json& object, std::initializer_list<std::string_view> known,
                const std::string& where);
// A document's "$schema", which names its JSON Schema for editors (schemas/, installed in
// share/fgr/schemas) and is otherwise not read: a string when present. Readers that refuse unknown
// keys list "$schema" among the known ones at the top level.
void check_schema_key(const nlohmann::json& document);

// Whether arrays and objects in the JSON `text` nest deeper than `limit` (brackets inside strings
// do not count): checked before parsing, so a hostile file never recurses through the JSON
// library.
bool nests_deeper_than(std::string_view text, int limit);

// How deep arrays and objects may nest in any file fgr reads: far deeper than any of its formats
// needs, far shallower than a recursion that could exhaust the stack.
inline constexpr int kMaxDocumentDepth = 64;

// The one way fgr parses a JSON file: the whole `text` is one JSON value and nothing else. Refused,
// with std::runtime_error("<what>: <reason>") on one line: a NUL byte (the JSON library would take
// it for the end and ignore what follows), nesting deeper than kMaxDocumentDepth (checked before
// parsing), a key twice in one object (the formats promise that no key passes silently, and a
// second copy would silently win), anything after the value, and every syntax error (its text
// shortened).
nlohmann::json parse_document(std::string_view text, const std::string& what);

// read_file_bytes of `file` (a regular file of at most max_bytes), then parse_document. Failures
// read "<what>: <reason>".
nlohmann::json read_document(const std::filesystem::path& file, std::uintmax_t max_bytes,
                             const std::string& what);

// A JSON value as it may appear in a one-line message: non-ASCII escaped, shortened to about 40
// characters. Only as much of the value as is shown is visited, so a huge or deep value costs no
// more than a small one.
std::string shown(const nlohmann::json& value);

}  // namespace fgr::json_fields
