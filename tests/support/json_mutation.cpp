// SPDX-License-Identifier: Apache-2.0
#include "json_mutation.hpp"

#include <cstdint>
#include <iterator>
#include <vector>

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

}  // namespace fgr::test
