// SPDX-License-Identifier: Apache-2.0
#include "json_mutation.hpp"

#include <cstdint>
#include <iterator>
#include <string_view>
#include <vector>

#include "util/json_fields.hpp"

namespace fgr::test {
namespace {

using nlohmann::json;

// Every value in `document`, by JSON pointer.
void collect_pointers(const json& value, const json::json_pointer& at,
                      std::vector<json::json_pointer>& out) {
    out.push_back(at);
    if (value.is_object()) {
        for (const auto& item : value.items()) collect_pointers(item.value(), at / item.key(), out);
    } else if (value.is_array()) {
        for (std::size_t i = 0; i < value.size(); ++i) collect_pointers(value[i], at / i, out);
    }
}

}  // namespace

json nasty_value(FuzzRng& rng) {
    switch (rng.below(16)) {
        case 0:
            return 0;
        case 1:
            return -1;
        case 2:
            return 1e308;
        case 3:
            return -1e308;
        case 4:
            return 4.9e-324;
        case 5:
            return 4294967297ull;
        case 6:
            return 0.999999999999;
        case 7:
            return 1.0000000001;
        case 8:
            return "x\n\x1b[31m";
        case 9:
            return nullptr;
        case 10:
            return true;
        case 11:
            return json::array();
        case 12:
            return json::object();
        case 13:
            return json::array({1e-300, 0.5, -2});
        case 14:
            return static_cast<double>(rng.below(2000)) / 1000.0 - 1.0;
        default:
            return std::string(rng.below(5000), 'a');
    }
}

void mutate_value(json& document, FuzzRng& rng) {
    std::vector<json::json_pointer> pointers;
    collect_pointers(document, json::json_pointer(), pointers);
    const json::json_pointer at = pointers[rng.below(pointers.size())];
    json& target = document[at];
    switch (rng.below(5)) {
        case 0:  // replace
            target = nasty_value(rng);
            break;
        case 1:  // nudge a number
            if (target.is_number()) target = target.get<double>() * (rng.chance(0.5) ? 1.5 : -0.7);
            break;
        case 2:  // remove a key or an element
            if (target.is_object() && !target.empty()) {
                auto it = target.begin();
                std::advance(it, static_cast<std::ptrdiff_t>(rng.below(target.size())));
                target.erase(it);
            } else if (target.is_array() && !target.empty()) {
                target.erase(rng.below(target.size()));
            }
            break;
        case 3:  // add a key or grow an array
            if (target.is_object()) {
                target[rng.chance(0.5) ? "scael" : "colour"] = nasty_value(rng);
            } else if (target.is_array() && !target.empty()) {
                const json copy = target[rng.below(target.size())];
                const std::size_t copies = rng.chance(0.1) ? 70 : 1;
                for (std::size_t i = 0; i < copies; ++i) target.push_back(copy);
            }
            break;
        default:  // a number becomes an integer-looking one
            if (target.is_number()) target = static_cast<std::int64_t>(rng.below(40)) - 5;
            break;
    }
}

void mutate_text(std::string& text, FuzzRng& rng) {
    if (text.empty()) return;
    const std::size_t at = rng.below(text.size());
    switch (rng.below(4)) {
        case 0:
            text.erase(at, 1 + rng.below(8));
            break;
        case 1: {
            static const char kBytes[] = "{}[],:\"0123456789.eE-+ \\\n\x01\xff\xc3";
            text.insert(at, 1, kBytes[rng.below(sizeof(kBytes) - 1)]);
            break;
        }
        case 2:
            text.insert(at, text.substr(rng.below(text.size()), rng.below(32)));
            break;
        default:
            text.resize(at);
            break;
    }
}

namespace {

// Where values start in `text` outside strings: after ':' , ',' or '[' (blanks skipped).
std::vector<std::size_t> value_starts(const std::string& text) {
    std::vector<std::size_t> starts;
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
        } else if (c == ':' || c == ',' || c == '[') {
            std::size_t at = i + 1;
            while (at < text.size() && (text[at] == ' ' || text[at] == '\n')) ++at;
            starts.push_back(at);
        }
    }
    return starts;
}

// The end of the scalar starting at `at` (a number, a literal or a string); `at` for a bracket.
std::size_t scalar_end(const std::string& text, std::size_t at) {
    if (at >= text.size()) return at;
    if (text[at] == '"') {
        for (std::size_t i = at + 1; i < text.size(); ++i) {
            if (text[i] == '\\') {
                ++i;
            } else if (text[i] == '"') {
                return i + 1;
            }
        }
        return text.size();
    }
    std::size_t end = at;
    while (end < text.size() && std::string_view(",]}: \n").find(text[end]) == std::string::npos &&
           text[end] != '{' && text[end] != '[') {
        ++end;
    }
    return end;
}

std::string nested(FuzzRng& rng) {
    static const std::size_t kDepths[] = {63, 64, 65, 1000, 100000};
    const std::size_t depth = rng.pick(kDepths);
    const bool closed = rng.chance(0.8);
    switch (rng.below(3)) {
        case 0:
            return std::string(depth, '[') + (closed ? std::string(depth, ']') : "");
        case 1: {
            std::string text;
            text.reserve(depth * 6);
            for (std::size_t i = 0; i < depth; ++i) text += "{\"a\":";
            return text + "0" + (closed ? std::string(depth, '}') : "");
        }
        default:
            return std::string(depth, '[') + "\"x\"" + (closed ? std::string(depth, ']') : "");
    }
}

std::string huge_number(FuzzRng& rng) {
    switch (rng.below(4)) {
        case 0:
            return "1e" + std::to_string(309 + rng.below(100000));
        case 1:
            return "-" + std::string(1 + rng.below(2000), '9');
        case 2:
            return "18446744073709551616";
        default:
            return "0." + std::string(1 + rng.below(2000), '0') + "1e-400";
    }
}

}  // namespace

void mutate_structure(std::string& text, FuzzRng& rng) {
    const std::vector<std::size_t> starts = value_starts(text);
    const std::size_t at =
        starts.empty() ? rng.below(text.size() + 1) : starts[rng.below(starts.size())];
    switch (rng.below(6)) {
        case 0:  // a value nested too deep
            text.replace(at, scalar_end(text, at) - at, nested(rng));
            break;
        case 1: {  // a key of the object that holds `at` given again, first
            const std::size_t open = text.rfind('{', at);
            if (open == std::string::npos) break;
            const std::size_t key = text.find('"', open);
            const std::size_t key_end = key == std::string::npos ? key : scalar_end(text, key);
            if (key_end == std::string::npos || key_end >= text.size()) break;
            const std::string copy = text.substr(key, key_end - key);
            static const char* const kValues[] = {"0", "\"x\"", "null", "[]", "{}", "1e308"};
            text.insert(open + 1, copy + ":" + rng.pick(kValues) + ",");
            break;
        }
        case 2:  // a number no double holds
            text.replace(at, scalar_end(text, at) - at, huge_number(rng));
            break;
        case 3:  // a NUL byte, anywhere
            text.insert(rng.below(text.size() + 1), 1, '\0');
            break;
        case 4: {  // bytes after the document
            static const char* const kTrailing[] = {"x", "{}", " []", "\0{\"a\":1}", ",", "}"};
            text += rng.pick(kTrailing);
            break;
        }
        default:  // an escaped NUL or control character inside a string
            if (const std::size_t quote = text.find('"', at); quote != std::string::npos) {
                static const char* const kEscapes[] = {"\\u0000", "\\u001b[31m", "\\n"};
                text.insert(quote + 1, rng.pick(kEscapes));
            }
            break;
    }
}

void mutate_document(std::string& text, FuzzRng& rng, int count) {
    for (int m = 0; m < count; ++m) {
        const double kind = rng.unit();
        if (kind < 0.15) {
            mutate_structure(text, rng);
            continue;
        }
        // Parsed only when shallow: walking or dumping a deep value recurses through it.
        const bool deep = json_fields::nests_deeper_than(text, 200);
        json document = deep ? json() : json::parse(text, nullptr, /*allow_exceptions=*/false);
        if (kind < 0.4 || deep || document.is_discarded()) {
            mutate_text(text, rng);
        } else {
            mutate_value(document, rng);
            text =
                document.dump(rng.chance(0.5) ? 1 : -1, ' ', false, json::error_handler_t::replace);
        }
    }
}

}  // namespace fgr::test
