// SPDX-License-Identifier: Apache-2.0
#pragma once
// View files (NAME.fgrview.json): everything that decides an image, kept so that a view found in
// the viewer or on the command line can be rendered again, shared, and embedded in the images it
// made. The format is versioned and documented in docs/keep-your-work.md; its JSON Schema is
// schemas/view.schema.json. The values are kept as the user chooses them (the environment as
// `--environment` takes it, effects by name, parameters by id), so a file reads like the command
// that made it and stays meaningful when a scene's parameter layout changes.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "camera/projection.hpp"
#include "camera/view.hpp"
#include "render/environment.hpp"
#include "render/path_settings.hpp"
#include "render/precision.hpp"
#include "scene/render_mode.hpp"
#include "scene/scene.hpp"

namespace fgr {

constexpr const char* kViewFormat = "fgr-view";
constexpr int kViewVersion = 1;
constexpr const char* kViewFileSuffix = ".fgrview.json";
// A view is a few kilobytes; anything far larger is not one.
constexpr std::size_t kMaxViewBytes = 1 << 20;

// The path tracer's choices (`fgr render --mode path` options).
struct ViewPathChoices {
    uint32_t seed = 0;
    int bounces = 8;
    int roulette_depth = 3;
    float radiance_clamp = 0.0f;
    bool light_sampling = true;
    bool mis = true;
    bool scene_lights = true;
    std::string environment = "sky";  // as --environment takes it
    float environment_rotation = 0.0f;
    float environment_intensity = 1.0f;
    std::optional<float> turbidity;
    std::optional<float> sun_elevation;
    std::optional<float> sun_azimuth;
    bool denoise = false;  // the image denoised (`--denoise`), the raw estimate kept in EXR files
    bool operator==(const ViewPathChoices&) const = default;
};

// A parameter's value as `--set` takes it (numbers that read back exactly), and how the file
// writes it: a number, true/false, a choice's name, or an array of three numbers.
struct ViewParameter {
    enum class Kind { Number, Bool, Choice, Vector };
    std::string id;
    Kind kind = Kind::Number;
    std::string text;  // "8", "true", "iterations", "1,0.5,0.25"
    bool operator==(const ViewParameter&) const = default;
};

struct ViewFile {
    std::string scene_id;
    std::string scene_fingerprint;  // scene_fingerprint(): 16 hex digits
    std::string scene_file;         // the scene file it was opened from by path; "" for an id
    std::string fgr_version;        // the fgr that wrote it (informative)
    int width = 640;
    int height = 480;
    int bit_depth = 8;
    bool alpha = false;
    std::string layers;  // EXR layers, as --aov takes them
    CameraView camera;
    Projection projection;
    std::vector<ViewParameter> parameters;  // those that differ from the defaults, by id
    RenderMode mode = RenderMode::Shaded;
    int samples = 1;
    std::vector<std::string> effects;  // the whole set compiled in, by name
    Precision precision = Precision::Auto;
    bool prepass = true;
    std::optional<ViewPathChoices> path;  // path mode only
    bool operator==(const ViewFile&) const = default;
};

// A fingerprint of everything in a scene that decides its pixels: source, parameters and their
// defaults, lights, effects, march settings, mode and scale (not its name, description or
// cameras). A view saved with one fingerprint and rendered with another is reported.
std::string scene_fingerprint(const Scene& scene);

// The parameters of `values` (laid out as default_param_values(scene)) that differ from the
// scene's defaults, by id.
std::vector<ViewParameter> changed_parameters(const Scene& scene, const std::vector<float>& values);

// The parameter as `--set` takes it: "id=value".
std::string parameter_assignment(const ViewParameter& parameter);

// The file as JSON text (two-space indent, keys in a fixed order, "$schema" first).
std::string view_file_text(const ViewFile& view);

// Parses and validates a view file's text. Throws std::runtime_error with one line naming the key
// that is wrong (e.g. `"camera.fov": must be a number in (0, 180)`); the caller adds the file.
ViewFile parse_view_file(const std::string& text);

// Reads `file` (a regular file of at most kMaxViewBytes); errors name the file.
ViewFile read_view_file(const std::filesystem::path& file);
// Writes `view` to `file` atomically; errors name the file.
void write_view_file(const std::filesystem::path& file, const ViewFile& view);

// Whether `file` is named like a view file (NAME.fgrview.json).
bool is_view_file_name(const std::filesystem::path& file);

// One line when `scene` is not the scene the view was saved with (its fingerprint differs): the
// image may differ from the one the view was saved from. "" when it matches.
std::string scene_change_warning(const ViewFile& view, const Scene& scene);

// The path tracer's choices of a render: its settings and what lights it (the environment as
// --environment names it; the sky's turbidity and sun only where they are not the defaults: the
// turbidity, and the sun when it does not follow the scene's key light).
ViewPathChoices path_choices_of(const PathSettings& settings, const EnvironmentChoice& environment);
// And back, as `fgr render` reads them: the settings without an environment (std::invalid_argument
// for values the path tracer refuses), and the environment (std::invalid_argument for a bad
// --environment text, or the sky's settings given for another environment).
PathSettings path_settings_of(const ViewPathChoices& path);
EnvironmentChoice environment_choice_of(const ViewPathChoices& path);

// A few lines for people: the scene, size, camera, mode and what differs from the defaults
// (`fgr info FILE`).
std::string view_summary(const ViewFile& view);

}  // namespace fgr
