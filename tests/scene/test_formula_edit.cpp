// SPDX-License-Identifier: Apache-2.0
// The hybrid editor's edits of a formula scene's sequence (scene/formulas/formula_edit.hpp): what
// each edit does to the sequence, the settings that follow from it and the scene's parameters, what
// it refuses, and that the user's values travel with their slots.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scene/formulas/formula_edit.hpp"
#include "scene/formulas/formulas.hpp"
#include "scene/parameters.hpp"
#include "util/installed_files.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;

FormulaScene shipped_formula(const std::string& id) {
    return read_formula_file(fs::path(FGR_TEST_FORMULA_DIR) / (id + ".formula.json"));
}

const Formula& library(const std::string& name) {
    const Formula* formula = find_formula(name);
    EXPECT_NE(formula, nullptr) << name;
    return *formula;
}

std::vector<std::string> names(const FormulaScene& scene) {
    std::vector<std::string> result;
    for (const FormulaSlot& slot : scene.sequence) result.push_back(slot.formula->name);
    return result;
}

std::vector<std::string> param_ids(const Scene& scene) {
    std::vector<std::string> ids;
    for (const ParamInfo& param : scene.params) {
        if (!param.builtin) ids.push_back(param.id);
    }
    return ids;
}

TEST(FormulaEdit, AddingAFormulaMakesAHybridWithPrefixedParameters) {
    const FormulaScene bulb = shipped_formula("mandelbulb-formula");
    ASSERT_EQ(names(bulb), std::vector<std::string>{"mandelbulb"});
    const Formula& box = library("amazing_box");
    const FormulaScene hybrid = with_formula_added(bulb, box);
    EXPECT_EQ(names(hybrid), (std::vector<std::string>{"mandelbulb", "amazing_box"}));
    EXPECT_EQ(hybrid.sequence[1].repeat, 1);
    ASSERT_EQ(hybrid.sequence[1].values.size(), box.params.size());
    EXPECT_EQ(hybrid.sequence[1].values[0], box.params[0].default_value);
    EXPECT_EQ(hybrid.march.step_factor, std::min(bulb.march.step_factor, box.step_factor));
    EXPECT_EQ(hybrid.iterations, std::max(bulb.iterations, box.iterations));
    EXPECT_EQ(hybrid.distance, FormulaDistance::Logarithmic) << "the bulb's growth wins";
    const FormulaScene quaternion = shipped_formula("quaternion");
    const Formula& careful = library("mandelbulb");
    ASSERT_LT(careful.step_factor, quaternion.march.step_factor);
    EXPECT_EQ(with_formula_added(quaternion, careful).march.step_factor, careful.step_factor)
        << "the march is as careful as its most careful formula";

    const Scene scene = formula_scene_to_scene(hybrid, "edited.formula.json");
    const std::vector<std::string> ids = param_ids(scene);
    EXPECT_NE(std::find(ids.begin(), ids.end(), "f1_power"), ids.end());
    EXPECT_NE(std::find(ids.begin(), ids.end(), "f2_" + box.params[0].id), ids.end());
    EXPECT_EQ(std::find(ids.begin(), ids.end(), "power"), ids.end())
        << "a hybrid's parameters are all prefixed";
    EXPECT_NE(scene.source.find("formula_amazing_box("), std::string::npos);
}

TEST(FormulaEdit, MovingAndRepeatingReorderTheKernelsLoop) {
    const FormulaScene hybrid = shipped_formula("bulb-box");
    ASSERT_EQ(names(hybrid), (std::vector<std::string>{"mandelbulb", "amazing_box"}));
    const FormulaScene moved = with_slot_moved(hybrid, 1, -1);
    EXPECT_EQ(names(moved), (std::vector<std::string>{"amazing_box", "mandelbulb"}));
    EXPECT_EQ(names(with_slot_moved(moved, 0, 1)), names(hybrid));
    const std::string source = formula_kernel_source(moved);
    EXPECT_LT(source.find("formula_amazing_box(&z"), source.find("formula_mandelbulb(&z"))
        << "the box steps first now";

    const FormulaScene repeated = with_repeat(hybrid, 0, 3);
    EXPECT_EQ(repeated.sequence[0].repeat, 3);
    const std::string loop = formula_kernel_source(repeated);
    EXPECT_NE(loop.find("i % 4"), std::string::npos) << "three bulb steps and a box step";
    EXPECT_NE(loop.find("phase < 3"), std::string::npos);
}

TEST(FormulaEdit, RemovingASlotGivesBackTheSettingsOfTheRest) {
    const FormulaScene kifs = shipped_formula("menger-kifs");
    ASSERT_EQ(kifs.distance, FormulaDistance::Own);
    const FormulaScene hybrid = with_formula_added(kifs, library("amazing_box"));
    EXPECT_EQ(hybrid.distance, FormulaDistance::Linear)
        << "a formula's own distance is for it alone; in a hybrid the folds decide";
    const FormulaScene alone = with_slot_removed(hybrid, 1);
    EXPECT_EQ(names(alone), names(kifs));
    EXPECT_EQ(alone.distance, FormulaDistance::Own);
    EXPECT_EQ(alone.estimate, FormulaEstimate::Analytic);
    // A formula without an estimate makes the hybrid an inside test, and takes it away with it;
    // a bicomplex formula's own distance holds alone, not in a hybrid.
    const FormulaScene lambda =
        with_formula_added(shipped_formula("mandelbulb-formula"), library("lambdabulb"));
    EXPECT_EQ(lambda.estimate, FormulaEstimate::Inside);
    EXPECT_EQ(with_slot_removed(lambda, 1).estimate, FormulaEstimate::Analytic);
    const FormulaScene bicomplex =
        with_formula_added(shipped_formula("tetrabrot"), library("mandelbulb"));
    EXPECT_EQ(bicomplex.estimate, FormulaEstimate::Inside);
    const FormulaScene tetrabrot_alone = with_slot_removed(bicomplex, 1);
    EXPECT_EQ(tetrabrot_alone.distance, FormulaDistance::Own);
    EXPECT_EQ(tetrabrot_alone.estimate, FormulaEstimate::Analytic);

    const FormulaScene bulb = shipped_formula("mandelbulb-formula");
    const FormulaScene with_quaternion = with_formula_added(bulb, library("quaternion"));
    EXPECT_EQ(with_quaternion.max_bailout,
              std::min(bulb.max_bailout, library("quaternion").max_bailout));
    EXPECT_LE(with_quaternion.bailout, with_quaternion.max_bailout);
}

TEST(FormulaEdit, EditsBeyondTheLimitsAreRefusedInOneLine) {
    FormulaScene scene = shipped_formula("mandelbulb-formula");
    const auto refused = [](auto edit, const std::string& words) {
        try {
            edit();
        } catch (const FormulaEditError& error) {
            const std::string message = error.what();
            EXPECT_NE(message.find(words), std::string::npos) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
            return;
        }
        ADD_FAILURE() << "not refused: " << words;
    };
    refused([&] { with_slot_removed(scene, 0); }, "at least one formula");
    refused([&] { with_slot_removed(scene, 1); }, "no formula 2");
    refused([&] { with_slot_moved(scene, 0, -1); }, "cannot move");
    refused([&] { with_slot_moved(scene, 0, 1); }, "cannot move");
    refused([&] { with_repeat(scene, 0, 0); }, "outside [1, 64]");
    refused([&] { with_repeat(scene, 0, kFormulaMaxRepeat + 1); }, "outside [1, 64]");
    EXPECT_EQ(with_repeat(scene, 0, kFormulaMaxRepeat).sequence[0].repeat, kFormulaMaxRepeat);
    while (scene.sequence.size() < kFormulaMaxSlots) {
        scene = with_formula_added(scene, library("mandelbulb"));
    }
    refused([&] { with_formula_added(scene, library("mandelbulb")); }, "at most 16");
}

TEST(FormulaEdit, TheUsersValuesTravelWithTheirSlots) {
    const FormulaScene hybrid = shipped_formula("bulb-box");
    const Scene before = formula_scene_to_scene(hybrid, "bulb-box.formula.json");
    std::vector<float> values = default_param_values(before);
    set_param_from_text(before, values, "f1_power=5");
    set_param_from_text(before, values, "bailout=3.5");
    set_param_from_text(before, values, "max_steps=100");

    FormulaScene edited = hybrid;
    take_slot_values(edited, before, values);
    EXPECT_EQ(edited.sequence[0].values[0][0], 5.0f);
    edited = with_slot_moved(edited, 0, 1);  // the bulb is second now: f2_power
    const Scene after = formula_scene_to_scene(edited, "bulb-box.formula.json");
    const std::vector<float> carried = values_after_edit(before, values, after, edited);
    EXPECT_EQ(param_value(after, carried, "f2_power"), 5.0f);
    EXPECT_EQ(param_value(after, carried, "bailout"), 3.5f);
    EXPECT_EQ(param_value(after, carried, "max_steps"), 100.0f);
    const std::string box_param = "f1_" + library("amazing_box").params[0].id;
    EXPECT_EQ(param_value(after, carried, box_param), hybrid.sequence[1].values[0][0])
        << "the box's slot took the bulb's old place, not its values";
}

// Two slots of one formula swapped: their parameters have the same ids after as before, so only
// the slots carrying their values (not ids) gives each its own.
TEST(FormulaEdit, SwappedSlotsOfOneFormulaSwapTheirValues) {
    const FormulaScene twice =
        with_formula_added(shipped_formula("mandelbulb-formula"), library("mandelbulb"));
    const Scene before = formula_scene_to_scene(twice, "twice.formula.json");
    std::vector<float> values = default_param_values(before);
    set_param_from_text(before, values, "f1_power=5");
    set_param_from_text(before, values, "f2_power=3");
    FormulaScene edited = twice;
    take_slot_values(edited, before, values);
    edited = with_slot_moved(edited, 1, -1);
    const Scene after = formula_scene_to_scene(edited, "twice.formula.json");
    const std::vector<float> carried = values_after_edit(before, values, after, edited);
    EXPECT_EQ(param_value(after, carried, "f1_power"), 3.0f);
    EXPECT_EQ(param_value(after, carried, "f2_power"), 5.0f);
}

// What the editor saves reads back as the same scene: source, parameters and their values,
// cameras, paths and lights; for every shipped file and for an edited hybrid.
// "Save as" writes a file that names its JSON Schema (schemas/formula.schema.json) beside the
// running executable, for editors; reading it takes "$schema" (SavedScenesReadBackAsTheSameScene).
TEST(FormulaEdit, SavedFilesNameTheirSchema) {
    const nlohmann::json saved =
        nlohmann::json::parse(formula_scene_json(shipped_formula("menger-kifs")));
    EXPECT_EQ(saved.at("$schema"), schema_reference("formula.schema.json"));
}

TEST(FormulaEdit, SavedScenesReadBackAsTheSameScene) {
    std::vector<FormulaScene> scenes;
    for (const auto& entry : fs::directory_iterator(FGR_TEST_FORMULA_DIR)) {
        if (is_formula_file_name(entry.path())) scenes.push_back(read_formula_file(entry.path()));
    }
    ASSERT_GE(scenes.size(), 36u);
    FormulaScene edited =
        with_formula_added(shipped_formula("menger-kifs"), library("amazing_box"));
    edited = with_repeat(edited, 1, 3);
    edited.sequence[0].values[0] = {2.5f, 2.5f, 2.5f};
    edited.environment = "studio";
    scenes.push_back(edited);
    for (const FormulaScene& scene : scenes) {
        SCOPED_TRACE(scene.id);
        const FormulaScene read = parse_formula_json(formula_scene_json(scene), "saved");
        EXPECT_EQ(formula_kernel_source(read), formula_kernel_source(scene));
        const Scene original = formula_scene_to_scene(scene, "a.formula.json");
        const Scene again = formula_scene_to_scene(read, "a.formula.json");
        EXPECT_EQ(default_param_values(again), default_param_values(original));
        EXPECT_EQ(param_ids(again), param_ids(original));
        ASSERT_EQ(again.cameras.size(), original.cameras.size());
        EXPECT_EQ(again.cameras[0].view.position, original.cameras[0].view.position);
        EXPECT_EQ(again.cameras[0].view.fov_degrees, original.cameras[0].view.fov_degrees);
        ASSERT_EQ(again.camera_paths.size(), original.camera_paths.size());
        EXPECT_EQ(again.camera_paths[0].keyframes.size(),
                  original.camera_paths[0].keyframes.size());
        ASSERT_EQ(again.lights.size(), original.lights.size());
        EXPECT_NEAR(again.lights[0].angular_radius, original.lights[0].angular_radius, 1e-6);
        EXPECT_EQ(again.march.step_factor, original.march.step_factor);
        EXPECT_EQ(again.march.max_distance, original.march.max_distance);
        EXPECT_EQ(again.environment, original.environment);
    }
}

}  // namespace
}  // namespace fgr
