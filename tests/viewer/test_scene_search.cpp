// SPDX-License-Identifier: Apache-2.0
// The formula browser's search (viewer/scene_search.hpp): a scene is found by its id, name
// and tags, a formula scene also by its formulas' names, titles and families; every word of the
// query must be found, ignoring case.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "scene/formulas/formulas.hpp"
#include "viewer/scene_search.hpp"

namespace fgr::viewer {
namespace {

namespace fs = std::filesystem;

struct Found {
    std::vector<Scene> scenes;
    std::vector<FormulaScene> formulas;
    std::vector<SceneSearchEntry> entries;

    std::vector<std::string> ids(const std::string& query) const {
        std::vector<std::string> result;
        for (const std::size_t i : matching_scenes(entries, query)) result.push_back(scenes[i].id);
        return result;
    }
};

// Two shipped formula scenes and a plugin-like scene without a sequence.
Found three_scenes() {
    Found found;
    for (const char* id : {"bulb-box", "quaternion-julia"}) {
        const fs::path file = fs::path(FGR_TEST_FORMULA_DIR) / (std::string(id) + ".formula.json");
        found.formulas.push_back(read_formula_file(file));
        found.scenes.push_back(formula_scene_to_scene(found.formulas.back(), file));
    }
    Scene plugin;
    plugin.id = "mandelbulb";
    plugin.name = "Mandelbulb (plugin)";
    found.scenes.push_back(plugin);
    found.entries = {search_entry(found.scenes[0], &found.formulas[0]),
                     search_entry(found.scenes[1], &found.formulas[1]),
                     search_entry(found.scenes[2], nullptr)};
    return found;
}

using Ids = std::vector<std::string>;

TEST(SceneSearch, AnEmptyQueryFindsEveryScene) {
    const Found found = three_scenes();
    EXPECT_EQ(found.ids(""), (Ids{"bulb-box", "quaternion-julia", "mandelbulb"}));
    EXPECT_EQ(found.ids("   "), (Ids{"bulb-box", "quaternion-julia", "mandelbulb"}));
}

TEST(SceneSearch, FindsByIdNameTagFormulaAndFamilyIgnoringCase) {
    const Found found = three_scenes();
    EXPECT_EQ(found.ids("BULB-BOX"), Ids{"bulb-box"}) << "id";
    EXPECT_EQ(found.ids("plugin"), Ids{"mandelbulb"}) << "name";
    EXPECT_EQ(found.ids("hybrid"), Ids{"bulb-box"}) << "tag";
    EXPECT_EQ(found.ids("amazing"), Ids{"bulb-box"}) << "a formula's title (Amazing Box)";
    EXPECT_EQ(found.ids("amazing_box"), Ids{"bulb-box"}) << "a formula's name";
    EXPECT_EQ(found.ids("hypercomplex"), Ids{"quaternion-julia"}) << "a formula's family";
    EXPECT_EQ(found.ids("Mandelbulb"), (Ids{"bulb-box", "mandelbulb"}))
        << "the hybrid's first formula and the plugin's id";
    EXPECT_EQ(found.ids("nothing-like-this"), Ids{});
}

TEST(SceneSearch, EveryWordMustBeFound) {
    const Found found = three_scenes();
    EXPECT_EQ(found.ids("bulb box"), Ids{"bulb-box"});
    EXPECT_EQ(found.ids("mandelbulb plugin"), Ids{"mandelbulb"});
    EXPECT_EQ(found.ids("quaternion box"), Ids{}) << "no scene has both";
}

}  // namespace
}  // namespace fgr::viewer
