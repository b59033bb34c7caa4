#include "fgr/precision.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>
#include <glm/geometric.hpp>

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

PrecisionChooser::PrecisionChooser(const DeviceInfo& device, Warn warn)
    : device_(device), warn_(std::move(warn)) {}

bool PrecisionChooser::in_double(Precision precision, const CameraView& view, int width) {
    const bool double_wanted = wants_double(precision, view, width);
    if (!warned_ && double_wanted && precision == Precision::Auto && !device_.has_fp64) {
        warned_ = true;
        if (warn_) {
            warn_(fmt::format("this view needs double precision, which {} lacks: rendering in float",
                              device_.name));
        }
    }
    return double_wanted && use_double_precision(precision, view, width, device_);
}

bool hits_finer_than_float(const Frame& frame, const CameraView& view, int width) {
    const CameraBasis basis = camera_basis(view);
    const float angle = pixel_angle(basis, width);
    const int probe_width = frame.image.width, probe_height = frame.image.height;
    long hits = 0, fine = 0;
    for (int y = 0; y < probe_height; ++y) {
        for (int x = 0; x < probe_width; ++x) {
            const float t = frame.depth[size_t(y) * size_t(probe_width) + size_t(x)];
            if (t < 0.0f) continue;
            const glm::dvec3 hit =
                basis.eye + glm::dvec3(primary_ray_direction(basis, probe_width, probe_height,
                                                             float(x), float(y))) * double(t);
            ++hits;
            fine += finer_than_float(
                t * angle, static_cast<float>(std::max(glm::length(hit), glm::length(basis.eye))));
        }
    }
    return fine * 100 > hits;
}

bool float_probe_finds_fine_surface(Renderer& in_float, const FrameRequest& request) {
    FrameRequest probe;
    probe.view = request.view;
    probe.params = request.params;
    probe.width = std::max(8, request.width / 8);
    probe.height = std::max(8, request.height * probe.width / request.width);
    return hits_finer_than_float(in_float.render(probe), request.view, request.width);
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
