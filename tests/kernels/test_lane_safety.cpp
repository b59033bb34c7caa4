// SPDX-License-Identifier: Apache-2.0
// Every scene renders finite colour, depth and normals at every precision and packet width the
// device supports, with a view that puts misses, hits and the origin's neighbourhood in the same
// packets: where a vector built-in lets one lane corrupt another (Debian's PoCL AVX-512 library
// does, in double8/16 pow and float16 sin), this is where non-finite pixels show up. Inside-only
// scenes (no DE) render in the brute-force mode, and their normals are its screen-space ones.
#include <gtest/gtest.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <glm/geometric.hpp>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "camera/camera.hpp"
#include "device/program_cache.hpp"
#include "render/renderer.hpp"
#include "scene/discovery.hpp"
#include "scene/parameters.hpp"
#include "test_scenes.hpp"

namespace fgr {
namespace {

using test::all_scenes;

struct LaneCase {
    std::string scene_id;
    std::string assignment;  // a parameter change, or ""
    bool double_precision;
};

void PrintTo(const LaneCase& lane_case, std::ostream* out) {
    *out << lane_case.scene_id << (lane_case.assignment.empty() ? "" : " " + lane_case.assignment)
         << (lane_case.double_precision ? " double" : " float");
}

std::vector<LaneCase> lane_cases() {
    std::vector<LaneCase> cases;
    for (bool double_precision : {false, true}) {
        for (const Scene& scene : all_scenes()) cases.push_back({scene.id, "", double_precision});
        // A non-integer power takes the Mandelbulb through pow, atan2, asin, sin and cos.
        cases.push_back({"mandelbulb", "power=7.5", double_precision});
    }
    return cases;
}

// The packet widths to try: 1, 4, 8 and 16, or those FGR_TEST_PACKET_WIDTHS lists (e.g. "1": the
// GPU kit, bench/gpu/run.sh, runs the one-ray-per-work-item layout a GPU renders with).
std::vector<int> packet_widths() {
    const char* listed = std::getenv("FGR_TEST_PACKET_WIDTHS");
    if (listed == nullptr || *listed == '\0') return {1, 4, 8, 16};
    std::vector<int> widths;
    std::stringstream in(listed);
    std::string item;
    while (std::getline(in, item, ',')) {
        if (item != "1" && item != "4" && item != "8" && item != "16") {
            throw std::invalid_argument("FGR_TEST_PACKET_WIDTHS: '" + item +
                                        "' is not 1, 4, 8 or 16");
        }
        widths.push_back(std::stoi(item));
    }
    return widths;
}

class LaneSafety : public ::testing::TestWithParam<LaneCase> {
protected:
    static ComputeDevice& device() {
        static ComputeDevice opened = open_device(-1);
        return opened;
    }
    const Scene& scene() const {
        for (const Scene& scene : all_scenes()) {
            if (scene.id == GetParam().scene_id) return scene;
        }
        throw std::runtime_error("no scene " + GetParam().scene_id);
    }
    ProgramCache cache_{std::filesystem::path()};
};

TEST_P(LaneSafety, ColourDepthAndNormalsAreFiniteAtEveryWidth) {
    const LaneCase& lane_case = GetParam();
    if (lane_case.double_precision && !device().info.has_fp64) GTEST_SKIP() << "no fp64";
    const Scene& scene = this->scene();
    FrameRequest request{64, 48, scene.cameras.front().view, default_param_values(scene)};
    if (!lane_case.assignment.empty())
        set_param_from_text(scene, request.params, lane_case.assignment);
    const CameraBasis basis = camera_basis(request.view);
    const float footprint = pixel_angle(basis, request.width);

    // Double lanes need at least 4 rays per work-item (see precision.hpp).
    for (int width : packet_widths()) {
        if (lane_case.double_precision && width == 1) continue;
        SCOPED_TRACE("requested packet width " + std::to_string(width));
        // A scene with only an inside test renders only by brute force.
        const bool brute = scene.inside_only();
        Renderer renderer(device(), cache_, scene,
                          {width, scene.effects, false, lane_case.double_precision,
                           brute ? RenderMode::Brute : RenderMode::Shaded});
        const Frame frame = renderer.render(request);
        long bad_colour = 0, bad_depth = 0;
        std::vector<glm::vec3> hits;
        std::vector<float> hit_depths;
        std::vector<glm::vec3> brute_normals;
        for (float value : frame.linear) bad_colour += !std::isfinite(value);
        for (int y = 0; y < request.height; ++y) {
            for (int x = 0; x < request.width; ++x) {
                const size_t pixel = size_t(y * request.width + x);
                const float t = frame.depth[pixel];
                if (!std::isfinite(t) || (t < 0.0f && t != -1.0f)) {
                    ++bad_depth;
                } else if (t >= 0.0f) {
                    // Sample 0 is the pixel centre.
                    hits.push_back(glm::vec3(basis.eye) +
                                   primary_ray_direction(basis, request.width, request.height,
                                                         float(x), float(y)) *
                                       t);
                    hit_depths.push_back(t);
                    if (brute) {
                        brute_normals.emplace_back(frame.normal[3 * pixel],
                                                   frame.normal[3 * pixel + 1],
                                                   frame.normal[3 * pixel + 2]);
                    }
                }
            }
        }
        EXPECT_EQ(bad_colour, 0) << "non-finite colour values of " << frame.linear.size();
        EXPECT_EQ(bad_depth, 0) << "non-finite or negative depths";
        ASSERT_FALSE(hits.empty()) << "the default view shows no surface";
        const float eps = footprint * *std::min_element(hit_depths.begin(), hit_depths.end());
        // No DE to probe for an inside-only scene: the normals the brute-force mode shaded with.
        const auto normals =
            brute ? brute_normals
                  : renderer.probe_normals(hits, request.params, std::max(eps, 1e-6f));
        long bad_normals = 0;
        for (const glm::vec3& n : normals) {
            bad_normals += !(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z)) ||
                           std::abs(glm::length(n) - 1.0f) > 1e-3f;
        }
        EXPECT_EQ(bad_normals, 0) << "of " << normals.size()
                                  << " normals are not finite unit vectors";
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, LaneSafety, ::testing::ValuesIn(lane_cases()),
                         [](const auto& test_info) {
                             std::string name =
                                 test_info.param.scene_id +
                                 (test_info.param.assignment.empty() ? "" : "_fractional") +
                                 (test_info.param.double_precision ? "_double" : "_float");
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

}  // namespace
}  // namespace fgr
