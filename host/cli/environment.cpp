// SPDX-License-Identifier: Apache-2.0
// fgr environment: writes one of the environment maps fgr generates (the studio, the daylight
// sky) as an equirectangular .hdr or .exr file, to look at, edit, or light other renderers with.
#include "render/environment.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <string>

#include "commands.hpp"
#include "image/hdr_io.hpp"
#include "util/lower_case.hpp"

namespace fgr {

void add_environment_command(CLI::App& app, EnvironmentOptions& options) {
    CLI::App* command = app.add_subcommand(
        "environment", "write a generated environment map (studio or sky) as .hdr or .exr");
    command->add_option("kind", options.kind, "studio or sky")
        ->required()
        ->check(CLI::IsMember({"studio", "sky"}));
    command->add_option("-o,--output", options.output, "output .hdr or .exr file")->required();
    command->add_option("--width", options.width, "map width in pixels; the height is half of it")
        ->check(CLI::Range(8, 16384));
    command->add_option("--turbidity", options.turbidity, "sky haze, 2 (clear) to 10 (hazy)")
        ->check(CLI::Range(1.7f, 10.0f));
    command->add_option("--sun-elevation", options.sun_elevation, "sun above the horizon, degrees")
        ->check(CLI::Range(-10.0f, 90.0f));
    command->add_option("--sun-azimuth", options.sun_azimuth, "sun's compass angle, degrees");
}

int command_environment(const EnvironmentOptions& options) {
    const std::filesystem::path output = options.output;
    const std::string extension = lower_extension(output);
    if (extension != ".hdr" && extension != ".exr") {
        throw UsageError(fmt::format("output '{}' must be a .hdr or .exr file", output.string()));
    }
    check_output_directory(output);
    HdrImage map;
    if (options.kind == "studio") {
        map = studio_environment(options.width);
    } else {
        SkySettings sky;
        sky.turbidity = options.turbidity;
        sky.sun_elevation_degrees = options.sun_elevation;
        sky.sun_azimuth_degrees = options.sun_azimuth;
        map = preetham_sky(sky, options.width);
    }
    try {
        if (extension == ".hdr") {
            write_radiance_hdr(output, map);
        } else {
            write_exr(output, map.width, map.height, {{"", {"R", "G", "B"}, map.rgb}});
        }
    } catch (const std::runtime_error& error) {
        throw RuntimeFailure(error.what());
    }
    fmt::print("wrote {} ({}x{})\n", output.string(), map.width, map.height);
    return 0;
}

}  // namespace fgr
