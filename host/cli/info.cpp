// SPDX-License-Identifier: Apache-2.0
// fgr info: the OpenCL devices, numbered for --device, and on request their math self-test; given
// an image or view file, the view it carries; given a scene, the scene in full (as fgr list SCENE).
#include <fmt/format.h>

#include <nlohmann/json.hpp>
#include <optional>
#include <system_error>

#include "commands.hpp"
#include "device/math_check.hpp"
#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"
#include "image/embedded_view.hpp"
#include "output/tiled/streaming_image.hpp"
#include "util/strings.hpp"
#include "view_file/view_file.hpp"

namespace fgr {
namespace {

// "float1 pass, float4 pass, ..., double16 FAIL (...)" for one device.
void print_math_check(const DeviceInfo& info) {
    const ComputeDevice device = open_device(info.index);
    ProgramCache cache(ProgramCache::default_directory());
    for (bool double_precision : {false, true}) {
        if (double_precision && !info.has_fp64) continue;
        for (int width : {1, 4, 8, 16}) {
            if (double_precision && width == 1) continue;  // double runs 4+ lanes
            const std::string verdict = math_check_verdict(device, cache, double_precision, width);
            fmt::print("  math {:<9} {}\n",
                       fmt::format("{}{}:", double_precision ? "double" : "float", width),
                       verdict.empty() ? "pass" : "FAIL: " + verdict);
        }
    }
}

// What `fgr info FILE` shows of the document `file` carries: the JSON, indented.
// What made the image or view: the view's summary, and how to render it again.
void print_view(const std::filesystem::path& file, const ViewFile& view) {
    fmt::print("{}", view_summary(view));
    fmt::print("render it again: fgr render --view {} -o OUTPUT\n", printable_path(file));
}

}  // namespace

int command_info_file(const std::filesystem::path& file) {
    if (is_view_file_name(file)) {
        try {
            print_view(file, read_view_file(file));
        } catch (const std::runtime_error& error) {
            throw UsageError(error.what());
        }
        return 0;
    }
    const std::optional<std::string> document = read_embedded_view(file);
    if (!document) {
        throw RuntimeFailure(fmt::format(
            "{}: no fgr view embedded (not written by fgr, or written before views were embedded)",
            printable_path(file)));
    }
    try {
        print_view(file, parse_view_file(*document));
    } catch (const std::runtime_error& error) {
        throw RuntimeFailure(fmt::format("{}: the fgr view it carries cannot be read: {}",
                                         printable_path(file), error.what()));
    }
    return 0;
}

int command_info_argument(const std::string& argument) {
    bool image = false;
    try {
        image_format_of(argument);
        image = true;
    } catch (const std::invalid_argument&) {
        // Not an image's name: a scene id or a scene file.
    }
    // A folder is no scene either: the image reader's error names it.
    std::error_code error;
    if (image || is_view_file_name(argument) || std::filesystem::is_directory(argument, error)) {
        return command_info_file(argument);
    }
    return command_list_scene(argument);
}

int command_info(bool math_check) {
    const auto devices = list_devices();
    if (devices.empty()) {
        throw RuntimeFailure(
            "no OpenCL device found (install an OpenCL driver, e.g. pocl-opencl-icd)");
    }
    for (const auto& device : devices) {
        fmt::print("device {}: {}\n", device.index, device.name);
        fmt::print("  platform:       {}\n", device.platform);
        fmt::print("  type:           {}\n", device.is_gpu   ? "GPU"
                                             : device.is_cpu ? "CPU"
                                                             : "other");
        fmt::print("  version:        {} (driver {}, {})\n", device.version, device.driver_version,
                   device.opencl_c_version);
        fmt::print("  compute units:  {}\n", device.compute_units);
        fmt::print("  global memory:  {} MiB\n", device.global_memory_bytes >> 20);
        fmt::print("  double:         {}\n", device.has_fp64 ? "yes (cl_khr_fp64)" : "no");
        fmt::print("  packet width:   {} rays per work-item\n", preferred_packet_width(device));
        if (math_check) print_math_check(device);
    }
    return 0;
}

}  // namespace fgr
