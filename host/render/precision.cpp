// SPDX-License-Identifier: Apache-2.0
#include "render/precision.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <span>
#include <stdexcept>
#include <utility>

#include "scene/ifs/ifs.hpp"
#include "scene/parameters.hpp"

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
        case Precision::Float:
            return "float";
        case Precision::Double:
            return "double";
        case Precision::Auto:
            break;
    }
    return "auto";
}

namespace {

// The view whose footprint decides: the target brought in to the nearest surface when the DE at
// the camera puts one nearer.
CameraView detail_view(const CameraView& view, float surface_distance) {
    const glm::dvec3 ahead = view.target - view.position;
    const double target_distance = glm::length(ahead);
    if (!(surface_distance >= 0.0f) || !(surface_distance < target_distance)) return view;
    CameraView nearer = view;
    nearer.target = view.position + ahead * (double(surface_distance) / target_distance);
    return nearer;
}

bool wants_double(Precision precision, const CameraView& view, int width,
                  const SurfaceDistance& distance) {
    if (precision != Precision::Auto) return precision == Precision::Double;
    // The target alone may decide, before anything is probed.
    if (auto_wants_double(view, width, -1.0f)) return true;
    return distance && auto_wants_double(view, width, distance());
}

}  // namespace

bool auto_wants_double(const CameraView& view, int width, float surface_distance) {
    return needs_double_precision(detail_view(view, surface_distance), width);
}

float surface_distance(Renderer& in_float, const CameraView& view,
                       const std::vector<float>& params) {
    if (const auto& ifs = in_float.scene().ifs) {
        // No DE in the kernel: a bound from the node tree, to the depth the slider allows.
        const int depth = static_cast<int>(param_value(in_float.scene(), params, "ifs_depth"));
        return static_cast<float>(ifs_distance_bound(*ifs, view.position, depth));
    }
    // An inside test alone says nothing about distance: unknown, the target alone decides.
    if (in_float.scene().inside_only()) return -1.0f;
    const std::vector<float> de = in_float.probe_de(std::span(&view.position, 1), params);
    return std::isfinite(de.at(0)) ? std::abs(de[0]) : -1.0f;
}

namespace {

void check_double_available(Precision precision, const DeviceInfo& device) {
    if (precision == Precision::Double && !device.has_fp64) {
        throw std::runtime_error(
            fmt::format("{} has no double precision (cl_khr_fp64)", device.name));
    }
}

}  // namespace

bool use_double_precision(Precision precision, const CameraView& view, int width,
                          const DeviceInfo& device, const SurfaceDistance& distance) {
    check_double_available(precision, device);
    return device.has_fp64 && wants_double(precision, view, width, distance);
}

PrecisionChooser::PrecisionChooser(const DeviceInfo& device, Warn warn)
    : device_(device), warn_(std::move(warn)) {}

bool PrecisionChooser::in_double(Precision precision, const CameraView& view, int width,
                                 const SurfaceDistance& distance) {
    check_double_available(precision, device_);
    const bool double_wanted = wants_double(precision, view, width, distance);
    if (!warned_ && double_wanted && precision == Precision::Auto && !device_.has_fp64) {
        warned_ = true;
        if (warn_) {
            warn_(
                fmt::format("this view needs double precision, which {} lacks: rendering in float",
                            device_.name));
        }
    }
    return double_wanted && device_.has_fp64;
}

KernelSwitches with_precision(KernelSwitches switches, bool double_precision) {
    switches.double_precision = double_precision;
    if (double_precision) {
        switches.packet_width = std::max(switches.packet_width, kMinDoublePacketWidth);
    }
    return switches;
}

PrecisionRenderers::PrecisionRenderers(const ComputeDevice& device, ProgramCache& cache,
                                       const Scene& scene, const KernelSwitches& switches)
    : device_(device), cache_(cache), scene_(scene), switches_(switches) {}

Renderer* PrecisionRenderers::built(bool double_precision) {
    return renderers_[double_precision].get();
}

Renderer& PrecisionRenderers::get(bool double_precision) {
    std::unique_ptr<Renderer>& renderer = renderers_[double_precision];
    if (!renderer) {
        renderer = std::make_unique<Renderer>(device_, cache_, scene_,
                                              with_precision(switches_, double_precision));
    }
    return *renderer;
}

}  // namespace fgr
