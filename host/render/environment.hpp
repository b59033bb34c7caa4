// SPDX-License-Identifier: Apache-2.0
#pragma once
// Environments for the path tracer: generated environment maps (a photographic studio, a
// Preetham daylight sky with its sun, a uniform map for furnace tests), the tables that let the
// kernels look a map up and sample it by importance (kernels/shading/fgr_environment.cl), and
// which environment a render asks for (EnvironmentChoice) made ready to render with
// (PreparedEnvironment).
//
// Directions: fgr's world is z-up (scene cameras use up = +z), so environments are too. A map is
// equirectangular, width x height texels, row 0 at the top. Texel (column i, row j) covers polar
// angles theta (from +z) in [j, j + 1] * pi / height and azimuths phi in [i, i + 1] * 2 pi / width,
// where the unit direction of (theta, phi) is
//     (-sin theta cos phi, sin theta sin phi, cos theta):
// phi = 0 looks along -x, phi = 90 degrees along +y, 180 along +x (the map's centre column) and
// 270 along -y, so phi turns clockwise seen from above and a panorama seen from inside reads left
// to right as it does on paper (Blender's convention: the image centre looks along +x). The seam
// (u = 0 and u = 1) lies along -x. Rotating an environment by R degrees adds R to every azimuth
// (what the map shows at phi is seen at phi + R).

#include <cstdint>
#include <filesystem>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "device/kernel_layout.hpp"
#include "image/hdr_image.hpp"
#include "scene/environment_spec.hpp"
#include "scene/scene.hpp"

namespace fgr {

// The unit direction of map coordinates (u, v) in [0, 1]^2 (u = phi / 2 pi, v = theta / pi).
glm::dvec3 environment_direction(double u, double v);
// The map coordinates (u in [0, 1), v in [0, 1]) of a non-zero direction.
glm::dvec2 environment_coordinates(glm::dvec3 direction);
// `direction` turned about +z as an environment rotation of `degrees` turns what it shows.
glm::dvec3 rotate_environment_direction(glm::dvec3 direction, double degrees);

// Solid angle of the texels of row `row` of a width x height map (every texel of a row has the
// same): (2 pi / width) (cos theta_top - cos theta_bottom), computed without cancellation.
double environment_texel_solid_angle(int row, int width, int height);

// Radiance units. Generated daylight is photometric: sky and sun radiance are luminance in cd/m^2
// divided by kDaylightUnit (luminous efficacy folded in), so one unit is 20 kcd/m^2. With the
// default SkySettings a white Lambertian floor then reads about 1 (the sun and sky together give
// it about 63 klx), and so is well exposed at exposure 1.
constexpr double kDaylightUnit = 20000.0;  // cd/m^2 per radiance unit

// A photographic studio, width x width / 2 (width even, 8 to 16384): a dim grey surround, a
// slightly darker floor below the horizon, and three large soft rectangular light boxes: a warm
// key high at front left (azimuth 270, elevation 40), a cool, dimmer and larger fill low at
// front right (azimuth 175, elevation 15) and a narrow upright rim light behind (azimuth 45,
// elevation 30), for a camera at azimuth ~225 looking at the origin (from +x -y, as the built-in
// scenes' default cameras do). A white surface facing the key reads about 0.8. Texels hold
// averages over 3 x 3 points, so the boxes' edges are anti-aliased.
HdrImage studio_environment(int width = 512);

// Preetham, Shirley, Smits, "A Practical Analytic Model for Daylight" (SIGGRAPH 1999).
struct SkySettings {
    float turbidity = 3.0f;               // 1.7 (very clear) to 10 (hazy), the model's fitted range
    float sun_elevation_degrees = 35.0f;  // 0 (on the horizon) to 90 (at the zenith)
    float sun_azimuth_degrees = 40.0f;    // phi of the sun, as the map's azimuth (see above)
    float ground_albedo = 0.3f;           // 0 to 1: the plain ground below the horizon
};

// One-line std::invalid_argument for settings outside the ranges above, or non-finite ones.
void validate_sky(const SkySettings& sky);

// The sky dome WITHOUT the sun's disc (the circumsolar glow is the sky's), width x width / 2
// (width even, 8 to 16384), in daylight units. Above the horizon each texel holds the model's
// radiance at its centre: the Perez distribution of luminance Y and chromaticity x, y, scaled by
// the zenith values, xyY -> XYZ -> linear sRGB (Rec. 709 primaries, D65), negative components
// (outside the gamut) clamped to 0. Below the horizon a plain grey Lambertian ground of albedo
// ground_albedo lit by the sun and this sky: constant radiance albedo * E / pi, where E is the
// horizontal irradiance of the sky (integrated over its upper hemisphere) plus the sun's.
HdrImage preetham_sky(const SkySettings& sky, int width = 512);

// The same radiance at one unit direction (no texel averaging): the sky above the horizon
// (direction.z >= 0), the ground below it.
glm::vec3 preetham_sky_radiance(const SkySettings& sky, glm::dvec3 direction);

// The model's CIE xyY at a direction above the horizon, Y in cd/m^2, before any gamut clamping.
glm::dvec3 preetham_sky_xyY(const SkySettings& sky, glm::dvec3 direction);

// The sun's disc: unit direction towards it (z-up, azimuth as the map's), its radiance (daylight
// units, linear sRGB) and its true angular radius, 0.2667 degrees. The radiance is the
// extraterrestrial solar spectrum attenuated along the air mass by Rayleigh and aerosol
// scattering (turbidity), ozone, mixed gases and water vapour (the paper's Appendix A.1 and its
// tables), integrated against the CIE 1931 matching functions (Wyman, Sloan, Shirley, "Simple
// Analytic Approximations to the CIE XYZ Color Matching Functions", JCGT 2(2), 2013).
struct SunDisc {
    glm::vec3 direction;
    glm::vec3 radiance;
    float angular_radius_radians;
};
SunDisc preetham_sun(const SkySettings& sky);

// A small (8 x 4) map of one radiance everywhere, for furnace tests. Radiance must be finite and
// non-negative.
HdrImage uniform_environment(glm::vec3 radiance);

// Kernel-ready tables for importance sampling a map by luminance (Rec. 709 Y) times each texel's
// solid angle: a piecewise-constant distribution over the sphere that is constant within each
// texel (pbrt's Distribution2D, a row picked by its share and then a column by its share of the
// row, but uniform in solid angle inside a texel, so radiance / pdf is exactly constant where
// luminance is). Rows and columns are picked through alias tables (Walker, Vose), in constant
// time a lane. A map that is black everywhere is sampled uniformly.
//
// `data` is one flat float buffer for the kernel, laid out as kernels/shared/
// fgr_layout_environment.h says (the texels with the probability of each, the rows' alias table
// at rows_offset, the rows' columns' alias tables at columns_offset). Each texel's probability is
// the one the stored thresholds realise, so the kernel's sampling and pdf agree to a float's
// rounding; a texel of luminance 0 has probability 0.
struct EnvironmentTables {
    int width = 0;
    int height = 0;
    std::vector<float> data;
    int rows_offset = 0;
    int columns_offset = 0;
    double luminance_integral = 0.0;  // integral of luminance over the sphere (0: black map)
};

// Validates the map: non-empty, rgb holding width * height * 3 values, every value finite and
// non-negative, and small enough for int offsets. Errors are one-line std::invalid_argument
// messages starting with `name` (e.g. the file the map came from).
EnvironmentTables environment_tables(const HdrImage& map,
                                     std::string_view name = "environment map");

// `environment_info` of kernels/shared/fgr_layout_environment.h, passed by value as a kernel
// argument beside `data`.
using EnvironmentInfo = layout::environment_info;

// The kernel's view of `tables` turned by `rotation_degrees` (see above) and scaled by
// `intensity` (finite, non-negative; std::invalid_argument otherwise).
EnvironmentInfo environment_info(const EnvironmentTables& tables, double rotation_degrees = 0.0,
                                 float intensity = 1.0f);

struct EnvironmentChoice {
    EnvironmentKind kind = EnvironmentKind::Sky;  // scene/environment_spec.hpp
    std::filesystem::path file;                   // File
    glm::vec3 radiance{1.0f};                     // Uniform
    SkySettings sky;                              // Sky
    // Whether the user named it (--environment, the sky's settings, the viewer's panel). One the
    // user did not name gives way to the scene's own (with_scene_environment).
    bool given = false;
    // Sky: the sun stands where the scene's first directional light is, unless the sun's
    // elevation or azimuth was given.
    bool sun_from_scene = true;
    float rotation_degrees = 0.0f;  // about the world's up axis (z)
    float intensity = 1.0f;         // scales the environment's radiance (and its sun's)
};

// `--environment`'s value: "sky", "studio", "uniform" (radiance 1), "uniform:V" or
// "uniform:R,G,B", or else the path of an .hdr or .exr file (parse_environment_spec). Throws
// std::invalid_argument. The choice is `given`.
EnvironmentChoice parse_environment(std::string_view text);

// `--environment`'s value for `choice`'s kind, radiance or file, which parse_environment reads
// back to the same: "sky", "studio", "uniform" (radiance 1), "uniform:V", "uniform:R,G,B" (the
// shortest decimals that give back each float), or the file's path ("./" before a relative one
// that would read as another kind). Its other settings (rotation, intensity, the sky's) are
// options of their own.
std::string environment_argument(const EnvironmentChoice& choice);

// `choice`, or, when the user did not name it and the scene has an environment of its own
// (Scene::environment), that one, turned and scaled as `choice` says.
EnvironmentChoice with_scene_environment(EnvironmentChoice choice, const Scene& scene);

// Which lights shine in the path mode under `choice`, in a line for the log and the docs' terms:
// under the sky its sun takes the place of the scene's key light (its first directional light)
// and the scene's other lights shine too; under any other environment every scene light shines
// besides it; with `scene_lights` off the environment (and the sky's sun) alone. Under a uniform
// environment with scene lights it says that a furnace test wants --no-scene-lights, unless the
// environment is black (a closed room's: no light from outside, no furnace test).
std::string path_lights_text(const EnvironmentChoice& choice, const Scene& scene,
                             bool scene_lights);

// An environment ready to render with: its importance-sampling tables and, for the sky, its sun
// (a directional light with a disc, in fgr's z-up world), which takes the place of the scene's
// key light (its first directional light) while the scene's other lights still shine.
struct PreparedEnvironment {
    EnvironmentTables tables;
    std::optional<SunDisc> sun;
    float rotation_degrees = 0.0f;
    float intensity = 1.0f;
    float mean_luminance = 0.0f;  // over the sphere, intensity applied: light sampling weighs by it
    std::string description;      // one line for logs, e.g. "sky (turbidity 3, sun 35 deg up)"
};

// Generates or loads the environment (throws std::runtime_error naming a bad file).
std::shared_ptr<const PreparedEnvironment> prepare_environment(const EnvironmentChoice& choice,
                                                               const Scene& scene);

}  // namespace fgr
