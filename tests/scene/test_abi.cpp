// SPDX-License-Identifier: Apache-2.0
// The plugin ABI: struct layouts pinned, version packing, and copy_scene_description's validation
// of in-memory descriptions, valid and malformed.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "camera/camera.hpp"
#include "fgr/plugin.h"
#include "fgr/scene_helpers.h"
#include "scene/description_validation.hpp"
#include "scene/render_mode.hpp"
#include "test_math.hpp"

namespace fgr {
namespace {

// --- Layout --------------------------------------------------------------------------------------
// Plugins compiled against ABI 1 depend on these exact sizes and offsets (x86_64 SysV). Both a
// compile-time check and a test expectation, so a layout change names the field that moved.

#define PIN_SIZE(type, expected)                                      \
    static_assert(sizeof(type) == (expected), #type " changed size"); \
    EXPECT_EQ(sizeof(type), std::size_t{expected}) << #type

#define PIN_OFFSET(type, field, expected)                                           \
    static_assert(offsetof(type, field) == (expected), #type "::" #field " moved"); \
    EXPECT_EQ(offsetof(type, field), std::size_t{expected}) << #type "::" #field

TEST(AbiLayout, StructHeader) {
    PIN_SIZE(fgr_struct_header, 8);
    PIN_OFFSET(fgr_struct_header, struct_size, 0);
    PIN_OFFSET(fgr_struct_header, abi_version, 4);
}

TEST(AbiLayout, ParamDesc) {
    PIN_SIZE(fgr_param_desc, 72);
    PIN_OFFSET(fgr_param_desc, header, 0);
    PIN_OFFSET(fgr_param_desc, id, 8);
    PIN_OFFSET(fgr_param_desc, label, 16);
    PIN_OFFSET(fgr_param_desc, group, 24);
    PIN_OFFSET(fgr_param_desc, type, 32);
    PIN_OFFSET(fgr_param_desc, min_value, 36);
    PIN_OFFSET(fgr_param_desc, max_value, 40);
    PIN_OFFSET(fgr_param_desc, default_value, 44);
    PIN_OFFSET(fgr_param_desc, choices, 56);
    PIN_OFFSET(fgr_param_desc, description, 64);
}

TEST(AbiLayout, Camera) {
    PIN_SIZE(fgr_camera, 56);
    PIN_OFFSET(fgr_camera, name, 8);
    PIN_OFFSET(fgr_camera, position, 16);
    PIN_OFFSET(fgr_camera, target, 28);
    PIN_OFFSET(fgr_camera, up, 40);
    PIN_OFFSET(fgr_camera, fov_degrees, 52);
}

TEST(AbiLayout, Keyframe) {
    PIN_SIZE(fgr_keyframe, 52);
    PIN_OFFSET(fgr_keyframe, time, 8);
    PIN_OFFSET(fgr_keyframe, position, 12);
    PIN_OFFSET(fgr_keyframe, target, 24);
    PIN_OFFSET(fgr_keyframe, up, 36);
    PIN_OFFSET(fgr_keyframe, fov_degrees, 48);
}

TEST(AbiLayout, CameraPath) {
    PIN_SIZE(fgr_camera_path, 32);
    PIN_OFFSET(fgr_camera_path, name, 8);
    PIN_OFFSET(fgr_camera_path, keyframes, 16);
    PIN_OFFSET(fgr_camera_path, keyframe_count, 24);
}

TEST(AbiLayout, Light) {
    PIN_SIZE(fgr_light, 44);
    PIN_OFFSET(fgr_light, type, 8);
    PIN_OFFSET(fgr_light, vector, 12);
    PIN_OFFSET(fgr_light, colour, 24);
    PIN_OFFSET(fgr_light, intensity, 36);
    // ABI 1.2: after the 1.0 struct's 40 bytes; a float keeps the struct 4-aligned.
    PIN_OFFSET(fgr_light, angular_radius_degrees, 40);
    static_assert(alignof(fgr_light) == 4, "an appended field must not raise the alignment");
}

TEST(AbiLayout, MarchSettings) {
    PIN_SIZE(fgr_march_settings, 28);
    PIN_OFFSET(fgr_march_settings, max_steps, 8);
    PIN_OFFSET(fgr_march_settings, max_distance, 12);
    PIN_OFFSET(fgr_march_settings, hit_threshold, 16);
    PIN_OFFSET(fgr_march_settings, de_iterations, 20);
    PIN_OFFSET(fgr_march_settings, step_factor, 24);
}

TEST(AbiLayout, SceneDesc) {
    PIN_SIZE(fgr_scene_desc, 224);
    PIN_OFFSET(fgr_scene_desc, id, 8);
    PIN_OFFSET(fgr_scene_desc, name, 16);
    PIN_OFFSET(fgr_scene_desc, description, 24);
    PIN_OFFSET(fgr_scene_desc, source, 32);
    PIN_OFFSET(fgr_scene_desc, source_name, 40);
    PIN_OFFSET(fgr_scene_desc, params, 48);
    PIN_OFFSET(fgr_scene_desc, param_count, 56);
    PIN_OFFSET(fgr_scene_desc, cameras, 64);
    PIN_OFFSET(fgr_scene_desc, camera_count, 72);
    PIN_OFFSET(fgr_scene_desc, camera_paths, 80);
    PIN_OFFSET(fgr_scene_desc, camera_path_count, 88);
    PIN_OFFSET(fgr_scene_desc, lights, 96);
    PIN_OFFSET(fgr_scene_desc, light_count, 104);
    PIN_OFFSET(fgr_scene_desc, effects, 112);
    PIN_OFFSET(fgr_scene_desc, march, 120);
    // ABI 1.1: after the 1.0 struct's 152 bytes (its end padded to the pointer alignment).
    PIN_OFFSET(fgr_scene_desc, source_length, 152);
    // ABI 1.2.
    PIN_OFFSET(fgr_scene_desc, default_mode, 160);
    // ABI 1.3: the IFS maps and the depth slider's range (the struct's end padded to 8).
    PIN_OFFSET(fgr_scene_desc, ifs_maps, 168);
    PIN_OFFSET(fgr_scene_desc, ifs_map_count, 176);
    PIN_OFFSET(fgr_scene_desc, ifs_default_depth, 180);
    PIN_OFFSET(fgr_scene_desc, ifs_max_depth, 184);
    // ABI 1.4: the scene's built-in defaults, colour modes and scale (the end padded to 8).
    PIN_OFFSET(fgr_scene_desc, builtin_defaults, 192);
    PIN_OFFSET(fgr_scene_desc, builtin_default_count, 200);
    PIN_OFFSET(fgr_scene_desc, colour_modes, 204);
    PIN_OFFSET(fgr_scene_desc, scale, 208);
    // ABI 1.5: the scene's own environment, after the float padded to the pointer alignment.
    PIN_OFFSET(fgr_scene_desc, environment, 216);
    static_assert(alignof(fgr_scene_desc) == 8, "an appended field must not raise the alignment");
}

// ABI 1.3.
TEST(AbiLayout, IfsMap) {
    PIN_SIZE(fgr_ifs_map, 68);
    PIN_OFFSET(fgr_ifs_map, header, 0);
    PIN_OFFSET(fgr_ifs_map, matrix, 8);
    PIN_OFFSET(fgr_ifs_map, colour, 56);
    static_assert(alignof(fgr_ifs_map) == 4);
}

// ABI 1.4.
TEST(AbiLayout, BuiltinDefault) {
    PIN_SIZE(fgr_builtin_default, 32);
    PIN_OFFSET(fgr_builtin_default, header, 0);
    PIN_OFFSET(fgr_builtin_default, id, 8);
    PIN_OFFSET(fgr_builtin_default, value, 16);
    static_assert(alignof(fgr_builtin_default) == 8);
}

TEST(AbiVersion, PackingMacros) {
    static_assert(FGR_ABI_VERSION == ((FGR_ABI_VERSION_MAJOR << 16) | FGR_ABI_VERSION_MINOR));
    EXPECT_EQ(FGR_ABI_VERSION_MAJOR, 1u);
    EXPECT_EQ(FGR_ABI_MAJOR(FGR_ABI_VERSION), FGR_ABI_VERSION_MAJOR);
    EXPECT_EQ(FGR_ABI_MINOR(FGR_ABI_VERSION), FGR_ABI_VERSION_MINOR);
    EXPECT_EQ(FGR_ABI_MAJOR(0x00030007u), 3u);
    EXPECT_EQ(FGR_ABI_MINOR(0x00030007u), 7u);
    EXPECT_EQ(FGR_ABI_MINOR(0xffffffffu), 0xffffu);
    const fgr_struct_header header = FGR_HEADER(fgr_light);
    EXPECT_EQ(header.struct_size, sizeof(fgr_light));
    EXPECT_EQ(header.abi_version, FGR_ABI_VERSION);
}

// --- A valid description, built in memory --------------------------------------------------------

// Owns every array the description points into; tests break one field and expect a refusal.
// Not copyable: `desc` points into the object's own members.
struct SceneBuilder {
    SceneBuilder() {
        // clang-format off
        params = {
            {FGR_HEADER(fgr_param_desc), "power", "Power", "Fractal", FGR_PARAM_FLOAT, 1.0f, 16.0f,
             {8.0f, 0.0f, 0.0f}, nullptr, "exponent of the iteration"},
            {FGR_HEADER(fgr_param_desc), "colouring", nullptr, nullptr, FGR_PARAM_INT, 0.0f, 2.0f,
             {1.0f, 0.0f, 0.0f}, "orbit|normal|flat", nullptr},
            {FGR_HEADER(fgr_param_desc), "tint", "Tint", "Look", FGR_PARAM_COLOUR, 0.0f, 1.0f,
             {0.5f, 0.6f, 0.7f}, nullptr, nullptr},
            {FGR_HEADER(fgr_param_desc), "julia_mode", "Julia", "Fractal", FGR_PARAM_BOOL, 0.0f,
             1.0f, {0.0f, 0.0f, 0.0f}, nullptr, nullptr},
        };
        cameras = {
            {FGR_HEADER(fgr_camera), "front", {0, -3, 0}, {0, 0, 0}, {0, 0, 1}, 60.0f},
            {FGR_HEADER(fgr_camera), "top-down", {0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 45.0f},
        };
        keyframes = {
            {FGR_HEADER(fgr_keyframe), 0.0f, {0, -3, 0}, {0, 0, 0}, {0, 0, 1}, 60.0f},
            {FGR_HEADER(fgr_keyframe), 2.0f, {3, 0, 0}, {0, 0, 0}, {0, 0, 1}, 60.0f},
            {FGR_HEADER(fgr_keyframe), 5.0f, {0, 3, 0}, {0, 0, 0}, {0, 0, 1}, 50.0f},
        };
        paths = {{FGR_HEADER(fgr_camera_path), "orbit", keyframes.data(), 3}};
        lights = {
            {FGR_HEADER(fgr_light), FGR_LIGHT_DIRECTIONAL, {0, 0, 2}, {1, 1, 1}, 1.0f, 0.0f},
            {FGR_HEADER(fgr_light), FGR_LIGHT_POINT, {1, 2, 3}, {1, 0.5f, 0}, 4.0f, 0.0f},
        };
        desc = {FGR_HEADER(fgr_scene_desc),
                "test-scene",
                "Test scene",
                "a scene built in memory",
                "real scene_de(vec3 p, PARAMS) { return length(p) - 1; }\n",
                "test.cl",
                params.data(),
                static_cast<uint32_t>(params.size()),
                cameras.data(),
                static_cast<uint32_t>(cameras.size()),
                paths.data(),
                static_cast<uint32_t>(paths.size()),
                lights.data(),
                static_cast<uint32_t>(lights.size()),
                FGR_EFFECT_ALL_V1,
                {FGR_HEADER(fgr_march_settings), 256, 10.0f, 1.5f, 12, 0.9f},
                0,
                nullptr,
                nullptr,
                0,
                0,
                0,
                nullptr,
                0,
                0,
                0.0f,
                nullptr};
        // clang-format on
    }
    SceneBuilder(const SceneBuilder&) = delete;
    SceneBuilder& operator=(const SceneBuilder&) = delete;

    std::vector<fgr_param_desc> params;
    std::vector<fgr_camera> cameras;
    std::vector<fgr_keyframe> keyframes;
    std::vector<fgr_camera_path> paths;
    std::vector<fgr_light> lights;
    fgr_scene_desc desc{};
};

class CopyScene : public ::testing::Test {
protected:
    // Expects a refusal whose reason contains `reason_part`.
    void expect_refused(const std::string& reason_part) {
        expect_refused(&built.desc, reason_part);
    }
    static void expect_refused(const fgr_scene_desc* desc, const std::string& reason_part) {
        const LoadResult result = copy_scene_description(desc);
        EXPECT_FALSE(result.scene.has_value());
        EXPECT_NE(result.error.find(reason_part), std::string::npos)
            << "reason was: " << result.error << "\nexpected it to contain: " << reason_part;
        EXPECT_EQ(result.error.find('\n'), std::string::npos) << "reason must be one line";
    }
    Scene expect_accepted() {
        LoadResult result = copy_scene_description(&built.desc);
        EXPECT_TRUE(result.scene.has_value()) << result.error;
        return result.scene.value_or(Scene{});
    }

    SceneBuilder built;
};

using test::kNaN;

TEST_F(CopyScene, CopiesEverything) {
    const Scene scene = expect_accepted();
    EXPECT_EQ(scene.id, "test-scene");
    EXPECT_EQ(scene.name, "Test scene");
    EXPECT_EQ(scene.description, "a scene built in memory");
    EXPECT_EQ(scene.source, built.desc.source);
    EXPECT_EQ(scene.source_name, "test.cl");
    EXPECT_TRUE(scene.plugin_file.empty());
    EXPECT_EQ(scene.effects, uint64_t{FGR_EFFECT_ALL_V1});
    EXPECT_EQ(scene.march.max_steps, 256u);
    EXPECT_FLOAT_EQ(scene.march.max_distance, 10.0f);
    EXPECT_FLOAT_EQ(scene.march.hit_threshold, 1.5f);
    EXPECT_EQ(scene.march.de_iterations, 12u);
    EXPECT_FLOAT_EQ(scene.march.step_factor, 0.9f);
}

TEST_F(CopyScene, CopiesParams) {
    const Scene scene = expect_accepted();
    ASSERT_EQ(scene.params.size(), 4u + builtin_param_count());
    const ParamInfo& power = scene.params[0];
    EXPECT_EQ(power.id, "power");
    EXPECT_EQ(power.label, "Power");
    EXPECT_EQ(power.group, "Fractal");
    EXPECT_EQ(power.description, "exponent of the iteration");
    EXPECT_EQ(power.type, ParamType::Float);
    EXPECT_FLOAT_EQ(power.min_value, 1.0f);
    EXPECT_FLOAT_EQ(power.max_value, 16.0f);
    EXPECT_FLOAT_EQ(power.default_value[0], 8.0f);
    EXPECT_FALSE(power.builtin);

    const ParamInfo& colouring = scene.params[1];
    EXPECT_EQ(colouring.label, "colouring") << "NULL label means the id";
    EXPECT_EQ(colouring.group, "Scene") << "NULL group means Scene";
    EXPECT_EQ(colouring.description, "");
    EXPECT_EQ(colouring.choices, (std::vector<std::string>{"orbit", "normal", "flat"}));

    const ParamInfo& tint = scene.params[2];
    EXPECT_EQ(tint.type, ParamType::Colour);
    EXPECT_EQ(tint.default_value, (std::array<float, 3>{0.5f, 0.6f, 0.7f}));
    EXPECT_EQ(scene.params[3].type, ParamType::Bool);
}

TEST_F(CopyScene, AppendsBuiltinParamsFromMarchSettings) {
    const Scene scene = expect_accepted();
    const std::vector<std::pair<std::string, float>> expected = {{"max_steps", 256.0f},
                                                                 {"max_distance", 10.0f},
                                                                 {"hit_threshold", 1.5f},
                                                                 {"iterations", 12.0f}};
    for (const auto& [id, default_value] : expected) {
        const ParamInfo* param = scene.find_param(id);
        ASSERT_NE(param, nullptr) << id;
        EXPECT_TRUE(param->builtin) << id;
        EXPECT_EQ(param->group, "Quality") << id;
        EXPECT_FLOAT_EQ(param->default_value[0], default_value) << id;
    }
    EXPECT_EQ(scene.params[4].id, "max_steps") << "built-ins come after the scene's own";
    EXPECT_EQ(scene.find_param("max_steps")->type, ParamType::Int);
    EXPECT_EQ(scene.find_param("hit_threshold")->description,
              "hit when DE < threshold * pixel footprint");
    EXPECT_EQ(scene.find_param("iterations")->description, "distance estimator iterations");
    EXPECT_EQ(scene.find_param("nonexistent"), nullptr);
}

TEST_F(CopyScene, CopiesCamerasAndPaths) {
    const Scene scene = expect_accepted();
    ASSERT_EQ(scene.cameras.size(), 2u);
    EXPECT_EQ(scene.cameras[0].name, "front");
    EXPECT_EQ(scene.cameras[0].view.position, glm::dvec3(0, -3, 0));
    EXPECT_EQ(scene.cameras[0].view.up, glm::vec3(0, 0, 1));
    EXPECT_FLOAT_EQ(scene.cameras[1].view.fov_degrees, 45.0f);
    ASSERT_NE(scene.find_camera("top-down"), nullptr);
    EXPECT_EQ(scene.find_camera("top-down")->view.position, glm::dvec3(0, 0, 3));
    EXPECT_EQ(scene.find_camera("side"), nullptr);

    const CameraPath* orbit = scene.find_camera_path("orbit");
    ASSERT_NE(orbit, nullptr);
    ASSERT_EQ(orbit->keyframes.size(), 3u);
    EXPECT_FLOAT_EQ(orbit->keyframes[2].time, 5.0f);
    EXPECT_EQ(orbit->keyframes[1].view.position, glm::dvec3(3, 0, 0));
    EXPECT_FLOAT_EQ(orbit->duration(), 5.0f);
    EXPECT_EQ(scene.find_camera_path("spiral"), nullptr);
}

TEST_F(CopyScene, CopiesLightsNormalisingDirections) {
    const Scene scene = expect_accepted();
    ASSERT_EQ(scene.lights.size(), 2u);
    EXPECT_EQ(scene.lights[0].type, LightType::Directional);
    EXPECT_EQ(scene.lights[0].vector, glm::vec3(0, 0, 1));
    EXPECT_EQ(scene.lights[1].type, LightType::Point);
    EXPECT_EQ(scene.lights[1].vector, glm::vec3(1, 2, 3)) << "a position is not normalised";
    EXPECT_EQ(scene.lights[1].colour, glm::vec3(1, 0.5f, 0));
    EXPECT_FLOAT_EQ(scene.lights[1].intensity, 4.0f);
}

TEST_F(CopyScene, DefaultsSourceNameToId) {
    built.desc.source_name = nullptr;
    EXPECT_EQ(expect_accepted().source_name, "test-scene.cl");
}

TEST_F(CopyScene, AcceptsNoParamsAndNoPaths) {
    built.desc.params = nullptr;
    built.desc.param_count = 0;
    built.desc.camera_paths = nullptr;
    built.desc.camera_path_count = 0;
    const Scene scene = expect_accepted();
    EXPECT_EQ(scene.params.size(), builtin_param_count());
    EXPECT_TRUE(scene.camera_paths.empty());
}

// --- Versions and struct sizes -------------------------------------------------------------------

TEST_F(CopyScene, RefusesNullDescription) { expect_refused(nullptr, "NULL"); }

TEST_F(CopyScene, RefusesTooSmallStruct) {
    built.desc.header.struct_size = offsetof(fgr_scene_desc, march);
    expect_refused("description struct too small (120 bytes)");
}

// --- The source's length (ABI 1.1) ---------------------------------------------------------------

TEST_F(CopyScene, SourceIsReadToItsLengthWithoutANul) {
    const std::string text = "real scene_de(vec3 p, PARAMS) { return v3_length(p) - 1.0f; }";
    // Exactly the source's bytes, no NUL after them (the vector's own end is all there is).
    const std::vector<char> unterminated(text.begin(), text.end());
    built.desc.source = unterminated.data();
    built.desc.source_length = unterminated.size();
    EXPECT_EQ(expect_accepted().source, text);
    // A NUL within the length ends the source there, so sizeof an array is a fine length.
    built.desc.source = "real scene_de(vec3 p, PARAMS) { return p.x; }\0junk";
    built.desc.source_length = sizeof("real scene_de(vec3 p, PARAMS) { return p.x; }\0junk");
    EXPECT_EQ(expect_accepted().source, "real scene_de(vec3 p, PARAMS) { return p.x; }");
    // A shorter length cuts the source.
    built.desc.source_length = 4;
    EXPECT_EQ(expect_accepted().source, "real");
}

TEST_F(CopyScene, SourceLengthIsReadOnlyWhenTheStructCoversIt) {
    const std::string text = "real scene_de(vec3 p, PARAMS) { return p.x; }";
    built.desc.source = text.c_str();
    built.desc.source_length = 4;
    built.desc.header.struct_size = offsetof(fgr_scene_desc, source_length);  // a 1.0 plugin
    EXPECT_EQ(expect_accepted().source, text) << "source_length read beyond struct_size";
    built.desc.header.struct_size = sizeof(fgr_scene_desc);
    built.desc.source_length = 0;  // 0: NUL-terminated, as in 1.0
    EXPECT_EQ(expect_accepted().source, text);
}

TEST_F(CopyScene, RefusesSourceLengthOverTheLimitUnread) {
    const char unterminated[4] = {'r', 'e', 'a', 'l'};
    built.desc.source = unterminated;
    built.desc.source_length = (4u << 20) + 2;
    expect_refused("source longer than 4194304 bytes (source_length 4194306)");
    built.desc.source = nullptr;
    built.desc.source_length = 10;
    expect_refused("source is NULL");
    built.desc.source = "";
    built.desc.source_length = 1;
    expect_refused("source is empty");
}

// --- The default render mode and light discs (ABI 1.2) -------------------------------------------

TEST_F(CopyScene, DefaultModeIsShadedUnlessTheSceneAsks) {
    EXPECT_EQ(expect_accepted().default_mode, RenderMode::Shaded) << "NULL means shaded";
    built.desc.default_mode = "";
    EXPECT_EQ(expect_accepted().default_mode, RenderMode::Shaded) << "\"\" means shaded";
    built.desc.default_mode = "path";
    EXPECT_EQ(expect_accepted().default_mode, RenderMode::Path);
    built.desc.default_mode = "shaded";
    EXPECT_EQ(expect_accepted().default_mode, RenderMode::Shaded);
}

// Every mode the host has can be asked for by its name (and so the refusal's list is complete).
TEST_F(CopyScene, DefaultModeAcceptsEveryRenderModeName) {
    ASSERT_FALSE(render_modes().empty());
    for (const RenderModeInfo& info : render_modes()) {
        const std::string name(info.name);
        built.desc.default_mode = name.c_str();
        EXPECT_EQ(expect_accepted().default_mode, info.mode) << name;
    }
}

TEST_F(CopyScene, RefusesUnknownDefaultMode) {
    const std::string choices = "(choose " + render_mode_choices() + ")";
    EXPECT_EQ(choices, "(choose shaded|path|brute)");
    built.desc.default_mode = "pathz";
    expect_refused("default_mode 'pathz' is not a render mode " + choices);
    built.desc.default_mode = "Path";
    expect_refused("default_mode 'Path' is not a render mode " + choices);
    built.desc.default_mode = " path";
    expect_refused("default_mode ' path' is not a render mode");
    built.desc.default_mode = "path\n\x1b[31m";
    expect_refused("default_mode 'path\\x0a\\x1b[31m' is not a render mode");
    const std::string too_long(64, 'p');
    built.desc.default_mode = too_long.c_str();
    expect_refused("default_mode longer than 63 bytes");
}

// A plugin built against 1.0 or 1.1 has no default_mode: whatever follows its struct is not read.
TEST_F(CopyScene, DefaultModeIsReadOnlyWhenTheStructCoversIt) {
    built.desc.default_mode = "path";
    built.desc.header.struct_size = offsetof(fgr_scene_desc, default_mode);  // a 1.1 plugin
    EXPECT_EQ(expect_accepted().default_mode, RenderMode::Shaded) << "read beyond struct_size";
    built.desc.default_mode = "pathz";
    EXPECT_EQ(expect_accepted().default_mode, RenderMode::Shaded) << "checked beyond struct_size";
    built.desc.header.struct_size = offsetof(fgr_scene_desc, source_length);  // a 1.0 plugin
    EXPECT_EQ(expect_accepted().default_mode, RenderMode::Shaded);
}

TEST_F(CopyScene, CopiesAngularRadiusInRadians) {
    const Scene delta = expect_accepted();
    ASSERT_EQ(delta.lights.size(), 2u);
    EXPECT_EQ(delta.lights[0].angular_radius, 0.0f) << "0: a delta light";
    constexpr double kDegree = 3.14159265358979323846 / 180.0;
    for (const float degrees : {5.0f, 0.27f, 45.0f, 1e-30f}) {
        built.lights[0].angular_radius_degrees = degrees;
        const Scene scene = expect_accepted();
        ASSERT_EQ(scene.lights.size(), 2u);
        // Within one float ulp of the exact angle.
        const double expected = double{degrees} * kDegree;
        EXPECT_NEAR(scene.lights[0].angular_radius, expected, expected * 1.2e-7) << degrees;
    }
}

TEST_F(CopyScene, PointLightsIgnoreTheAngularRadius) {
    built.lights[1].angular_radius_degrees = 10.0f;
    const Scene scene = expect_accepted();
    ASSERT_EQ(scene.lights.size(), 2u);
    EXPECT_EQ(scene.lights[1].type, LightType::Point);
    EXPECT_EQ(scene.lights[1].angular_radius, 0.0f);
}

TEST_F(CopyScene, RefusesAngularRadiusOutsideZeroTo45Degrees) {
    built.lights[0].angular_radius_degrees = -1.0f;
    expect_refused("light 0: angular_radius_degrees -1 outside [0, 45]");
    built.lights[0].angular_radius_degrees = 46.0f;
    expect_refused("light 0: angular_radius_degrees 46 outside [0, 45]");
    built.lights[0].angular_radius_degrees = 45.001f;
    expect_refused("light 0: angular_radius_degrees 45.001 outside [0, 45]");
    built.lights[0].angular_radius_degrees = kNaN;
    expect_refused("light 0: angular_radius_degrees nan outside [0, 45]");
    built.lights[0].angular_radius_degrees = std::numeric_limits<float>::infinity();
    expect_refused("light 0: angular_radius_degrees inf outside [0, 45]");
    built.lights[0].angular_radius_degrees = -std::numeric_limits<float>::infinity();
    expect_refused("light 0: angular_radius_degrees -inf outside [0, 45]");
    built.lights[0].angular_radius_degrees = 0.0f;
    // A point light ignores the value, but it must still be one a directional light may have.
    built.lights[1].angular_radius_degrees = kNaN;
    expect_refused("light 1: angular_radius_degrees nan outside [0, 45]");
}

// The 1.1 light as a plugin built against 1.1 lays it out: 40 bytes, no angular radius.
struct LightV1_1 {
    fgr_struct_header header;
    uint32_t type;
    float vector[3];
    float colour[3];
    float intensity;
};
static_assert(sizeof(LightV1_1) == 40 && alignof(LightV1_1) == alignof(fgr_light));

// A 1.1 plugin's lights have no radius: the host walks them with the 40-byte stride and reads
// nothing past each one (here the next light's header, and after the last one a float that would
// be a valid radius).
TEST_F(CopyScene, AngularRadiusIsReadOnlyWhenTheLightCoversIt) {
    struct {
        LightV1_1 lights[2];
        float after;
    } v1_1 = {{{{40, (1u << 16) | 1u}, FGR_LIGHT_DIRECTIONAL, {0, 0, 1}, {1, 1, 1}, 1.0f},
               {{40, (1u << 16) | 1u}, FGR_LIGHT_DIRECTIONAL, {0, 1, 0}, {1, 1, 1}, 2.0f}},
              5.0f};
    static_assert(sizeof(v1_1) == 84);
    built.desc.lights = reinterpret_cast<const fgr_light*>(&v1_1.lights[0]);
    const Scene scene = expect_accepted();
    ASSERT_EQ(scene.lights.size(), 2u);
    EXPECT_EQ(scene.lights[1].vector, glm::vec3(0, 1, 0)) << "walked with the 1.1 stride";
    EXPECT_FLOAT_EQ(scene.lights[1].intensity, 2.0f);
    EXPECT_EQ(scene.lights[0].angular_radius, 0.0f) << "read the next light's header";
    EXPECT_EQ(scene.lights[1].angular_radius, 0.0f) << "read past the last light";
    // Nor is it checked: a 1.1 light followed by bytes that would be refused still loads.
    v1_1.after = kNaN;
    const Scene again = expect_accepted();
    ASSERT_EQ(again.lights.size(), 2u);
    EXPECT_EQ(again.lights[1].angular_radius, 0.0f);
}

// fgr/scene_helpers.h: FGR_SCENE asks for no mode and its lights are point-like; the 1.2 helpers
// set both.
namespace helpers {
const fgr_param_desc params[] = {
    FGR_FLOAT_PARAM("radius", "Radius", "Shape", 0.5f, 2.0f, 1.0f, "sphere radius")};
const fgr_camera cameras[] = {FGR_CAMERA_Z_UP("front", 0.0f, -3.0f, 0.0f, 0, 0, 0, 60.0f)};
const fgr_keyframe keys[] = {FGR_KEYFRAME_Z_UP(0.0f, 0.0f, -3.0f, 0.0f, 0, 0, 0, 60.0f),
                             FGR_KEYFRAME_Z_UP(1.0f, 3.0f, 0.0f, 0.0f, 0, 0, 0, 60.0f)};
const fgr_camera_path paths[] = {FGR_CAMERA_PATH("orbit", keys)};
const fgr_light lights[] = {
    FGR_DIRECTIONAL_LIGHT(0.0f, 0.0f, 1.0f, 1.0f, 1.0f, 1.0f, 1.0f),
    FGR_DIRECTIONAL_DISC_LIGHT(1.0f, 0.0f, 1.0f, 1.0f, 0.9f, 0.8f, 3.0f, 5.0f),
    FGR_POINT_LIGHT(0.0f, 0.0f, 3.0f, 1.0f, 1.0f, 1.0f, 2.0f),
};
const char source[] = "real scene_de(vec3 p, PARAMS) { return v3_length(p) - param_radius; }";
const fgr_scene_desc plain =
    FGR_SCENE("helper-scene", "Helper scene", "built by the helpers", source, "helper.cl", params,
              cameras, paths, lights, FGR_EFFECT_SHADOWS, FGR_MARCH(64u, 10.0f, 1.0f, 8u, 1.0f));
const fgr_scene_desc path_traced = FGR_SCENE_WITH_MODE(
    "helper-scene", "Helper scene", "built by the helpers", source, "helper.cl", params, cameras,
    paths, lights, FGR_EFFECT_SHADOWS, FGR_MARCH(64u, 10.0f, 1.0f, 8u, 1.0f), "path");
}  // namespace helpers

TEST(SceneHelpers, FillTheV1_2Fields) {
    EXPECT_EQ(helpers::plain.header.struct_size, sizeof(fgr_scene_desc));
    EXPECT_EQ(helpers::plain.default_mode, nullptr);
    const LoadResult plain = copy_scene_description(&helpers::plain);
    ASSERT_TRUE(plain.scene) << plain.error;
    EXPECT_EQ(plain.scene->default_mode, RenderMode::Shaded);
    EXPECT_EQ(plain.scene->source, helpers::source);
    ASSERT_EQ(plain.scene->lights.size(), 3u);
    EXPECT_EQ(plain.scene->lights[0].angular_radius, 0.0f);
    EXPECT_NEAR(plain.scene->lights[1].angular_radius, 0.0872664626, 1e-8) << "5 degrees";
    EXPECT_FLOAT_EQ(plain.scene->lights[1].intensity, 3.0f);
    EXPECT_EQ(plain.scene->lights[2].type, LightType::Point);

    const LoadResult path_traced = copy_scene_description(&helpers::path_traced);
    ASSERT_TRUE(path_traced.scene) << path_traced.error;
    EXPECT_EQ(path_traced.scene->default_mode, RenderMode::Path);
    EXPECT_EQ(path_traced.scene->source, helpers::source);
}

TEST_F(CopyScene, RefusesOtherMajorVersion) {
    built.desc.header.abi_version = 2u << 16;
    expect_refused("ABI major version 2, host supports 1");
}

// A plugin built against a newer minor version: its structs carry appended fields.
struct NewerSceneDesc {
    fgr_scene_desc v1;
    uint64_t appended_field;
};
struct NewerParamDesc {
    fgr_param_desc v1;
    double appended_field;
};

TEST_F(CopyScene, AcceptsNewerMinorWithBiggerStructs) {
    NewerSceneDesc newer{built.desc, 42};
    newer.v1.header = {sizeof(NewerSceneDesc), FGR_ABI_VERSION + 1};
    std::vector<NewerParamDesc> newer_params;
    for (const fgr_param_desc& param : built.params) {
        newer_params.push_back({param, 1.0});
        newer_params.back().v1.header = {sizeof(NewerParamDesc), FGR_ABI_VERSION + 1};
    }
    newer.v1.params = &newer_params[0].v1;

    const LoadResult result = copy_scene_description(&newer.v1);
    ASSERT_TRUE(result.scene.has_value()) << result.error;
    ASSERT_EQ(result.scene->params.size(), 4u + builtin_param_count());
    EXPECT_EQ(result.scene->params[2].id, "tint") << "elements read with the bigger stride";
    EXPECT_FLOAT_EQ(result.scene->params[2].default_value[2], 0.7f);
    EXPECT_EQ(result.scene->params[3].id, "julia_mode");
}

TEST_F(CopyScene, RefusesMixedElementSizes) {
    built.lights[1].header.struct_size += 8;
    expect_refused("light 1 has struct_size");
}

TEST_F(CopyScene, RefusesTooSmallElement) {
    for (fgr_camera& camera : built.cameras) camera.header.struct_size = 16;
    expect_refused("camera struct too small");
}

TEST_F(CopyScene, RefusesElementWithOtherMajorVersion) {
    built.params[0].header.abi_version = 2u << 16;
    expect_refused("parameter has ABI major version 2");
}

// --- Scene identity and source -------------------------------------------------------------------

TEST_F(CopyScene, RefusesBadIds) {
    for (const char* id : {"", "Mandelbulb", "1bulb", "-bulb", "bulb box", "bulb.so"}) {
        built.desc.id = id;
        expect_refused("must match [a-z][a-z0-9_-]*");
    }
    const std::string too_long(64, 'a');
    built.desc.id = too_long.c_str();
    expect_refused("longer than 63");
    built.desc.id = nullptr;
    expect_refused("scene id is NULL");
}

TEST_F(CopyScene, AcceptsIdAtLengthLimit) {
    // 63 bytes, "a--...-"; not written "a" + std::string(62, '-'): inlined into a unity batch,
    // that sum trips GCC 12's false -Warray-bounds inside std::string's move.
    std::string longest(63, '-');
    longest.front() = 'a';
    built.desc.id = longest.c_str();
    EXPECT_EQ(expect_accepted().id, longest);
}

TEST_F(CopyScene, RefusesMissingTexts) {
    built.desc.name = "";
    expect_refused("scene name is empty");
    built.desc.name = nullptr;
    expect_refused("scene name is NULL");
    built.desc.name = "Test";
    built.desc.description = nullptr;
    expect_refused("scene description is NULL");
}

TEST_F(CopyScene, RefusesNullSource) {
    built.desc.source = nullptr;
    expect_refused("source is NULL");
}

TEST_F(CopyScene, RefusesEmptyAndOversizedSource) {
    built.desc.source = "";
    expect_refused("source is empty");
    const std::string huge((4u << 20) + 1, ' ');
    built.desc.source = huge.c_str();
    expect_refused("source longer than 4194304 bytes");
}

// --- Parameters ----------------------------------------------------------------------------------

TEST_F(CopyScene, RefusesMinGreaterThanMax) {
    built.params[0].min_value = 17.0f;
    expect_refused("parameter 'power': min 17 greater than max 16");
}

TEST_F(CopyScene, RefusesNanDefault) {
    built.params[0].default_value[0] = kNaN;
    expect_refused("parameter 'power': default not finite");
}

TEST_F(CopyScene, RefusesInfiniteRange) {
    built.params[0].max_value = std::numeric_limits<float>::infinity();
    expect_refused("parameter 'power': min/max not finite");
}

TEST_F(CopyScene, RefusesDefaultOutOfRange) {
    built.params[0].default_value[0] = 20.0f;
    expect_refused("parameter 'power': default 20 outside [1, 16]");
}

TEST_F(CopyScene, RefusesVectorComponentOutOfRange) {
    built.params[2].default_value[2] = 1.5f;
    expect_refused("parameter 'tint': default 1.5 outside [0, 1]");
}

TEST_F(CopyScene, RefusesWrongChoiceCount) {
    built.params[1].choices = "orbit|normal";
    expect_refused("parameter 'colouring': 2 choices for 3 values");
}

TEST_F(CopyScene, RefusesEmptyChoiceName) {
    built.params[1].choices = "orbit||flat";
    expect_refused("parameter 'colouring': empty name in choices");
}

TEST_F(CopyScene, RefusesChoicesOnFloat) {
    built.params[0].choices = "a|b";
    expect_refused("parameter 'power': choices are only allowed on int");
}

TEST_F(CopyScene, RefusesNonIntegralInt) {
    built.params[1].default_value[0] = 0.5f;
    expect_refused("parameter 'colouring': int min, max and default must be integral");
}

TEST_F(CopyScene, RefusesBadBool) {
    built.params[3].default_value[0] = 0.5f;
    expect_refused("parameter 'julia_mode': bool default must be 0 or 1");
    built.params[3].default_value[0] = 1.0f;
    built.params[3].max_value = 2.0f;
    expect_refused("parameter 'julia_mode': bool needs min 0 and max 1");
}

TEST_F(CopyScene, RefusesUnknownParamType) {
    built.params[0].type = 5;
    expect_refused("parameter 'power': unknown type 5");
}

TEST_F(CopyScene, RefusesDuplicateParamId) {
    built.params[2].id = "power";
    expect_refused("parameter 'power': duplicate id");
}

TEST_F(CopyScene, RefusesParamIdOfBuiltin) {
    built.params[0].id = "iterations";
    expect_refused("parameter 'iterations': id is reserved for a built-in");
}

TEST_F(CopyScene, RefusesBadParamIds) {
    // '-' is allowed in scene ids but not here: a parameter id becomes a C identifier.
    for (const char* id : {"", "bail-out", "Power", "2x", "_x"}) {
        built.params[0].id = id;
        expect_refused("id must match [a-z][a-z0-9_]*");
    }
    built.params[0].id = nullptr;
    expect_refused("parameter 0 id is NULL");
}

TEST_F(CopyScene, RefusesNullParamArray) {
    built.desc.params = nullptr;
    expect_refused("parameter count is 4 but the array is NULL");
}

TEST_F(CopyScene, RefusesTooManyParams) {
    built.desc.param_count = 1025;
    expect_refused("parameter count 1025 outside [0, 1024]");
}

// --- Cameras and paths ---------------------------------------------------------------------------

TEST_F(CopyScene, RefusesZeroCameras) {
    built.desc.camera_count = 0;
    expect_refused("camera count 0 outside [1, 256]");
}

TEST_F(CopyScene, RefusesBadFov) {
    for (float fov : {0.0f, 180.0f, -10.0f}) {
        built.cameras[1].fov_degrees = fov;
        expect_refused("camera 'top-down': fov");
    }
    built.cameras[1].fov_degrees = kNaN;
    expect_refused("camera 'top-down': numbers not finite");
}

TEST_F(CopyScene, RefusesCameraAtItsTarget) {
    built.cameras[0].target[1] = -3.0f;
    expect_refused("camera 'front': position equals target");
}

TEST_F(CopyScene, RefusesUpParallelToView) {
    built.cameras[0].up[0] = 0.0f;
    built.cameras[0].up[1] = 2.0f;
    built.cameras[0].up[2] = 0.0f;
    expect_refused("camera 'front': up is zero or parallel");
}

// Views whose camera basis would be NaN or infinite in float, as the kernel gets it, are refused
// by name: the distance from position to target under- or overflows when squared.
TEST_F(CopyScene, RefusesCamerasWhoseBasisWouldNotBeFinite) {
    built.cameras[0].target[0] = 1e-30f;
    built.cameras[0].target[1] = -3.0f;
    built.cameras[0].position[0] = 0.0f;
    expect_refused(
        "camera 'front': position and target 1e-30 apart: too close together for a camera "
        "basis in float");
    const float far_away[3] = {1e30f, -1e30f, 1e30f};
    std::copy(far_away, far_away + 3, built.cameras[0].position);
    std::copy(far_away, far_away + 3, built.cameras[0].target);
    built.cameras[0].target[0] = -1e30f;
    expect_refused("camera 'front': position and target 2e+30 apart: too far apart");
}

TEST_F(CopyScene, RefusesKeyframesWhoseBasisWouldNotBeFinite) {
    built.keyframes[1].position[0] = 1e30f;
    built.keyframes[1].target[0] = -1e30f;
    expect_refused(
        "camera path 'orbit' keyframe 1: position and target 2e+30 apart: too far apart");
    built.keyframes[1].position[0] = 3.0f;
    built.keyframes[1].target[0] = 3.0f + 3e-7f;  // a float step away, but 3e-7 is no problem
    expect_accepted();
    built.keyframes[1].position[0] = 0.0f;
    built.keyframes[1].target[0] = 1e-30f;
    expect_refused("camera path 'orbit' keyframe 1: position and target 1e-30 apart: too close");
    built.keyframes[1].target[0] = 0.0f;
    built.keyframes[1].fov_degrees = kNaN;
    expect_refused("camera path 'orbit' keyframe 1: numbers not finite");
}

// An up hint along the view is refused where it is given, for cameras and keyframes alike; an up
// that is accepted is the one the camera basis uses (camera_basis replaces only what would be
// refused here), however short or long it is.
TEST_F(CopyScene, UpParallelToTheViewIsRefusedAndAnAcceptedUpIsTheOneUsed) {
    built.keyframes[2].up[0] = 0.0f;
    built.keyframes[2].up[1] = -1.0f;
    built.keyframes[2].up[2] = 0.0f;
    expect_refused("camera path 'orbit' keyframe 2: up is zero or parallel to the view direction");
    built.keyframes[2].up[2] = 1e-7f;  // 1e-7 off parallel: the roll is not defined by it
    expect_refused("camera path 'orbit' keyframe 2: up is zero or parallel");
    built.keyframes[2].up[1] = 0.0f;
    built.keyframes[2].up[2] = 1.0f;
    built.cameras[1].up[1] = 1e-30f;  // perpendicular to the view, and tiny
    expect_refused("camera 'top-down': up is zero or parallel");  // its float length is 0
    built.cameras[1].up[1] = 1e-12f;
    const Scene scene = expect_accepted();
    ASSERT_EQ(scene.cameras.size(), 2u);
    const CameraBasis basis = camera_basis(scene.cameras[1].view);
    EXPECT_NEAR(basis.up.y, 1.0f, 1e-6f) << "the camera's own up, not a replacement axis";
    built.cameras[1].up[1] = 1e30f;
    expect_refused("camera 'top-down': up too long for float");
}

TEST_F(CopyScene, RefusesBadCameraNames) {
    built.cameras[1].name = "front";
    expect_refused("camera 'front': duplicate name");
    built.cameras[1].name = "Top View";
    expect_refused("must match [a-z0-9_-]+");
}

TEST_F(CopyScene, RefusesKeyframeTimesNotIncreasing) {
    built.keyframes[2].time = 2.0f;
    expect_refused("camera path 'orbit' keyframe 2: time 2 not after 2");
}

TEST_F(CopyScene, RefusesSingleKeyframe) {
    built.paths[0].keyframe_count = 1;
    expect_refused("camera path 'orbit' keyframe count 1 outside [2, 10000]");
}

TEST_F(CopyScene, RefusesBadKeyframeView) {
    built.keyframes[1].fov_degrees = 200.0f;
    expect_refused("camera path 'orbit' keyframe 1: fov 200 outside (0, 180)");
}

// --- Lights, effects, march settings -------------------------------------------------------------

TEST_F(CopyScene, RefusesUnknownEffectBit) {
    built.desc.effects = FGR_EFFECT_SHADOWS | (uint64_t{1} << 9) | (uint64_t{1} << 40);
    expect_refused("unknown effect bits 0x10000000200");
}

TEST_F(CopyScene, RefusesZeroLights) {
    built.desc.light_count = 0;
    expect_refused("light count is 0: a scene needs at least one light");
}

// A count over a NULL array says a light is missing, and the refusal carries the scene's id so
// discovery's warning and `fgr render ID` can name the scene.
TEST_F(CopyScene, RefusesNullLightsSayingASceneNeedsOneAndNamingTheScene) {
    built.desc.lights = nullptr;
    built.desc.light_count = 8;
    expect_refused("light count is 8 but the array is NULL: a scene needs at least one light");
    EXPECT_EQ(copy_scene_description(&built.desc).declared_id, std::string(built.desc.id));
}

TEST_F(CopyScene, RefusalBeforeTheIdIsValidDeclaresNoId) {
    built.desc.id = "Not An Id";
    EXPECT_EQ(copy_scene_description(&built.desc).declared_id, "");
}

TEST_F(CopyScene, RefusesSeventeenLights) {
    std::vector<fgr_light> many(17, built.lights[0]);
    built.desc.lights = many.data();
    built.desc.light_count = 17;
    expect_refused("light count 17 outside [1, 16]");
}

TEST_F(CopyScene, RefusesNegativeIntensity) {
    built.lights[1].intensity = -1.0f;
    expect_refused("light 1: negative intensity -1");
}

TEST_F(CopyScene, RefusesNegativeColour) {
    built.lights[0].colour[1] = -0.1f;
    expect_refused("light 0: negative colour");
}

TEST_F(CopyScene, RefusesZeroDirection) {
    built.lights[0].vector[2] = 0.0f;
    expect_refused("light 0: zero direction");
}

TEST_F(CopyScene, RefusesUnknownLightType) {
    built.lights[0].type = 7;
    expect_refused("light 0: unknown type 7");
}

TEST_F(CopyScene, RefusesZeroMaxSteps) {
    built.desc.march.max_steps = 0;
    expect_refused("march settings: max_steps 0 outside [1, 100000]");
}

TEST_F(CopyScene, RefusesBadMarchSettings) {
    built.desc.march.de_iterations = 1001;
    expect_refused("de_iterations 1001 outside [1, 1000]");
    built.desc.march.de_iterations = 12;
    built.desc.march.hit_threshold = 0.0f;
    expect_refused("hit_threshold 0 must be finite and > 0");
    built.desc.march.hit_threshold = 1.0f;
    built.desc.march.max_distance = kNaN;
    expect_refused("max_distance nan must be finite and > 0");
    built.desc.march.max_distance = 2e6f;
    expect_refused("march settings: max_distance 2000000 outside the built-in range");
    built.desc.march.max_distance = 10.0f;
    built.desc.march.step_factor = 1.5f;
    expect_refused("march settings: step_factor 1.5 outside [0, 1]");
    built.desc.march.step_factor = -0.5f;
    expect_refused("march settings: step_factor -0.5 outside [0, 1]");
}

TEST_F(CopyScene, ZeroStepFactorMeansFullSteps) {
    built.desc.march.step_factor = 0.0f;
    const LoadResult result = copy_scene_description(&built.desc);
    ASSERT_TRUE(result.scene) << result.error;
    EXPECT_FLOAT_EQ(result.scene->march.step_factor, 1.0f);
    EXPECT_FLOAT_EQ(result.scene->find_param("step_factor")->default_value[0], 1.0f);
}

TEST_F(CopyScene, RefusesTooSmallMarchStruct) {
    built.desc.march.header.struct_size = 8;
    expect_refused("march settings struct too small");
}

// --- ABI 1.4: the scene's own built-in defaults, colour modes and scale --------------------------

class CopyTunedScene : public CopyScene {
protected:
    void give(std::vector<fgr_builtin_default> given) {
        defaults = std::move(given);
        built.desc.builtin_defaults = defaults.data();
        built.desc.builtin_default_count = static_cast<uint32_t>(defaults.size());
    }
    // The enum parameter `colouring` (orbit|normal|flat, default 1) as the scene's colour_mode.
    void name_colour_mode() { built.params[1].id = "colour_mode"; }

    std::vector<fgr_builtin_default> defaults;
};

TEST_F(CopyTunedScene, AcceptsBuiltinDefaultsInRange) {
    give({FGR_BUILTIN_DEFAULT("ao_radius", 0.002f),
          FGR_BUILTIN_COLOUR_DEFAULT("fog_colour", 0.9f, 0.8f, 0.7f),
          FGR_BUILTIN_DEFAULT("tone_map", 1.0f)});
    const Scene scene = expect_accepted();
    EXPECT_FLOAT_EQ(scene.find_param("ao_radius")->default_value[0], 0.002f);
    EXPECT_EQ(scene.find_param("fog_colour")->default_value,
              (std::array<float, 3>{0.9f, 0.8f, 0.7f}));
    EXPECT_FLOAT_EQ(scene.find_param("tone_map")->default_value[0], 1.0f);
    EXPECT_TRUE(scene.find_param("tone_map")->scene_default);
    EXPECT_FALSE(scene.find_param("exposure")->scene_default);
}

TEST_F(CopyTunedScene, RefusesBadBuiltinDefaultsNamingTheParameter) {
    give({FGR_BUILTIN_DEFAULT("ao_radius", 500.0f)});
    expect_refused("built-in parameter 'ao_radius': scene default 500 outside [1e-09, 100]");
    give({FGR_BUILTIN_DEFAULT("glow_radius", kNaN)});
    expect_refused("built-in parameter 'glow_radius': scene default not finite");
    give({FGR_BUILTIN_COLOUR_DEFAULT("fog_colour", 0.5f, 1.5f, 0.5f)});
    expect_refused("built-in parameter 'fog_colour': scene default 1.5 outside [0, 1]");
    give({FGR_BUILTIN_DEFAULT("reflection_bounces", 2.5f)});
    expect_refused("built-in parameter 'reflection_bounces': scene default 2.5 is not a whole");
    give({FGR_BUILTIN_DEFAULT("ao_radus", 0.01f)});
    expect_refused("built-in default 0: 'ao_radus' is not a built-in parameter");
    give({FGR_BUILTIN_DEFAULT("power", 4.0f)});  // the scene's own: set it in its params
    expect_refused("built-in default 0: 'power' is not a built-in parameter");
    give({FGR_BUILTIN_DEFAULT("max_steps", 64.0f)});
    expect_refused("built-in parameter 'max_steps': its default comes from the march settings");
    give({FGR_BUILTIN_DEFAULT("ao_radius", 0.01f), FGR_BUILTIN_DEFAULT("ao_radius", 0.02f)});
    expect_refused("built-in parameter 'ao_radius': default given twice");
    give({FGR_BUILTIN_DEFAULT(nullptr, 0.01f)});
    expect_refused("built-in default 0 id is NULL");
}

TEST_F(CopyTunedScene, RefusesAScaleOutOfRange) {
    for (const float scale : {-1.0f, 1e-7f, 2e6f, kNaN}) {
        built.desc.scale = scale;
        expect_refused("scale ");
    }
    built.desc.scale = 0.0f;
    EXPECT_FLOAT_EQ(expect_accepted().scale, 1.0f) << "0 means 1";
}

TEST_F(CopyTunedScene, OffersTheColourModesItNames) {
    name_colour_mode();
    built.desc.colour_modes = 0b011;
    const Scene scene = expect_accepted();
    EXPECT_EQ(scene.find_param("colour_mode")->offered, (std::vector<bool>{true, true, false}));
    EXPECT_EQ(offered_choices_text(*scene.find_param("colour_mode")), "orbit|normal");
    built.desc.colour_modes = 0;
    EXPECT_TRUE(expect_accepted().find_param("colour_mode")->offered.empty()) << "0 means all";
}

TEST_F(CopyTunedScene, RefusesBadColourModes) {
    built.desc.colour_modes = FGR_COLOUR_MODE_POINT;
    expect_refused("colour_modes 0x1 given, but the scene has no colour_mode enum parameter");
    name_colour_mode();
    built.desc.colour_modes = 0b101;  // leaves out the default, 1 ("normal")
    expect_refused(
        "parameter 'colour_mode': default 'normal' is not among the colour modes offered "
        "(orbit|flat)");
    built.desc.colour_modes = FGR_COLOUR_MODE_ITERATIONS;  // bit 3: the enum has three choices
    expect_refused("colour_modes 0x8: parameter 'colour_mode' has only 3 choices");
    built.desc.colour_modes = 0x10;
    expect_refused("colour_modes 0x10: unknown bits 0x10");
}

// --- ABI 1.5: the scene's own environment ------------------------------------------------------

// A generated environment named as --environment names it is the scene's own; NULL and "" are
// none, the sky.
TEST_F(CopyScene, AcceptsAnEnvironmentFgrGenerates) {
    for (const char* text : {"sky", "studio", "uniform", "uniform:0.5", "uniform:1,0.5,0.25"}) {
        built.desc.environment = text;
        EXPECT_EQ(expect_accepted().environment, text);
    }
    for (const char* none : {static_cast<const char*>(nullptr), ""}) {
        built.desc.environment = none;
        EXPECT_EQ(expect_accepted().environment, "");
    }
}

// Anything else is refused in one line that quotes it: a map file (the user's --environment
// FILE), a name fgr does not have, radiances that are negative, not numbers or not one or three,
// text longer than 63 bytes or with control bytes.
TEST_F(CopyScene, RefusesAnEnvironmentItCannotMake) {
    built.desc.environment = "studio.hdr";
    expect_refused("environment 'studio.hdr' is not one fgr generates");
    built.desc.environment = "nebula";
    expect_refused("environment 'nebula' is not one fgr generates");
    built.desc.environment = "uniform:-1";
    expect_refused("environment uniform:RADIANCE: '-1' is not a non-negative number");
    built.desc.environment = "uniform:1,2";
    expect_refused("give one value or R,G,B, not '1,2'");
    built.desc.environment = "uniform:nan";
    expect_refused("is not a non-negative number");
    const std::string long_text = "uniform:" + std::string(60, '1');
    built.desc.environment = long_text.c_str();
    expect_refused("environment longer than 63 bytes");
    built.desc.environment = "sky\x1b[2J";
    expect_refused("'sky\\x1b[2J'");
}

// A description of 1.4's size ends before the field: what follows it is not read.
TEST_F(CopyScene, AnOlderDescriptionHasNoEnvironment) {
    built.desc.environment = "not an environment";
    built.desc.header.struct_size = offsetof(fgr_scene_desc, environment);
    EXPECT_EQ(expect_accepted().environment, "");
}

}  // namespace
}  // namespace fgr
