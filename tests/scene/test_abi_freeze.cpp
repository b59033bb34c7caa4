// SPDX-License-Identifier: Apache-2.0
// The ABI 1.0 and 1.1 freezes. tests/fixtures/frozen_v1 builds a plugin against the frozen copy of
// the 1.0 header (tests/abi_v1/fgr/plugin.h); here the current host loads it with every field
// intact and renders it, its table of 1.0 offsets and sizes matches the current header's, the same
// plugin claiming major version 2 is refused by name, and the frozen copy itself has not changed.
// tests/fixtures/frozen_v1_1 does the same for 1.1 (tests/abi_v1_1), whose one addition is the
// source's length, and tests/fixtures/frozen_v1_2 for 1.2 (tests/abi_v1_2): the render mode a scene
// asks for and the angular radius of a directional light's disc. Plugins built against 1.0 and 1.1
// get 1.2's defaults. tests/fixtures/frozen_v1_3 (tests/abi_v1_3) is an IFS scene: maps instead of
// a source; older plugins' descriptions end before the maps. tests/fixtures/frozen_v1_4
// (tests/abi_v1_4) gives its own defaults for built-in parameters, the colour modes it offers and
// a length scale; older plugins get fgr's defaults, all colour modes and scale 1.
// tests/fixtures/frozen_v1_5 (tests/abi_v1_5) names an environment of its own for the path mode;
// older plugins have none (the sky).

#include <dlfcn.h>
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "child_process.hpp"
#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"
#include "fgr/plugin.h"
#include "fixtures/frozen_v1/frozen_layout.h"
#include "fixtures/frozen_v1_1/frozen_layout_v1_1.h"
#include "fixtures/frozen_v1_2/frozen_layout_v1_2.h"
#include "fixtures/frozen_v1_3/frozen_layout_v1_3.h"
#include "fixtures/frozen_v1_4/frozen_layout_v1_4.h"
#include "fixtures/frozen_v1_5/frozen_layout_v1_5.h"
#include "render/environment.hpp"
#include "render/renderer.hpp"
#include "scene/discovery.hpp"
#include "scene/ifs/ifs.hpp"
#include "scene/parameters.hpp"
#include "scene/plugin_loader.hpp"
#include "scene/render_mode.hpp"

namespace fgr {
namespace {
namespace fs = std::filesystem;

const fs::path kFrozenDir = fs::path(FGR_TEST_FIXTURE_DIR) / "frozen_v1";
const fs::path kFrozenPlugin = kFrozenDir / "frozen_v1.so";
const fs::path kMajor2Plugin = kFrozenDir / "frozen_v1_major2.so";
const fs::path kFrozenHeader = fs::path(FGR_TEST_SOURCE_DIR) / "abi_v1" / "fgr" / "plugin.h";
const fs::path kFrozenV1_1Plugin =
    fs::path(FGR_TEST_FIXTURE_DIR) / "frozen_v1_1" / "frozen_v1_1.so";
const fs::path kFrozenV1_1Header = fs::path(FGR_TEST_SOURCE_DIR) / "abi_v1_1" / "fgr" / "plugin.h";
const fs::path kFrozenV1_2Plugin =
    fs::path(FGR_TEST_FIXTURE_DIR) / "frozen_v1_2" / "frozen_v1_2.so";
const fs::path kFrozenV1_2Header = fs::path(FGR_TEST_SOURCE_DIR) / "abi_v1_2" / "fgr" / "plugin.h";
const fs::path kFrozenV1_3Plugin =
    fs::path(FGR_TEST_FIXTURE_DIR) / "frozen_v1_3" / "frozen_v1_3.so";
const fs::path kFrozenV1_3Header = fs::path(FGR_TEST_SOURCE_DIR) / "abi_v1_3" / "fgr" / "plugin.h";
const fs::path kFrozenV1_4Plugin =
    fs::path(FGR_TEST_FIXTURE_DIR) / "frozen_v1_4" / "frozen_v1_4.so";
const fs::path kFrozenV1_4Header = fs::path(FGR_TEST_SOURCE_DIR) / "abi_v1_4" / "fgr" / "plugin.h";
const fs::path kFrozenV1_5Plugin =
    fs::path(FGR_TEST_FIXTURE_DIR) / "frozen_v1_5" / "frozen_v1_5.so";
const fs::path kFrozenV1_5Header = fs::path(FGR_TEST_SOURCE_DIR) / "abi_v1_5" / "fgr" / "plugin.h";

// FNV-1a (64 bit) of tests/abi_v1/fgr/plugin.h as committed. Never update it: see
// FrozenHeaderNeverChanges.
constexpr uint64_t kFrozenHeaderHash = 0x725cb0f5e489cfb4u;
// The same of tests/abi_v1_1/fgr/plugin.h.
constexpr uint64_t kFrozenV1_1HeaderHash = 0x5f1aab15c211936u;
// The same of tests/abi_v1_2/fgr/plugin.h.
constexpr uint64_t kFrozenV1_2HeaderHash = 0x2c4886571464b29au;
// The same of tests/abi_v1_3/fgr/plugin.h.
constexpr uint64_t kFrozenV1_3HeaderHash = 0x813ebe43a6b91a8au;
// The same of tests/abi_v1_4/fgr/plugin.h.
constexpr uint64_t kFrozenV1_4HeaderHash = 0xc1cffbc5c5d2f5dbu;
// The same of tests/abi_v1_5/fgr/plugin.h.
constexpr uint64_t kFrozenV1_5HeaderHash = 0x1a75830cef57bcbeu;

// How many rows ABI 1.0 has in each list of frozen_layout.h: a row dropped from a list would
// otherwise quietly stop being checked.
constexpr std::size_t kV1StructCount = 8;
constexpr std::size_t kV1FieldCount = 55;
constexpr std::size_t kV1ConstantCount = 18;
// ABI 1.1 added one field: fgr_scene_desc::source_length.
constexpr std::size_t kV1_1StructCount = kV1StructCount;
constexpr std::size_t kV1_1FieldCount = kV1FieldCount + 1;
constexpr std::size_t kV1_1ConstantCount = kV1ConstantCount;
// ABI 1.2 added two: fgr_light::angular_radius_degrees and fgr_scene_desc::default_mode.
constexpr std::size_t kV1_2StructCount = kV1_1StructCount;
constexpr std::size_t kV1_2FieldCount = kV1_1FieldCount + 2;
constexpr std::size_t kV1_2ConstantCount = kV1_1ConstantCount;
// ABI 1.3 added a struct, fgr_ifs_map (three fields), and four fields of fgr_scene_desc.
constexpr std::size_t kV1_3StructCount = kV1_2StructCount + 1;
constexpr std::size_t kV1_3FieldCount = kV1_2FieldCount + 3 + 4;
constexpr std::size_t kV1_3ConstantCount = kV1_2ConstantCount;
// ABI 1.4 added a struct, fgr_builtin_default (three fields), four fields of fgr_scene_desc, and
// the four colour mode flags with their union.
constexpr std::size_t kV1_4StructCount = kV1_3StructCount + 1;
constexpr std::size_t kV1_4FieldCount = kV1_3FieldCount + 3 + 4;
constexpr std::size_t kV1_4ConstantCount = kV1_3ConstantCount + 5;
// ABI 1.5 added one field: fgr_scene_desc::environment.
constexpr std::size_t kV1_5StructCount = kV1_4StructCount;
constexpr std::size_t kV1_5FieldCount = kV1_4FieldCount + 1;
constexpr std::size_t kV1_5ConstantCount = kV1_4ConstantCount;

Scene load_frozen_scene() {
    LoadResult loaded = load_scene_plugin(kFrozenPlugin);
    if (!loaded.scene) {
        ADD_FAILURE() << kFrozenPlugin << ": " << loaded.error;
        return Scene{};
    }
    return std::move(*loaded.scene);
}

// Pixels of the scene's default view (32x24, its own effects) that hit: it builds and renders.
long default_view_hits(const Scene& scene) {
    const ComputeDevice device = open_device(-1);
    ProgramCache cache{fs::path()};
    Renderer renderer(device, cache, scene, {preferred_packet_width(device.info), scene.effects});
    FrameRequest request;
    request.width = 32;
    request.height = 24;
    request.view = scene.cameras.front().view;
    request.params = default_param_values(scene);
    return renderer.render(request).hits;
}

void expect_vec3(const glm::vec3& actual, const glm::vec3& expected, const std::string& what) {
    for (glm::vec3::length_type i = 0; i < 3; ++i) {
        EXPECT_FLOAT_EQ(actual[i], expected[i]) << what << " component " << i;
    }
}

void expect_view(const CameraView& view, const glm::vec3& position, const glm::vec3& target,
                 const glm::vec3& up, float fov_degrees, const std::string& what) {
    expect_vec3(view.position, position, what + " position");
    expect_vec3(view.target, target, what + " target");
    expect_vec3(view.up, up, what + " up");
    EXPECT_FLOAT_EQ(view.fov_degrees, fov_degrees) << what << " fov";
}

struct ExpectedParam {
    std::string id, label, group, description;
    ParamType type;
    float min_value, max_value;
    std::array<float, 3> default_value;
    std::vector<std::string> choices;
};

// --- (a) Loading: every value the 1.0 plugin wrote arrives in the host's copy -------------------

TEST(AbiFreeze, FrozenV1PluginLoadsWithEveryField) {
    const Scene scene = load_frozen_scene();
    ASSERT_FALSE(scene.id.empty());
    EXPECT_EQ(scene.id, "frozen-v1");
    EXPECT_EQ(scene.name, "Frozen ABI 1.0");
    EXPECT_EQ(scene.description, "a scene plugin built against the frozen ABI 1.0 header");
    EXPECT_EQ(scene.source_name, "frozen_v1.cl");
    EXPECT_NE(scene.source.find("real scene_de(vec3 p, PARAMS)"), std::string::npos);
    EXPECT_EQ(scene.plugin_file, kFrozenPlugin);

    // Label, group and description NULL in `copies`: the documented fallbacks.
    // clang-format off
    const std::vector<ExpectedParam> expected_params = {
        {"size", "Size", "Shape", "radius of each shape", ParamType::Float, 0.2f, 1.5f,
         {0.8f, 0.0f, 0.0f}, {}},
        {"shape", "Shape", "Shape", "which primitive", ParamType::Int, 0.0f, 2.0f,
         {0.0f, 0.0f, 0.0f}, {"sphere", "box", "torus"}},
        {"copies", "copies", "Scene", "", ParamType::Int, 1.0f, 3.0f, {2.0f, 0.0f, 0.0f}, {}},
        {"ground", "Ground", "Scene", "a floor under the shapes", ParamType::Bool, 0.0f, 1.0f,
         {1.0f, 0.0f, 0.0f}, {}},
        {"centre", "Centre", "Shape", "middle of the row", ParamType::Vec3, -1.0f, 1.0f,
         {0.0f, 0.25f, 0.1f}, {}},
        {"albedo", "Albedo", "Look", "surface colour", ParamType::Colour, 0.0f, 1.0f,
         {0.8f, 0.5f, 0.3f}, {}},
    };
    // clang-format on
    ASSERT_EQ(scene.params.size(), expected_params.size() + builtin_param_count());
    for (std::size_t i = 0; i < expected_params.size(); ++i) {
        const ExpectedParam& expected = expected_params[i];
        const ParamInfo& param = scene.params[i];
        SCOPED_TRACE("parameter " + expected.id);
        EXPECT_EQ(param.id, expected.id);
        EXPECT_EQ(param.label, expected.label);
        EXPECT_EQ(param.group, expected.group);
        EXPECT_EQ(param.description, expected.description);
        EXPECT_EQ(param.type, expected.type);
        EXPECT_FLOAT_EQ(param.min_value, expected.min_value);
        EXPECT_FLOAT_EQ(param.max_value, expected.max_value);
        for (std::size_t c = 0; c < 3; ++c) {
            EXPECT_FLOAT_EQ(param.default_value[c], expected.default_value[c]) << "component " << c;
        }
        EXPECT_EQ(param.choices, expected.choices);
        EXPECT_FALSE(param.builtin);
    }

    ASSERT_EQ(scene.cameras.size(), 3u);
    EXPECT_EQ(scene.cameras[0].name, "front");
    expect_view(scene.cameras[0].view, {0, -5, 1.5f}, {0, 0, 0}, {0, 0, 1}, 50.0f, "front");
    EXPECT_EQ(scene.cameras[1].name, "side");
    expect_view(scene.cameras[1].view, {5, 0, 1}, {0, 0, 0}, {0, 0, 1}, 40.0f, "side");
    EXPECT_EQ(scene.cameras[2].name, "top-down");
    expect_view(scene.cameras[2].view, {0, 0, 6}, {0, 0, 0}, {0, 1, 0}, 60.0f, "top-down");

    ASSERT_EQ(scene.camera_paths.size(), 2u);
    const CameraPath& orbit = scene.camera_paths[0];
    EXPECT_EQ(orbit.name, "orbit");
    ASSERT_EQ(orbit.keyframes.size(), 3u);
    EXPECT_FLOAT_EQ(orbit.keyframes[0].time, 0.0f);
    expect_view(orbit.keyframes[0].view, {0, -5, 1.5f}, {0, 0, 0}, {0, 0, 1}, 50.0f, "orbit 0");
    EXPECT_FLOAT_EQ(orbit.keyframes[1].time, 2.0f);
    expect_view(orbit.keyframes[1].view, {5, 0, 1.5f}, {0, 0, 0}, {0, 0, 1}, 50.0f, "orbit 1");
    EXPECT_FLOAT_EQ(orbit.keyframes[2].time, 4.5f);
    expect_view(orbit.keyframes[2].view, {0, 5, 2}, {0, 0, 0}, {0, 0, 1}, 45.0f, "orbit 2");
    const CameraPath& rise = scene.camera_paths[1];
    EXPECT_EQ(rise.name, "rise");
    ASSERT_EQ(rise.keyframes.size(), 2u);
    EXPECT_FLOAT_EQ(rise.keyframes[0].time, 0.5f);
    expect_view(rise.keyframes[0].view, {0, -4, 0.2f}, {0, 0, 0}, {0, 0, 1}, 55.0f, "rise 0");
    EXPECT_FLOAT_EQ(rise.keyframes[1].time, 3.0f);
    expect_view(rise.keyframes[1].view, {0, -4, 4}, {0, 0, -0.5f}, {0, 0, 1}, 35.0f, "rise 1");

    ASSERT_EQ(scene.lights.size(), 2u);
    EXPECT_EQ(scene.lights[0].type, LightType::Directional);
    // The host normalises directions.
    expect_vec3(scene.lights[0].vector, glm::normalize(glm::vec3(1, -1, 2)), "light 0 vector");
    expect_vec3(scene.lights[0].colour, {1.0f, 0.95f, 0.9f}, "light 0 colour");
    EXPECT_FLOAT_EQ(scene.lights[0].intensity, 1.25f);
    EXPECT_EQ(scene.lights[1].type, LightType::Point);
    expect_vec3(scene.lights[1].vector, {2, -2, 3}, "light 1 position");
    expect_vec3(scene.lights[1].colour, {0.6f, 0.7f, 1.0f}, "light 1 colour");
    EXPECT_FLOAT_EQ(scene.lights[1].intensity, 8.0f);

    EXPECT_EQ(scene.effects,
              uint64_t{FGR_EFFECT_SHADOWS | FGR_EFFECT_AMBIENT_OCCLUSION | FGR_EFFECT_FOG});

    EXPECT_EQ(scene.march.max_steps, 160u);
    EXPECT_FLOAT_EQ(scene.march.max_distance, 40.0f);
    EXPECT_FLOAT_EQ(scene.march.hit_threshold, 1.5f);
    EXPECT_EQ(scene.march.de_iterations, 5u);
    EXPECT_FLOAT_EQ(scene.march.step_factor, 0.9f);
    // ... and they became the built-in parameters' defaults.
    const ParamInfo* iterations = scene.find_param("iterations");
    const ParamInfo* step_factor = scene.find_param("step_factor");
    ASSERT_TRUE(iterations != nullptr && step_factor != nullptr);
    EXPECT_FLOAT_EQ(iterations->default_value[0], 5.0f);
    EXPECT_FLOAT_EQ(step_factor->default_value[0], 0.9f);
}

// --- (b) Rendering: its kernel still builds against the current kernel library ------------------

TEST(AbiFreeze, FrozenV1PluginRenders) {
    const Scene scene = load_frozen_scene();
    ASSERT_FALSE(scene.cameras.empty());
    const ComputeDevice device = open_device(-1);
    ProgramCache cache{fs::path()};
    Renderer renderer(device, cache, scene, {preferred_packet_width(device.info), scene.effects});
    constexpr int kWidth = 32, kHeight = 24;
    for (const NamedCamera& camera : scene.cameras) {
        FrameRequest request;
        request.width = kWidth;
        request.height = kHeight;
        request.view = camera.view;
        request.params = default_param_values(scene);
        const Frame frame = renderer.render(request);
        EXPECT_GT(frame.hits, 0) << "camera " << camera.name;
        // The default view has sky above the horizon: not every ray may hit.
        if (&camera == &scene.cameras.front()) {
            EXPECT_LT(frame.hits, long{kWidth * kHeight});
        }
    }
}

// --- (c) Layout: the current header keeps every 1.0 field where 1.0 put it ----------------------

// A dlopen handle, closed on destruction.
struct LibraryCloser {
    void operator()(void* handle) const { dlclose(handle); }
};
using Library = std::unique_ptr<void, LibraryCloser>;

template <typename Fn>
Fn find_symbol(const Library& library, const char* name) {
    // POSIX guarantees a data pointer from dlsym converts to a function pointer.
    return reinterpret_cast<Fn>(dlsym(library.get(), name));
}

#define CURRENT_STRUCT_ROW(type)                                      \
    fgr_frozen_struct_row{#type, static_cast<uint32_t>(sizeof(type)), \
                          static_cast<uint32_t>(alignof(type))},
#define CURRENT_FIELD_ROW(type, field)                                                    \
    fgr_frozen_field_row{#type "::" #field, static_cast<uint32_t>(offsetof(type, field)), \
                         static_cast<uint32_t>(sizeof(type::field))},
#define CURRENT_CONSTANT_ROW(name) fgr_frozen_constant_row{#name, static_cast<uint64_t>(name)},

const std::vector<fgr_frozen_struct_row> kCurrentStructs = {
    FGR_FROZEN_V1_STRUCTS(CURRENT_STRUCT_ROW)};
const std::vector<fgr_frozen_field_row> kCurrentFields = {FGR_FROZEN_V1_FIELDS(CURRENT_FIELD_ROW)};
const std::vector<fgr_frozen_constant_row> kCurrentConstants = {
    FGR_FROZEN_V1_CONSTANTS(CURRENT_CONSTANT_ROW)};

const std::vector<fgr_frozen_struct_row> kCurrentV1_1Structs = {
    FGR_FROZEN_V1_1_STRUCTS(CURRENT_STRUCT_ROW)};
const std::vector<fgr_frozen_field_row> kCurrentV1_1Fields = {
    FGR_FROZEN_V1_1_FIELDS(CURRENT_FIELD_ROW)};
const std::vector<fgr_frozen_constant_row> kCurrentV1_1Constants = {
    FGR_FROZEN_V1_1_CONSTANTS(CURRENT_CONSTANT_ROW)};

const std::vector<fgr_frozen_struct_row> kCurrentV1_2Structs = {
    FGR_FROZEN_V1_2_STRUCTS(CURRENT_STRUCT_ROW)};
const std::vector<fgr_frozen_field_row> kCurrentV1_2Fields = {
    FGR_FROZEN_V1_2_FIELDS(CURRENT_FIELD_ROW)};
const std::vector<fgr_frozen_constant_row> kCurrentV1_2Constants = {
    FGR_FROZEN_V1_2_CONSTANTS(CURRENT_CONSTANT_ROW)};

const std::vector<fgr_frozen_struct_row> kCurrentV1_3Structs = {
    FGR_FROZEN_V1_3_STRUCTS(CURRENT_STRUCT_ROW)};
const std::vector<fgr_frozen_field_row> kCurrentV1_3Fields = {
    FGR_FROZEN_V1_3_FIELDS(CURRENT_FIELD_ROW)};
const std::vector<fgr_frozen_constant_row> kCurrentV1_3Constants = {
    FGR_FROZEN_V1_3_CONSTANTS(CURRENT_CONSTANT_ROW)};

const std::vector<fgr_frozen_struct_row> kCurrentV1_4Structs = {
    FGR_FROZEN_V1_4_STRUCTS(CURRENT_STRUCT_ROW)};
const std::vector<fgr_frozen_field_row> kCurrentV1_4Fields = {
    FGR_FROZEN_V1_4_FIELDS(CURRENT_FIELD_ROW)};
const std::vector<fgr_frozen_constant_row> kCurrentV1_4Constants = {
    FGR_FROZEN_V1_4_CONSTANTS(CURRENT_CONSTANT_ROW)};
const std::vector<fgr_frozen_struct_row> kCurrentV1_5Structs = {
    FGR_FROZEN_V1_5_STRUCTS(CURRENT_STRUCT_ROW)};
const std::vector<fgr_frozen_field_row> kCurrentV1_5Fields = {
    FGR_FROZEN_V1_5_FIELDS(CURRENT_FIELD_ROW)};
const std::vector<fgr_frozen_constant_row> kCurrentV1_5Constants = {
    FGR_FROZEN_V1_5_CONSTANTS(CURRENT_CONSTANT_ROW)};

// The frozen plugin's table against the current header's rows for the same lists: nothing moved,
// shrank, changed alignment or value. Then its description's header is what FGR_HEADER gave it:
// the frozen struct size and `version`.
void expect_layout_kept(const fs::path& plugin, const char* layout_symbol, uint32_t version,
                        const std::vector<fgr_frozen_struct_row>& structs,
                        const std::vector<fgr_frozen_field_row>& fields,
                        const std::vector<fgr_frozen_constant_row>& constants,
                        std::size_t struct_count, std::size_t field_count,
                        std::size_t constant_count) {
    const Library library(dlopen(plugin.c_str(), RTLD_NOW | RTLD_LOCAL));
    ASSERT_TRUE(library) << plugin << ": " << dlerror();
    const auto layout_fn = find_symbol<fgr_frozen_layout_fn>(library, layout_symbol);
    ASSERT_NE(layout_fn, nullptr) << "no " << layout_symbol << " in " << plugin;
    const fgr_frozen_layout* frozen = layout_fn();
    ASSERT_NE(frozen, nullptr);

    ASSERT_EQ(frozen->struct_count, struct_count) << "the layout table must list every struct";
    ASSERT_EQ(frozen->field_count, field_count) << "the layout table must list every field";
    ASSERT_EQ(frozen->constant_count, constant_count)
        << "the layout table must list every constant";
    ASSERT_EQ(structs.size(), struct_count);
    ASSERT_EQ(fields.size(), field_count);
    ASSERT_EQ(constants.size(), constant_count);

    for (std::size_t i = 0; i < struct_count; ++i) {
        const fgr_frozen_struct_row& then = frozen->structs[i];
        const fgr_frozen_struct_row& now = structs[i];
        ASSERT_STREQ(then.name, now.name);
        // Appending fields may grow a struct; it may never shrink it.
        EXPECT_GE(now.size, then.size) << then.name << " is smaller than in " << plugin;
        // A plugin's arrays have its stride; the host refuses a stride that is not a multiple of
        // the current alignment, so an appended field must not raise it.
        EXPECT_EQ(now.align, then.align) << then.name << " changed its alignment";
    }
    for (std::size_t i = 0; i < field_count; ++i) {
        const fgr_frozen_field_row& then = frozen->fields[i];
        const fgr_frozen_field_row& now = fields[i];
        ASSERT_STREQ(then.name, now.name);
        EXPECT_EQ(now.offset, then.offset) << then.name << " moved since " << plugin;
        EXPECT_EQ(now.size, then.size) << then.name << " changed size since " << plugin;
    }
    for (std::size_t i = 0; i < constant_count; ++i) {
        const fgr_frozen_constant_row& then = frozen->constants[i];
        const fgr_frozen_constant_row& now = constants[i];
        ASSERT_STREQ(then.name, now.name);
        EXPECT_EQ(now.value, then.value) << then.name << " changed value since " << plugin;
    }

    // The plugin filled its headers as plugins do (FGR_HEADER): the frozen size and version.
    const auto entry = find_symbol<fgr_scene_entry_fn>(library, FGR_SCENE_ENTRY_SYMBOL);
    ASSERT_NE(entry, nullptr);
    const fgr_scene_desc* desc = entry();
    ASSERT_NE(desc, nullptr);
    EXPECT_EQ(desc->header.struct_size, frozen->structs[struct_count - 1].size);
    EXPECT_EQ(desc->header.abi_version, version);
    EXPECT_EQ(std::string_view(frozen->structs[struct_count - 1].name), "fgr_scene_desc");
}

TEST(AbiFreeze, CurrentHeaderKeepsTheV1Layout) {
    expect_layout_kept(kFrozenPlugin, FGR_FROZEN_LAYOUT_SYMBOL, 0x00010000u, kCurrentStructs,
                       kCurrentFields, kCurrentConstants, kV1StructCount, kV1FieldCount,
                       kV1ConstantCount);
}

TEST(AbiFreeze, CurrentHeaderKeepsTheV1_1Layout) {
    expect_layout_kept(kFrozenV1_1Plugin, FGR_FROZEN_V1_1_LAYOUT_SYMBOL, 0x00010001u,
                       kCurrentV1_1Structs, kCurrentV1_1Fields, kCurrentV1_1Constants,
                       kV1_1StructCount, kV1_1FieldCount, kV1_1ConstantCount);
}

TEST(AbiFreeze, CurrentHeaderKeepsTheV1_2Layout) {
    expect_layout_kept(kFrozenV1_2Plugin, FGR_FROZEN_V1_2_LAYOUT_SYMBOL, 0x00010002u,
                       kCurrentV1_2Structs, kCurrentV1_2Fields, kCurrentV1_2Constants,
                       kV1_2StructCount, kV1_2FieldCount, kV1_2ConstantCount);
}

TEST(AbiFreeze, CurrentHeaderKeepsTheV1_3Layout) {
    expect_layout_kept(kFrozenV1_3Plugin, FGR_FROZEN_V1_3_LAYOUT_SYMBOL, 0x00010003u,
                       kCurrentV1_3Structs, kCurrentV1_3Fields, kCurrentV1_3Constants,
                       kV1_3StructCount, kV1_3FieldCount, kV1_3ConstantCount);
}

TEST(AbiFreeze, CurrentHeaderKeepsTheV1_4Layout) {
    expect_layout_kept(kFrozenV1_4Plugin, FGR_FROZEN_V1_4_LAYOUT_SYMBOL, 0x00010004u,
                       kCurrentV1_4Structs, kCurrentV1_4Fields, kCurrentV1_4Constants,
                       kV1_4StructCount, kV1_4FieldCount, kV1_4ConstantCount);
}

TEST(AbiFreeze, CurrentHeaderKeepsTheV1_5Layout) {
    expect_layout_kept(kFrozenV1_5Plugin, FGR_FROZEN_V1_5_LAYOUT_SYMBOL, 0x00010005u,
                       kCurrentV1_5Structs, kCurrentV1_5Fields, kCurrentV1_5Constants,
                       kV1_5StructCount, kV1_5FieldCount, kV1_5ConstantCount);
}

// The 1.1 plugin's source has no NUL: its source_length says where it ends, and the bytes after
// it ("NOT-SRC!") are not part of it.
TEST(AbiFreeze, FrozenV1_1PluginLoadsItsSourceByLengthAndRenders) {
    LoadResult loaded = load_scene_plugin(kFrozenV1_1Plugin);
    ASSERT_TRUE(loaded.scene) << kFrozenV1_1Plugin << ": " << loaded.error;
    const Scene& scene = *loaded.scene;
    EXPECT_EQ(scene.id, "frozen-v1-1");
    EXPECT_EQ(scene.source,
              "real scene_de(vec3 p, PARAMS) { return v3_length(p) - param_radius; }\n");
    EXPECT_EQ(scene.plugin_file, kFrozenV1_1Plugin);

    EXPECT_GT(default_view_hits(scene), 0);
}

// The 1.2 plugin asks for the path mode; its directional lights have discs of 5 and 0.27 degrees,
// which the host keeps in radians, and its point light's radius is ignored.
TEST(AbiFreeze, FrozenV1_2PluginLoadsItsModeAndLightDiscs) {
    LoadResult loaded = load_scene_plugin(kFrozenV1_2Plugin);
    ASSERT_TRUE(loaded.scene) << kFrozenV1_2Plugin << ": " << loaded.error;
    const Scene& scene = *loaded.scene;
    EXPECT_EQ(scene.id, "frozen-v1-2");
    EXPECT_EQ(scene.source,
              "real scene_de(vec3 p, PARAMS) { return v3_length(p) - param_radius; }\n");
    EXPECT_EQ(scene.default_mode, RenderMode::Path);
    ASSERT_EQ(scene.lights.size(), 3u);
    // 5 and 0.27 degrees in radians, to float's precision (a relative 6e-8).
    EXPECT_NEAR(scene.lights[0].angular_radius, 0.08726646259971647, 1e-8);
    EXPECT_NEAR(scene.lights[1].angular_radius, 0.004712388980384690, 1e-9);
    expect_vec3(scene.lights[1].vector, glm::normalize(glm::vec3(-1, 0.5f, 1)), "light 1 vector");
    EXPECT_FLOAT_EQ(scene.lights[1].intensity, 0.5f);
    EXPECT_EQ(scene.lights[2].type, LightType::Point);
    EXPECT_EQ(scene.lights[2].angular_radius, 0.0f) << "point lights ignore the radius";
    expect_vec3(scene.lights[2].vector, {0, 0, 3}, "light 2 position");
}

// The 1.3 plugin is an IFS scene: its three maps (two of them rotations, so rows and columns
// cannot be swapped unseen), their colours and its depths arrive intact, and it renders.
TEST(AbiFreeze, FrozenV1_3PluginLoadsItsMapsAndRenders) {
    LoadResult loaded = load_scene_plugin(kFrozenV1_3Plugin);
    ASSERT_TRUE(loaded.scene) << kFrozenV1_3Plugin << ": " << loaded.error;
    const Scene& scene = *loaded.scene;
    EXPECT_EQ(scene.id, "frozen-v1-3");
    ASSERT_TRUE(scene.ifs);
    EXPECT_EQ(scene.effects, uint64_t{FGR_EFFECT_SHADOWS | FGR_EFFECT_FOG});
    EXPECT_EQ(scene.ifs->default_depth, 4);
    EXPECT_EQ(scene.ifs->max_depth, 10);
    ASSERT_EQ(scene.ifs->maps.size(), 3u);
    // Each map applied to a point: w(x) = A x + t, with the rows the plugin wrote.
    const glm::dvec3 x(1.0, 2.0, 3.0);
    const glm::dvec3 expected[3] = {
        {0.5, 1.0, 1.5}, {1.0 - 1.0, 0.5, 1.5}, {0.4, 1.0 - 1.2f, 0.5 + 0.8f}};
    for (std::size_t i = 0; i < 3; ++i) {
        const IfsMap& map = scene.ifs->maps[i];
        const glm::dvec3 image = map.linear * x + map.offset;
        for (glm::dvec3::length_type c = 0; c < 3; ++c) {
            EXPECT_NEAR(image[c], expected[i][c], 1e-6) << "map " << i << " component " << c;
        }
    }
    expect_vec3(scene.ifs->maps[1].colour, {0.2f, 0.8f, 0.3f}, "map 1 colour");

    EXPECT_GT(default_view_hits(scene), 0);
}

// The 1.4 plugin gives ao_radius and fog_colour defaults of its own, offers the colour modes point
// and axes only, and has scale 0.5: the other distance-like built-ins' defaults follow it.
TEST(AbiFreeze, FrozenV1_4PluginLoadsItsDefaultsColourModesAndScale) {
    LoadResult loaded = load_scene_plugin(kFrozenV1_4Plugin);
    ASSERT_TRUE(loaded.scene) << kFrozenV1_4Plugin << ": " << loaded.error;
    const Scene& scene = *loaded.scene;
    EXPECT_EQ(scene.id, "frozen-v1-4");
    EXPECT_FLOAT_EQ(scene.scale, 0.5f);
    const ParamInfo* ao_radius = scene.find_param("ao_radius");
    const ParamInfo* fog_colour = scene.find_param("fog_colour");
    const ParamInfo* glow_radius = scene.find_param("glow_radius");
    const ParamInfo* fog_density = scene.find_param("fog_density");
    const ParamInfo* colour_mode = scene.find_param("colour_mode");
    ASSERT_TRUE(ao_radius && fog_colour && glow_radius && fog_density && colour_mode);
    EXPECT_FLOAT_EQ(ao_radius->default_value[0], 0.02f);
    EXPECT_TRUE(ao_radius->scene_default);
    expect_vec3(
        {fog_colour->default_value[0], fog_colour->default_value[1], fog_colour->default_value[2]},
        {0.8f, 0.7f, 0.6f}, "fog_colour");
    EXPECT_TRUE(fog_colour->scene_default);
    // Scale 0.5: glow_radius 0.05 * 0.5, fog_density 0.15 / 0.5.
    EXPECT_FLOAT_EQ(glow_radius->default_value[0], 0.025f);
    EXPECT_FLOAT_EQ(fog_density->default_value[0], 0.3f);
    EXPECT_FALSE(glow_radius->scene_default);
    EXPECT_EQ(colour_mode->offered, (std::vector<bool>{true, false, true, false}));
    EXPECT_EQ(offered_choices_text(*colour_mode), "point|axes");

    EXPECT_GT(default_view_hits(scene), 0);
}

// The 1.5 plugin names a uniform environment of three radiances for the path mode, which it asks
// for: the path mode's environment, when the user names none.
TEST(AbiFreeze, FrozenV1_5PluginLoadsItsEnvironment) {
    LoadResult loaded = load_scene_plugin(kFrozenV1_5Plugin);
    ASSERT_TRUE(loaded.scene) << kFrozenV1_5Plugin << ": " << loaded.error;
    const Scene& scene = *loaded.scene;
    EXPECT_EQ(scene.id, "frozen-v1-5");
    EXPECT_EQ(scene.default_mode, RenderMode::Path);
    EXPECT_EQ(scene.environment, "uniform:0.25,0.5,1");
    const EnvironmentChoice choice = with_scene_environment(EnvironmentChoice{}, scene);
    EXPECT_EQ(choice.kind, EnvironmentKind::Uniform);
    expect_vec3(choice.radiance, {0.25f, 0.5f, 1.0f}, "the environment's radiance");
}

// Plugins built before 1.5 name no environment: whatever follows their smaller descriptions is not
// read as one, and the path mode lights them with the sky.
TEST(AbiFreeze, OlderPluginsGetTheV1_5Default) {
    for (const fs::path& plugin : {kFrozenPlugin, kFrozenV1_1Plugin, kFrozenV1_2Plugin,
                                   kFrozenV1_3Plugin, kFrozenV1_4Plugin}) {
        LoadResult loaded = load_scene_plugin(plugin);
        ASSERT_TRUE(loaded.scene) << plugin << ": " << loaded.error;
        EXPECT_EQ(loaded.scene->environment, "") << plugin;
        EXPECT_EQ(with_scene_environment(EnvironmentChoice{}, *loaded.scene).kind,
                  EnvironmentKind::Sky)
            << plugin;
    }
}

// Plugins built before 1.4 keep fgr's defaults for every built-in, offer every colour mode and
// have scale 1; what follows their smaller descriptions is not read as 1.4 fields.
TEST(AbiFreeze, OlderPluginsGetTheV1_4Defaults) {
    Scene unit;
    add_builtin_params(unit);
    for (const fs::path& plugin :
         {kFrozenPlugin, kFrozenV1_1Plugin, kFrozenV1_2Plugin, kFrozenV1_3Plugin}) {
        LoadResult loaded = load_scene_plugin(plugin);
        ASSERT_TRUE(loaded.scene) << plugin << ": " << loaded.error;
        EXPECT_EQ(loaded.scene->scale, 1.0f) << plugin;
        for (const char* id : {"ao_radius", "glow_radius", "fog_density", "fog_colour",
                               "absorption", "aperture", "exposure"}) {
            const ParamInfo* param = loaded.scene->find_param(id);
            ASSERT_NE(param, nullptr) << plugin << " " << id;
            EXPECT_EQ(param->default_value, unit.find_param(id)->default_value)
                << plugin << " " << id;
            EXPECT_FALSE(param->scene_default) << plugin << " " << id;
        }
        for (const ParamInfo& param : loaded.scene->params) {
            EXPECT_TRUE(param.offered.empty()) << plugin << " " << param.id;
        }
    }
}

// Plugins built before 1.2 ask for no mode and have point-like lights. The 1.0 plugin's first light
// is followed by the second's header, which a host reading past 1.0's 40 bytes would take for a
// radius.
TEST(AbiFreeze, OlderPluginsGetTheV1_2Defaults) {
    for (const fs::path& plugin : {kFrozenPlugin, kFrozenV1_1Plugin}) {
        LoadResult loaded = load_scene_plugin(plugin);
        ASSERT_TRUE(loaded.scene) << plugin << ": " << loaded.error;
        EXPECT_EQ(loaded.scene->default_mode, RenderMode::Shaded) << plugin;
        ASSERT_FALSE(loaded.scene->lights.empty());
        for (const Light& light : loaded.scene->lights) {
            EXPECT_EQ(light.angular_radius, 0.0f) << plugin;
        }
    }
}

// Plugins built before 1.3 have no maps: whatever follows their smaller descriptions is not read
// as maps, and they stay distance-estimated scenes.
TEST(AbiFreeze, OlderPluginsAreDistanceEstimated) {
    for (const fs::path& plugin : {kFrozenPlugin, kFrozenV1_1Plugin, kFrozenV1_2Plugin}) {
        LoadResult loaded = load_scene_plugin(plugin);
        ASSERT_TRUE(loaded.scene) << plugin << ": " << loaded.error;
        EXPECT_FALSE(loaded.scene->ifs) << plugin;
        EXPECT_EQ(loaded.scene->find_param("ifs_depth"), nullptr) << plugin;
    }
}

// --- (d) A plugin for another major version is refused, by file name ----------------------------

constexpr std::string_view kMajor2Reason = "ABI major version 2, host supports 1";

TEST(AbiFreeze, Major2PluginIsRefused) {
    const LoadResult loaded = load_scene_plugin(kMajor2Plugin);
    EXPECT_FALSE(loaded.scene) << kMajor2Plugin << " was loaded";
    EXPECT_EQ(loaded.error, kMajor2Reason);

    const Discovery discovery = discover_scenes({kFrozenDir});
    ASSERT_EQ(discovery.scenes.size(), 1u);
    EXPECT_EQ(discovery.scenes[0].id, "frozen-v1");
    ASSERT_EQ(discovery.skipped.size(), 1u);
    EXPECT_EQ(discovery.skipped[0].file, kMajor2Plugin);
    EXPECT_EQ(discovery.skipped[0].reason, kMajor2Reason);
}

TEST(AbiFreeze, Major2RefusalNamesTheFileInFgrOutput) {
    ASSERT_TRUE(fs::exists(FGR_TEST_FGR_EXE)) << FGR_TEST_FGR_EXE << " does not exist";
    test::ChildOptions options;
    options.environment["FGR_PLUGIN_PATH"] = kFrozenDir.string();
    options.timeout = std::chrono::seconds(120);
    const test::RunResult result = test::run_child(FGR_TEST_FGR_EXE, {"list"}, options);
    ASSERT_TRUE(result.exited && result.exit_code == 0) << result;
    EXPECT_NE(result.out.find("frozen-v1"), std::string::npos) << result;
    const std::string message =
        "skipping plugin " + kMajor2Plugin.string() + ": " + std::string(kMajor2Reason);
    EXPECT_NE(result.err.find(message), std::string::npos) << "expected: " << message << "\n"
                                                           << result;
}

// --- (e) The frozen header never changes ---------------------------------------------------------

uint64_t fnv1a64(std::string_view bytes) {
    uint64_t hash = 0xcbf29ce484222325u;
    for (const char byte : bytes) {
        hash ^= static_cast<unsigned char>(byte);
        hash *= 0x100000001b3u;
    }
    return hash;
}

std::string hex(uint64_t value) {
    std::ostringstream out;
    out << "0x" << std::hex << value;
    return out.str();
}

TEST(AbiFreeze, FrozenV1_5HeaderNeverChanges) {
    ASSERT_TRUE(fs::is_regular_file(kFrozenV1_5Header)) << kFrozenV1_5Header << " is missing";
    const uint64_t hash = fnv1a64(test::read_file(kFrozenV1_5Header));
    EXPECT_EQ(hash, kFrozenV1_5HeaderHash)
        << kFrozenV1_5Header << " has changed (FNV-1a " << hex(hash) << ", frozen "
        << hex(kFrozenV1_5HeaderHash) << "). It is the ABI 1.5 header exactly as released and "
        << "must never change: restore it from git.";
}

TEST(AbiFreeze, FrozenV1_4HeaderNeverChanges) {
    ASSERT_TRUE(fs::is_regular_file(kFrozenV1_4Header)) << kFrozenV1_4Header << " is missing";
    const uint64_t hash = fnv1a64(test::read_file(kFrozenV1_4Header));
    EXPECT_EQ(hash, kFrozenV1_4HeaderHash)
        << kFrozenV1_4Header << " has changed (FNV-1a " << hex(hash) << ", frozen "
        << hex(kFrozenV1_4HeaderHash) << "). It is the ABI 1.4 header exactly as released and "
        << "must never change: restore it from git.";
}

TEST(AbiFreeze, FrozenV1_3HeaderNeverChanges) {
    ASSERT_TRUE(fs::is_regular_file(kFrozenV1_3Header)) << kFrozenV1_3Header << " is missing";
    const uint64_t hash = fnv1a64(test::read_file(kFrozenV1_3Header));
    EXPECT_EQ(hash, kFrozenV1_3HeaderHash)
        << kFrozenV1_3Header << " has changed (FNV-1a " << hex(hash) << ", frozen "
        << hex(kFrozenV1_3HeaderHash) << "). It is the ABI 1.3 header exactly as released and "
        << "must never change: restore it from git.";
}

TEST(AbiFreeze, FrozenV1_2HeaderNeverChanges) {
    ASSERT_TRUE(fs::is_regular_file(kFrozenV1_2Header)) << kFrozenV1_2Header << " is missing";
    const uint64_t hash = fnv1a64(test::read_file(kFrozenV1_2Header));
    EXPECT_EQ(hash, kFrozenV1_2HeaderHash)
        << kFrozenV1_2Header << " has changed (FNV-1a " << hex(hash) << ", frozen "
        << hex(kFrozenV1_2HeaderHash) << "). It is the ABI 1.2 header exactly as released and "
        << "must never change: restore it from git.";
}

TEST(AbiFreeze, FrozenV1_1HeaderNeverChanges) {
    ASSERT_TRUE(fs::is_regular_file(kFrozenV1_1Header)) << kFrozenV1_1Header << " is missing";
    const uint64_t hash = fnv1a64(test::read_file(kFrozenV1_1Header));
    EXPECT_EQ(hash, kFrozenV1_1HeaderHash)
        << kFrozenV1_1Header << " has changed (FNV-1a " << hex(hash) << ", frozen "
        << hex(kFrozenV1_1HeaderHash) << "). It is the ABI 1.1 header exactly as released and "
        << "must never change: restore it from git.";
}

TEST(AbiFreeze, FrozenHeaderNeverChanges) {
    ASSERT_TRUE(fs::is_regular_file(kFrozenHeader)) << kFrozenHeader << " is missing";
    const std::string content = test::read_file(kFrozenHeader);
    ASSERT_FALSE(content.empty()) << kFrozenHeader << " could not be read";
    const uint64_t hash = fnv1a64(content);
    EXPECT_EQ(hash, kFrozenHeaderHash)
        << kFrozenHeader << " has changed (FNV-1a " << hex(hash) << ", frozen "
        << hex(kFrozenHeaderHash) << "). It is the ABI 1.0 header exactly as released and must "
        << "never change: restore it from git. Change plugin_api/include/fgr/plugin.h instead, "
        << "following plugin_api/ABI.md.";
}

}  // namespace
}  // namespace fgr
