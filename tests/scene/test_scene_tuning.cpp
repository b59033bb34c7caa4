// SPDX-License-Identifier: Apache-2.0
// What a scene tunes beyond fgr's defaults (ABI 1.4): its own defaults for built-in parameters
// (rendered with, shown as its own), its length scale (the distance-like built-ins' defaults follow
// it) and the colour modes it offers (the others refused in one line and not listed).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"
#include "fgr/plugin.h"
#include "fgr/scene_helpers.h"
#include "render/renderer.hpp"
#include "scene/description_validation.hpp"
#include "scene/ifs/ifs.hpp"
#include "scene/parameters.hpp"
#include "scene/scene.hpp"
#include "test_scenes.hpp"

namespace fgr {
namespace {

// A small-scale scene: a ball 0.05 in radius resting on the floor z = 0, seen from 0.3 away. With
// sampled occlusion the floor around the ball darkens over about ao_radius: fgr's 0.1 is twice
// the ball, which is what "ao_radius 0.1 darkens a small-scale scene entirely" means.
struct SmallScene {
    explicit SmallScene(std::vector<fgr_builtin_default> given = {}, float scale = 0.0f)
        : defaults(std::move(given)) {
        desc = FGR_SCENE_TUNED("small-ball", "Small ball", "a ball 0.05 in radius on a floor",
                               kSource, "small_ball.cl", params, cameras, paths, lights,
                               FGR_EFFECT_SAMPLED_OCCLUSION, FGR_MARCH(256u, 4.0f, 1.0f, 1u, 1.0f),
                               nullptr, defaults.empty() ? nullptr : defaults.data(),
                               static_cast<uint32_t>(defaults.size()), 0u, scale);
        desc.camera_paths = nullptr;  // FGR_COUNT needs an array; the scene has no paths
        desc.camera_path_count = 0;
    }
    Scene load() const {
        LoadResult loaded = copy_scene_description(&desc);
        if (!loaded.scene) throw std::runtime_error(loaded.error);
        return std::move(*loaded.scene);
    }

    static constexpr char kSource[] =
        "real scene_de(vec3 p, PARAMS) {\n"
        "    (void)fgr_params;\n"
        "    return fmin(v3_length(v3_sub(p, v3_splat(0.0f, 0.0f, 0.05f))) - 0.05f, p.z);\n"
        "}\n";
    const fgr_param_desc params[1] = {
        FGR_FLOAT_PARAM("unused", "Unused", "Shape", 0.0f, 1.0f, 0.5f, "nothing reads it")};
    const fgr_camera cameras[1] = {
        FGR_CAMERA_Z_UP("front", 0.0f, -0.3f, 0.15f, 0.0f, 0.0f, 0.03f, 50.0f)};
    const fgr_camera_path paths[1] = {};
    // Intensity 0: the image is the ambient term alone, which the occlusion scales.
    const fgr_light lights[1] = {FGR_DIRECTIONAL_LIGHT(0.3f, -0.5f, 1.0f, 1.0f, 1.0f, 1.0f, 0.0f)};
    std::vector<fgr_builtin_default> defaults;
    fgr_scene_desc desc{};
};

Frame render(const Scene& scene, const std::vector<float>& params) {
    static const ComputeDevice device = open_device(-1);
    ProgramCache cache{std::filesystem::path()};
    Renderer renderer(device, cache, scene, {preferred_packet_width(device.info), scene.effects});
    FrameRequest request;
    request.width = 64;
    request.height = 48;
    request.view = scene.cameras.front().view;
    request.params = params;
    return renderer.render(request);
}

double mean_byte(const Frame& frame) {
    double sum = 0.0;
    for (const uint8_t value : frame.image.rgb) sum += value;
    return sum / double(std::max<std::size_t>(frame.image.rgb.size(), 1));
}

double mean_abs_difference(const Frame& a, const Frame& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.image.rgb.size() && i < b.image.rgb.size(); ++i) {
        sum += std::abs(double(a.image.rgb[i]) - double(b.image.rgb[i]));
    }
    return sum / double(std::max<std::size_t>(a.image.rgb.size(), 1));
}

TEST(SceneTuning, ASceneAoRadiusDefaultIsTheOneItRendersWith) {
    const Scene tuned = SmallScene({FGR_BUILTIN_DEFAULT("ao_radius", 0.01f)}).load();
    const Scene plain = SmallScene().load();
    ASSERT_NE(tuned.find_param("ao_radius"), nullptr);
    EXPECT_FLOAT_EQ(tuned.find_param("ao_radius")->default_value[0], 0.01f);
    EXPECT_TRUE(tuned.find_param("ao_radius")->scene_default);
    EXPECT_FLOAT_EQ(plain.find_param("ao_radius")->default_value[0], 0.1f);
    EXPECT_FALSE(plain.find_param("ao_radius")->scene_default);

    // The tuned scene's defaults render exactly as the plain scene with ao_radius=0.01 set ...
    const Frame with_scene_default = render(tuned, default_param_values(tuned));
    std::vector<float> set_by_hand = default_param_values(plain);
    set_param_from_text(plain, set_by_hand, "ao_radius=0.01");
    EXPECT_EQ(with_scene_default.image.rgb, render(plain, set_by_hand).image.rgb);
    // ... and not as fgr's global default, whose probes reach twice the ball's size and darken
    // the floor round it: the same geometry, darker (the light has intensity 0, so the image is
    // the occluded ambient term alone; measured: mean byte 41.6 against 52.2, a mean difference
    // of 10.6 per byte; 8 and 5 leave room for other devices' rounding).
    const Frame with_global_default = render(plain, default_param_values(plain));
    EXPECT_GT(with_scene_default.hits, 64 * 48 / 2);
    EXPECT_EQ(with_global_default.hits, with_scene_default.hits) << "the same geometry";
    EXPECT_GT(mean_abs_difference(with_global_default, with_scene_default), 8.0);
    EXPECT_LT(mean_byte(with_global_default), mean_byte(with_scene_default) - 5.0)
        << "fgr's ao_radius darkens the small scene";
}

TEST(SceneTuning, ScaleMovesTheDistanceLikeDefaultsAndNothingElse) {
    const Scene unit = SmallScene().load();
    const Scene small = SmallScene({}, 0.01f).load();
    EXPECT_FLOAT_EQ(small.scale, 0.01f);
    EXPECT_FLOAT_EQ(unit.scale, 1.0f);
    // Lengths scale with it, rates per unit length inversely.
    EXPECT_FLOAT_EQ(small.find_param("ao_radius")->default_value[0], 0.001f);
    EXPECT_FLOAT_EQ(small.find_param("glow_radius")->default_value[0], 0.0005f);
    EXPECT_FLOAT_EQ(small.find_param("aperture")->default_value[0], 0.0005f);
    EXPECT_FLOAT_EQ(small.find_param("fog_density")->default_value[0], 15.0f);
    EXPECT_FLOAT_EQ(small.find_param("absorption")->default_value[0], 100.0f);
    for (const ParamInfo& param : unit.params) {
        if (param.id == "ao_radius" || param.id == "glow_radius" || param.id == "aperture" ||
            param.id == "fog_density" || param.id == "absorption") {
            continue;
        }
        EXPECT_EQ(small.find_param(param.id)->default_value, param.default_value) << param.id;
    }
    // A scene default overrides the scaled one; a huge scale is clamped to the ranges.
    const Scene both = SmallScene({FGR_BUILTIN_DEFAULT("ao_radius", 0.004f)}, 0.01f).load();
    EXPECT_FLOAT_EQ(both.find_param("ao_radius")->default_value[0], 0.004f);
    const Scene huge = SmallScene({}, 1e6f).load();
    EXPECT_FLOAT_EQ(huge.find_param("ao_radius")->default_value[0],
                    huge.find_param("ao_radius")->max_value);
}

// --- Colour modes --------------------------------------------------------------------------------

const ParamInfo& colour_mode_of(const Scene& scene) {
    const ParamInfo* param = scene.find_param("colour_mode");
    if (param == nullptr) throw std::runtime_error(scene.id + " has no colour_mode");
    return *param;
}

// The in-tree KIFS scenes leave out "iterations" (every point reaches the last iteration, so it
// is one flat colour); escape-time fractals keep it.
TEST(SceneTuning, KifsScenesDoNotOfferIterations) {
    for (const char* file : {"menger.so", "sierpinski.so"}) {
        const Scene scene = test::built_scene(file);
        EXPECT_EQ(offered_choices_text(colour_mode_of(scene)), "point|planes|axes") << file;
        std::vector<float> values = default_param_values(scene);
        try {
            set_param_from_text(scene, values, "colour_mode=iterations");
            ADD_FAILURE() << file << " accepted colour_mode=iterations";
        } catch (const UsageError& error) {
            EXPECT_EQ(
                std::string(error.what()),
                "scene '" + scene.id +
                    "' does not offer colour_mode 'iterations' (it offers point|planes|axes)");
        }
        // By number too: 3 is iterations.
        EXPECT_THROW(set_param_from_text(scene, values, "colour_mode=3"), UsageError) << file;
        set_param_from_text(scene, values, "colour_mode=axes");
        EXPECT_EQ(param_value(scene, values, "colour_mode"), 2.0f) << "numbers stay the kernel's";
    }
    for (const char* file : {"mandelbulb.so", "mandelbox.so"}) {
        const Scene scene = test::built_scene(file);
        EXPECT_TRUE(colour_mode_of(scene).offered.empty()) << file;
        EXPECT_EQ(offered_choices_text(colour_mode_of(scene)), "point|planes|axes|iterations");
        std::vector<float> values = default_param_values(scene);
        set_param_from_text(scene, values, "colour_mode=iterations");
        EXPECT_EQ(param_value(scene, values, "colour_mode"), 3.0f) << file;
    }
}

// The built-ins `fgr list SCENE` and the viewer's panel show: those some mode of the scene's kind
// reads. Pure host: no kernel is built.
std::vector<std::string> applying_builtins(const Scene& scene) {
    std::vector<std::string> ids;
    for (const ParamInfo& param : scene.params) {
        if (param.builtin && param_applies(scene, param)) ids.push_back(param.id);
    }
    return ids;
}

bool lists(const std::vector<std::string>& ids, const char* id) {
    return std::find(ids.begin(), ids.end(), id) != ids.end();
}

TEST(SceneTuning, EachKindOfSceneListsTheBuiltInsItsModesRead) {
    Scene de;
    de.source = "real scene_de(vec3 p, PARAMS) { return v3_length(p) - 1.0f; }\n";
    add_builtin_params(de);
    const std::vector<std::string> all = applying_builtins(de);
    EXPECT_EQ(all.size(), builtin_param_count()) << "a DE scene offers every mode";

    Scene ifs = de;
    ifs.ifs = std::make_shared<IfsScene>();
    const std::vector<std::string> traced = applying_builtins(ifs);
    for (const char* march : {"iterations", "step_factor", "over_relaxation", "normal_epsilon",
                              "brute_samples", "brute_solid"}) {
        EXPECT_FALSE(lists(traced, march)) << "an IFS scene lists " << march;
    }
    for (const char* read : {"max_steps", "max_distance", "hit_threshold", "exposure"}) {
        EXPECT_TRUE(lists(traced, read)) << "an IFS scene does not list " << read;
    }

    Scene inside = de;
    inside.source = "#define FGR_SCENE_INSIDE_ONLY\n" + de.source;
    const std::vector<std::string> brute = applying_builtins(inside);
    for (const char* march : {"max_steps", "step_factor", "over_relaxation", "normal_epsilon"}) {
        EXPECT_FALSE(lists(brute, march)) << "an inside-only scene lists " << march;
    }
    for (const char* read : {"iterations", "hit_threshold", "max_distance", "brute_samples"}) {
        EXPECT_TRUE(lists(brute, read)) << "an inside-only scene does not list " << read;
    }
    ParamInfo own;
    own.id = "step_factor_of_its_own";
    EXPECT_TRUE(param_applies(ifs, own)) << "a scene's own parameters always apply";
}

// A value a rebuilt scene no longer offers falls back to its default when the viewer reloads it.
TEST(SceneTuning, ReloadDropsAValueNoLongerOffered) {
    const Scene before = test::built_scene("mandelbulb.so");
    Scene after = before;
    std::vector<float> values = default_param_values(before);
    set_param_from_text(before, values, "colour_mode=iterations");
    for (ParamInfo& param : after.params) {
        if (param.id == "colour_mode") param.offered = {true, true, true, false};
    }
    const std::vector<float> carried = carry_param_values(before, values, after);
    EXPECT_EQ(param_value(after, carried, "colour_mode"), colour_mode_of(after).default_value[0]);
}

TEST(SceneTuning, FgrRenderRefusesAColourModeTheSceneDoesNotOfferInOneLine) {
    const test::TempDir dir("fgr_colour_modes");
    const test::RunResult refused =
        test::run_fgr({"render", "menger", "--colour", "iterations", "--width", "8", "--height",
                       "8", "-o", (dir.path() / "menger.png").string()},
                      dir.path());
    ASSERT_TRUE(refused.exited) << refused;
    EXPECT_EQ(refused.exit_code, 2) << refused;
    EXPECT_NE(refused.err.find("scene 'menger' does not offer colour_mode 'iterations' (it offers "
                               "point|planes|axes)"),
              std::string::npos)
        << refused;
    // Exactly one line on stderr (a trailing newline at most).
    const std::string err = refused.err.substr(0, refused.err.find_last_not_of('\n') + 1);
    EXPECT_EQ(err.find('\n'), std::string::npos) << "more than one line on stderr: " << refused;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "menger.png"));
}

TEST(SceneTuning, FgrListShowsOfferedColourModesOnly) {
    const test::TempDir dir("fgr_colour_modes_list");
    // `fgr list SCENE` starts at the scene's id; its colour_mode row follows.
    const auto colour_row = [&](const std::string& id) {
        const test::RunResult listed = test::run_fgr({"list", id}, dir.path());
        EXPECT_TRUE(listed.exited && listed.exit_code == 0) << listed;
        const std::string text = "\n" + listed.out;
        const std::size_t block = text.find("\n" + id + "  ");
        EXPECT_NE(block, std::string::npos) << id << " not listed";
        const std::size_t row = text.find("colour_mode", block);
        if (block == std::string::npos || row == std::string::npos) return std::string();
        return text.substr(row, text.find('\n', row) - row);
    };
    const std::string menger = colour_row("menger");
    EXPECT_NE(menger.find("point|planes|axes "), std::string::npos) << menger;
    EXPECT_EQ(menger.find("iterations"), std::string::npos) << menger;
    const std::string mandelbulb = colour_row("mandelbulb");
    EXPECT_NE(mandelbulb.find("point|planes|axes|iterations"), std::string::npos) << mandelbulb;
}

}  // namespace
}  // namespace fgr
