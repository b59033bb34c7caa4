// SPDX-License-Identifier: Apache-2.0
// View files: the text round trip keeps every value exactly, every bad key is one line naming it,
// parameters read back through --set to the same float bits, and mutated files never crash the
// reader.

#include <gtest/gtest.h>
#include <unistd.h>

#include <bit>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "fuzz_rng.hpp"
#include "json_mutation.hpp"
#include "scene/parameters.hpp"
#include "test_scenes.hpp"
#include "view_file/view_file.hpp"

namespace fgr {
namespace {

using nlohmann::json;

ViewFile example_view() {
    ViewFile view;
    view.scene_id = "mandelbulb";
    view.scene_fingerprint = "0123456789abcdef";
    view.fgr_version = "0.1.0";
    view.width = 320;
    view.height = 200;
    view.bit_depth = 16;
    view.alpha = true;
    view.layers = "albedo,depth";
    view.camera.position = {0.1234567890123456789, -2.718281828459045, 1e-7};
    view.camera.target = {1.0 / 3.0, 0.0, -0.5};
    view.camera.up = {0.0f, 0.1f, 1.0f};
    view.camera.fov_degrees = 33.3f;
    view.projection.kind = ProjectionKind::StereoSideBySide;
    view.projection.eye_separation = 0.0625;
    view.projection.convergence = 2.5;
    // In the order a file reads back: by id.
    view.parameters = {{"colour_mode", ViewParameter::Kind::Choice, "iterations"},
                       {"power", ViewParameter::Kind::Number, "7.25"},
                       {"shadows_on", ViewParameter::Kind::Bool, "true"},
                       {"tint", ViewParameter::Kind::Vector, "0.1,0.2,0.3"}};
    view.mode = RenderMode::Path;
    view.samples = 12;
    view.effects = {"shadows", "fog"};
    view.precision = Precision::Double;
    view.prepass = false;
    ViewPathChoices path;
    path.seed = 7;
    path.bounces = 3;
    path.environment = "uniform:0.5";
    path.environment_intensity = 0.75f;
    path.turbidity = 4.5f;
    view.path = path;
    return view;
}

TEST(ViewFile, TextRoundTripKeepsEveryValue) {
    const ViewFile view = example_view();
    EXPECT_EQ(view_file_text(parse_view_file(view_file_text(view))), view_file_text(view));
    EXPECT_EQ(parse_view_file(view_file_text(view)), view);
    ViewFile plain;
    plain.scene_id = "menger";
    plain.camera.position = {0.0, -3.0, 0.0};
    EXPECT_EQ(parse_view_file(view_file_text(plain)), plain);
}

TEST(ViewFile, DoublesOfTheCameraRoundTripBitForBit) {
    test::FuzzRng rng(11);
    for (int i = 0; i < 1000; ++i) {
        ViewFile view = example_view();
        const auto random_double = [&] {
            return std::bit_cast<double>((rng.next() & 0x3fffffffffffffffull) |
                                         0x3ff0000000000000ull) -
                   1.5;
        };
        view.camera.position = {random_double(), random_double(), random_double()};
        view.camera.target = view.camera.position + glm::dvec3(0.5, random_double(), 0.25);
        const ViewFile back = parse_view_file(view_file_text(view));
        ASSERT_EQ(back.camera.position, view.camera.position) << i;
        ASSERT_EQ(back.camera.target, view.camera.target) << i;
    }
}

// A scene's changed parameters, written and read back through --set's parser, are the same float
// bits: a view renders the same pixels.
TEST(ViewFile, ParametersReadBackToTheSameFloatBits) {
    const Scene scene = test::built_scene("mandelbulb.so");
    test::FuzzRng rng(5);
    for (int i = 0; i < 200; ++i) {
        std::vector<float> values = default_param_values(scene);
        const std::vector<int> offsets = param_offsets(scene);
        for (std::size_t p = 0; p < scene.params.size(); ++p) {
            const ParamInfo& param = scene.params[p];
            if (param.type != ParamType::Float || !rng.chance(0.5)) continue;
            values[static_cast<std::size_t>(offsets[p])] =
                rng.uniform(param.min_value, param.max_value);
        }
        ViewFile view = example_view();
        view.parameters = changed_parameters(scene, values);
        const ViewFile back = parse_view_file(view_file_text(view));
        std::vector<float> again = default_param_values(scene);
        for (const ViewParameter& parameter : back.parameters) {
            set_param_from_text(scene, again, parameter_assignment(parameter));
        }
        for (std::size_t v = 0; v < values.size(); ++v) {
            ASSERT_EQ(std::bit_cast<uint32_t>(again[v]), std::bit_cast<uint32_t>(values[v]))
                << "value " << v << " of case " << i;
        }
    }
}

TEST(ViewFile, OnlyChangedParametersAreKept) {
    const Scene scene = test::built_scene("mandelbulb.so");
    std::vector<float> values = default_param_values(scene);
    EXPECT_TRUE(changed_parameters(scene, values).empty());
    set_param_from_text(scene, values, "power=5.5");
    const std::vector<ViewParameter> changed = changed_parameters(scene, values);
    ASSERT_EQ(changed.size(), 1u);
    EXPECT_EQ(parameter_assignment(changed[0]), "power=5.5");
}

TEST(ViewFile, FingerprintFollowsWhatDecidesPixels) {
    Scene scene = test::built_scene("mandelbulb.so");
    const std::string before = scene_fingerprint(scene);
    EXPECT_EQ(scene_fingerprint(scene), before);
    Scene renamed = scene;
    renamed.name = "Another name";
    renamed.description = "another description";
    EXPECT_EQ(scene_fingerprint(renamed), before) << "names do not change pixels";
    Scene edited = scene;
    edited.source += "\n// an edit\n";
    EXPECT_NE(scene_fingerprint(edited), before);
    Scene new_default = scene;
    new_default.params[0].default_value[0] += 0.5f;
    EXPECT_NE(scene_fingerprint(new_default), before);

    ViewFile view = example_view();
    view.scene_fingerprint = before;
    EXPECT_EQ(scene_change_warning(view, scene), "");
    EXPECT_NE(scene_change_warning(view, edited).find("changed since this view was saved"),
              std::string::npos);
}

// The path tracer's choices of a render as a view holds them, and back: the settings, and the
// environment with the sky's own settings only where they are not the defaults.
TEST(ViewFile, PathChoicesReadBackToTheSameSettingsAndEnvironment) {
    PathSettings settings;
    settings.max_bounces = 3;
    settings.roulette_depth = 1;
    settings.radiance_clamp = 2.5f;
    settings.light_sampling = false;
    settings.mis = false;
    settings.scene_lights = false;
    settings.seed = 11;
    EnvironmentChoice sky;
    sky.rotation_degrees = -45.0f;
    sky.intensity = 0.3f;
    const ViewPathChoices plain = path_choices_of(settings, sky);
    EXPECT_EQ(plain.environment, "sky");
    EXPECT_FALSE(plain.turbidity || plain.sun_elevation || plain.sun_azimuth)
        << "the defaults are not written";
    EXPECT_EQ(path_settings_of(plain), settings);
    sky.sky.turbidity = 6.0f;
    sky.sun_from_scene = false;
    sky.sky.sun_elevation_degrees = 12.5f;
    EnvironmentChoice studio;
    studio.kind = EnvironmentKind::Studio;
    studio.sky.turbidity = 9.0f;  // not the studio's: not written
    for (const EnvironmentChoice& choice : {sky, studio}) {
        const ViewPathChoices path = path_choices_of(settings, choice);
        const EnvironmentChoice back = environment_choice_of(path);
        EXPECT_EQ(back.kind, choice.kind);
        EXPECT_EQ(back.rotation_degrees, choice.rotation_degrees);
        EXPECT_EQ(back.intensity, choice.intensity);
        EXPECT_EQ(back.sun_from_scene, choice.sun_from_scene);
        if (choice.kind == EnvironmentKind::Sky) {
            EXPECT_EQ(back.sky.turbidity, choice.sky.turbidity);
            EXPECT_EQ(back.sky.sun_elevation_degrees, choice.sky.sun_elevation_degrees);
            EXPECT_EQ(back.sky.sun_azimuth_degrees, choice.sky.sun_azimuth_degrees);
        }
    }
    ViewPathChoices hazy_studio = path_choices_of(settings, studio);
    hazy_studio.turbidity = 4.0f;
    EXPECT_THROW(environment_choice_of(hazy_studio), std::invalid_argument);
    ViewPathChoices no_bounces = plain;
    no_bounces.bounces = -1;
    EXPECT_THROW(path_settings_of(no_bounces), std::invalid_argument);
}

struct BadView {
    const char* name;
    const char* pointer;  // JSON pointer of the value replaced ("" for the whole document)
    json value;           // replacement; null with remove set: the key removed
    bool remove;
    const char* mention;  // what the one-line reason must say
};

void PrintTo(const BadView& bad, std::ostream* os) { *os << bad.name; }

const BadView kBadViews[] = {
    {"WrongFormat", "/format", "fgr-camera-path", false, "\"format\""},
    {"WrongVersion", "/version", 2, false, "version"},
    {"MissingScene", "/scene", nullptr, true, "\"scene\" is missing"},
    {"BadSceneId", "/scene/id", "Not An Id", false, "\"scene.id\""},
    {"BadFingerprint", "/scene/fingerprint", "xyz", false, "\"scene.fingerprint\""},
    {"UnknownTopKey", "/colour", 1, false, "unknown key \"colour\""},
    {"UnknownCameraKey", "/camera/zoom", 2, false, "unknown key \"zoom\""},
    {"MissingCamera", "/camera", nullptr, true, "\"camera\" is missing"},
    {"MissingEye", "/camera/eye", nullptr, true, "\"camera.eye\""},
    {"EyeNotVector", "/camera/eye", json::array({1, 2}), false, "\"camera.eye\""},
    {"EyeNotFinite", "/camera/eye", json::array({1e300, 0, 0}), false, "\"camera.eye\""},
    {"FovTooWide", "/camera/fov", 180, false, "\"camera.fov\""},
    {"FovText", "/camera/fov", "wide", false, "\"camera.fov\""},
    {"EyeAtTarget", "/camera/target",
     json::array({0.1234567890123456789, -2.718281828459045, 1e-7}), false, "\"camera\""},
    {"BadProjection", "/camera/projection", "cylindrical", false, "\"camera.projection\""},
    {"ZeroWidth", "/image/width", 0, false, "\"image.width\""},
    {"HugeHeight", "/image/height", 1e12, false, "\"image.height\""},
    {"FractionalWidth", "/image/width", 10.5, false, "\"image.width\""},
    {"BitDepth12", "/image/bit_depth", 12, false, "\"image.bit_depth\""},
    {"AlphaText", "/image/alpha", "yes", false, "\"image.alpha\""},
    {"UnknownMode", "/render/mode", "raster", false, "\"render.mode\""},
    {"ZeroSamples", "/render/samples", 0, false, "\"render.samples\""},
    {"UnknownEffect", "/render/effects", json::array({"shadows", "bloom"}), false,
     "\"render.effects\""},
    {"EffectsNotArray", "/render/effects", "shadows", false, "\"render.effects\""},
    {"BadPrecision", "/render/precision", "half", false, "\"render.precision\""},
    {"ParameterObject", "/parameters/power", json::object(), false, "\"parameters.power\""},
    {"ParameterBadId", "/parameters/Power!", 1, false, "\"parameters\""},
    {"ParameterNotFinite", "/parameters/power", json::array({1, 2, 1e300}), false,
     "\"parameters.power\""},
    {"NegativeBounces", "/path/bounces", -1, false, "\"path.bounces\""},
    {"SeedTooLarge", "/path/seed", 4294967296ll, false, "\"path.seed\""},
    {"TurbidityOutOfRange", "/path/turbidity", 50, false, "\"path.turbidity\""},
    {"EnvironmentControl", "/path/environment", "sky\n", false, "\"path.environment\""},
    {"UnknownPathKey", "/path/spp", 4, false, "unknown key \"spp\""},
};

class ViewFileBad : public ::testing::TestWithParam<BadView> {};

TEST_P(ViewFileBad, IsRefusedWithOneLineNamingTheKey) {
    const BadView& bad = GetParam();
    json document = json::parse(view_file_text(example_view()));
    const json::json_pointer pointer(bad.pointer);
    if (bad.remove) {
        document[pointer.parent_pointer()].erase(pointer.back());
    } else {
        document[pointer] = bad.value;
    }
    try {
        parse_view_file(document.dump());
        FAIL() << "accepted: " << document.dump();
    } catch (const std::runtime_error& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find(bad.mention), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

INSTANTIATE_TEST_SUITE_P(ViewFile, ViewFileBad, ::testing::ValuesIn(kBadViews),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

TEST(ViewFile, DeepNestingIsRefusedBeforeParsing) {
    const std::string deep = std::string(100000, '[') + std::string(100000, ']');
    json document = json::parse(view_file_text(example_view()));
    std::string text = document.dump();
    text.insert(text.find("\"scene\""), "\"deep\": " + deep + ", ");
    try {
        parse_view_file(text);
        FAIL() << "accepted";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find("nested"), std::string::npos) << error.what();
    }
}

// 10^4 seeded mutations (FGR_FUZZ_CASES, FGR_FUZZ_SEED; a failure prints its seed) of a valid
// file: of its text, its structure and its values. Each is read or refused with one short line,
// never a crash or an exception of another kind; what is read writes back to the same view.
TEST(FuzzViewFile, SeededCasesAreReadOrRefusedWithOneLine) {
    const std::string valid = view_file_text(example_view());
    const uint64_t base = test::fuzz_base_seed(0x5669657746696c65);  // "ViewFile"
    const uint64_t cases = test::fuzz_case_count();
    uint64_t refused = 0;
    for (uint64_t i = 0; i < cases; ++i) {
        const uint64_t seed = base + i;
        test::FuzzRng rng(seed);
        std::string text = valid;
        test::mutate_document(text, rng, rng.range(1, 3));
        try {
            const ViewFile view = parse_view_file(text);
            ASSERT_EQ(parse_view_file(view_file_text(view)), view) << "seed " << seed;
        } catch (const std::runtime_error& error) {
            ++refused;
            const std::string message = error.what();
            ASSERT_FALSE(message.empty()) << "seed " << seed;
            ASSERT_EQ(message.find('\n'), std::string::npos) << "seed " << seed << ": " << message;
            ASSERT_LT(message.size(), 500u) << "seed " << seed << ": " << message;
        }
    }
    if (cases >= 1000) {
        EXPECT_GT(refused, cases / 10) << "the mutations should break most files";
    }
}

TEST(ViewFile, FilesAreWrittenAndReadBackAndOnlyRegularFilesAreRead) {
    const std::filesystem::path directory =
        std::filesystem::temp_directory_path() / ("fgr_view_file_" + std::to_string(getpid()));
    std::filesystem::create_directories(directory);
    const std::filesystem::path file = directory / "a.fgrview.json";
    write_view_file(file, example_view());
    EXPECT_EQ(read_view_file(file), example_view());
    EXPECT_TRUE(is_view_file_name(file));
    EXPECT_FALSE(is_view_file_name(directory / "a.json"));
    EXPECT_FALSE(is_view_file_name(directory / ".fgrview.json"));
    try {
        read_view_file(directory);
        FAIL() << "a directory was read";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find(directory.string()), std::string::npos);
    }
    std::filesystem::remove_all(directory);
}

}  // namespace
}  // namespace fgr
