// SPDX-License-Identifier: Apache-2.0
#include "util/json_fields.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <vector>

#include "util/files.hpp"

namespace fgr::json_fields {
namespace {

using nlohmann::json;

std::string limit_text(double limit) { return fmt::format("{:g}", limit); }

}  // namespace

double finite_double(const json& value, const std::string& what, double limit) {
    if (!value.is_number()) fail(what + " must be a number");
    const double number = value.get<double>();
    if (!std::isfinite(number) || std::abs(number) > limit) {
        fail(what + " must be finite and at most " + limit_text(limit) + " in magnitude");
    }
    return number;
}

glm::dvec3 dvec3_from(const json& object, const char* key, const std::string& where, double limit) {
    const std::string what = where + " \"" + key + "\"";
    if (!object.contains(key)) fail(what + " is missing");
    const json& value = object.at(key);
    if (!value.is_array() || value.size() != 3) fail(what + " must be an array of 3 numbers");
    return {finite_double(value[0], what, limit), finite_double(value[1], what, limit),
            finite_double(value[2], what, limit)};
}

bool integer_in(const json& value, std::int64_t low, std::int64_t high, std::int64_t& out) {
    std::int64_t number = 0;
    if (value.is_number_unsigned()) {
        const auto unsigned_number = value.get<std::uint64_t>();
        if (unsigned_number >
            static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
            return false;
        }
        number = static_cast<std::int64_t>(unsigned_number);
    } else if (value.is_number_integer()) {
        number = value.get<std::int64_t>();
    } else {
        return false;
    }
    if (number < low || number > high) return false;
    out = number;
    return true;
}

void check_version(const json& document, int version) {
    const std::string reads = fmt::format("(this fgr reads version {})", version);
    if (!document.contains("version")) fail("\"version\" is missing " + reads);
    std::int64_t number = 0;
    if (!integer_in(document.at("version"), version, version, number)) {
        fail("unsupported \"version\" " + shown(document.at("version")) + " " + reads);
    }
}

json vec3_json(glm::dvec3 v) { return json::array({v.x, v.y, v.z}); }

void check_keys(const json& object, std::initializer_list<std::string_view> known,
                const std::string& where) {
    for (const auto& item : object.items()) {
        const std::string& key = item.key();
        if (std::find(known.begin(), known.end(), key) != known.end()) continue;
        std::string names;
        for (const std::string_view name : known) {
            names += fmt::format("{}\"{}\"", names.empty() ? "" : ", ", name);
        }
        fail(fmt::format("{}: unknown key {} (known: {})", where, shown(json(key)), names));
    }
}

void check_schema_key(const json& document) {
    if (document.contains("$schema") && !document.at("$schema").is_string()) {
        fail("\"$schema\" {} must be a string (the URI of the file's JSON Schema)",
             shown(document.at("$schema")));
    }
}

bool nests_deeper_than(std::string_view text, int limit) {
    int depth = 0;
    bool in_string = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (in_string) {
            if (c == '\\') {
                ++i;
            } else if (c == '"') {
                in_string = false;
            }
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            if (++depth > limit) return true;
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return false;
}

namespace {

constexpr std::size_t kShownLength = 40;

// Appends `value` to `out` until out holds more than kShownLength characters: a walk that stops
// where the message stops, so neither the value's size nor its depth matters.
void append_shown(const json& value, std::string& out) {
    if (out.size() > kShownLength) return;
    if (value.is_array()) {
        out += '[';
        bool first = true;
        for (const json& item : value) {
            if (out.size() > kShownLength) return;
            if (!first) out += ',';
            first = false;
            append_shown(item, out);
        }
        out += ']';
    } else if (value.is_object()) {
        out += '{';
        bool first = true;
        for (const auto& item : value.items()) {
            if (out.size() > kShownLength) return;
            if (!first) out += ',';
            first = false;
            append_shown(json(item.key().substr(0, kShownLength + 1)), out);
            out += ':';
            append_shown(item.value(), out);
        }
        out += '}';
    } else if (value.is_string()) {
        // Only the part that can be shown is escaped; cutting may split a UTF-8 sequence, which
        // the replacing dump turns into U+FFFD.
        const json shortened = value.get_ref<const std::string&>().substr(0, kShownLength + 1);
        out += shortened.dump(-1, ' ', /*ensure_ascii=*/true, json::error_handler_t::replace);
    } else {
        out += value.dump();
    }
}

// nlohmann's parse error without its "[json.exception.parse_error.101] " tag, shortened: its
// "last read" quotes the token, which may be a whole long string.
std::string syntax_error_text(const std::string& library_text) {
    std::string text = library_text;
    if (const auto tag_end = text.find("] "); text.starts_with("[json.") && tag_end != text.npos) {
        text.erase(0, tag_end + 2);
    }
    constexpr std::size_t kLongest = 160;
    if (text.size() > kLongest) text = text.substr(0, kLongest) + "...";
    for (char& c : text) {
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
    }
    return text;
}

// Thrown by KeyCheckingBuilder when an object repeats a key; caught in parse_document.
struct DuplicateKey {
    std::string key;
};

// The JSON library's own document builder, told every key first so that a key twice in one object
// is refused. A SAX handler rather than the parser's callback: after every object or array the
// callback parser scans the enclosing container for values it discarded, which makes an array of
// n objects cost n^2 (seconds for the 100,000 maps of a hostile IFS file).
class KeyCheckingBuilder : public nlohmann::detail::json_sax_dom_parser<json> {
public:
    explicit KeyCheckingBuilder(json& result) : json_sax_dom_parser(result, true) {}
    bool start_object(std::size_t size) {
        open_objects_.emplace_back();
        return json_sax_dom_parser::start_object(size);
    }
    bool end_object() {
        open_objects_.pop_back();
        return json_sax_dom_parser::end_object();
    }
    bool key(json::string_t& key) {
        if (!open_objects_.back().insert(key).second) throw DuplicateKey{key};
        return json_sax_dom_parser::key(key);
    }

private:
    // The keys seen in each object being built, innermost last.
    std::vector<std::set<std::string>> open_objects_;
};

}  // namespace

json parse_document(std::string_view text, const std::string& what) {
    if (const auto nul = text.find('\0'); nul != text.npos) {
        fail("{}: a NUL byte at offset {} (a JSON file is text)", what, nul);
    }
    if (nests_deeper_than(text, kMaxDocumentDepth)) {
        fail("{}: arrays and objects nest deeper than {} levels", what, kMaxDocumentDepth);
    }
    json document;
    KeyCheckingBuilder builder(document);
    try {
        json::sax_parse(text, &builder, nlohmann::detail::input_format_t::json, /*strict=*/true);
    } catch (const DuplicateKey& duplicate) {
        fail("{}: the key {} appears twice in one object", what, shown(json(duplicate.key)));
    } catch (const json::exception& error) {
        fail("{}: {}", what, syntax_error_text(error.what()));
    }
    return document;
}

json read_document(const std::filesystem::path& file, std::uintmax_t max_bytes,
                   const std::string& what) {
    std::string text;
    if (const std::string failure = read_file_bytes(file, text, max_bytes); !failure.empty()) {
        fail("{}: {}", what, failure);
    }
    return parse_document(text, what);
}

std::string shown(const json& value) {
    std::string text;
    append_shown(value, text);
    if (text.size() > kShownLength) text = text.substr(0, kShownLength) + "...";
    return text;
}

}  // namespace fgr::json_fields
