#pragma once
// What the path tracer (render mode "path") is asked to do beyond the view: how long paths run,
// which sampling strategies it combines, and the environment that lights the scene.

#include <cstdint>
#include <filesystem>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "render/environment.hpp"
#include "scene/scene.hpp"

namespace fgr {

enum class EnvironmentKind {
    Sky,      // Preetham's daylight sky with its sun (the default)
    Studio,   // fgr's generated photo studio: soft boxes in a grey room
    Uniform,  // the same radiance from every direction (furnace tests)
    File,     // an equirectangular .hdr or .exr
};

struct EnvironmentChoice {
    EnvironmentKind kind = EnvironmentKind::Sky;
    std::filesystem::path file;  // File
    glm::vec3 radiance{1.0f};    // Uniform
    SkySettings sky;             // Sky
    // Sky: the sun stands where the scene's first directional light is, unless the sun's
    // elevation or azimuth was given.
    bool sun_from_scene = true;
    float rotation_degrees = 0.0f;  // about the world's up axis (z)
    float intensity = 1.0f;         // scales the environment's radiance (and its sun's)
};

// `--environment`'s value: "sky", "studio", "uniform" (radiance 1), "uniform:V" or
// "uniform:R,G,B", or else the path of an .hdr or .exr file. Throws std::invalid_argument.
EnvironmentChoice parse_environment(std::string_view text);

// An environment ready to render with: its importance-sampling tables and, for the sky, its sun
// (a directional light with a disc, in fgr's z-up world), which takes the place of the scene's
// key light (its first directional light) while the scene's other lights still shine.
struct PreparedEnvironment {
    EnvironmentTables tables;
    std::optional<SunDisc> sun;
    float rotation_degrees = 0.0f;
    float intensity = 1.0f;
    float mean_luminance = 0.0f;  // over the sphere, intensity applied: its share of light picks
    std::string description;      // one line for logs, e.g. "sky (turbidity 3, sun 35 deg up)"
};

// Generates or loads the environment (throws std::runtime_error naming a bad file).
std::shared_ptr<const PreparedEnvironment> prepare_environment(const EnvironmentChoice& choice,
                                                               const Scene& scene);

struct PathSettings {
    int max_bounces = 8;          // scattering events after the camera ray, at most
    int roulette_depth = 3;       // Russian roulette from this bounce on (unbiased)
    float radiance_clamp = 0.0f;  // > 0 clamps each sample's radiance (removes fireflies, biased)
    bool light_sampling = true;   // next-event estimation towards the environment and lights
    bool mis = true;              // power-heuristic weights between light and BSDF sampling
    bool environment_importance = true;  // sample the environment by its luminance
    bool scene_lights = true;            // the scene's own lights shine besides the environment
    // Stratified samples (scrambled Sobol per pixel); false draws independent random ones, to
    // measure what stratification buys (the error then falls exactly as 1 / sqrt(samples)).
    bool stratified = true;
    uint32_t seed = 0;  // another seed, another noise pattern
    // What lights the scene; null renders with the default sky.
    std::shared_ptr<const PreparedEnvironment> environment;
    // The environment compares by identity: a prepared environment is never changed in place.
    bool operator==(const PathSettings&) const = default;
};

// Limits fgr accepts, checked by check_path_settings (std::invalid_argument, one line).
constexpr int kMaxBounces = 1024;
void check_path_settings(const PathSettings& settings);

}  // namespace fgr
