// SPDX-License-Identifier: Apache-2.0
// The cost estimate behind the refusal of renders that would take hours
// (render/render_cost.hpp, scene/ifs/ifs_cost.hpp), all on the host: an IFS file whose maps
// overlap so much that its rays open astronomically many nodes is refused from its estimate,
// before anything is built, and the estimate is checked against the reference IFS tracer's own
// node counts; the shipped IFS scenes, a slowly shrinking map's fine detail and ordinary renders
// in every mode pass; absurd path and brute-force settings are refused with what to change.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "camera/camera.hpp"
#include "camera/projection.hpp"
#include "child_process.hpp"
#include "cli/commands.hpp"
#include "render/render_cost.hpp"
#include "scene/ifs/ifs.hpp"
#include "scene/ifs/ifs_cost.hpp"
#include "scene/parameters.hpp"
#include "test_files.hpp"
#include "test_scenes.hpp"

namespace fgr {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kIfsDir = FGR_TEST_IFS_DIR;

// The 2-core CPU the pace is measured on.
DeviceInfo small_cpu() {
    DeviceInfo device;
    device.is_cpu = true;
    device.compute_units = 2;
    return device;
}

// An IFS file's text: `maps` as given, the depth's default and maximum `depth`.
std::string ifs_text(const json& maps, int depth, const std::string& id) {
    json document = {
        {"format", "fgr-ifs"}, {"version", 1}, {"id", id}, {"name", id}, {"maps", maps}};
    if (depth >= 0) document["depth"] = {{"default", depth}, {"max", depth}};
    return document.dump();
}

// 64 maps of scale 0.95 with small seeded random offsets: balls that overlap 55-fold a level.
std::string overlapping_ifs_text() {
    std::mt19937 random(38);
    std::uniform_real_distribution<double> offset(-0.1, 0.1);
    json maps = json::array();
    for (int i = 0; i < 64; ++i) {
        maps.push_back(
            {{"scale", 0.95}, {"translate", {offset(random), offset(random), offset(random)}}});
    }
    return ifs_text(maps, 24, "overlapping");
}

Scene scene_of(const std::string& text, const std::string& name) {
    return ifs_scene_to_scene(parse_ifs_json(text, name), name);
}

// The request of `scene`'s default view at `width` x `height`, with its defaults.
FrameRequest default_request(const Scene& scene, int width, int height) {
    FrameRequest request;
    request.width = width;
    request.height = height;
    request.view = scene.cameras.front().view;
    request.params = default_param_values(scene);
    return request;
}

double seconds_on_small_cpu(const RenderCost& cost) {
    return cost.steps / estimated_pace(small_cpu());
}

// 64 maps of 0.95 at depth 24 took 15 s for 16x12 and would have taken hours at 640x480, in
// silence: refused now from the estimate alone, at either size, saying what to change.
TEST(RenderCost, AnIfsWhoseBallsOverlapEveryLevelIsRefusedWithTheDepthToLowerTo) {
    const Scene scene = scene_of(overlapping_ifs_text(), "overlapping.ifs.json");
    for (const auto& [width, height] : {std::pair{640, 480}, std::pair{16, 12}}) {
        const FrameRequest request = default_request(scene, width, height);
        const RenderCost cost = estimate_render_cost(scene, request, RenderMode::Shaded);
        EXPECT_TRUE(cost.rays_unfinished) << width << "x" << height << ": " << cost.costly;
        const std::string refusal =
            cost_refusal(cost, 1.0, estimated_pace(small_cpu()), kCostLimitSeconds, "OVERRIDE");
        EXPECT_NE(refusal.find("IFS scene 'overlapping'"), std::string::npos) << refusal;
        EXPECT_NE(refusal.find("64 maps"), std::string::npos) << refusal;
        EXPECT_NE(refusal.find("lower ifs_depth to "), std::string::npos) << refusal;
        EXPECT_NE(refusal.find("OVERRIDE"), std::string::npos) << refusal;
        EXPECT_EQ(refusal.find('\n'), std::string::npos) << refusal;
    }
    const IfsCost ray = estimate_ifs_cost(*scene.ifs, 24, 1e-3, 10.0);
    EXPECT_NEAR(ray.overlap, 64 * 0.95 * 0.95 * 0.95, 1e-9);
    EXPECT_NEAR(ray.dimension, std::log(64.0) / std::log(1.0 / 0.95), 1e-6);
}

// The estimate against the reference tracer, which counts the nodes it takes out: on the
// overlapping maps the default view's central ray at depth 24 runs into a cap of 500 nodes
// unfinished, as the estimate says; at the depth the refusal suggests it finishes within the
// kernel's cap and within the estimate.
TEST(RenderCost, TheOverlappingIfsEstimateAgreesWithTheReferenceTracer) {
    const Scene scene = scene_of(overlapping_ifs_text(), "overlapping.ifs.json");
    const IfsScene& ifs = *scene.ifs;
    const CameraView view = scene.cameras.front().view;
    const glm::dvec3 dir = glm::normalize(view.target - view.position);
    const double footprint = pixel_angle(camera_basis(view), 640);
    const double distance = glm::length(view.position - ifs.bounds.centre) - ifs.bounds.radius;
    IfsTraceRules rules;
    rules.footprint = footprint;
    rules.max_depth = 24;
    rules.max_nodes = 500;
    const IfsRayHit capped = trace_ifs_ray(ifs, view.position, dir, rules);
    EXPECT_EQ(capped.visited, 500) << "the reference finished: " << capped.visited;
    EXPECT_GT(estimate_ifs_cost(ifs, 24, footprint, distance).nodes_per_ray, 500.0);
    const FrameRequest request = default_request(scene, 640, 480);
    const double max_nodes = param_value(scene, request.params, "max_steps") * 256.0;
    const int affordable =
        deepest_affordable_ifs_depth(ifs, 24, footprint, distance, max_nodes / 64.0);
    ASSERT_GE(affordable, 1);
    ASSERT_LT(affordable, 24);
    rules.max_depth = affordable;
    rules.max_nodes = static_cast<long>(max_nodes);
    const IfsRayHit finished = trace_ifs_ray(ifs, view.position, dir, rules);
    EXPECT_TRUE(finished.hit);
    EXPECT_LT(finished.visited, rules.max_nodes);
    EXPECT_LE(double(finished.visited),
              estimate_ifs_cost(ifs, affordable, footprint, distance).nodes_per_ray);
}

// Every shipped IFS scene, at its default and its deepest depth from its default camera: the
// estimate stays far from a refusal, and bounds the mean nodes the reference tracer takes out
// over a grid of the view's rays that hit.
TEST(RenderCost, TheShippedIfsScenesPassAndTheirEstimatesBoundTheReference) {
    for (const auto& entry : fs::directory_iterator(kIfsDir)) {
        if (!is_ifs_file_name(entry.path())) continue;
        SCOPED_TRACE(entry.path().filename().string());
        const IfsScene ifs = read_ifs_file(entry.path());
        const Scene scene = ifs_scene_to_scene(ifs, entry.path());
        for (const int depth : {ifs.default_depth, ifs.max_depth}) {
            SCOPED_TRACE(depth);
            FrameRequest request = default_request(scene, 640, 480);
            set_param_from_text(scene, request.params, fmt::format("ifs_depth={}", depth));
            const RenderCost cost = estimate_render_cost(scene, request, RenderMode::Shaded);
            EXPECT_FALSE(cost.rays_unfinished) << cost.costly;
            EXPECT_LT(seconds_on_small_cpu(cost), 60.0) << cost.costly;
            const CameraView& view = request.view;
            const CameraModel model = camera_model(view, Projection{});
            IfsTraceRules rules;
            rules.max_depth = depth;
            rules.footprint = pixel_angle(camera_basis(view), 640);
            double visited = 0.0, hits = 0.0;
            for (int y = 0; y < 480; y += 20) {
                for (int x = 0; x < 640; x += 40) {
                    const auto ray =
                        projected_ray_direction(model, 640, 480, float(x) + 0.5f, float(y) + 0.5f);
                    const IfsRayHit hit =
                        trace_ifs_ray(ifs, view.position, glm::dvec3(*ray), rules);
                    if (!hit.hit) continue;
                    visited += double(hit.visited);
                    hits += 1.0;
                }
            }
            const double distance =
                glm::length(view.position - ifs.bounds.centre) - ifs.bounds.radius;
            const IfsCost estimate = estimate_ifs_cost(ifs, depth, rules.footprint, distance);
            ASSERT_GT(hits, 0.0);
            EXPECT_LE(visited / hits, estimate.nodes_per_ray)
                << "estimated " << estimate.nodes_per_ray << " nodes a ray";
        }
    }
}

// A 3D fern: a frond map that shrinks by 0.85 a level (with a slight turn), two leaflets and a
// stem. Its tip (the frond map's fixed point) is only reached at the deepest level: a file that
// gave no depth used to stop at 6 and draw a large ball there. Now the depth follows the
// footprint up to the cap, and the estimate stays within the default's budget.
TEST(IfsCost, ASlowlyShrinkingFrondReachesItsTipWithoutADepthGiven) {
    const json maps = {{{"scale", 0.85},
                        {"rotate", {{"axis", {0, 1, 0}}, {"degrees", 4}}},
                        {"translate", {0, 0, 0.5}}},
                       {{"scale", 0.3},
                        {"rotate", {{"axis", {0, 1, 0}}, {"degrees", 50}}},
                        {"translate", {0, 0, 0.3}}},
                       {{"scale", 0.3},
                        {"rotate", {{"axis", {0, 1, 0}}, {"degrees", -50}}},
                        {"translate", {0, 0, 0.3}}},
                       {{"scale", {0.05, 0.05, 0.2}}}};
    const IfsScene fern = parse_ifs_json(ifs_text(maps, -1, "fern"), "fern.ifs.json");
    EXPECT_EQ(fern.default_depth, kIfsMaxDepth);
    EXPECT_EQ(fern.max_depth, kIfsMaxDepth);
    const CameraView view = fern.cameras.front().view;
    const double footprint = pixel_angle(camera_basis(view), 640);
    const double distance = glm::length(view.position - fern.bounds.centre) - fern.bounds.radius;
    const IfsCost cost = estimate_ifs_cost(fern, fern.default_depth, footprint, distance);
    EXPECT_LE(cost.nodes_per_ray, kIfsDefaultDepthNodes);
    EXPECT_EQ(cost.levels, kIfsMaxDepth);
    // The ray through the tip ends in a leaf at the cap, whose ball is a fiftieth of the whole.
    const IfsMap& frond = fern.maps[0];
    const glm::dvec3 tip = glm::inverse(glm::dmat3(1.0) - frond.linear) * frond.offset;
    IfsTraceRules rules;
    rules.max_depth = fern.default_depth;
    rules.footprint = footprint;
    const IfsRayHit hit =
        trace_ifs_ray(fern, view.position, glm::normalize(tip - view.position), rules);
    ASSERT_TRUE(hit.hit);
    EXPECT_EQ(hit.depth, kIfsMaxDepth);
    const Scene scene = ifs_scene_to_scene(fern, "fern.ifs.json");
    const RenderCost render =
        estimate_render_cost(scene, default_request(scene, 640, 480), RenderMode::Shaded);
    EXPECT_EQ(cost_refusal(render, 1.0, estimated_pace(small_cpu()), kCostLimitSeconds, "O"), "")
        << render.costly;
}

// Path tracing at the largest size and sample count, and the brute mode at the finest sampling
// and most passes, imply days: refused, saying what to change. Their defaults pass.
TEST(RenderCost, AbsurdPathAndBruteSettingsAreRefusedAndDefaultsPass) {
    const Scene scene = test::built_scene("mandelbulb.so");
    const double pace = estimated_pace(small_cpu());
    for (const RenderMode mode : {RenderMode::Shaded, RenderMode::Path, RenderMode::Brute}) {
        FrameRequest request = default_request(scene, 640, 480);
        request.samples = mode == RenderMode::Path ? 64 : mode == RenderMode::Brute ? 16 : 1;
        const RenderCost usual = estimate_render_cost(scene, request, mode);
        EXPECT_EQ(cost_refusal(usual, 1.0, pace, kCostLimitSeconds, "OVERRIDE"), "")
            << render_mode_name(mode) << ": " << usual.costly;
        request.width = 16384;
        request.height = 16384;
        request.samples = 4096;
        if (mode == RenderMode::Brute) {
            set_param_from_text(scene, request.params, "brute_samples=1024");
        }
        const RenderCost absurd = estimate_render_cost(scene, request, mode);
        const std::string refusal = cost_refusal(absurd, 1.0, pace, kCostLimitSeconds, "OVERRIDE");
        EXPECT_NE(refusal.find("this render would take about "), std::string::npos) << refusal;
        EXPECT_NE(refusal.find("over the limit of"), std::string::npos) << refusal;
        EXPECT_NE(refusal.find("--spp"), std::string::npos) << refusal;
        EXPECT_NE(refusal.find("OVERRIDE"), std::string::npos) << refusal;
    }
}

// What fgr render and fgr video do with the estimate: refuse (UsageError) unless --no-cost-limit;
// under --time-limit, which bounds the render, only an IFS whose rays would stop unfinished.
TEST(RenderCost, TheCommandsRefuseUnlessTheLimitIsLiftedOrATimeLimitBoundsTheRender) {
    const Scene bulb = test::built_scene("mandelbulb.so");
    StillJob path;
    path.settings.mode = RenderMode::Path;
    path.request = default_request(bulb, 16384, 16384);
    path.request.samples = 4096;
    const Scene overlapping = scene_of(overlapping_ifs_text(), "overlapping.ifs.json");
    StillJob ifs;
    ifs.request = default_request(overlapping, 16, 12);
    RenderOptions options;
    EXPECT_THROW(check_render_cost(bulb, path, options, small_cpu()), UsageError);
    EXPECT_THROW(check_render_cost(overlapping, ifs, options, small_cpu()), UsageError);
    // A video of frames that each pass can be refused as a whole.
    StillJob small = path;
    small.request.width = 64;
    small.request.height = 48;
    small.request.samples = 16;
    EXPECT_NO_THROW(check_render_cost(bulb, small, options, small_cpu()));
    EXPECT_THROW(check_render_cost(bulb, small, options, small_cpu(), 1e6), UsageError);
    options.time_limit = 60.0;
    EXPECT_NO_THROW(check_render_cost(bulb, path, options, small_cpu()));
    EXPECT_THROW(check_render_cost(overlapping, ifs, options, small_cpu()), UsageError);
    options.no_cost_limit = true;
    EXPECT_NO_THROW(check_render_cost(bulb, path, options, small_cpu()));
    EXPECT_NO_THROW(check_render_cost(overlapping, ifs, options, small_cpu()));
}

// `fgr render` of the overlapping IFS file: one line, at once, before any kernel is built.
TEST(RenderCost, FgrRenderRefusesTheOverlappingIfsInOneLine) {
    const test::TempDir dir("fgr_render_cost");
    const fs::path file = dir.path() / "overlapping.ifs.json";
    test::write_text(file, overlapping_ifs_text());
    const test::RunResult result = test::run_fgr(
        {"render", file.string(), "-o", "o.png", "--width", "16", "--height", "12"}, dir.path());
    ASSERT_TRUE(result.exited) << result;
    EXPECT_NE(result.exit_code, 0) << result;
    std::string err = result.err;
    if (!err.empty() && err.back() == '\n') err.pop_back();
    EXPECT_EQ(err.rfind("fgr: error: IFS scene 'overlapping'", 0), 0u) << result;
    EXPECT_EQ(err.find('\n'), std::string::npos) << "more than one line: " << result;
    EXPECT_NE(err.find("--no-cost-limit"), std::string::npos) << result;
    EXPECT_FALSE(fs::exists(dir.path() / "o.png"));
}

}  // namespace
}  // namespace fgr
