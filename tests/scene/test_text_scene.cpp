// SPDX-License-Identifier: Apache-2.0
// Text scenes (scene/text_scene.hpp): a header with every key reaches the Scene as a plugin's
// description would; the defaults; each key's bad value is refused in one line naming the key;
// seeded fuzzing of the header; discovery of a folder with a text scene, a header-less .cl and a
// broken one; the scene index; and what a scene argument names (scene/scene_argument.hpp). No
// kernel is compiled here (tests/cli/test_cli.cpp renders the SDK guide's example).
//
// Reproduce a fuzz failure with FGR_FUZZ_SEED=<case seed> FGR_FUZZ_CASES=1 (the seed is printed
// with it); FGR_FUZZ_CASES=<n> runs more or fewer cases.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "cli/scaffold.hpp"
#include "fuzz_rng.hpp"
#include "json_mutation.hpp"
#include "scene/discovery.hpp"
#include "scene/parameters.hpp"
#include "scene/scene_argument.hpp"
#include "scene/scene_index.hpp"
#include "scene/text_scene.hpp"
#include "test_files.hpp"
#include "text_scene_example.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* kSource = "real scene_de(vec3 p, PARAMS) { return v3_length(p) - 1.0f; }\n";

// A header with every key, each with a value other than its default.
json full_header() {
    return json::parse(R"({
      "$schema": "text-scene.schema.json",
      "id": "table", "name": "Table", "description": "every key",
      "parameters": [
        {"id": "power", "type": "float", "min": 2, "max": 16, "default": 8, "label": "Power",
         "group": "Shape", "description": "the bulb's power"},
        {"id": "variant", "type": "int", "choices": ["one", "two"], "default": "two"},
        {"id": "offset", "type": "vec3", "min": -1, "max": 1, "default": [0.5, 0, -0.5]},
        {"id": "mirror", "type": "bool", "default": true}],
      "colour_parameters": {"mode": "planes", "palette": "ocean", "base_colour": [1, 0.9, 0.8]},
      "cameras": [{"name": "front", "position": [0, -3, 1], "target": [0, 0, 0], "up": [0, 0, 1],
                   "fov": 50}],
      "camera_paths": [{"name": "spin", "keyframes": [
          {"time": 0, "position": [0, -3, 1], "target": [0, 0, 0]},
          {"time": 2, "position": [3, 0, 1], "target": [0, 0, 0], "fov": 40}]}],
      "lights": [{"type": "directional", "direction": [0, 0, 2], "colour": [1, 0.5, 0.25],
                  "intensity": 2, "angular_radius_degrees": 0.5},
                 {"type": "point", "position": [0, 0, 4], "intensity": 5}],
      "effects": ["shadows", "fog"],
      "march": {"max_steps": 200, "max_distance": 12, "hit_threshold": 2, "iterations": 10,
                "step_factor": 0.9},
      "default_mode": "path",
      "builtin_defaults": {"ao_radius": 0.2, "fog_colour": [0.1, 0.1, 0.2]},
      "colour_modes": ["point", "planes", "axes"],
      "scale": 1.5,
      "environment": "studio"})");
}

std::string text_scene(const std::string& header, const std::string& source = kSource) {
    return "/* fgr-scene\n" + header + "\n*/\n" + source;
}

LoadResult parse(const json& header) {
    return parse_text_scene(text_scene(header.dump(1)), "table.cl");
}

const ParamInfo& param(const Scene& scene, const std::string& id) {
    const ParamInfo* found = scene.find_param(id);
    if (found == nullptr) throw std::runtime_error("no parameter " + id);
    return *found;
}

// --- What a header becomes -----------------------------------------------------------------------

TEST(TextScene, EveryKeyOfTheHeaderReachesTheScene) {
    const std::string text = text_scene(full_header().dump(1));
    const LoadResult loaded = parse_text_scene(text, "dir/table.cl");
    ASSERT_TRUE(loaded.scene) << loaded.error;
    const Scene& scene = *loaded.scene;
    EXPECT_EQ(scene.id, "table");
    EXPECT_EQ(scene.name, "Table");
    EXPECT_EQ(scene.description, "every key");
    // The whole file is the source, header comment and all, so compiler lines are the file's.
    EXPECT_EQ(scene.source, text);
    EXPECT_EQ(scene.source_name, "dir/table.cl");
    EXPECT_EQ(scene.plugin_file, fs::path("dir/table.cl"));

    const ParamInfo& power = param(scene, "power");
    EXPECT_EQ(power.type, ParamType::Float);
    EXPECT_EQ(power.label, "Power");
    EXPECT_EQ(power.group, "Shape");
    EXPECT_EQ(power.description, "the bulb's power");
    EXPECT_EQ(power.min_value, 2.0f);
    EXPECT_EQ(power.max_value, 16.0f);
    EXPECT_EQ(power.default_value[0], 8.0f);
    const ParamInfo& variant = param(scene, "variant");
    EXPECT_EQ(variant.type, ParamType::Int);
    EXPECT_EQ(variant.choices, (std::vector<std::string>{"one", "two"}));
    EXPECT_EQ(variant.max_value, 1.0f);
    EXPECT_EQ(variant.default_value[0], 1.0f) << "the default given by name";
    EXPECT_EQ(variant.group, "Scene");
    EXPECT_EQ(param(scene, "offset").default_value, (std::array<float, 3>{0.5f, 0.0f, -0.5f}));
    EXPECT_EQ(param(scene, "mirror").default_value[0], 1.0f);
    // colour_parameters: FGR_COLOUR_PARAMS's three, with the chosen defaults.
    EXPECT_EQ(param(scene, "colour_mode").default_value[0], 1.0f);
    EXPECT_EQ(param(scene, "palette").default_value[0], 1.0f);
    EXPECT_EQ(param(scene, "base_colour").default_value, (std::array<float, 3>{1.0f, 0.9f, 0.8f}));
    EXPECT_EQ(param(scene, "colour_mode").offered, (std::vector<bool>{true, true, true, false}));

    ASSERT_EQ(scene.cameras.size(), 1u);
    EXPECT_EQ(scene.cameras[0].name, "front");
    EXPECT_EQ(scene.cameras[0].view.position, glm::dvec3(0, -3, 1));
    EXPECT_EQ(scene.cameras[0].view.fov_degrees, 50.0f);
    ASSERT_EQ(scene.camera_paths.size(), 1u);
    EXPECT_EQ(scene.camera_paths[0].name, "spin");
    ASSERT_EQ(scene.camera_paths[0].keyframes.size(), 2u);
    EXPECT_EQ(scene.camera_paths[0].keyframes[0].view.fov_degrees, 60.0f) << "the default fov";
    EXPECT_EQ(scene.camera_paths[0].keyframes[1].view.fov_degrees, 40.0f);
    ASSERT_EQ(scene.lights.size(), 2u);
    EXPECT_EQ(scene.lights[0].type, LightType::Directional);
    EXPECT_EQ(scene.lights[0].vector, glm::vec3(0, 0, 1)) << "normalised";
    EXPECT_EQ(scene.lights[0].intensity, 2.0f);
    EXPECT_NEAR(scene.lights[0].angular_radius, 0.5 * std::numbers::pi / 180.0, 1e-7);
    EXPECT_EQ(scene.lights[1].type, LightType::Point);
    EXPECT_EQ(scene.lights[1].colour, glm::vec3(1.0f)) << "the default colour";
    EXPECT_EQ(scene.effects, uint64_t{FGR_EFFECT_SHADOWS | FGR_EFFECT_FOG});
    EXPECT_EQ(scene.march.max_steps, 200u);
    EXPECT_EQ(scene.march.max_distance, 12.0f);
    EXPECT_EQ(scene.march.hit_threshold, 2.0f);
    EXPECT_EQ(scene.march.de_iterations, 10u);
    EXPECT_EQ(scene.march.step_factor, 0.9f);
    EXPECT_EQ(scene.default_mode, RenderMode::Path);
    EXPECT_EQ(param(scene, "ao_radius").default_value[0], 0.2f);
    EXPECT_TRUE(param(scene, "ao_radius").scene_default);
    EXPECT_EQ(param(scene, "fog_colour").default_value, (std::array<float, 3>{0.1f, 0.1f, 0.2f}));
    EXPECT_EQ(scene.scale, 1.5f);
    EXPECT_EQ(scene.environment, "studio");
}

TEST(TextScene, AHeaderWithAnIdAndANameGetsTheUsualDefaults) {
    const LoadResult loaded =
        parse_text_scene(text_scene(R"({"id": "least", "name": "Least"})"), "least.cl");
    ASSERT_TRUE(loaded.scene) << loaded.error;
    const Scene& scene = *loaded.scene;
    EXPECT_EQ(scene.description, "");
    EXPECT_EQ(scene.params.size(), builtin_param_count());
    ASSERT_EQ(scene.cameras.size(), 1u);
    EXPECT_EQ(scene.cameras[0].name, "default");
    EXPECT_EQ(scene.cameras[0].view.target, glm::dvec3(0.0));
    ASSERT_EQ(scene.camera_paths.size(), 1u);
    EXPECT_EQ(scene.camera_paths[0].name, "orbit");
    EXPECT_EQ(scene.camera_paths[0].keyframes.size(), 5u);
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_NEAR(scene.lights[0].intensity, 1.1f, 1e-6);
    EXPECT_EQ(scene.effects, uint64_t{FGR_EFFECT_SHADOWS | FGR_EFFECT_AMBIENT_OCCLUSION});
    EXPECT_EQ(scene.march.max_steps, MarchSettings{}.max_steps);
    EXPECT_EQ(scene.default_mode, RenderMode::Shaded);
    EXPECT_EQ(scene.scale, 1.0f);
    EXPECT_EQ(scene.environment, "") << "none: the sky";

    // The default camera and the march's reach follow the scale.
    const LoadResult scaled = parse_text_scene(
        text_scene(R"({"id": "big", "name": "Big", "scale": 10, "camera_paths": []})"), "big.cl");
    ASSERT_TRUE(scaled.scene) << scaled.error;
    EXPECT_NEAR(scaled.scene->cameras[0].view.position.y, -36.0, 1e-5);
    EXPECT_EQ(scaled.scene->march.max_distance, 10.0f * MarchSettings{}.max_distance);
    EXPECT_TRUE(scaled.scene->camera_paths.empty()) << "[] means none";
}

TEST(TextScene, TheHeaderIsFoundAfterBlankLinesAndAsTheCommentsFirstWordOnly) {
    EXPECT_TRUE(starts_with_text_scene_header("/* fgr-scene {} */"));
    EXPECT_TRUE(starts_with_text_scene_header("\n\r\n  \t/*\n  fgr-scene\n{}*/"));
    EXPECT_TRUE(starts_with_text_scene_header("\xEF\xBB\xBF/* fgr-scene\n"));
    EXPECT_TRUE(starts_with_text_scene_header("/*fgr-scene*/"));
    EXPECT_FALSE(starts_with_text_scene_header(""));
    EXPECT_FALSE(starts_with_text_scene_header("// fgr-scene\n"));
    EXPECT_FALSE(starts_with_text_scene_header("/* the fgr-scene */"));
    EXPECT_FALSE(starts_with_text_scene_header("/* fgr-scenes */"));
    EXPECT_FALSE(starts_with_text_scene_header("#include \"x.cl\"\n/* fgr-scene */"));
    EXPECT_FALSE(starts_with_text_scene_header("/ * fgr-scene */"));
}

// A refusal of the JSON itself says where in the file, by the file's own line numbers.
TEST(TextScene, JsonErrorsGiveTheFilesLine) {
    const LoadResult broken = parse_text_scene(
        "\n/* fgr-scene\n{\"id\": \"x\",\n \"name\": \"X\",,\n}\n*/\n", "broken.cl");
    ASSERT_FALSE(broken.scene);
    EXPECT_EQ(broken.error.rfind("header: not valid JSON: parse error at line 4, column", 0), 0u)
        << broken.error;
}

// --- Each key's bad value: one line naming it ----------------------------------------------------

struct BadHeader {
    const char* name;
    const char* pointer;  // where in full_header() the value goes
    json value;           // nullptr with `remove`: the key is removed
    const char* expected;
    bool remove = false;
};

void PrintTo(const BadHeader& bad, std::ostream* os) { *os << bad.name; }

const std::vector<BadHeader> kBadHeaders = {
    {"IdNotAString", "/id", 3, R"(header "id": must be a string)"},
    {"IdMissing", "/id", nullptr, R"(header "id": is missing)", true},
    {"IdNotAnId", "/id", "Bad Id", "scene id 'Bad Id' must match [a-z][a-z0-9_-]*"},
    {"NameNotAString", "/name", json::array(), R"(header "name": must be a string)"},
    {"NameEmpty", "/name", "", "scene name is empty"},
    {"NameMissing", "/name", nullptr, R"(header "name": is missing)", true},
    {"DescriptionWithANewline", "/description", "a\nb",
     R"(header "description": must not hold control characters)"},
    {"ParametersNotAnArray", "/parameters", json::object(),
     R"(header "parameters": must be an array)"},
    {"ParameterNotAnObject", "/parameters/0", 3, R"(header "parameters[0]": must be an object)"},
    {"ParameterUnknownKey", "/parameters/0/colour", 1,
     R"(header "parameters[0]": unknown key "colour")"},
    {"ParameterIdMissing", "/parameters/0/id", nullptr, R"(header "parameters[0].id": is missing)",
     true},
    {"ParameterIdNotAnId", "/parameters/0/id", "Power",
     "parameter 'Power': id must match [a-z][a-z0-9_]*"},
    {"ParameterIdDuplicate", "/parameters/1/id", "power", "parameter 'power': duplicate id"},
    {"ParameterIdBuiltIn", "/parameters/0/id", "ao_radius",
     "parameter 'ao_radius': id is reserved for a built-in parameter"},
    {"ParameterTypeUnknown", "/parameters/0/type", "double",
     R"(header "parameters[0].type": unknown type "double")"},
    {"ParameterLabelNotAString", "/parameters/0/label", 5,
     R"(header "parameters[0].label": must be a string)"},
    {"ParameterGroupNotAString", "/parameters/0/group", false,
     R"(header "parameters[0].group": must be a string)"},
    {"ParameterDescriptionNotAString", "/parameters/0/description", json::array(),
     R"(header "parameters[0].description": must be a string)"},
    {"ParameterMinNotANumber", "/parameters/0/min", "low",
     R"(header "parameters[0].min": must be a number)"},
    {"ParameterMaxHuge", "/parameters/0/max", 1e300,
     R"(header "parameters[0].max": must be finite and at most 1e+30 in magnitude)"},
    {"ParameterMaxMissing", "/parameters/0/max", nullptr,
     R"(header "parameters[0].max": is missing)", true},
    {"ParameterMinAboveMax", "/parameters/0/min", 20, "parameter 'power': min 20 greater than max"},
    {"ParameterDefaultOutOfRange", "/parameters/0/default", 99,
     "parameter 'power': default 99 outside [2, 16]"},
    {"ParameterDefaultMissing", "/parameters/0/default", nullptr,
     R"(header "parameters[0].default": is missing)", true},
    {"ParameterChoicesOnAFloat", "/parameters/0/choices", json::array({"a"}),
     "parameter 'power': choices are only allowed on int"},
    {"ParameterChoicesEmpty", "/parameters/1/choices", json::array(),
     R"(header "parameters[1].choices": must name at least one choice)"},
    {"ParameterChoiceWithABar", "/parameters/1/choices/0", "a|b",
     R"(header "parameters[1].choices[0]": must not hold '|')"},
    {"ParameterChoiceEmpty", "/parameters/1/choices/0", "",
     R"(header "parameters[1].choices[0]": must not be empty)"},
    {"ParameterDefaultUnknownChoice", "/parameters/1/default", "three",
     R"(header "parameters[1].default": unknown choice "three" (known: one, two))"},
    {"ParameterIntNotWhole", "/parameters/1/default", 0.5,
     "parameter 'variant': int min, max and default must be integral"},
    {"ParameterVec3DefaultShort", "/parameters/2/default", json::array({1, 2}),
     R"(header "parameters[2].default": must be an array of 3 numbers)"},
    {"ParameterBoolDefaultTwo", "/parameters/3/default", 2,
     "parameter 'mirror': default 2 outside [0, 1]"},
    {"ColourParametersNotAnObject", "/colour_parameters", 1,
     R"(header "colour_parameters": must be an object)"},
    {"ColourParametersUnknownPalette", "/colour_parameters/palette", "neon",
     R"(header "colour_parameters.palette": unknown palette "neon")"},
    {"ColourParametersUnknownMode", "/colour_parameters/mode", "rainbow",
     R"(header "colour_parameters.mode": unknown colour mode "rainbow")"},
    {"ColourParametersBaseOutOfRange", "/colour_parameters/base_colour", json::array({2, 0, 0}),
     "parameter 'base_colour': default 2 outside [0, 1]"},
    {"CamerasEmpty", "/cameras", json::array(), "camera count 0 outside [1, 256]"},
    {"CameraNameBad", "/cameras/0/name", "Front", "camera 0: name 'Front' must match"},
    {"CameraNameMissing", "/cameras/0/name", nullptr, R"(header "cameras[0].name": is missing)",
     true},
    {"CameraPositionShort", "/cameras/0/position", json::array({0, 0}),
     R"(header "cameras[0].position": must be an array of 3 numbers)"},
    {"CameraTargetIsPosition", "/cameras/0/target", json::array({0, -3, 1}), "camera 'front': "},
    {"CameraUpNotAVector", "/cameras/0/up", "z",
     R"(header "cameras[0].up": must be an array of 3 numbers)"},
    {"CameraFovTooWide", "/cameras/0/fov", 200, "camera 'front': "},
    {"CameraUnknownKey", "/cameras/0/zoom", 2, R"(header "cameras[0]": unknown key "zoom")"},
    {"CameraPathsNotAnArray", "/camera_paths", "orbit",
     R"(header "camera_paths": must be an array)"},
    {"CameraPathNameNotAString", "/camera_paths/0/name", 3,
     R"(header "camera_paths[0].name": must be a string)"},
    {"CameraPathOneKeyframe", "/camera_paths/0/keyframes/1", nullptr,
     "camera path 'spin' keyframe count 1 outside [2, 10000]", true},
    {"KeyframeTimeNotAfter", "/camera_paths/0/keyframes/1/time", 0,
     "camera path 'spin' keyframe 1: time 0 not after 0"},
    {"KeyframeTimeMissing", "/camera_paths/0/keyframes/0/time", nullptr,
     R"(header "camera_paths[0].keyframes[0].time": is missing)", true},
    {"KeyframePositionNotANumber", "/camera_paths/0/keyframes/1/position/2", "up",
     R"(header "camera_paths[0].keyframes[1].position": must be a number)"},
    {"LightsEmpty", "/lights", json::array(), "light count is 0: a scene needs at least one light"},
    {"LightTypeUnknown", "/lights/0/type", "spot",
     R"(header "lights[0].type": "spot" must be "directional" or "point")"},
    {"LightDirectionZero", "/lights/0/direction", json::array({0, 0, 0}),
     "light 0: zero direction"},
    {"LightIntensityNegative", "/lights/0/intensity", -1, "light 0: negative intensity -1"},
    {"LightColourNegative", "/lights/1/colour", json::array({-1, 0, 0}),
     "light 1: negative colour"},
    {"LightDiscTooWide", "/lights/0/angular_radius_degrees", 50,
     "light 0: angular_radius_degrees 50 outside [0, 45]"},
    {"PointLightWithADisc", "/lights/1/angular_radius_degrees", 1,
     R"(header "lights[1]": unknown key "angular_radius_degrees")"},
    {"EffectsNotAnArray", "/effects", "shadows", R"(header "effects": must be an array)"},
    {"EffectUnknown", "/effects/1", "shadow",
     R"(header "effects[1]": unknown effect "shadow" (known: shadows,)"},
    {"MarchNotAnObject", "/march", 3, R"(header "march": must be an object)"},
    {"MarchMaxStepsZero", "/march/max_steps", 0, "march settings: max_steps 0 outside [1, 100000]"},
    {"MarchMaxStepsNegative", "/march/max_steps", -1,
     R"(header "march.max_steps": must be a whole number from 0 to 4294967295)"},
    {"MarchMaxStepsFractional", "/march/max_steps", 1.5,
     R"(header "march.max_steps": must be a whole number)"},
    {"MarchMaxDistanceZero", "/march/max_distance", 0,
     "march settings: max_distance 0 must be finite and > 0"},
    {"MarchHitThresholdNegative", "/march/hit_threshold", -1,
     "march settings: hit_threshold -1 must be finite and > 0"},
    {"MarchIterationsTooMany", "/march/iterations", 5000, "iterations 5000 outside [1, 1000]"},
    {"MarchStepFactorZero", "/march/step_factor", 0,
     R"(header "march.step_factor": must be above 0)"},
    {"MarchStepFactorTwo", "/march/step_factor", 2, "march settings: step_factor 2 outside [0, 1]"},
    {"MarchUnknownKey", "/march/speed", 1, R"(header "march": unknown key "speed")"},
    {"DefaultModeUnknown", "/default_mode", "fast", "default_mode 'fast' is not a render mode"},
    {"DefaultModeNotAString", "/default_mode", 1, R"(header "default_mode": must be a string)"},
    {"BuiltinDefaultsNotAnObject", "/builtin_defaults", json::array(),
     R"(header "builtin_defaults": must be an object)"},
    {"BuiltinDefaultOutOfRange", "/builtin_defaults/ao_radius", -1,
     "built-in parameter 'ao_radius': scene default -1 outside"},
    {"BuiltinColourDefaultAScalar", "/builtin_defaults/fog_colour", 0.5,
     R"(header "builtin_defaults.fog_colour": must be an array of 3 numbers)"},
    {"BuiltinDefaultOfAMarchKnob", "/builtin_defaults/max_steps", 10,
     "built-in parameter 'max_steps': its default comes from the march settings"},
    {"BuiltinDefaultUnknown", "/builtin_defaults/warp", 1, "'warp' is not a built-in parameter"},
    {"ColourModesEmpty", "/colour_modes", json::array(),
     R"(header "colour_modes": must name at least one colour mode)"},
    {"ColourModeUnknown", "/colour_modes/0", "rainbow",
     R"(header "colour_modes[0]": unknown colour mode "rainbow")"},
    {"ColourModesWithoutTheDefault", "/colour_modes", json::array({"point", "axes"}),
     "parameter 'colour_mode': default 'planes' is not among the colour modes offered"},
    {"ScaleZero", "/scale", 0, R"(header "scale": must be above 0)"},
    {"ScaleHuge", "/scale", 1e9, "scale 1000000000 outside [1e-06, 1000000]"},
    {"ScaleNotANumber", "/scale", "big", R"(header "scale": must be a number)"},
    {"EnvironmentAMapFile", "/environment", "studio.hdr",
     "environment 'studio.hdr' is not one fgr generates"},
    {"EnvironmentNegative", "/environment", "uniform:1,-1,1", "is not a non-negative number"},
    {"EnvironmentNotAString", "/environment", 3, R"(header "environment": must be a string)"},
    {"SchemaNotAString", "/$schema", 3, R"(header "$schema": must be a string)"},
    {"UnknownKey", "/colours", 1, R"(header: unknown key "colours")"},
};

class TextSceneBadHeader : public ::testing::TestWithParam<BadHeader> {};

TEST_P(TextSceneBadHeader, IsRefusedInOneLineNamingTheKey) {
    const BadHeader& bad = GetParam();
    json header = full_header();
    const json::json_pointer at(bad.pointer);
    if (bad.remove) {
        json& parent = header[at.parent_pointer()];
        if (parent.is_array()) {
            parent.erase(std::stoul(at.back()));
        } else {
            parent.erase(at.back());
        }
    } else {
        header[at] = bad.value;
    }
    const LoadResult loaded = parse(header);
    ASSERT_FALSE(loaded.scene) << "accepted: " << header.dump();
    EXPECT_NE(loaded.error.find(bad.expected), std::string::npos)
        << loaded.error << "\n  expected to contain: " << bad.expected;
    EXPECT_EQ(loaded.error.find('\n'), std::string::npos) << loaded.error;
    // Refused once its id is known, it is still found by it (unknown_scene_message).
    if (header.contains("id") && header["id"] == "table") {
        EXPECT_EQ(loaded.declared_id, "table");
    }
}

INSTANTIATE_TEST_SUITE_P(Keys, TextSceneBadHeader, ::testing::ValuesIn(kBadHeaders),
                         [](const ::testing::TestParamInfo<BadHeader>& param_info) {
                             return std::string(param_info.param.name);
                         });

// Problems with the file rather than a key: each one line, none a crash.
TEST(TextScene, BrokenFilesAreRefusedInOneLine) {
    const std::string deep = std::string(100000, '[') + std::string(100000, ']');
    std::string with_nul = "/* fgr-scene {\"id\": \"x\", \"name\": \"X\"} */\nreal";
    with_nul += '\0';
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"/* fgr-scene {\"id\": \"x\", \"name\": \"X\"}\n", "header: the comment is not closed"},
        {"/* fgr-scene */\n", "header: no JSON object after fgr-scene"},
        {"/* fgr-scene [1, 2] */", "header: must be a JSON object"},
        {"/* fgr-scene {\"id\": \"x\", \"name\": \"X\", \"scale\": 1e400} */",
         "header: not valid JSON: number overflow"},
        {"/* fgr-scene {\"id\": \"x\", \"name\": \"X\", \"d\": " + deep + "} */",
         "header: nested deeper than 16 levels"},
        {with_nul, "holds a NUL byte"},
        {"real scene_de(vec3 p, PARAMS);", "does not start with a text scene's header"},
        {"/* fgr-scene {\"id\": \"x\", \"name\": \"X\"} */\n#define FGR_KERNEL_API 99\n",
         "kernel API '99'"},
    };
    for (const auto& [text, expected] : cases) {
        const LoadResult loaded = parse_text_scene(text, "broken.cl");
        ASSERT_FALSE(loaded.scene) << text.substr(0, 80);
        EXPECT_NE(loaded.error.find(expected), std::string::npos) << loaded.error;
        EXPECT_EQ(loaded.error.find('\n'), std::string::npos) << loaded.error;
    }
}

TEST(TextScene, LoadingAFileBoundsItsSize) {
    const test::TempDir dir("fgr_text_scene");
    const fs::path big = dir.path() / "big.cl";
    test::write_text(big, text_scene(R"({"id": "big", "name": "Big"})") +
                              std::string(scene_limits::kMaxSourceBytes, ' '));
    const LoadResult loaded = load_text_scene(big);
    ASSERT_FALSE(loaded.scene);
    EXPECT_EQ(loaded.error.rfind("file too large (", 0), 0u) << loaded.error;
    EXPECT_NE(loaded.error.find("the limit is 4194304)"), std::string::npos) << loaded.error;
    const LoadResult missing = load_text_scene(dir.path() / "missing.cl");
    EXPECT_EQ(missing.error, "No such file or directory");
}

// --- Fuzzing the header --------------------------------------------------------------------------
//
// Each case starts from a valid text scene (the table's header, the SDK guide's example, the
// new-scene template) and mutates it: the header's text (bytes deleted, inserted, duplicated, cut
// short), its parsed value (a value swapped for a nasty one, a key removed or misspelt, an array
// grown, two values swapped), the whole file's text, deep nesting and huge numbers. Every case
// must give a scene or a one-line refusal, and never crash. Nothing is compiled.

constexpr uint64_t kTextFuzzSeed = 0x5465787446757a31;  // "TextFuz1"

// The header's JSON and what comes after it, of a text scene whose header is closed.
struct Split {
    std::string json;
    std::string rest;
};
Split split(const std::string& text) {
    const std::size_t begin = text.find("fgr-scene") + 9;
    const std::size_t end = text.find("*/", begin);
    return {text.substr(begin, end - begin), text.substr(end)};
}

void swap_two_values(json& document, test::FuzzRng& rng) {
    std::vector<json::json_pointer> pointers;
    if (!document.is_object()) return;
    for (const auto& item : document.items()) {
        const json::json_pointer at = json::json_pointer() / item.key();
        pointers.push_back(at);
        for (std::size_t i = 0; item.value().is_array() && i < item.value().size(); ++i) {
            pointers.push_back(at / i);
        }
    }
    if (pointers.size() < 2) return;
    const json::json_pointer a = pointers[rng.below(pointers.size())];
    const json::json_pointer b = pointers[rng.below(pointers.size())];
    if (a == b || a.to_string().starts_with(b.to_string()) ||
        b.to_string().starts_with(a.to_string())) {
        return;
    }
    std::swap(document[a], document[b]);
}

// Text no JSON library may hold as a tree: nesting up to 200000 deep (which anything that
// recurses over a value, such as printing it in a message, could not survive), numbers past
// double's range.
std::string pathological(test::FuzzRng& rng) {
    const std::size_t depth = rng.chance(0.5) ? 1 + rng.below(40) : 1 + rng.below(200000);
    switch (rng.below(5)) {
        case 0:
            return std::string(depth, '[');  // never closed
        case 1:
            return "1e" + std::to_string(300 + rng.below(400));
        case 2:
            return "-" + std::string(1 + rng.below(500), '9');
        case 3: {
            std::string nested;
            for (std::size_t i = 0; i < depth; ++i) nested += "{\"a\":";
            return nested + "0" + std::string(depth, '}');
        }
        default:
            return std::string(depth, '[') + "\"x\"" + std::string(depth, ']');
    }
}

// The pathological text in place of a random value of the header (or anywhere in its text when
// it is not JSON).
void insert_pathological(std::string& text, test::FuzzRng& rng) {
    json document = json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (document.is_discarded() || rng.chance(0.2)) {
        text.insert(text.empty() ? 0 : rng.below(text.size()), pathological(rng));
        return;
    }
    std::vector<json::json_pointer> pointers;
    const auto collect = [&](const auto& self, const json& value,
                             const json::json_pointer& at) -> void {
        pointers.push_back(at);
        if (value.is_object()) {
            for (const auto& item : value.items()) self(self, item.value(), at / item.key());
        } else if (value.is_array()) {
            for (std::size_t i = 0; i < value.size(); ++i) self(self, value[i], at / i);
        }
    };
    collect(collect, document, json::json_pointer());
    constexpr const char* kPlaceholder = "\"fgr-fuzz-placeholder\"";
    document[pointers[rng.below(pointers.size())]] = "fgr-fuzz-placeholder";
    text = document.dump(-1, ' ', false, json::error_handler_t::replace);
    text.replace(text.find(kPlaceholder), std::string_view(kPlaceholder).size(), pathological(rng));
}

TEST(FuzzTextSceneHeader, EveryMutatedHeaderGivesASceneOrOneLine) {
    std::vector<std::string> seeds = {
        text_scene(full_header().dump(1)), test::sdk_guide_text_scene_example(),
        fill_template(test::read_file(test::kSdkDir / "template" / "text_scene.cl"),
                      {{"SCENE_ID", "fuzz"}, {"SCENE_NAME", "Fuzz"}})};
    for (const std::string& seed : seeds) {
        const LoadResult loaded = parse_text_scene(seed, "fuzz.cl");
        ASSERT_TRUE(loaded.scene) << "a seed is refused: " << loaded.error;
    }
    const uint64_t base = test::fuzz_base_seed(kTextFuzzSeed);
    const uint64_t cases = test::fuzz_case_count();
    int accepted = 0;
    for (uint64_t i = 0; i < cases; ++i) {
        const uint64_t case_seed = base + i;
        test::FuzzRng rng(case_seed);
        Split parts = split(seeds[rng.below(seeds.size())]);
        const std::size_t mutations = 1 + rng.below(3);
        for (std::size_t m = 0; m < mutations; ++m) {
            json document = json::parse(parts.json, nullptr, /*allow_exceptions=*/false);
            if (rng.chance(0.3) || document.is_discarded()) {
                test::mutate_text(parts.json, rng);
                continue;
            }
            if (rng.chance(0.2)) {
                swap_two_values(document, rng);
            } else {
                test::mutate_value(document, rng);
            }
            parts.json =
                document.dump(rng.chance(0.5) ? 1 : -1, ' ', false, json::error_handler_t::replace);
        }
        // Last, as the parse above must never see it: nesting and numbers no tree can hold, keys
        // given twice, NUL bytes.
        if (rng.chance(0.15)) insert_pathological(parts.json, rng);
        if (rng.chance(0.1)) test::mutate_structure(parts.json, rng);
        std::string text = "/* fgr-scene\n" + parts.json + parts.rest;
        if (rng.chance(0.05)) test::mutate_text(text, rng);  // the comment's own markers too
        const LoadResult loaded = parse_text_scene(text, "fuzz.cl");
        if (loaded.scene) {
            ++accepted;
            ASSERT_FALSE(loaded.scene->cameras.empty()) << "case " << case_seed;
            ASSERT_FALSE(loaded.scene->lights.empty()) << "case " << case_seed;
            ASSERT_EQ(loaded.scene->source, text) << "case " << case_seed;
        } else {
            ASSERT_FALSE(loaded.error.empty()) << "case " << case_seed;
            ASSERT_EQ(loaded.error.find('\n'), std::string::npos)
                << "case " << case_seed << ": " << loaded.error;
            ASSERT_LT(loaded.error.size(), 500u) << "case " << case_seed << ": " << loaded.error;
        }
    }
    // Both outcomes are exercised, not just refusals.
    if (cases >= 1000) {
        EXPECT_GT(accepted, static_cast<int>(cases / 20));
        EXPECT_LT(accepted, static_cast<int>(cases * 19 / 20));
    }
}

// --- Discovery, the scene index and scene arguments ----------------------------------------------

// A plugin folder with a text scene, a .cl file without the header (an include file: no scene,
// no warning) and a text scene whose header is broken (skipped, with its reason).
struct TextSceneFolder {
    test::TempDir root{"fgr_text_scenes"};
    fs::path folder = root.path() / "plugins";
    fs::path good = folder / "good.cl";
    fs::path include = folder / "helpers.cl";
    fs::path broken = folder / "broken.cl";
    TextSceneFolder() {
        fs::create_directories(folder);
        test::write_text(good, text_scene(R"({"id": "good-text", "name": "Good"})"));
        test::write_text(include, "inline real helper(real x) { return x; }\n");
        test::write_text(broken, text_scene(R"({"id": "broken-text", "name": 7})"));
    }
};

TEST(TextSceneDiscovery, FindsTextScenesIgnoresOtherClFilesAndSkipsBrokenOnes) {
    const TextSceneFolder dirs;
    EXPECT_TRUE(is_scene_file(dirs.good));
    EXPECT_FALSE(is_scene_file(dirs.include));
    const Discovery found = discover_scenes({dirs.folder});
    ASSERT_EQ(found.scenes.size(), 1u);
    EXPECT_EQ(found.scenes[0].id, "good-text");
    EXPECT_EQ(found.scenes[0].plugin_file, dirs.good);
    ASSERT_EQ(found.skipped.size(), 1u);
    EXPECT_EQ(found.skipped[0].file, dirs.broken);
    EXPECT_EQ(found.skipped[0].reason, R"(header "name": must be a string)");
    // `fgr render broken-text` says which file that was and why.
    EXPECT_EQ(unknown_scene_message(found, "broken-text"),
              "unknown scene 'broken-text': plugin " + dirs.broken.string() +
                  R"( was refused: header "name": must be a string)");
}

TEST(TextSceneDiscovery, TheSceneIndexFindsATextScene) {
    const TextSceneFolder dirs;
    const fs::path index = dirs.root.path() / "cache" / kSceneIndexName;
    for (int run = 0; run < 2; ++run) {  // building the index, then through it
        const Discovery found = discover_scene({dirs.folder}, "good-text", index);
        ASSERT_EQ(found.scenes.size(), 1u) << run;
        EXPECT_EQ(found.scenes[0].plugin_file, dirs.good);
    }
    const std::optional<FileStamp> stamp = file_stamp(dirs.good);
    ASSERT_TRUE(stamp);
    EXPECT_EQ(SceneIndex::read(index).id_of(dirs.good, *stamp), "good-text");
    EXPECT_FALSE(SceneIndex::read(index).id_of(dirs.include, *file_stamp(dirs.include)));
}

TEST(SceneArgument, PathsAreToldFromIdsAndTheirKindByName) {
    const TextSceneFolder dirs;
    EXPECT_EQ(scene_argument_kind("mandelbulb"), SceneArgumentKind::Id);
    EXPECT_EQ(scene_argument_kind(""), SceneArgumentKind::Id);
    EXPECT_EQ(scene_argument_kind("x.so"), SceneArgumentKind::PluginFile);
    EXPECT_EQ(scene_argument_kind("a/x.ifs.json"), SceneArgumentKind::IfsFile);
    EXPECT_EQ(scene_argument_kind("x.formula.json"), SceneArgumentKind::FormulaFile);
    EXPECT_EQ(scene_argument_kind("x.cl"), SceneArgumentKind::TextFile);
    // An existing file without a scene file's suffix: its first bytes say.
    const fs::path renamed = dirs.root.path() / "good-scene";
    fs::copy_file(dirs.good, renamed);
    EXPECT_EQ(scene_argument_kind(renamed.string()), SceneArgumentKind::TextFile);
    const fs::path other = dirs.root.path() / "notes.txt";
    test::write_text(other, "notes");
    for (const fs::path& path : {other, dirs.root.path() / "missing" / "scene"}) {
        try {
            scene_argument_kind(path.string());
            ADD_FAILURE() << path << " was taken for a scene";
        } catch (const UsageError& error) {
            EXPECT_EQ(std::string(error.what()).rfind(path.string() + ": ", 0), 0u) << error.what();
        }
    }
}

TEST(SceneArgument, AFileByPathIsLoadedAloneAndRefusedNamingIt) {
    const TextSceneFolder dirs;
    // No folder is searched: the broken file beside it is never read.
    const Scene scene = find_scene_argument(dirs.good.string(), {dirs.folder}, {});
    EXPECT_EQ(scene.id, "good-text");
    try {
        find_scene_argument(dirs.broken.string(), {}, {});
        ADD_FAILURE() << "the broken file was accepted";
    } catch (const UsageError& error) {
        EXPECT_EQ(std::string(error.what()),
                  dirs.broken.string() + R"(: header "name": must be a string)");
    }
    try {
        find_scene_argument(dirs.include.string(), {}, {});
        ADD_FAILURE() << "a .cl without the header was accepted";
    } catch (const UsageError& error) {
        EXPECT_NE(std::string(error.what()).find("does not start with a text scene's header"),
                  std::string::npos)
            << error.what();
    }
    // By id, through discovery.
    EXPECT_EQ(find_scene_argument("good-text", {dirs.folder}, {}).plugin_file, dirs.good);
}

// The guide's example and the new-scene template load as they are (test_cli.cpp renders them).
TEST(TextScene, TheGuidesExampleAndTheTemplateLoad) {
    const LoadResult example = parse_text_scene(test::sdk_guide_text_scene_example(), "my-bulb.cl");
    ASSERT_TRUE(example.scene) << example.error;
    EXPECT_EQ(example.scene->id, "my-bulb");
    const test::TempDir dir("fgr_text_template");
    const fs::path file = scaffold_text_scene("my-scene", dir.path());
    EXPECT_EQ(file, dir.path() / "my-scene.cl");
    const LoadResult scaffolded = load_text_scene(file);
    ASSERT_TRUE(scaffolded.scene) << scaffolded.error;
    EXPECT_EQ(scaffolded.scene->name, "My Scene");
    EXPECT_THROW(scaffold_text_scene("my-scene", dir.path()), UsageError) << "overwrote it";
    EXPECT_THROW(scaffold_text_scene("My Scene", dir.path()), UsageError);
}

}  // namespace
}  // namespace fgr
