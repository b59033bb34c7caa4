#include "render/path_settings.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <stdexcept>
#include <string>

#include "image/hdr_io.hpp"

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

glm::vec3 parse_radiance(std::string_view text) {
    const std::string what = "--environment uniform:RADIANCE";
    const size_t first = text.find(',');
    if (first == std::string_view::npos) return glm::vec3(parse_float(text, what));
    const size_t second = text.find(',', first + 1);
    if (second == std::string_view::npos || text.find(',', second + 1) != std::string_view::npos) {
        throw std::invalid_argument(
            fmt::format("{}: give one value or R,G,B, not '{}'", what, text));
    }
    return {parse_float(text.substr(0, first), what),
            parse_float(text.substr(first + 1, second - first - 1), what),
            parse_float(text.substr(second + 1), what)};
}

// The first directional light of the scene, the sky's sun unless the user placed it.
const Light* key_light(const Scene& scene) {
    const auto found = std::find_if(scene.lights.begin(), scene.lights.end(), [](const Light& l) {
        return l.type == LightType::Directional;
    });
    return found == scene.lights.end() ? nullptr : &*found;
}

}  // namespace

EnvironmentChoice parse_environment(std::string_view text) {
    EnvironmentChoice choice;
    if (text == "sky") {
        choice.kind = EnvironmentKind::Sky;
    } else if (text == "studio") {
        choice.kind = EnvironmentKind::Studio;
    } else if (text == "uniform") {
        choice.kind = EnvironmentKind::Uniform;
    } else if (text.starts_with("uniform:")) {
        choice.kind = EnvironmentKind::Uniform;
        choice.radiance = parse_radiance(text.substr(8));
    } else if (text.empty()) {
        throw std::invalid_argument(
            "--environment: give sky, studio, uniform[:RADIANCE] or an .hdr/.exr file");
    } else {
        choice.kind = EnvironmentKind::File;
        choice.file = std::filesystem::path(std::string(text));
    }
    return choice;
}

std::shared_ptr<const PreparedEnvironment> prepare_environment(const EnvironmentChoice& choice,
                                                               const Scene& scene) {
    if (!std::isfinite(choice.intensity) || choice.intensity < 0.0f) {
        throw std::invalid_argument("environment intensity must be a non-negative number");
    }
    if (!std::isfinite(choice.rotation_degrees)) {
        throw std::invalid_argument("environment rotation must be a finite angle");
    }
    auto prepared = std::make_shared<PreparedEnvironment>();
    prepared->rotation_degrees = choice.rotation_degrees;
    prepared->intensity = choice.intensity;
    HdrImage map;
    switch (choice.kind) {
        case EnvironmentKind::Sky: {
            SkySettings sky = choice.sky;
            const Light* key = key_light(scene);
            if (choice.sun_from_scene && key) {
                // The map turns with the rotation, and the sun with it; the key light's direction
                // is where the sun must end up.
                const glm::dvec3 towards = rotate_environment_direction(
                    glm::normalize(glm::dvec3(key->vector)), -choice.rotation_degrees);
                const glm::dvec2 uv = environment_coordinates(towards);
                sky.sun_azimuth_degrees = static_cast<float>(uv.x * 360.0);
                sky.sun_elevation_degrees =
                    static_cast<float>(std::clamp(90.0 - uv.y * 180.0, 0.0, 90.0));
            }
            validate_sky(sky);
            map = preetham_sky(sky);
            SunDisc sun = preetham_sun(sky);
            sun.direction = glm::vec3(
                rotate_environment_direction(glm::dvec3(sun.direction), choice.rotation_degrees));
            prepared->sun = sun;
            prepared->description =
                fmt::format("sky (turbidity {:g}, sun {:.0f} deg above the horizon)", sky.turbidity,
                            sky.sun_elevation_degrees);
            break;
        }
        case EnvironmentKind::Studio:
            map = studio_environment();
            prepared->description = "studio";
            break;
        case EnvironmentKind::Uniform:
            map = uniform_environment(choice.radiance);
            prepared->description =
                fmt::format("uniform radiance {:g} {:g} {:g}", choice.radiance.r, choice.radiance.g,
                            choice.radiance.b);
            break;
        case EnvironmentKind::File:
            map = read_hdr_image(choice.file);
            prepared->description =
                fmt::format("{} ({}x{})", choice.file.string(), map.width, map.height);
            break;
    }
    prepared->tables = environment_tables(
        map, choice.kind == EnvironmentKind::File ? choice.file.string() : prepared->description);
    prepared->mean_luminance = static_cast<float>(prepared->tables.luminance_integral /
                                                  (4.0 * 3.14159265358979) * choice.intensity);
    return prepared;
}

void check_path_settings(const PathSettings& settings) {
    if (settings.max_bounces < 0 || settings.max_bounces > kMaxBounces) {
        throw std::invalid_argument(fmt::format("bounces must be between 0 and {}", kMaxBounces));
    }
    if (settings.roulette_depth < 0 || settings.roulette_depth > kMaxBounces) {
        throw std::invalid_argument(
            fmt::format("Russian roulette depth must be between 0 (off) and {}", kMaxBounces));
    }
    if (!std::isfinite(settings.radiance_clamp) || settings.radiance_clamp < 0.0f) {
        throw std::invalid_argument("radiance clamp must be 0 (off) or a positive number");
    }
}

}  // namespace fgr
