// SPDX-License-Identifier: Apache-2.0
#include "scene/environment_spec.hpp"

#include <fmt/format.h>

#include <cmath>
#include <exception>
#include <stdexcept>
#include <string>

#include "scene/description_validation.hpp"
#include "scene/scene_limits.hpp"

namespace fgr {
namespace {

float parse_float(std::string_view text, std::string_view what) {
    const std::string copy(text);
    size_t used = 0;
    float value = 0.0f;
    try {
        value = std::stof(copy, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != copy.size() || copy.empty() || !std::isfinite(value) || value < 0.0f) {
        throw std::invalid_argument(
            fmt::format("{}: '{}' is not a non-negative number", what, text));
    }
    return value;
}

glm::vec3 parse_radiance(std::string_view text, std::string_view what) {
    const std::string where = fmt::format("{} uniform:RADIANCE", what);
    const size_t first = text.find(',');
    if (first == std::string_view::npos) return glm::vec3(parse_float(text, where));
    const size_t second = text.find(',', first + 1);
    if (second == std::string_view::npos || text.find(',', second + 1) != std::string_view::npos) {
        throw std::invalid_argument(
            fmt::format("{}: give one value or R,G,B, not '{}'", where, text));
    }
    return {parse_float(text.substr(0, first), where),
            parse_float(text.substr(first + 1, second - first - 1), where),
            parse_float(text.substr(second + 1), where)};
}

}  // namespace

EnvironmentSpec parse_environment_spec(std::string_view text, std::string_view what) {
    EnvironmentSpec spec;
    if (text == "sky") {
        spec.kind = EnvironmentKind::Sky;
    } else if (text == "studio") {
        spec.kind = EnvironmentKind::Studio;
    } else if (text == "uniform") {
        spec.kind = EnvironmentKind::Uniform;
    } else if (text.starts_with("uniform:")) {
        spec.kind = EnvironmentKind::Uniform;
        spec.radiance = parse_radiance(text.substr(8), what);
    } else if (text.empty()) {
        throw std::invalid_argument(
            fmt::format("{}: give sky, studio, uniform[:RADIANCE] or an .hdr/.exr file", what));
    } else {
        spec.kind = EnvironmentKind::File;
        spec.file = std::filesystem::path(std::string(text));
    }
    return spec;
}

void check_scene_environment(std::string_view text) {
    if (text.empty()) return;
    if (text.size() > scene_limits::kMaxIdLength) {
        throw std::invalid_argument(
            fmt::format("environment is over {} bytes", scene_limits::kMaxIdLength));
    }
    const std::string quoted = printable(text);
    EnvironmentSpec spec;
    try {
        spec = parse_environment_spec(text, "environment");
    } catch (const std::invalid_argument& error) {
        throw std::invalid_argument(fmt::format("{} (got '{}')", error.what(), quoted));
    }
    if (spec.kind == EnvironmentKind::File) {
        throw std::invalid_argument(fmt::format(
            "environment '{}' is not one fgr generates: a scene names sky, studio, uniform, "
            "uniform:V or uniform:R,G,B (a map file is the user's --environment FILE)",
            quoted));
    }
}

}  // namespace fgr
