// SPDX-License-Identifier: Apache-2.0
// The formula library and formula scene files (scene/formulas/formulas.hpp): every formula has its
// kernel function; the shipped files load (30 formulas and 5 hybrids at least); bad files are
// refused in one line naming the file, fuzzed ones too; a formula in two slots renders as the
// formula alone; formulas that are the same map under two names give the same distances; the delta
// estimate agrees with the analytic one where both exist. `fgr check` runs on every shipped file as
// its own ctest (SceneCheck.*.formula.json).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <glm/geometric.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "device_suite.hpp"
#include "fgr/kernel_library.hpp"
#include "fuzz_rng.hpp"
#include "json_mutation.hpp"
#include "random_points.hpp"
#include "render/renderer.hpp"
#include "render_probes.hpp"
#include "scene/formulas/formulas.hpp"
#include "scene/parameters.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A formula document of `sequence` (one slot's object, or an array of them).
json document(const json& sequence) {
    return {{"format", "fgr-formula"},
            {"version", 1},
            {"id", "test-formula"},
            {"name", "Test"},
            {"sequence", sequence.is_object() ? json::array({sequence}) : sequence}};
}

FormulaScene parse(const json& doc) { return parse_formula_json(doc.dump(), "test.formula.json"); }

Scene scene_of(const json& doc) { return formula_scene_to_scene(parse(doc), "test.formula.json"); }

std::vector<fs::path> shipped_formula_files() {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(FGR_TEST_FORMULA_DIR)) {
        if (is_formula_file_name(entry.path())) files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

// --- The library ------------------------------------------------------------------------------

TEST(FormulaLibrary, EveryFormulaHasItsKernelFunctionsInItsFamilysFile) {
    std::set<std::string> names;
    for (const Formula& formula : formula_library()) {
        EXPECT_TRUE(names.insert(formula.name).second) << "two formulas named " << formula.name;
        const KernelFile* family = formula_family(formula.family);
        ASSERT_NE(family, nullptr) << formula.name << ": no family " << formula.family;
        const std::string source = family->source;
        EXPECT_NE(source.find("inline void formula_" + formula.name + "("), std::string::npos)
            << formula.name;
        if (formula.distance == FormulaDistance::Own) {
            EXPECT_NE(source.find("inline real formula_" + formula.name + "_distance("),
                      std::string::npos)
                << formula.name;
        }
        if (formula.own_inside) {
            EXPECT_EQ(formula.estimate, FormulaEstimate::Inside) << formula.name;
            EXPECT_NE(source.find("inline mask formula_" + formula.name + "_inside("),
                      std::string::npos)
                << formula.name;
        }
        EXPECT_FALSE(formula.origin.empty()) << formula.name << " says where it comes from";
        for (const FormulaParam& param : formula.params) {
            for (const float value : param.default_value) {
                EXPECT_TRUE(param.min_value <= value && value <= param.max_value)
                    << formula.name << "." << param.id;
            }
        }
        EXPECT_LE(formula.bailout, formula.max_bailout) << formula.name;
    }
    EXPECT_GE(names.size(), 30u);
}

TEST(FormulaLibrary, TheShippedFilesCoverThirtyFormulasAndFiveHybrids) {
    std::set<std::string> alone;
    int hybrids = 0;
    for (const fs::path& file : shipped_formula_files()) {
        const FormulaScene scene = read_formula_file(file);
        EXPECT_EQ(file.filename().string(), scene.id + ".formula.json");
        if (scene.sequence.size() == 1) alone.insert(scene.sequence[0].formula->name);
        if (scene.sequence.size() > 1) ++hybrids;
    }
    EXPECT_GE(alone.size(), 30u);
    EXPECT_GE(hybrids, 5);
}

// --- Reading files ----------------------------------------------------------------------------

struct FormulaRefusal {
    const char* name;
    json doc;
    const char* says;
};

TEST(FormulaFile, RefusesBadDocumentsInOneLineNamingTheFile) {
    const json bulb = {{"formula", "mandelbulb"}};
    std::vector<FormulaRefusal> cases = {
        {"unknown formula", document({{{"formula", "mandelblub"}}}),
         "unknown formula 'mandelblub'"},
        {"no sequence", document(json::array()), "\"sequence\" has 0 entries"},
        {"repeat zero", document({{{"formula", "mandelbulb"}, {"repeat", 0}}}), "\"repeat\" 0"},
        {"repeat float", document({{{"formula", "mandelbulb"}, {"repeat", 1.5}}}),
         "\"repeat\" 1.5"},
        {"unknown parameter",
         document({{{"formula", "mandelbulb"}, {"parameters", {{"powr", 8}}}}}),
         "has no parameter 'powr'"},
        {"parameter out of range",
         document({{{"formula", "mandelbulb"}, {"parameters", {{"power", 40}}}}}),
         "parameter \"power\" 40 outside [2, 16]"},
        {"vector parameter of two",
         document({{{"formula", "menger"}, {"parameters", {{"offset", {1, 1}}}}}}),
         "must be an array of three numbers"},
        {"own distance in a hybrid", document({{{"formula", "pseudo_kleinian"}}, bulb}),
         "needs \"distance\""},
        {"bailout over what the power takes",
         [&] {
             json d = document({bulb});
             d["bailout"] = 1e6;
             return d;
         }(),
         "\"bailout\" 1000000 outside [0.5, 64]"},
        {"delta estimate of an own distance",
         [&] {
             json d = document({{{"formula", "menger"}}});
             d["estimate"] = "delta";
             return d;
         }(),
         "\"estimate\": \"delta\" needs \"distance\""},
        {"analytic estimate of an inside-only formula",
         [&] {
             json d = document({{{"formula", "lambdabulb"}}});
             d["estimate"] = "analytic";
             return d;
         }(),
         "\"estimate\" \"analytic\": lambdabulb has no distance estimate, only an inside test"},
        {"delta estimate of a hybrid with an inside-only formula",
         [&] {
             json d = document({bulb, {{"formula", "lambdabulb"}}});
             d["estimate"] = "delta";
             return d;
         }(),
         "lambdabulb has no distance estimate"},
        {"unknown estimate",
         [&] {
             json d = document({bulb});
             d["estimate"] = "exact";
             return d;
         }(),
         "must be \"analytic\", \"delta\" or \"inside\""},
        {"misspelt key",
         [&] {
             json d = document({bulb});
             d["iteratons"] = 5;
             return d;
         }(),
         "iteratons"},
        {"wrong format",
         [&] {
             json d = document({bulb});
             d["format"] = "fgr-ifs";
             return d;
         }(),
         "must be \"fgr-formula\""},
        {"\"$schema\" a number",
         [&] {
             json d = document({bulb});
             d["$schema"] = 3;
             return d;
         }(),
         "\"$schema\" 3 must be a string"},
        {"bad tag",
         [&] {
             json d = document({bulb});
             d["tags"] = {"Bulb!"};
             return d;
         }(),
         "\"tags\" entry 0"},
        {"environment from a file",
         [&] {
             json d = document({bulb});
             d["environment"] = "hall.hdr";
             return d;
         }(),
         "\"environment\": environment 'hall.hdr' is not one fgr generates"},
        {"environment not a string",
         [&] {
             json d = document({bulb});
             d["environment"] = 1;
             return d;
         }(),
         "\"environment\" must be a string"},
    };
    json many = json::array();
    for (std::size_t i = 0; i <= kFormulaMaxSlots; ++i) many.push_back(bulb);
    cases.push_back({"too many slots", document(many), "\"sequence\" has 17 entries"});
    for (const FormulaRefusal& refusal : cases) {
        try {
            (void)parse(refusal.doc);
            ADD_FAILURE() << refusal.name << ": accepted";
        } catch (const FormulaError& error) {
            const std::string message = error.what();
            EXPECT_EQ(message.rfind("test.formula.json: ", 0), 0u)
                << refusal.name << ": " << message;
            EXPECT_NE(message.find(refusal.says), std::string::npos)
                << refusal.name << ": " << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << refusal.name << ": " << message;
        }
    }
}

// "$schema" names the file's JSON Schema for editors (schemas/formula.schema.json): taken at the
// top level, and not read.
TEST(FormulaFile, ASchemaReferenceIsAcceptedAtTheTopLevel) {
    json doc = document({{"formula", "mandelbulb"}});
    doc["$schema"] = "file:///usr/share/fgr/schemas/formula.schema.json";
    EXPECT_EQ(parse(doc).sequence.size(), 1u);
}

// A file may name the path mode's environment, which its scene keeps; without one it has none.
TEST(FormulaFile, NamesItsOwnEnvironment) {
    json d = document({{{"formula", "mandelbulb"}}});
    EXPECT_EQ(scene_of(d).environment, "");
    d["environment"] = "uniform:0.5";
    EXPECT_EQ(scene_of(d).environment, "uniform:0.5");
}

TEST(FormulaFile, DefaultsComeFromTheFormulasAndHybridsPrefixTheirParameters) {
    const Scene alone = scene_of(document({{{"formula", "mandelbox"}}}));
    ASSERT_NE(alone.find_param("scale"), nullptr);
    EXPECT_EQ(alone.find_param("scale")->default_value[0], 2.0f);
    const Scene hybrid = scene_of(document(
        {{{"formula", "mandelbulb"}, {"parameters", {{"power", 5}}}}, {{"formula", "mandelbox"}}}));
    ASSERT_NE(hybrid.find_param("f1_power"), nullptr);
    EXPECT_EQ(hybrid.find_param("f1_power")->default_value[0], 5.0f);
    ASSERT_NE(hybrid.find_param("f2_scale"), nullptr);
    EXPECT_EQ(hybrid.find_param("scale"), nullptr);
    // The bailout is the largest the formulas start with, within what the bulb's power takes.
    EXPECT_EQ(hybrid.find_param("bailout")->default_value[0], 64.0f);
    EXPECT_EQ(hybrid.find_param("bailout")->max_value, 64.0f);
}

// "format", "version" or a tag nested 100000 deep (which once crashed the reader printing it), a
// key given twice, bytes after a NUL or after the document: refused in one short line naming the
// file.
TEST(FormulaFile, HostileDocumentsAreRefusedInOneShortLine) {
    const std::string deep = std::string(100000, '[') + std::string(100000, ']');
    json tagged = document({{{"formula", "mandelbulb"}}});
    tagged["tags"] = {"DEEP"};
    const auto with_deep = [&](json doc, const std::string& key) {
        doc[key] = "DEEP";
        std::string text = doc.dump();
        text.replace(text.find("\"DEEP\""), 6, deep);
        return text;
    };
    std::string twice = document({{{"formula", "mandelbulb"}}}).dump();
    twice.insert(1, R"("id": "other", )");
    // A tag nested deep: the tags array's one entry.
    std::string tag = tagged.dump();
    tag.replace(tag.find("\"DEEP\""), 6, deep);
    const std::string valid = document({{{"formula", "mandelbulb"}}}).dump();
    const std::vector<std::pair<std::string, std::string>> cases = {
        {with_deep(document({{{"formula", "mandelbulb"}}}), "format"),
         "nest deeper than 64 levels"},
        {with_deep(document({{{"formula", "mandelbulb"}}}), "version"),
         "nest deeper than 64 levels"},
        {tag, "nest deeper than 64 levels"},
        {twice, "the key \"id\" appears twice"},
        {valid + std::string(1, '\0') + "junk", "a NUL byte at offset"},
        {valid + "[]", "not valid JSON"},
    };
    for (const auto& [text, expected] : cases) {
        try {
            (void)parse_formula_json(text, "bad.formula.json");
            ADD_FAILURE() << "accepted: " << text.substr(0, 80);
        } catch (const FormulaError& error) {
            const std::string message = error.what();
            EXPECT_EQ(message.rfind("bad.formula.json: ", 0), 0u) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
            EXPECT_LT(message.size(), 400u) << message.substr(0, 400);
            EXPECT_NE(message.find(expected), std::string::npos) << message;
        }
    }
}

// 10^4 seeded cases (FGR_FUZZ_CASES, FGR_FUZZ_SEED; the seed of a failing case is printed): the
// shipped files with their text, structure or values mutated. Each is read, keeping the
// invariants the renderer relies on, or refused in one line naming the file.
TEST(FuzzFormulaFile, ParsesOrRefusesEveryMutatedFile) {
    std::vector<std::string> seeds;
    for (const fs::path& file : shipped_formula_files()) seeds.push_back(test::read_file(file));
    ASSERT_FALSE(seeds.empty());
    const uint64_t base = test::fuzz_base_seed(0x466f726d756c6131);  // "Formula1"
    const uint64_t cases = test::fuzz_case_count();
    uint64_t accepted = 0;
    for (uint64_t c = 0; c < cases; ++c) {
        const uint64_t case_seed = base + c;
        test::FuzzRng rng(case_seed);
        std::string text = seeds[rng.below(seeds.size())];
        test::mutate_document(text, rng, rng.range(1, 3));
        try {
            const FormulaScene scene = parse_formula_json(text, "fuzz.formula.json");
            ++accepted;
            ASSERT_FALSE(scene.sequence.empty()) << "case " << case_seed;
            ASSERT_LE(scene.bailout, scene.max_bailout) << "case " << case_seed;
            for (const FormulaSlot& slot : scene.sequence) {
                ASSERT_EQ(slot.values.size(), slot.formula->params.size()) << "case " << case_seed;
            }
            const Scene built = formula_scene_to_scene(scene, "fuzz.formula.json");
            ASSERT_FALSE(built.cameras.empty()) << "case " << case_seed;
        } catch (const FormulaError& error) {
            const std::string message = error.what();
            ASSERT_EQ(message.rfind("fuzz.formula.json: ", 0), 0u) << "case " << case_seed;
            ASSERT_EQ(message.find('\n'), std::string::npos) << "case " << case_seed;
            ASSERT_LT(message.size(), 1000u) << "case " << case_seed << ": " << message;
        }
    }
    if (cases >= 1000) {
        EXPECT_GT(accepted, cases / 20);
        EXPECT_LT(accepted, cases * 19 / 20);
    }
}

// A formula with no safe distance estimate makes an inside test, the brute-force mode's scene,
// and so does any hybrid it is in, or a file that asks; every other scene keeps its estimate.
TEST(FormulaFile, FormulasWithoutAnEstimateMakeInsideOnlyScenesForTheBruteForceMode) {
    const json bulb = {{"formula", "mandelbulb"}};
    const Scene lambdabulb = scene_of(document({{{"formula", "lambdabulb"}}}));
    EXPECT_TRUE(lambdabulb.inside_only());
    EXPECT_EQ(lambdabulb.default_mode, RenderMode::Brute);
    EXPECT_TRUE(scene_of(document({bulb, {{"formula", "lambdabulb"}}})).inside_only());
    // The bicomplex formulas measure their own distance alone; in a hybrid they are inside tests.
    EXPECT_FALSE(scene_of(document({{{"formula", "tetrabrot"}}})).inside_only());
    json bicomplex_hybrid = document({bulb, {{"formula", "tetrabrot"}}});
    bicomplex_hybrid["distance"] = "logarithmic";
    EXPECT_TRUE(scene_of(bicomplex_hybrid).inside_only());
    const Scene bulb_alone = scene_of(document({bulb}));
    EXPECT_FALSE(bulb_alone.inside_only());
    EXPECT_EQ(bulb_alone.default_mode, RenderMode::Shaded);
    json asked = document({bulb});
    asked["estimate"] = "inside";
    EXPECT_TRUE(scene_of(asked).inside_only());
    for (const Formula& formula : formula_library()) {
        const Scene scene = scene_of(document({{{"formula", formula.name}}}));
        EXPECT_EQ(scene.inside_only(), formula.estimate == FormulaEstimate::Inside &&
                                           formula.distance != FormulaDistance::Own)
            << formula.name;
    }
}

// --- Rendering --------------------------------------------------------------------------------

class FormulaScenes : public test::DeviceSuite<> {
protected:
    static Frame render(const Scene& scene, int width) {
        Renderer renderer(*device_, *cache_, scene, {width, scene.effects});
        return renderer.render(test::default_view_request(scene));
    }

    // The scene's inside test at each point (test::eye_inside, the eye put at the point).
    static std::vector<bool> inside(const Scene& scene, const std::vector<glm::dvec3>& points) {
        KernelSwitches switches;
        switches.packet_width = 16;
        switches.mode = RenderMode::Brute;
        Renderer renderer(*device_, *cache_, scene, switches);
        std::vector<bool> verdicts;
        for (const glm::dvec3& point : points) {
            CameraView view = scene.cameras.front().view;
            view.target += point - view.position;
            view.position = point;
            verdicts.push_back(test::eye_inside(renderer, scene, view));
        }
        return verdicts;
    }

    static std::vector<float> distances(const Scene& scene, const std::vector<glm::vec3>& points) {
        Renderer renderer(*device_, *cache_, scene, {16, 0});
        return renderer.probe_de(points, default_param_values(scene));
    }
};

// A hybrid of one formula (in one slot repeated, or in two slots) iterates exactly the formula's
// steps: the same image, bit for bit, at the GPU layout and the CPU's. And a slot repeated is the
// same as the slot written out again: [8 x2, 4] steps as [8, 8, 4], which a wrong count of the
// slots' turns would not.
TEST_F(FormulaScenes, AFormulaInTwoSlotsRendersAsTheFormulaAlone) {
    const json power8 = {{"formula", "mandelbulb"}, {"parameters", {{"power", 8}}}};
    const json power4 = {{"formula", "mandelbulb"}, {"parameters", {{"power", 4}}}};
    json power8_twice = power8;
    power8_twice["repeat"] = 2;
    const Scene eight_twice = scene_of(document(json::array({power8_twice, power4})));
    const Scene written_out = scene_of(document(json::array({power8, power8, power4})));
    for (const int width : {1, 16}) {
        const Frame a = render(eight_twice, width);
        const Frame b = render(written_out, width);
        ASSERT_GT(a.hits, 500) << "width " << width;
        EXPECT_EQ(a.image.rgb, b.image.rgb) << "width " << width;
    }
    const json& bulb = power8;
    const Scene alone = scene_of(document({bulb}));
    const Scene twice = scene_of(document({bulb, bulb}));
    json repeated = bulb;
    repeated["repeat"] = 3;
    const Scene thrice = scene_of(document({repeated}));
    for (const int width : {1, 16}) {
        const Frame a = render(alone, width);
        ASSERT_GT(a.hits, 500) << "width " << width;
        for (const Scene* other : {&twice, &thrice}) {
            const Frame b = render(*other, width);
            EXPECT_EQ(a.hits, b.hits) << "width " << width;
            EXPECT_EQ(a.image.rgb, b.image.rgb) << "width " << width;
        }
    }
}

// Two names for one map: Xenodreambuie with no turns is White and Nylander's Mandelbulb, and the
// White-Nylander polynomial is the power-2 Mandelbulb. Their distances agree to float rounding of
// a few steps (2e-5 relative; the trigonometric and polynomial forms round differently).
TEST_F(FormulaScenes, TheSameMapUnderTwoNamesGivesTheSameDistances) {
    const auto points = test::random_points(400, 1.6f, 7);
    struct Pair {
        json a, b;
    } pairs[] = {
        {{{"formula", "mandelbulb"}, {"parameters", {{"power", 8}}}},
         {{"formula", "xenodreambuie"}, {"parameters", {{"power", 8}, {"alpha", 0}, {"beta", 0}}}}},
        {{{"formula", "mandelbulb"}, {"parameters", {{"power", 2}}}},
         {{"formula", "white_nylander"}}},
    };
    for (const Pair& pair : pairs) {
        json a = document({pair.a}), b = document({pair.b});
        a["bailout"] = b["bailout"] = 16;
        const auto da = distances(scene_of(a), points);
        const auto db = distances(scene_of(b), points);
        int compared = 0;
        for (std::size_t i = 0; i < points.size(); ++i) {
            if (!(std::abs(da[i]) > 1e-3f)) continue;  // near the surface rounding decides
            ++compared;
            EXPECT_NEAR(db[i], da[i], 2e-5f * std::abs(da[i]) + 1e-6f)
                << pair.b["formula"] << " at point " << i;
        }
        EXPECT_GT(compared, 200) << pair.b["formula"];
    }
}

// The delta estimate (finite differences of |z|) against the analytic one (the running derivative
// dr), at points in a shell off the surface (the Mandelbox's inside is full of surface). For the
// bulbs dr is the Jacobian's stretch, so the two agree: the median ratio within 2% of 1, nine in
// ten within 5% (measured: 0.999 to 1.012). The Mandelbox's dr adds |scale| dr + 1 whatever the
// fold's reflection did to the sign, a bound on the stretch, not the stretch: its distance never
// exceeds the delta one, which is up to about 3 times longer in the far field (measured: median
// 3.0), the price of the bound.
std::vector<double> delta_over_analytic(const std::vector<float>& analytic,
                                        const std::vector<float>& delta) {
    std::vector<double> ratios;
    for (std::size_t i = 0; i < analytic.size(); ++i) {
        if (analytic[i] > 0.0f && std::isfinite(delta[i])) ratios.push_back(delta[i] / analytic[i]);
    }
    std::sort(ratios.begin(), ratios.end());
    return ratios;
}

TEST_F(FormulaScenes, TheDeltaEstimateAgreesWithTheAnalyticOne) {
    struct Case {
        const char* name;
        float inner, outer;  // the shell of |p| the points lie in
        bool bound;          // dr is a bound on the stretch, not the stretch
    } cases[] = {{"mandelbulb", 1.3f, 2.5f, false},
                 {"juliabulb", 1.3f, 2.5f, false},
                 {"mandelbox", 7.0f, 12.0f, true}};
    for (const Case& c : cases) {
        json analytic = document({{"formula", c.name}});
        json delta = analytic;
        delta["estimate"] = "delta";
        std::vector<glm::vec3> points;
        for (const glm::vec3& p : test::random_points(4000, c.outer, 11)) {
            const float r = glm::length(p);
            if (r >= c.inner && r <= c.outer) points.push_back(p);
        }
        const auto ratios = delta_over_analytic(distances(scene_of(analytic), points),
                                                distances(scene_of(delta), points));
        ASSERT_GT(ratios.size(), 500u) << c.name;
        const double low = ratios[ratios.size() / 20], median = ratios[ratios.size() / 2],
                     high = ratios[ratios.size() * 19 / 20];
        std::printf("%s: delta / analytic over %zu points: 5%% %.3f, median %.3f, 95%% %.3f\n",
                    c.name, ratios.size(), low, median, high);
        if (c.bound) {
            EXPECT_GE(ratios.front(), 0.99) << c.name;
        } else {
            EXPECT_NEAR(median, 1.0, 0.02) << c.name;
            EXPECT_GT(low, 0.95) << c.name;
            EXPECT_LT(high, 1.05) << c.name;
        }
    }
}

}  // namespace
}  // namespace fgr

namespace fgr {
namespace {

// The Tetrabrot's inside test against the bicomplex numbers' other description: in idempotent
// coordinates z1 + z2 j = (z1 - i z2) e1 + (z1 + i z2) e2 squares component by component, so the
// orbit of (x, y, z, 0) is two complex Mandelbrot orbits, of x + i (y - z) and x + i (y + z), and
// |z|^2 = (|u|^2 + |v|^2) / 2. The host runs those (double) with the scene's bailout and
// iterations; points whose largest |z| on the way comes within 2% of the bailout are left out
// (float against double). A wrong sign or term in the kernel's square moves the set.
TEST_F(FormulaScenes, TheTetrabrotIsTwoMandelbrotSetsInIdempotentCoordinates) {
    json inside_test = document({{{"formula", "tetrabrot"}}});
    inside_test["estimate"] = "inside";
    const Scene tetrabrot = scene_of(inside_test);
    const auto params = default_param_values(tetrabrot);
    const double bailout = param_value(tetrabrot, params, "bailout");
    const int iterations = int(param_value(tetrabrot, params, "iterations"));
    test::FuzzRng rng(2026);
    std::vector<glm::dvec3> points;
    std::vector<bool> expected;
    while (points.size() < 240) {
        const glm::dvec3 p(rng.uniform(-1.9f, 0.4f), rng.uniform(-0.8f, 0.8f),
                           rng.uniform(-0.8f, 0.8f));
        std::complex<double> u(p.x, p.y - p.z), v(p.x, p.y + p.z);
        const std::complex<double> cu = u, cv = v;
        bool in = true, close = false;
        for (int i = 0; i <= iterations; ++i) {
            const double norm = std::sqrt(0.5 * (std::norm(u) + std::norm(v)));
            close = close || std::abs(norm - bailout) < 0.02 * bailout;
            if (norm > bailout) {
                in = false;
                break;
            }
            if (i < iterations) {
                u = u * u + cu;
                v = v * v + cv;
            }
        }
        if (close) continue;
        points.push_back(p);
        expected.push_back(in);
    }
    const std::vector<bool> verdicts = inside(tetrabrot, points);
    int in_count = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        in_count += expected[i];
        EXPECT_EQ(verdicts[i], expected[i])
            << "at (" << points[i].x << ", " << points[i].y << ", " << points[i].z << ")";
    }
    EXPECT_GT(in_count, 20);  // both verdicts are tried
    EXPECT_LT(in_count, 220);
}

}  // namespace
}  // namespace fgr

namespace fgr {
namespace {

// Jos Leys' Kleinian set is invariant under its group's translations, x and z by twice the box's
// half sizes (2 at the defaults): points on a grid of 2^-10 and the same points moved by 2 have
// exactly the same wrapped orbits, so the inside test must agree at every one. A wrap of the
// wrong period, or none, moves the set under the translation.
TEST_F(FormulaScenes, JosLeysKleinianIsInvariantUnderItsGroupsTranslations) {
    // Thick spheres, so that a fair share of the points is inside.
    const Scene kleinian =
        scene_of(document({{{"formula", "jos_kleinian"}, {"parameters", {{"thickness", 0.1}}}}}));
    ASSERT_TRUE(kleinian.inside_only());
    test::FuzzRng rng(1957);
    std::vector<glm::dvec3> points;
    for (int i = 0; i < 800; ++i) {
        const auto grid = [&](float low, float high) {
            return std::round(double(rng.uniform(low, high)) * 1024.0) / 1024.0;
        };
        points.emplace_back(grid(-1.0f, 1.0f), grid(0.0f, 1.9f), grid(-1.0f, 1.0f));
    }
    std::vector<glm::dvec3> moved_x, moved_z;
    for (const glm::dvec3& p : points) {
        moved_x.push_back(p + glm::dvec3(2.0, 0.0, 0.0));
        moved_z.push_back(p + glm::dvec3(0.0, 0.0, -2.0));
    }
    const std::vector<bool> here = inside(kleinian, points);
    const std::vector<bool> along_x = inside(kleinian, moved_x);
    const std::vector<bool> along_z = inside(kleinian, moved_z);
    int in_count = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        in_count += here[i];
        EXPECT_EQ(along_x[i], here[i]) << "at (" << points[i].x << ", " << points[i].y << ", "
                                       << points[i].z << ") moved by 2 along x";
        EXPECT_EQ(along_z[i], here[i]) << "at (" << points[i].x << ", " << points[i].y << ", "
                                       << points[i].z << ") moved by -2 along z";
    }
    EXPECT_GT(in_count, 10);  // both verdicts are tried (about 3% of the points are inside)
    EXPECT_LT(in_count, 790);
}

}  // namespace
}  // namespace fgr

namespace fgr {
namespace {

// Whether the host proves c out of the complex Mandelbrot set: its orbit passes |u| = 2 within
// 4000 steps (double precision).
bool escapes_mandelbrot(std::complex<double> c) {
    std::complex<double> u = c;
    for (int i = 0; i < 4000; ++i) {
        if (std::norm(u) > 4.0) return true;
        u = u * u + c;
    }
    return false;
}

// The Tetrabrot's distance is a lower bound: every point nearer than it (9/10 of it) to where it
// was measured is out of the set, which the host proves in idempotent coordinates (either
// complex orbit, of x + i (y - z) or x + i (y + z), escapes). A distance without the sqrt(2) of
// the cylinders' stretch, or with the derivative's + 1 left out, claims balls that reach into
// the set.
TEST_F(FormulaScenes, TheTetrabrotsDistanceIsALowerBound) {
    const Scene tetrabrot = scene_of(document({{{"formula", "tetrabrot"}}}));
    ASSERT_FALSE(tetrabrot.inside_only());
    test::FuzzRng rng(1892);
    std::vector<glm::vec3> centres;
    for (int i = 0; i < 400; ++i) {
        centres.emplace_back(rng.uniform(-2.0f, 0.6f), rng.uniform(-1.2f, 1.2f),
                             rng.uniform(-1.2f, 1.2f));
    }
    const std::vector<float> de = distances(tetrabrot, centres);
    const auto in_set = [](const glm::dvec3& p) {
        return !escapes_mandelbrot({p.x, p.y - p.z}) && !escapes_mandelbrot({p.x, p.y + p.z});
    };
    int balls = 0, largest_ball_index = -1;
    float largest = 0.0f;
    for (std::size_t i = 0; i < centres.size(); ++i) {
        if (!(de[i] > 1e-3f)) continue;
        ++balls;
        if (de[i] > largest) largest = de[i], largest_ball_index = int(i);
        for (int k = 0; k < 24; ++k) {
            const glm::vec3 direction = glm::normalize(glm::vec3(
                rng.uniform(-1.0f, 1.0f), rng.uniform(-1.0f, 1.0f), rng.uniform(-1.0f, 1.0f)));
            const glm::dvec3 q =
                glm::dvec3(centres[i]) +
                glm::dvec3(direction) * (0.9 * double(de[i]) * rng.uniform(0.5f, 1.0f));
            ASSERT_FALSE(in_set(q)) << "distance " << de[i] << " at (" << centres[i].x << ", "
                                    << centres[i].y << ", " << centres[i].z << ") reaches (" << q.x
                                    << ", " << q.y << ", " << q.z << ") in the set";
        }
    }
    EXPECT_GT(balls, 200);  // most points are outside, and their balls were tried
    EXPECT_GE(largest_ball_index, 0);
}

}  // namespace
}  // namespace fgr
