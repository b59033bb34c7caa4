// SPDX-License-Identifier: Apache-2.0
// Which host module serves which render mode.
#include <array>
#include <glm/geometric.hpp>
#include <stdexcept>

#include "render/modes/brute_mode.hpp"
#include "render/modes/mode_kernel.hpp"
#include "render/modes/path_mode.hpp"
#include "render/modes/shaded_mode.hpp"
#include "util/parallel_bands.hpp"

namespace fgr {

cl::Buffer upload_floats(const ComputeDevice& device, const std::vector<float>& values) {
    // A zero-sized buffer is invalid in OpenCL: an empty list uploads one unused float.
    const std::vector<float> padded = values.empty() ? std::vector<float>{0.0f} : values;
    return cl::Buffer(device.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                      padded.size() * sizeof(float), const_cast<float*>(padded.data()));
}

std::vector<float> planes_in_rows(std::span<const float> planes, const TileLayout& layout,
                                  int first, int count, int width, int height, float scale) {
    const size_t plane = static_cast<size_t>(layout.plane_size());
    std::vector<float> rows(static_cast<size_t>(width) * height * count);
    const std::vector<int> columns = layout.column_offsets(width);
    in_parallel_rows(static_cast<size_t>(height), static_cast<size_t>(width) * count,
                     [&](size_t first_row, size_t last_row) {
                         for (size_t y = first_row; y < last_row; ++y) {
                             const int row = layout.row_offset(static_cast<int>(y));
                             for (int x = 0; x < width; ++x) {
                                 const size_t source =
                                     static_cast<size_t>(row + columns[static_cast<size_t>(x)]);
                                 const size_t pixel = y * static_cast<size_t>(width) + x;
                                 for (int c = 0; c < count; ++c) {
                                     rows[pixel * count + c] =
                                         planes[(first + c) * plane + source] * scale;
                                 }
                             }
                         }
                     });
    return rows;
}

std::vector<float> scene_light_values(const Scene& scene) {
    std::vector<float> values;
    values.reserve(scene.lights.size() * FGR_LIGHT_FLOATS);
    for (const Light& light : scene.lights) {
        const glm::vec3 vector =
            light.type == LightType::Directional ? glm::normalize(light.vector) : light.vector;
        std::array<float, FGR_LIGHT_FLOATS> floats{};
        floats[FGR_LIGHT_KIND] = static_cast<float>(
            light.type == LightType::Point ? FGR_LIGHT_KIND_POINT : FGR_LIGHT_KIND_DIRECTIONAL);
        for (int c = 0; c < 3; ++c) {
            floats[FGR_LIGHT_VECTOR + c] = vector[c];
            floats[FGR_LIGHT_COLOUR + c] = light.colour[c];
        }
        floats[FGR_LIGHT_INTENSITY] = light.intensity;
        values.insert(values.end(), floats.begin(), floats.end());
    }
    return values;
}

std::unique_ptr<ModeKernel> make_mode_kernel(const KernelSwitches& switches,
                                             const ComputeDevice& device,
                                             const cl::Program& program, const Scene& scene) {
    switch (switches.mode) {
        case RenderMode::Shaded:
            return std::make_unique<ShadedMode>(device, scene, switches);
        case RenderMode::Path:
            return std::make_unique<PathMode>(device, scene, switches);
        case RenderMode::Brute:
            return std::make_unique<BruteMode>(device, program, scene, switches);
    }
    throw std::invalid_argument("unknown render mode");
}

}  // namespace fgr
