// SPDX-License-Identifier: Apache-2.0
// A compiled plugin that hands over IFS maps instead of a distance estimator (ABI 1.3,
// fgr_scene_desc::ifs_maps): tests/fixtures/ifs_plugin builds the shipped sierpinski.ifs.json as a
// plugin. It loads as an IFS scene with the maps it handed over, renders the same depth planes as
// the file, and the description's IFS fields are read only when its struct_size covers them. The
// bad IFS plugins (maps not contractive, singular or NaN, too many, too deep, with a source) are in
// test_bad_plugins.cpp's table.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <string>

#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"
#include "fgr/plugin.h"
#include "fgr/scene_helpers.h"
#include "render/renderer.hpp"
#include "scene/description_validation.hpp"
#include "scene/ifs/ifs.hpp"
#include "scene/parameters.hpp"
#include "scene/plugin_loader.hpp"

namespace fgr {
namespace {
namespace fs = std::filesystem;

const fs::path kIfsPluginFixtureDir = fs::path(FGR_TEST_FIXTURE_DIR) / "ifs_plugin";
const fs::path kPlugin = kIfsPluginFixtureDir / "sierpinski_ifs_plugin.so";
const fs::path kShippedFile = fs::path(FGR_TEST_IFS_DIR) / "sierpinski.ifs.json";

// What the plugin hands over (tests/fixtures/ifs_plugin/sierpinski_ifs_plugin.c): x -> x / 2 + t.
constexpr float kOffsets[4][3] = {{0.0f, 0.0f, 0.866025403784f},
                                  {0.0f, -0.816496580928f, -0.288675134595f},
                                  {0.707106781187f, 0.408248290464f, -0.288675134595f},
                                  {-0.707106781187f, 0.408248290464f, -0.288675134595f}};
constexpr float kColours[4][3] = {
    {0.95f, 0.8f, 0.42f}, {0.9f, 0.47f, 0.36f}, {0.32f, 0.7f, 0.74f}, {0.62f, 0.52f, 0.86f}};

Scene load_plugin() {
    LoadResult loaded = load_scene_plugin(kPlugin);
    if (!loaded.scene) {
        ADD_FAILURE() << kPlugin << ": " << loaded.error;
        return Scene{};
    }
    return std::move(*loaded.scene);
}

TEST(IfsPlugin, LoadsAsAnIfsSceneWithTheMapsItHandedOver) {
    const Scene scene = load_plugin();
    ASSERT_TRUE(scene.ifs) << "not an IFS scene";
    EXPECT_EQ(scene.id, "sierpinski-ifs-plugin");
    EXPECT_EQ(scene.name, "Sierpinski tetrahedron (IFS plugin)");
    EXPECT_EQ(scene.plugin_file, kPlugin);
    EXPECT_NE(scene.source.find("#define FGR_GEOMETRY_IFS"), std::string::npos);
    EXPECT_NE(scene.source.find("#define FGR_IFS_MAPS 4"), std::string::npos);
    EXPECT_EQ(scene.effects, uint64_t{FGR_EFFECT_SHADOWS});
    EXPECT_EQ(scene.default_mode, RenderMode::Shaded);

    // Its own parameter is the depth slider, with the plugin's default and maximum; then the
    // built-ins.
    ASSERT_EQ(scene.params.size(), 1 + builtin_param_count());
    const ParamInfo& depth = scene.params[0];
    EXPECT_EQ(depth.id, "ifs_depth");
    EXPECT_FALSE(depth.builtin);
    EXPECT_EQ(depth.type, ParamType::Int);
    EXPECT_EQ(depth.default_value[0], 5.0f);
    EXPECT_EQ(depth.max_value, 16.0f);
    EXPECT_EQ(scene.ifs->default_depth, 5);
    EXPECT_EQ(scene.ifs->max_depth, 16);

    // The maps, exactly as handed over (floats widen exactly to double).
    ASSERT_EQ(scene.ifs->maps.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        SCOPED_TRACE("map " + std::to_string(i));
        const IfsMap& map = scene.ifs->maps[i];
        for (int c = 0; c < 3; ++c) {
            for (int r = 0; r < 3; ++r) EXPECT_EQ(map.linear[c][r], r == c ? 0.5 : 0.0);
            EXPECT_EQ(map.offset[c], double{kOffsets[i][c]});
            EXPECT_EQ(map.colour[c], kColours[i][c]);
        }
        EXPECT_DOUBLE_EQ(map.contraction, 0.5);
    }
    // The bounding sphere holds every corner of the tetrahedron (each map's fixed point, 2t).
    for (const auto& offset : kOffsets) {
        const glm::dvec3 corner = 2.0 * glm::dvec3(offset[0], offset[1], offset[2]);
        EXPECT_LE(glm::length(corner - scene.ifs->bounds.centre), scene.ifs->bounds.radius);
    }

    ASSERT_EQ(scene.cameras.size(), 3u);
    EXPECT_EQ(scene.cameras[0].name, "front");
    ASSERT_EQ(scene.camera_paths.size(), 1u);
    EXPECT_EQ(scene.camera_paths[0].name, "fly-in");
    ASSERT_EQ(scene.lights.size(), 2u);
}

// The shipped file describes the same maps in double precision: the plugin's are the file's
// rounded to float.
TEST(IfsPlugin, MapsAreTheShippedFilesToFloatPrecision) {
    const Scene scene = load_plugin();
    ASSERT_TRUE(scene.ifs);
    const IfsScene file = read_ifs_file(kShippedFile);
    ASSERT_EQ(file.maps.size(), scene.ifs->maps.size());
    for (std::size_t i = 0; i < file.maps.size(); ++i) {
        SCOPED_TRACE("map " + std::to_string(i));
        for (int c = 0; c < 3; ++c) {
            for (int r = 0; r < 3; ++r) {
                EXPECT_EQ(scene.ifs->maps[i].linear[c][r], file.maps[i].linear[c][r]);
            }
            EXPECT_EQ(scene.ifs->maps[i].offset[c], double(float(file.maps[i].offset[c])));
            EXPECT_EQ(scene.ifs->maps[i].colour[c], file.maps[i].colour[c]);
        }
    }
    EXPECT_EQ(scene.ifs->default_depth, file.default_depth);
    EXPECT_EQ(scene.ifs->max_depth, file.max_depth);
    EXPECT_NEAR(scene.ifs->bounds.radius, file.bounds.radius, 1e-6 * file.bounds.radius);
}

// It renders, and from the file's default view at several depths the plugin and the file hit the
// same pixels at the same distances, to the bit: the kernel computes in float, to which the file's
// double offsets round as the plugin's did. A plugin hands over no leaf shape, so the file's
// tetrahedron leaf is set aside: both draw balls.
TEST(IfsPlugin, RendersTheSameDepthPlanesAsTheShippedFile) {
    const Scene plugin = load_plugin();
    ASSERT_TRUE(plugin.ifs);
    IfsScene file_ifs = read_ifs_file(kShippedFile);
    file_ifs.leaf = IfsLeaf{};
    const Scene file = ifs_scene_to_scene(file_ifs, kShippedFile);
    const ComputeDevice device = open_device(-1);
    ProgramCache cache{fs::path()};
    const int packet = preferred_packet_width(device.info);
    Renderer plugin_renderer(device, cache, plugin, {packet, plugin.effects});
    Renderer file_renderer(device, cache, file, {packet, file.effects});
    constexpr int kWidth = 32, kHeight = 24;
    for (const int depth : {0, 3, 8}) {
        SCOPED_TRACE("depth " + std::to_string(depth));
        FrameRequest request{kWidth, kHeight, plugin.cameras[0].view, default_param_values(plugin)};
        set_param_from_text(plugin, request.params, "ifs_depth=" + std::to_string(depth));
        FrameRequest file_request{kWidth, kHeight, file.cameras[0].view,
                                  default_param_values(file)};
        set_param_from_text(file, file_request.params, "ifs_depth=" + std::to_string(depth));
        const Frame from_plugin = plugin_renderer.render(request);
        const Frame from_file = file_renderer.render(file_request);
        EXPECT_GT(from_plugin.hits, 10);
        EXPECT_LT(from_plugin.hits, long{kWidth * kHeight});
        EXPECT_EQ(from_plugin.hits, from_file.hits);
        EXPECT_EQ(from_plugin.depth, from_file.depth);
    }
}

// --- The description's IFS fields, directly ------------------------------------------------------

const fgr_ifs_map kMaps[] = {
    FGR_IFS_SCALE_MAP(0.5f, 0.0f, 0.0f, 0.0f, 0.5f, 0.5f, 0.5f),
    FGR_IFS_SCALE_MAP(0.5f, 1.0f, 0.0f, 0.0f, 0.5f, 0.5f, 0.5f),
};
const fgr_camera kCameras[] = {
    FGR_CAMERA_Z_UP("front", 1.0f, -5.0f, 1.0f, 1.0f, 0.0f, 0.0f, 50.0f)};
const fgr_light kLights[] = {FGR_DIRECTIONAL_LIGHT(1.0f, -1.0f, 1.0f, 1.0f, 1.0f, 1.0f, 1.0f)};

fgr_scene_desc ifs_description(uint32_t default_depth, uint32_t max_depth) {
    const fgr_camera_path* no_paths = nullptr;
    fgr_scene_desc desc{};
    desc.header = FGR_HEADER(fgr_scene_desc);
    desc.id = "two-maps";
    desc.name = "Two maps";
    desc.description = "";
    desc.cameras = kCameras;
    desc.camera_count = 1;
    desc.camera_paths = no_paths;
    desc.lights = kLights;
    desc.light_count = 1;
    desc.march = FGR_MARCH(1u, 100.0f, 1.0f, 1u, 1.0f);
    desc.ifs_maps = kMaps;
    desc.ifs_map_count = 2;
    desc.ifs_default_depth = default_depth;
    desc.ifs_max_depth = max_depth;
    return desc;
}

// 0 means "not given", as in an IFS file that leaves the depth out.
TEST(IfsPlugin, DepthZeroMeansNotGivenAsInAnIfsFile) {
    struct Case {
        uint32_t given_default, given_max;
        int default_depth, max_depth;
    };
    // Without a default, the maximum (24 without one): two maps reach their detail cheaply.
    for (const Case& c : {Case{0, 0, 24, 24}, Case{15, 0, 15, 24}, Case{3, 0, 3, 24},
                          Case{0, 4, 4, 4}, Case{0, 20, 20, 20}, Case{2, 24, 2, 24}}) {
        SCOPED_TRACE(::testing::Message() << c.given_default << ", " << c.given_max);
        const fgr_scene_desc desc = ifs_description(c.given_default, c.given_max);
        const LoadResult result = copy_scene_description(&desc);
        ASSERT_TRUE(result.scene) << result.error;
        ASSERT_TRUE(result.scene->ifs);
        EXPECT_EQ(result.scene->ifs->default_depth, c.default_depth);
        EXPECT_EQ(result.scene->ifs->max_depth, c.max_depth);
    }
    const fgr_scene_desc inverted = ifs_description(9, 4);
    EXPECT_EQ(copy_scene_description(&inverted).error,
              "ifs_default_depth 9 is above ifs_max_depth 4");
}

// A plugin built against 1.2 has no IFS fields: whatever lies behind its smaller struct is never
// read as maps, so without a source it is refused for that, not loaded as an IFS scene.
TEST(IfsPlugin, FieldsBeyondAnOlderStructSizeAreNotRead) {
    fgr_scene_desc desc = ifs_description(0, 0);
    desc.header.struct_size =
        static_cast<uint32_t>(offsetof(fgr_scene_desc, default_mode) + sizeof(const char*));
    desc.header.abi_version = 0x00010002u;
    EXPECT_EQ(copy_scene_description(&desc).error, "source is NULL");
    desc.source = "real scene_de(vec3 p, PARAMS) { return v3_length(p) - 1.0f; }\n";
    const LoadResult result = copy_scene_description(&desc);
    ASSERT_TRUE(result.scene) << result.error;
    EXPECT_FALSE(result.scene->ifs) << "a 1.2 description's trailing bytes were read as maps";
    // With the full 1.3 size, the same description (maps and a source) is refused.
    desc.header = FGR_HEADER(fgr_scene_desc);
    const LoadResult both = copy_scene_description(&desc);
    EXPECT_FALSE(both.scene);
    EXPECT_NE(both.error.find("IFS maps and a source"), std::string::npos) << both.error;
}

}  // namespace
}  // namespace fgr
