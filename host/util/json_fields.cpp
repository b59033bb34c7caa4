// SPDX-License-Identifier: Apache-2.0
#include "util/json_fields.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

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

std::string shown(const json& value) {
    std::string text = value.dump(-1, ' ', /*ensure_ascii=*/true, json::error_handler_t::replace);
    if (text.size() > 40) text = text.substr(0, 40) + "...";
    return text;
}

}  // namespace fgr::json_fields
