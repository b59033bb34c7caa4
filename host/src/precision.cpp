#include "fgr/precision.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

namespace fgr {

Precision parse_precision(std::string_view text) {
    if (text == "float") return Precision::Float;
    if (text == "double") return Precision::Double;
    if (text == "auto") return Precision::Auto;
    throw std::invalid_argument(
        fmt::format("unknown precision '{}' (choose float, double or auto)", text));
}

std::string_view precision_name(Precision precision) {
    switch (precision) {
        case Precision::Float: return "float";
        case Precision::Double: return "double";
        case Precision::Auto: break;
    }
    return "auto";
}

namespace {

bool wants_double(Precision precision, const CameraView& view, int width) {
    return precision == Precision::Double ||
           (precision == Precision::Auto && needs_double_precision(view, width));
}

}  // namespace

bool use_double_precision(Precision precision, const CameraView& view, int width,
                          const DeviceInfo& device) {
    if (!wants_double(precision, view, width)) return false;
    if (device.has_fp64) return true;
    if (precision == Precision::Double) {
        throw std::runtime_error(
            fmt::format("{} has no double precision (cl_khr_fp64)", device.name));
    }
    return false;
}

bool precision_fallback(Precision precision, const CameraView& view, int width,
                        const DeviceInfo& device) {
    return precision == Precision::Auto && !device.has_fp64 && wants_double(precision, view, width);
}

std::string precision_fallback_message(const DeviceInfo& device) {
    return fmt::format("this view needs double precision, which {} lacks: rendering in float",
                       device.name);
}

KernelSwitches with_precision(KernelSwitches switches, bool double_precision) {
    switches.double_precision = double_precision;
    if (double_precision) {
        switches.packet_width = std::max(switches.packet_width, kMinDoublePacketWidth);
    }
    return switches;
}

}  // namespace fgr
