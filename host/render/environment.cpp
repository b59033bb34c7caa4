// SPDX-License-Identifier: Apache-2.0
#include "render/environment.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "image/hdr_io.hpp"
#include "scene/environment_spec.hpp"

namespace fgr {
namespace {

constexpr double kPi = std::numbers::pi;

// Rec. 709 / sRGB luminance of linear RGB.
double luminance(double r, double g, double b) { return 0.2126 * r + 0.7152 * g + 0.0722 * b; }

// CIE XYZ -> linear sRGB (Rec. 709 primaries, D65 white), negative components clamped to 0.
glm::dvec3 xyz_to_rgb(glm::dvec3 xyz) {
    const glm::dvec3 rgb(3.2404542 * xyz.x - 1.5371385 * xyz.y - 0.4985314 * xyz.z,
                         -0.9692660 * xyz.x + 1.8760108 * xyz.y + 0.0415560 * xyz.z,
                         0.0556434 * xyz.x - 0.2040259 * xyz.y + 1.0572252 * xyz.z);
    return glm::max(rgb, glm::dvec3(0.0));
}

void validate_width(int width, const char* what) {
    if (width < 8 || width > 16384 || width % 2 != 0) {
        throw std::invalid_argument(
            fmt::format("{} width {} must be even and in [8, 16384]", what, width));
    }
}

// The map's direction at polar angle theta (from +z) and azimuth phi, from their sines and
// cosines: (-sin theta cos phi, sin theta sin phi, cos theta).
glm::dvec3 direction_from_angles(double sin_theta, double cos_theta, double cos_phi,
                                 double sin_phi) {
    return {-sin_theta * cos_phi, sin_theta * sin_phi, cos_theta};
}

// Fills a width x width / 2 map with `radiance(direction)` averaged over n x n points of each
// texel, equally spaced in cos theta and phi (so equally weighted by solid angle). The points'
// sines and cosines are computed once per row and once per column, as environment_direction
// computes them: a map of 512 x 256 texels has 1.2 M points and only 768 rows and 1536 columns
// of them.
template <typename F>
HdrImage generate_map(int width, int n, F&& radiance) {
    HdrImage map;
    map.width = width;
    map.height = width / 2;
    map.rgb.assign(size_t(map.width) * size_t(map.height) * 3, 0.0f);
    std::vector<double> cos_phi(size_t(map.width) * n), sin_phi(cos_phi.size());
    for (int x = 0; x < map.width; ++x) {
        for (int i = 0; i < n; ++i) {
            const double phi = 2.0 * kPi * ((x + (i + 0.5) / n) / map.width);
            cos_phi[size_t(x) * n + i] = std::cos(phi);
            sin_phi[size_t(x) * n + i] = std::sin(phi);
        }
    }
    std::vector<double> sin_theta(n), cos_theta(n);
    for (int y = 0; y < map.height; ++y) {
        const double cos_top = std::cos(kPi * y / map.height);
        const double cos_bottom = std::cos(kPi * (y + 1) / map.height);
        for (int j = 0; j < n; ++j) {
            const double z = cos_top + (cos_bottom - cos_top) * (j + 0.5) / n;
            // pi times v = acos(z) / pi, rounded as environment_direction(u, v) rounds it.
            const double theta = kPi * (std::acos(std::clamp(z, -1.0, 1.0)) / kPi);
            sin_theta[j] = std::sin(theta);
            cos_theta[j] = std::cos(theta);
        }
        for (int x = 0; x < map.width; ++x) {
            glm::dvec3 sum(0.0);
            for (int j = 0; j < n; ++j) {
                for (int i = 0; i < n; ++i) {
                    const size_t column = size_t(x) * n + i;
                    sum += glm::dvec3(radiance(direction_from_angles(
                        sin_theta[j], cos_theta[j], cos_phi[column], sin_phi[column])));
                }
            }
            const glm::dvec3 mean = sum / double(n * n);
            const size_t index = map.pixel_index(x, y);
            map.rgb[index] = float(mean.x);
            map.rgb[index + 1] = float(mean.y);
            map.rgb[index + 2] = float(mean.z);
        }
    }
    return map;
}

// ---- The studio ----

// A soft rectangular light box: a planar rectangle seen from the centre (gnomonic projection
// around its centre direction), `half_width` x `half_height` degrees, edges softened over
// `soft` (in tangent units), a little brighter in the middle as a diffuser is.
struct LightBox {
    double azimuth_degrees;
    double elevation_degrees;
    double half_width_degrees;
    double half_height_degrees;
    glm::dvec3 radiance;
};

double smooth_step(double edge0, double edge1, double x) {
    const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// A light box where the map sees it: its centre direction, the tangent frame around it (`up`
// towards +z in the box's plane, `side` across it) and its half extents in tangent units.
struct PlacedLightBox {
    glm::dvec3 centre, up, side;
    double half_x, half_y;
    glm::dvec3 radiance;
};

PlacedLightBox place_light_box(const LightBox& box) {
    PlacedLightBox placed;
    placed.centre =
        environment_direction(box.azimuth_degrees / 360.0, (90.0 - box.elevation_degrees) / 180.0);
    placed.up = glm::normalize(glm::dvec3(0.0, 0.0, 1.0) - placed.centre * placed.centre.z);
    placed.side = glm::cross(placed.up, placed.centre);
    placed.half_x = std::tan(box.half_width_degrees * kPi / 180.0);
    placed.half_y = std::tan(box.half_height_degrees * kPi / 180.0);
    placed.radiance = box.radiance;
    return placed;
}

glm::dvec3 light_box(const PlacedLightBox& box, glm::dvec3 direction) {
    const double facing = glm::dot(direction, box.centre);
    if (facing <= 0.0) return glm::dvec3(0.0);
    const double x = glm::dot(direction, box.side) / facing;
    const double y = glm::dot(direction, box.up) / facing;
    constexpr double soft = 0.06;
    const double inside = smooth_step(-soft, soft, box.half_x - std::abs(x)) *
                          smooth_step(-soft, soft, box.half_y - std::abs(y));
    const double r2 = (x * x) / (box.half_x * box.half_x) + (y * y) / (box.half_y * box.half_y);
    return box.radiance * inside * (1.0 - 0.15 * std::min(r2, 2.0));
}

// ---- Preetham, Shirley, Smits, "A Practical Analytic Model for Daylight", SIGGRAPH 1999 ----

// The Perez et al. distribution F(theta, gamma) = (1 + A e^(B / cos theta))
// (1 + C e^(D gamma) + E cos^2 gamma), with the paper's turbidity-linear coefficients
// (Appendix A.2).
struct Perez {
    double a, b, c, d, e;
    double operator()(double cos_theta, double gamma, double cos_gamma) const {
        // At the horizon B / cos theta -> -inf (B < 0 in the fitted range): the term vanishes.
        const double horizon_term = a * std::exp(b / std::max(cos_theta, 1e-6));
        return (1.0 + horizon_term) * (1.0 + c * std::exp(d * gamma) + e * cos_gamma * cos_gamma);
    }
};

struct PreethamModel {
    glm::dvec3 sun;  // unit, towards the sun
    double theta_s;  // the sun's zenith angle
    Perez luminance, x, y;
    double zenith_luminance;  // cd/m^2
    double zenith_x, zenith_y;
    glm::dvec3 ground;  // radiance below the horizon, daylight units

    explicit PreethamModel(const SkySettings& sky) {
        validate_sky(sky);
        const double t = sky.turbidity;
        theta_s = (90.0 - double(sky.sun_elevation_degrees)) * kPi / 180.0;
        sun = environment_direction(double(sky.sun_azimuth_degrees) / 360.0, theta_s / kPi);
        luminance = {0.1787 * t - 1.4630, -0.3554 * t + 0.4275, -0.0227 * t + 5.3251,
                     0.1206 * t - 2.5771, -0.0670 * t + 0.3703};
        x = {-0.0193 * t - 0.2592, -0.0665 * t + 0.0008, -0.0004 * t + 0.2125, -0.0641 * t - 0.8989,
             -0.0033 * t + 0.0452};
        y = {-0.0167 * t - 0.2608, -0.0950 * t + 0.0092, -0.0079 * t + 0.2102, -0.0441 * t - 1.6537,
             -0.0109 * t + 0.0529};
        // Zenith luminance (kcd/m^2 in the paper) and chromaticity (Appendix A.2).
        const double chi = (4.0 / 9.0 - t / 120.0) * (kPi - 2.0 * theta_s);
        zenith_luminance = 1000.0 * ((4.0453 * t - 4.9710) * std::tan(chi) - 0.2155 * t + 2.4192);
        const double s1 = theta_s, s2 = s1 * s1, s3 = s2 * s1, t2 = t * t;
        zenith_x = t2 * (0.00166 * s3 - 0.00375 * s2 + 0.00209 * s1) +
                   t * (-0.02903 * s3 + 0.06377 * s2 - 0.03202 * s1 + 0.00394) +
                   (0.11693 * s3 - 0.21196 * s2 + 0.06052 * s1 + 0.25886);
        zenith_y = t2 * (0.00275 * s3 - 0.00610 * s2 + 0.00317 * s1) +
                   t * (-0.04214 * s3 + 0.08970 * s2 - 0.04153 * s1 + 0.00516) +
                   (0.15346 * s3 - 0.26756 * s2 + 0.06670 * s1 + 0.26688);
        ground = glm::dvec3(0.0);
    }

    // xyY at a direction above the horizon: each quantity is its zenith value times
    // F(theta, gamma) / F(0, theta_s).
    glm::dvec3 xyY(glm::dvec3 direction) const {
        const double cos_theta = std::max(direction.z, 0.0);
        const double cos_gamma = std::clamp(glm::dot(direction, sun), -1.0, 1.0);
        const double gamma = std::acos(cos_gamma);
        const double cos_s = std::cos(theta_s);
        const auto value = [&](const Perez& f, double zenith) {
            return zenith * f(cos_theta, gamma, cos_gamma) / f(1.0, theta_s, cos_s);
        };
        return {value(x, zenith_x), value(y, zenith_y), value(luminance, zenith_luminance)};
    }

    glm::dvec3 sky_rgb(glm::dvec3 direction) const {
        const glm::dvec3 c = xyY(direction);
        const double big_y = std::max(c.z, 0.0);
        const glm::dvec3 xyz(c.x / c.y * big_y, big_y, (1.0 - c.x - c.y) / c.y * big_y);
        return xyz_to_rgb(xyz) / kDaylightUnit;
    }

    glm::dvec3 radiance(glm::dvec3 direction) const {
        return direction.z >= 0.0 ? sky_rgb(direction) : ground;
    }
};

// ---- The sun: Preetham et al. Appendix A.1, with its tables (from Iqbal, "An Introduction to
// Solar Radiation", 1983) restricted to the visible range integrated here, 380-750 nm. ----

// Extraterrestrial solar spectral radiance, W / (m^2 nm sr), 380 to 750 nm every 10 nm.
constexpr std::array<double, 38> kSolarRadiance = {
    16559.0, 16233.7, 21127.5, 25888.2, 25829.1, 24232.3, 26760.5, 29658.3, 30545.4, 30057.5,
    30663.7, 28830.4, 28712.1, 27825.0, 27100.6, 27233.6, 26361.3, 25503.8, 25060.2, 25311.6,
    25355.9, 25134.2, 24631.5, 24173.2, 23685.3, 23212.1, 22827.7, 22339.8, 21970.2, 21526.7,
    21097.9, 20728.3, 20240.4, 19870.8, 19427.2, 19072.4, 18628.9, 18259.2};

struct TablePoint {
    double wavelength, value;
};

// Ozone absorption coefficient k_o (1/cm), the table's points from 355 nm up (it is 0 at 355 and
// tabulated from 445 nm).
constexpr std::array<TablePoint, 54> kOzone = {{
    {355, 0.0},   {445, 0.003}, {450, 0.003}, {455, 0.004}, {460, 0.006}, {465, 0.008},
    {470, 0.009}, {475, 0.012}, {480, 0.014}, {485, 0.017}, {490, 0.021}, {495, 0.025},
    {500, 0.03},  {505, 0.035}, {510, 0.04},  {515, 0.045}, {520, 0.048}, {525, 0.057},
    {530, 0.063}, {535, 0.07},  {540, 0.075}, {545, 0.08},  {550, 0.085}, {555, 0.095},
    {560, 0.103}, {565, 0.110}, {570, 0.12},  {575, 0.122}, {580, 0.12},  {585, 0.118},
    {590, 0.115}, {595, 0.12},  {600, 0.125}, {605, 0.130}, {610, 0.12},  {620, 0.105},
    {630, 0.09},  {640, 0.079}, {650, 0.067}, {660, 0.057}, {670, 0.048}, {680, 0.036},
    {690, 0.028}, {700, 0.023}, {710, 0.018}, {720, 0.014}, {730, 0.011}, {740, 0.010},
    {750, 0.009}, {760, 0.007}, {770, 0.004}, {780, 0.0},   {790, 0.0},   {800, 0.0},
}};

// Water vapour absorption coefficient k_wa (1/cm), 0 below 689 nm.
constexpr std::array<TablePoint, 9> kWaterVapour = {{
    {689, 0.0},
    {690, 0.016},
    {700, 0.024},
    {710, 0.0125},
    {720, 1.0},
    {730, 0.87},
    {740, 0.061},
    {750, 0.001},
    {760, 0.00001},
}};
// (Mixed gases absorb only from 759 nm, outside the range integrated.)

template <size_t N>
double interpolate(const std::array<TablePoint, N>& table, double wavelength) {
    if (wavelength <= table.front().wavelength) return table.front().value;
    for (size_t i = 1; i < N; ++i) {
        if (wavelength <= table[i].wavelength) {
            const double s = (wavelength - table[i - 1].wavelength) /
                             (table[i].wavelength - table[i - 1].wavelength);
            return table[i - 1].value + s * (table[i].value - table[i - 1].value);
        }
    }
    return table.back().value;
}

double solar_radiance(double wavelength) {
    const double position = std::clamp((wavelength - 380.0) / 10.0, 0.0, 37.0);
    const size_t i = std::min(size_t(position), size_t(36));
    const double s = position - double(i);
    return kSolarRadiance[i] + s * (kSolarRadiance[i + 1] - kSolarRadiance[i]);
}

// Wyman, Sloan, Shirley (JCGT 2013): the CIE 1931 2-degree matching functions as sums of
// piecewise Gaussians.
double lobe(double wavelength, double mean, double sigma_below, double sigma_above) {
    const double t = (wavelength - mean) / (wavelength < mean ? sigma_below : sigma_above);
    return std::exp(-0.5 * t * t);
}
glm::dvec3 cie_1931(double l) {
    return {1.056 * lobe(l, 599.8, 37.9, 31.0) + 0.362 * lobe(l, 442.0, 16.0, 26.7) -
                0.065 * lobe(l, 501.1, 20.4, 26.2),
            0.821 * lobe(l, 568.8, 46.9, 40.5) + 0.286 * lobe(l, 530.9, 16.3, 31.1),
            1.217 * lobe(l, 437.0, 11.8, 36.0) + 0.681 * lobe(l, 459.0, 26.0, 13.8)};
}

constexpr double kSunAngularRadius = 0.2667 * kPi / 180.0;

// CIE XYZ (cd/m^2 in Y) of the sun's disc seen through the atmosphere at zenith angle theta_s.
glm::dvec3 sun_xyz(double turbidity, double theta_s) {
    const double beta = 0.04608365822050 * turbidity - 0.04586025928522;
    constexpr double alpha = 1.3;   // ratio of small to large aerosol particles
    constexpr double ozone = 0.35;  // cm (NTP)
    constexpr double water = 2.0;   // cm of precipitable water vapour
    // Relative optical air mass (Kasten's formula, as the paper gives it).
    const double theta_degrees = theta_s * 180.0 / kPi;
    const double mass = 1.0 / (std::cos(theta_s) + 0.15 * std::pow(93.885 - theta_degrees, -1.253));
    glm::dvec3 xyz(0.0);
    constexpr double step = 5.0;
    for (double l = 380.0; l <= 750.0 + 1e-9; l += step) {
        const double micrometres = l / 1000.0;
        const double rayleigh = std::exp(-mass * 0.008735 * std::pow(micrometres, -4.08));
        const double aerosol = std::exp(-mass * beta * std::pow(micrometres, -alpha));
        const double ozone_t = std::exp(-mass * interpolate(kOzone, l) * ozone);
        const double k_wa = interpolate(kWaterVapour, l);
        const double water_t = std::exp(-0.2385 * k_wa * water * mass /
                                        std::pow(1.0 + 20.07 * k_wa * water * mass, 0.45));
        const double weight = (l == 380.0 || l > 750.0 - 1e-9) ? 0.5 : 1.0;  // trapezoid
        xyz += weight * step * solar_radiance(l) * rayleigh * aerosol * ozone_t * water_t *
               cie_1931(l);
    }
    return xyz * 683.0;  // lm / W: radiance weighted by the matching functions -> cd/m^2
}

glm::dvec3 sun_rgb(const SkySettings& sky) {
    const double theta_s = (90.0 - double(sky.sun_elevation_degrees)) * kPi / 180.0;
    return xyz_to_rgb(sun_xyz(sky.turbidity, theta_s)) / kDaylightUnit;
}

// Horizontal irradiance from the sky above (midpoint rule over equal-solid-angle cells).
glm::dvec3 sky_horizontal_irradiance(const PreethamModel& model) {
    constexpr int rings = 96, sectors = 192;
    glm::dvec3 sum(0.0);
    const double cell = 2.0 * kPi / (rings * sectors);  // the hemisphere's 2 pi sr, divided
    for (int j = 0; j < rings; ++j) {
        const double cos_theta = (j + 0.5) / rings;
        const double v = std::acos(cos_theta) / kPi;
        for (int i = 0; i < sectors; ++i) {
            const double u = (i + 0.5) / sectors;
            sum += model.sky_rgb(environment_direction(u, v)) * cos_theta * cell;
        }
    }
    return sum;
}

PreethamModel sky_model_with_ground(const SkySettings& sky) {
    PreethamModel model(sky);
    const double sun_solid_angle = 2.0 * kPi * (1.0 - std::cos(kSunAngularRadius));
    const glm::dvec3 sun_irradiance = sun_rgb(sky) * sun_solid_angle * std::max(model.sun.z, 0.0);
    model.ground =
        double(sky.ground_albedo) / kPi * (sky_horizontal_irradiance(model) + sun_irradiance);
    return model;
}

}  // namespace

glm::dvec3 environment_direction(double u, double v) {
    const double phi = 2.0 * kPi * u;
    const double theta = kPi * v;
    return direction_from_angles(std::sin(theta), std::cos(theta), std::cos(phi), std::sin(phi));
}

glm::dvec2 environment_coordinates(glm::dvec3 direction) {
    const glm::dvec3 d = glm::normalize(direction);
    const double theta = std::atan2(std::hypot(d.x, d.y), d.z);
    double u = std::atan2(d.y, -d.x) / (2.0 * kPi);
    if (u < 0.0) u += 1.0;
    if (u >= 1.0) u -= 1.0;
    return {u, theta / kPi};
}

glm::dvec3 rotate_environment_direction(glm::dvec3 direction, double degrees) {
    // Adding R to phi in (-sin theta cos phi, sin theta sin phi): a turn by -R about +z.
    const double r = degrees * kPi / 180.0;
    const double c = std::cos(r), s = std::sin(r);
    return {c * direction.x + s * direction.y, -s * direction.x + c * direction.y, direction.z};
}

double environment_texel_solid_angle(int row, int width, int height) {
    const double band = kPi / height;
    return (4.0 * kPi / width) * std::sin((row + 0.5) * band) * std::sin(0.5 * band);
}

HdrImage studio_environment(int width) {
    validate_width(width, "studio environment");
    // Azimuths as the map's (phi: 0 along -x, 90 along +y); the built-in scenes' cameras look
    // from about phi = 225 (from +x -y, above) towards the origin.
    const std::array<LightBox, 3> specs = {{
        {270.0, 40.0, 22.0, 16.0, glm::dvec3(1.0, 0.93, 0.84) * 6.5},  // key: front left, high
        {175.0, 15.0, 30.0, 20.0, glm::dvec3(0.82, 0.9, 1.0) * 1.6},   // fill: front right, low
        {45.0, 30.0, 6.0, 30.0, glm::dvec3(1.0) * 6.0},                // rim: behind, a strip
    }};
    std::array<PlacedLightBox, 3> boxes;
    std::transform(specs.begin(), specs.end(), boxes.begin(), place_light_box);
    const glm::dvec3 surround(0.045, 0.045, 0.047);
    const glm::dvec3 floor(0.028, 0.027, 0.026);
    return generate_map(width, 3, [&](glm::dvec3 d) {
        // The floor meets the surround in a soft band a few degrees wide at the horizon.
        const double above = smooth_step(-0.05, 0.05, d.z);
        glm::dvec3 value = floor + (surround - floor) * above;
        for (const PlacedLightBox& box : boxes) value += light_box(box, d);
        return value;
    });
}

void validate_sky(const SkySettings& sky) {
    if (!std::isfinite(sky.turbidity) || sky.turbidity < 1.7f || sky.turbidity > 10.0f) {
        throw std::invalid_argument(
            fmt::format("sky turbidity {} is outside [1.7, 10]", sky.turbidity));
    }
    if (!std::isfinite(sky.sun_elevation_degrees) || sky.sun_elevation_degrees < 0.0f ||
        sky.sun_elevation_degrees > 90.0f) {
        throw std::invalid_argument(
            fmt::format("sun elevation {} degrees is outside [0, 90]", sky.sun_elevation_degrees));
    }
    if (!std::isfinite(sky.sun_azimuth_degrees)) {
        throw std::invalid_argument(
            fmt::format("sun azimuth {} degrees is not finite", sky.sun_azimuth_degrees));
    }
    if (!std::isfinite(sky.ground_albedo) || sky.ground_albedo < 0.0f || sky.ground_albedo > 1.0f) {
        throw std::invalid_argument(
            fmt::format("ground albedo {} is outside [0, 1]", sky.ground_albedo));
    }
}

HdrImage preetham_sky(const SkySettings& sky, int width) {
    validate_width(width, "sky");
    const PreethamModel model = sky_model_with_ground(sky);
    return generate_map(width, 1, [&](glm::dvec3 d) { return model.radiance(d); });
}

glm::vec3 preetham_sky_radiance(const SkySettings& sky, glm::dvec3 direction) {
    const PreethamModel model = sky_model_with_ground(sky);
    return glm::vec3(model.radiance(glm::normalize(direction)));
}

glm::dvec3 preetham_sky_xyY(const SkySettings& sky, glm::dvec3 direction) {
    return PreethamModel(sky).xyY(glm::normalize(direction));
}

SunDisc preetham_sun(const SkySettings& sky) {
    const PreethamModel model(sky);
    return {glm::vec3(model.sun), glm::vec3(sun_rgb(sky)), float(kSunAngularRadius)};
}

HdrImage uniform_environment(glm::vec3 radiance) {
    for (int c = 0; c < 3; ++c) {
        if (!std::isfinite(radiance[c]) || radiance[c] < 0.0f) {
            throw std::invalid_argument(
                fmt::format("uniform environment radiance ({}, {}, {}) must be finite and "
                            "non-negative",
                            radiance.r, radiance.g, radiance.b));
        }
    }
    HdrImage map;
    map.width = 8;
    map.height = 4;
    for (int i = 0; i < map.width * map.height; ++i) {
        map.rgb.insert(map.rgb.end(), {radiance.r, radiance.g, radiance.b});
    }
    return map;
}

namespace {

// Walker's alias method, built as Vose does ("A linear algorithm for generating random numbers
// with a given distribution", IEEE TSE 1991), for `weights` (non-negative, not all 0): writes
// FGR_ENV_ALIAS_FLOATS per entry to `table` and returns the probability of each index that the
// stored (float) thresholds realise, which is what the kernel's pdf must use.
std::vector<double> build_alias_table(const std::vector<double>& weights, float* table) {
    const size_t n = weights.size();
    double sum = 0.0;
    for (double weight : weights) sum += weight;
    std::vector<double> scaled(n);
    std::vector<int> small, large;
    for (size_t i = 0; i < n; ++i) {
        scaled[i] = weights[i] * double(n) / sum;
        (scaled[i] < 1.0 ? small : large).push_back(int(i));
    }
    std::vector<double> threshold(n, 1.0);
    std::vector<int> alias(n);
    for (size_t i = 0; i < n; ++i) alias[i] = int(i);
    while (!small.empty() && !large.empty()) {
        const int less = small.back(), more = large.back();
        small.pop_back();
        threshold[size_t(less)] = scaled[size_t(less)];
        alias[size_t(less)] = more;
        scaled[size_t(more)] -= 1.0 - scaled[size_t(less)];
        if (scaled[size_t(more)] < 1.0) {
            large.pop_back();
            small.push_back(more);
        }
    }
    // What rounding leaves in either list keeps its own index (threshold 1). A threshold below
    // 2^-24 becomes 0: the kernel's uniform fraction could not realise it, and the texel's
    // probability, a product of two such, could fall below float's range while the kernel still
    // picked it.
    std::vector<double> realised(n, 0.0);
    for (size_t k = 0; k < n; ++k) {
        const double kept = threshold[k] < 0x1p-24 ? 0.0 : std::min(threshold[k], 1.0);
        const float stored = float(kept);
        table[FGR_ENV_ALIAS_FLOATS * k + FGR_ENV_ALIAS_THRESHOLD] = stored;
        std::memcpy(&table[FGR_ENV_ALIAS_FLOATS * k + FGR_ENV_ALIAS_INDEX], &alias[k], sizeof(int));
        realised[k] += double(stored) / double(n);
        realised[size_t(alias[k])] += (1.0 - double(stored)) / double(n);
    }
    return realised;
}

}  // namespace

EnvironmentTables environment_tables(const HdrImage& map, std::string_view name) {
    if (map.width <= 0 || map.height <= 0) {
        throw std::invalid_argument(
            fmt::format("{}: empty ({} x {} pixels)", name, map.width, map.height));
    }
    const int64_t w = map.width, h = map.height;
    const int64_t floats = FGR_ENV_TEXEL_FLOATS * w * h + FGR_ENV_ALIAS_FLOATS * (h + w * h);
    if (floats > int64_t(INT_MAX)) {
        throw std::invalid_argument(
            fmt::format("{}: {} x {} pixels is too large", name, map.width, map.height));
    }
    if (int64_t(map.rgb.size()) != 3 * w * h) {
        throw std::invalid_argument(fmt::format("{}: holds {} values, {} x {} pixels need {}", name,
                                                map.rgb.size(), w, h, 3 * w * h));
    }
    for (size_t i = 0; i < map.rgb.size(); ++i) {
        const float value = map.rgb[i];
        if (!std::isfinite(value) || value < 0.0f) {
            const size_t pixel = i / 3;
            throw std::invalid_argument(fmt::format(
                "{}: pixel ({}, {}) has {} {} value {} (values must be finite and non-negative)",
                name, pixel % size_t(w), pixel / size_t(w), std::isnan(value) ? "a" : "the",
                "RGB"[i % 3], value));
        }
    }

    EnvironmentTables tables;
    tables.width = map.width;
    tables.height = map.height;
    tables.rows_offset = int(FGR_ENV_TEXEL_FLOATS * w * h);
    tables.columns_offset = int(FGR_ENV_TEXEL_FLOATS * w * h + FGR_ENV_ALIAS_FLOATS * h);
    tables.data.assign(size_t(floats), 0.0f);
    for (size_t i = 0; i < size_t(w * h); ++i) {
        std::copy_n(map.rgb.begin() + ptrdiff_t(3 * i), 3,
                    tables.data.begin() + ptrdiff_t(FGR_ENV_TEXEL_FLOATS * i));
    }

    // Weights: luminance times solid angle, in double.
    std::vector<double> weights(size_t(w * h));
    double total = 0.0;
    for (int64_t y = 0; y < h; ++y) {
        const double solid_angle = environment_texel_solid_angle(int(y), map.width, map.height);
        for (int64_t x = 0; x < w; ++x) {
            const size_t i = size_t(y * w + x);
            weights[i] =
                luminance(map.rgb[3 * i], map.rgb[3 * i + 1], map.rgb[3 * i + 2]) * solid_angle;
            total += weights[i];
        }
    }
    tables.luminance_integral = total;
    if (!(total > 0.0)) {
        // Black everywhere: sample uniformly over the sphere.
        for (int64_t y = 0; y < h; ++y) {
            const double solid_angle = environment_texel_solid_angle(int(y), map.width, map.height);
            std::fill_n(weights.begin() + y * w, w, solid_angle);
        }
    }

    std::vector<double> row_sums(size_t(h), 0.0);
    for (int64_t y = 0; y < h; ++y) {
        for (int64_t x = 0; x < w; ++x) row_sums[size_t(y)] += weights[size_t(y * w + x)];
    }
    const std::vector<double> rows =
        build_alias_table(row_sums, tables.data.data() + tables.rows_offset);
    std::vector<double> row_weights(static_cast<size_t>(w));
    for (int64_t y = 0; y < h; ++y) {
        // A row of weight 0 is never picked; its columns get a uniform table all the same.
        if (row_sums[size_t(y)] > 0.0) {
            std::copy_n(weights.begin() + y * w, w, row_weights.begin());
        } else {
            std::fill(row_weights.begin(), row_weights.end(), 1.0);
        }
        const std::vector<double> columns = build_alias_table(
            row_weights, tables.data.data() + tables.columns_offset + FGR_ENV_ALIAS_FLOATS * y * w);
        for (int64_t x = 0; x < w; ++x) {
            tables.data[size_t(FGR_ENV_TEXEL_FLOATS * (y * w + x) + FGR_ENV_TEXEL_PROBABILITY)] =
                float(rows[size_t(y)] * columns[size_t(x)]);
        }
    }
    return tables;
}

EnvironmentInfo environment_info(const EnvironmentTables& tables, double rotation_degrees,
                                 float intensity) {
    if (!std::isfinite(rotation_degrees)) {
        throw std::invalid_argument(
            fmt::format("environment rotation {} degrees is not finite", rotation_degrees));
    }
    if (!std::isfinite(intensity) || intensity < 0.0f) {
        throw std::invalid_argument(
            fmt::format("environment intensity {} must be finite and non-negative", intensity));
    }
    double turns = std::fmod(rotation_degrees / 360.0, 1.0);
    if (turns < 0.0) turns += 1.0;
    EnvironmentInfo info{};
    info.transform.s[0] = float(turns);
    info.transform.s[1] = intensity;
    info.width = tables.width;
    info.height = tables.height;
    info.rows_offset = tables.rows_offset;
    info.columns_offset = tables.columns_offset;
    return info;
}

namespace {

// The first directional light of the scene, the sky's sun unless the user placed it.
const Light* key_light(const Scene& scene) {
    const auto found = std::find_if(scene.lights.begin(), scene.lights.end(), [](const Light& l) {
        return l.type == LightType::Directional;
    });
    return found == scene.lights.end() ? nullptr : &*found;
}

}  // namespace

EnvironmentChoice parse_environment(std::string_view text) {
    const EnvironmentSpec spec = parse_environment_spec(text, "--environment");
    EnvironmentChoice choice;
    choice.kind = spec.kind;
    choice.radiance = spec.radiance;
    choice.file = spec.file;
    choice.given = true;
    return choice;
}

std::string environment_argument(const EnvironmentChoice& choice) {
    switch (choice.kind) {
        case EnvironmentKind::Sky:
            return "sky";
        case EnvironmentKind::Studio:
            return "studio";
        case EnvironmentKind::Uniform: {
            const glm::vec3 radiance = choice.radiance;
            if (radiance == glm::vec3(1.0f)) return "uniform";
            if (radiance.x == radiance.y && radiance.y == radiance.z) {
                return fmt::format("uniform:{}", radiance.x);
            }
            return fmt::format("uniform:{},{},{}", radiance.x, radiance.y, radiance.z);
        }
        case EnvironmentKind::File:
            break;
    }
    const std::string path = choice.file.string();
    if (!path.empty() && choice.file.is_relative() &&
        parse_environment(path).kind != EnvironmentKind::File) {
        return "./" + path;
    }
    return path;
}

EnvironmentChoice with_scene_environment(EnvironmentChoice choice, const Scene& scene) {
    if (choice.given || scene.environment.empty()) return choice;
    // Checked when the scene was loaded (check_scene_environment).
    const EnvironmentSpec spec = parse_environment_spec(scene.environment, "environment");
    choice.kind = spec.kind;
    choice.radiance = spec.radiance;
    choice.file = spec.file;
    return choice;
}

std::string path_lights_text(const EnvironmentChoice& choice, const Scene& scene,
                             bool scene_lights) {
    const bool sky = choice.kind == EnvironmentKind::Sky;
    // A black uniform environment is a closed scene's, lit from inside: no furnace test.
    const bool black =
        choice.kind == EnvironmentKind::Uniform && choice.radiance == glm::vec3(0.0f);
    const std::string environment = sky                                      ? "the sky and its sun"
                                    : choice.kind == EnvironmentKind::Studio ? "the studio"
                                    : black                                  ? "a black environment"
                                    : choice.kind == EnvironmentKind::Uniform
                                        ? "the uniform environment"
                                        : "the environment map";
    // Under the sky its sun stands in for the key light (light_list in render/modes/path_mode).
    const size_t replaced = sky && key_light(scene) != nullptr ? 1 : 0;
    const size_t shining = scene_lights ? scene.lights.size() - replaced : 0;
    if (shining == 0) {
        return environment + (scene_lights ? "" : " alone (--no-scene-lights)") +
               (replaced && scene_lights ? " (the sun in place of the scene's key light)" : "");
    }
    std::string text = fmt::format("{} and the scene's {}{} light{}", environment,
                                   replaced ? "other " : "", shining, shining == 1 ? "" : "s");
    if (replaced) text += " (the sun in place of its key light)";
    if (choice.kind == EnvironmentKind::Uniform && !black) {
        text += ": a furnace test wants the environment alone, --no-scene-lights";
    }
    return text;
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

}  // namespace fgr
