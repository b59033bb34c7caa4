// SPDX-License-Identifier: Apache-2.0
#include "camera/view_override.hpp"

#include <spdlog/fmt/fmt.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "camera/view_validation.hpp"

namespace fgr {
namespace {

[[noreturn]] void refuse(const std::string& option, const std::string& text,
                         const std::string& needs) {
    throw std::invalid_argument(fmt::format("{} '{}': {}", option, text, needs));
}

// One finite number filling `text` (blanks around it allowed), or nothing.
std::optional<double> finite_number(const std::string& text) {
    const char* begin = text.c_str();
    while (*begin == ' ' || *begin == '\t') ++begin;
    if (*begin == '\0') return std::nullopt;
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(begin, &end);
    while (*end == ' ' || *end == '\t') ++end;
    if (*end != '\0' || errno == ERANGE || !std::isfinite(value)) return std::nullopt;
    return value;
}

glm::dvec3 parse_vector(const std::string& option, const std::string& text) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    for (std::size_t comma; (comma = text.find(',', start)) != std::string::npos;
         start = comma + 1) {
        parts.push_back(text.substr(start, comma - start));
    }
    parts.push_back(text.substr(start));
    const std::string needs = "expected three finite numbers X,Y,Z";
    if (parts.size() != 3) refuse(option, text, needs);
    glm::dvec3 vector(0.0);
    for (int i = 0; i < 3; ++i) {
        const std::optional<double> value = finite_number(parts[static_cast<std::size_t>(i)]);
        if (!value) refuse(option, text, needs);
        vector[i] = *value;
    }
    return vector;
}

std::string vector_text(const glm::dvec3& v) {
    return fmt::format("{:g},{:g},{:g}", v.x, v.y, v.z);
}

}  // namespace

ViewOverride parse_view_override(const ViewOverrideText& text) {
    ViewOverride parsed;
    if (text.eye) parsed.eye = parse_vector("--eye", *text.eye);
    if (text.target) parsed.target = parse_vector("--target", *text.target);
    // Up and fov go through double as camera path files read them, so the same numbers typed
    // here and written there give the same view to the bit.
    if (text.up) parsed.up = glm::vec3(parse_vector("--up", *text.up));
    if (text.fov) {
        const std::optional<double> degrees = finite_number(*text.fov);
        if (!degrees || !(*degrees > 0.0 && *degrees < 180.0)) {
            refuse("--fov", *text.fov, "expected degrees between 0 and 180 (exclusive)");
        }
        parsed.fov_degrees = static_cast<float>(*degrees);
    }
    return parsed;
}

CameraView apply_view_override(const CameraView& base, const ViewOverride& override_view) {
    CameraView view = base;
    if (override_view.eye) view.position = *override_view.eye;
    if (override_view.target) view.target = *override_view.target;
    if (override_view.up) view.up = *override_view.up;
    if (override_view.fov_degrees) view.fov_degrees = *override_view.fov_degrees;
    if (const std::string problem = view_problem(view); !problem.empty()) {
        throw std::invalid_argument(fmt::format(
            "--eye/--target/--up/--fov give a view fgr cannot render: {} (eye {}, target {}, up "
            "{}, fov {:g})",
            problem, vector_text(view.position), vector_text(view.target),
            vector_text(glm::dvec3(view.up)), view.fov_degrees));
    }
    return view;
}

}  // namespace fgr
