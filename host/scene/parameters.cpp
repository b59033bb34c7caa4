// SPDX-License-Identifier: Apache-2.0
#include "scene/parameters.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

#include "util/suggest.hpp"

namespace fgr {
namespace {

std::string_view trim(std::string_view text) {
    while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
    while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
    return text;
}

// The whole of `text` as a finite float, or a UsageError naming the parameter.
float parse_number(const ParamInfo& param, std::string_view text) {
    text = trim(text);
    float value = 0.0f;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size()) {
        throw UsageError(fmt::format("parameter '{}': '{}' is not a number", param.id, text));
    }
    if (!std::isfinite(value)) {
        throw UsageError(fmt::format("parameter '{}': value must be finite", param.id));
    }
    return value;
}

void check_range(const ParamInfo& param, float value) {
    if (value < param.min_value || value > param.max_value) {
        throw UsageError(fmt::format("parameter '{}' = {} is outside [{}, {}]", param.id, value,
                                     param.min_value, param.max_value));
    }
}

std::string joined_choices(const ParamInfo& param) {
    std::string names;
    for (const auto& choice : param.choices) names += (names.empty() ? "" : "|") + choice;
    return names;
}

// The names of the choices the scene offers, for "did you mean".
std::vector<std::string> offered_choices(const ParamInfo& param) {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < param.choices.size(); ++i) {
        if (choice_offered(param, i)) names.push_back(param.choices[i]);
    }
    return names;
}

float parse_int(const ParamInfo& param, std::string_view text) {
    for (size_t i = 0; i < param.choices.size(); ++i) {
        if (param.choices[i] == trim(text)) return param.min_value + static_cast<float>(i);
    }
    if (!param.choices.empty() && !text.empty() &&
        std::isalpha(static_cast<unsigned char>(trim(text).front()))) {
        throw UsageError(fmt::format("parameter '{}' takes {} or a number, not '{}'{}", param.id,
                                     joined_choices(param), trim(text),
                                     did_you_mean(trim(text), offered_choices(param))));
    }
    const float value = parse_number(param, text);
    if (value != std::floor(value)) {
        throw UsageError(
            fmt::format("parameter '{}' takes whole numbers, not {}", param.id, value));
    }
    return value;
}

float parse_bool(const ParamInfo& param, std::string_view text) {
    text = trim(text);
    if (text == "true" || text == "on" || text == "1") return 1.0f;
    if (text == "false" || text == "off" || text == "0") return 0.0f;
    throw UsageError(fmt::format("parameter '{}' takes true or false, not '{}'", param.id, text));
}

std::vector<std::string_view> split_components(std::string_view text) {
    std::vector<std::string_view> parts;
    size_t start = 0;
    for (size_t comma; (comma = text.find(',', start)) != std::string_view::npos;
         start = comma + 1) {
        parts.push_back(text.substr(start, comma - start));
    }
    parts.push_back(text.substr(start));
    return parts;
}

// An enum value the scene does not offer (ABI 1.4 colour_modes): refused in one line, naming
// what it offers.
void check_offered(const Scene& scene, const ParamInfo& param, float value) {
    const auto index = static_cast<std::size_t>(value - param.min_value);
    if (param.choices.empty() || index >= param.choices.size() || choice_offered(param, index)) {
        return;
    }
    throw UsageError(fmt::format("scene '{}' does not offer {} '{}' (it offers {})", scene.id,
                                 param.id, param.choices[index], offered_choices_text(param)));
}

}  // namespace

std::vector<int> param_offsets(const Scene& scene) {
    std::vector<int> offsets;
    int offset = 0;
    for (const auto& param : scene.params) {
        offsets.push_back(offset);
        offset += param_components(param.type);
    }
    offsets.push_back(offset);
    return offsets;
}

std::vector<float> default_param_values(const Scene& scene) {
    std::vector<float> values;
    for (const auto& param : scene.params) {
        const int components = param_components(param.type);
        for (int c = 0; c < components; ++c) values.push_back(param.default_value[c]);
    }
    return values;
}

void set_param_from_text(const Scene& scene, std::vector<float>& values,
                         std::string_view assignment) {
    const size_t equals = assignment.find('=');
    if (equals == std::string_view::npos) {
        throw UsageError(fmt::format("--set expects id=value, got '{}'", assignment));
    }
    const std::string id(trim(assignment.substr(0, equals)));
    const std::string_view text = assignment.substr(equals + 1);
    const auto offsets = param_offsets(scene);
    for (size_t i = 0; i < scene.params.size(); ++i) {
        const ParamInfo& param = scene.params[i];
        if (param.id != id) continue;
        float* slot = values.data() + offsets[i];
        switch (param.type) {
            case ParamType::Float:
                slot[0] = parse_number(param, text);
                break;
            case ParamType::Int:
                slot[0] = parse_int(param, text);
                check_range(param, slot[0]);
                check_offered(scene, param, slot[0]);
                break;
            case ParamType::Bool:
                slot[0] = parse_bool(param, text);
                break;
            case ParamType::Vec3:
            case ParamType::Colour: {
                const auto parts = split_components(text);
                if (parts.size() != 3) {
                    throw UsageError(fmt::format("parameter '{}' takes x,y,z", param.id));
                }
                for (int c = 0; c < 3; ++c) slot[c] = parse_number(param, parts[c]);
                break;
            }
        }
        for (int c = 0; c < param_components(param.type); ++c) check_range(param, slot[c]);
        return;
    }
    std::vector<std::string> ids;
    for (const ParamInfo& param : scene.params) ids.push_back(param.id);
    throw UsageError(
        unknown_name_message(fmt::format("scene '{}' has no parameter '{}'", scene.id, id), id, ids,
                             fmt::format(" (`fgr list {}` lists its parameters)", scene.id)));
}

std::string param_text(const ParamInfo& param, const float* value) {
    if (param_components(param.type) == 3) {
        return fmt::format("{},{},{}", value[0], value[1], value[2]);
    }
    const auto index = static_cast<size_t>(value[0] - param.min_value);
    if (!param.choices.empty() && value[0] >= param.min_value && index < param.choices.size()) {
        return param.choices[index];
    }
    if (param.type == ParamType::Bool) return value[0] != 0.0f ? "true" : "false";
    return fmt::format("{}", value[0]);
}

std::vector<std::string> changed_params(const Scene& scene, const std::vector<float>& values) {
    std::vector<std::string> changed;
    const auto offsets = param_offsets(scene);
    for (size_t i = 0; i < scene.params.size(); ++i) {
        const ParamInfo& param = scene.params[i];
        const float* value = values.data() + offsets[i];
        if (!std::equal(value, value + param_components(param.type), param.default_value.begin())) {
            changed.push_back(param.id + "=" + param_text(param, value));
        }
    }
    return changed;
}

float param_value(const Scene& scene, const std::vector<float>& values, std::string_view id) {
    const auto offsets = param_offsets(scene);
    for (size_t i = 0; i < scene.params.size(); ++i) {
        if (scene.params[i].id == id) return values.at(offsets[i]);
    }
    throw std::out_of_range(fmt::format("scene '{}' has no parameter '{}'", scene.id, id));
}

std::vector<float> carry_param_values(const Scene& from, const std::vector<float>& values,
                                      const Scene& to) {
    std::vector<float> carried = default_param_values(to);
    const std::vector<int> from_offsets = param_offsets(from);
    const std::vector<int> to_offsets = param_offsets(to);
    for (size_t i = 0; i < to.params.size(); ++i) {
        const ParamInfo& param = to.params[i];
        const ParamInfo* old = from.find_param(param.id);
        if (old == nullptr || old->type != param.type) continue;
        const auto old_offset =
            static_cast<size_t>(from_offsets[static_cast<size_t>(old - from.params.data())]);
        const int components = param_components(param.type);
        bool edited = false;
        for (int c = 0; c < components; ++c) {
            edited |= values.at(old_offset + c) != old->default_value[static_cast<size_t>(c)];
        }
        if (!edited) continue;  // untouched: the new version's default
        if (!param.choices.empty()) {
            // An enum value the new version no longer offers falls back to its default.
            const float value = std::clamp(values.at(old_offset), param.min_value, param.max_value);
            if (!choice_offered(param, static_cast<std::size_t>(value - param.min_value))) continue;
        }
        for (int c = 0; c < components; ++c) {
            carried[static_cast<size_t>(to_offsets[i] + c)] =
                std::clamp(values.at(old_offset + c), param.min_value, param.max_value);
        }
    }
    return carried;
}

}  // namespace fgr
