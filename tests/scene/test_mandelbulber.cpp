// SPDX-License-Identifier: Apache-2.0
// fgr's formula library against Mandelbulber 2: for every case in
// bench/mandelbulber_formulas.json whose agreement is claimed, fgr renders the formula scene with
// the case's parameters and camera, and its hit silhouette (`--alpha`) must cover the same
// pixels as Mandelbulber 2's, kept in tests/fixtures/mandelbulber/ID.png (written by
// bench/compare_formulas_mandelbulber.py --fixtures from `--format png16alpha` renders): an
// intersection over union of at least 0.95, the figure. Mandelbulber is not needed here.
//
// The camera is built as the script builds it: Mandelbulber's fov 1 (tan of half the vertical
// field of view 0.5), and the view turned half a pixel left and up, as Mandelbulber traces each
// pixel's corner where fgr traces its centre.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "image/image_io.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kSilhouetteWidth = 320;  // the fixtures' size
constexpr int kSilhouetteHeight = 240;
constexpr double kTanHalfVertical = 0.5;
constexpr double kMinimumIou = 0.95;

const fs::path kSourceDir = FGR_TEST_SOURCE_DIR;
const fs::path kCasesFile = kSourceDir / ".." / "bench" / "mandelbulber_formulas.json";
const fs::path kMaskDir = kSourceDir / "fixtures" / "mandelbulber";

// One case of bench/mandelbulber_formulas.json. gtest (and so ctest's test names) prints a case
// by its id alone, not its whole JSON.
struct ComparisonCase {
    json item;
    std::string id() const { return item.at("id").get<std::string>(); }
};
void PrintTo(const ComparisonCase& comparison, std::ostream* out) { *out << comparison.id(); }

std::vector<ComparisonCase> comparison_cases() {
    std::ifstream in(kCasesFile);
    if (!in) return {};
    const json document = json::parse(in);
    std::vector<ComparisonCase> cases;
    for (const json& item : document.at("cases")) {
        cases.push_back({item});
    }
    return cases;
}

glm::dvec3 vec(const json& item, const char* key, glm::dvec3 fallback) {
    if (!item.contains(key)) return fallback;
    const json& v = item.at(key);
    return {v.at(0).get<double>(), v.at(1).get<double>(), v.at(2).get<double>()};
}

std::string text(glm::dvec3 v) { return fmt::format("{:.9g},{:.9g},{:.9g}", v.x, v.y, v.z); }

std::vector<std::string> render_arguments(const json& item, const fs::path& output) {
    const glm::dvec3 eye = vec(item, "eye", {});
    glm::dvec3 target = vec(item, "target", {0, 0, 0});
    const glm::dvec3 up = vec(item, "up", {0, 0, 1});
    const glm::dvec3 forward = glm::normalize(target - eye);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, up));
    const glm::dvec3 camera_up = glm::cross(right, forward);
    const double distance = glm::length(target - eye);
    const double pixel = 2.0 * kTanHalfVertical / kSilhouetteHeight * distance;
    target += 0.5 * pixel * (camera_up - right);
    const double fov =
        2.0 * std::atan(kTanHalfVertical * kSilhouetteWidth / kSilhouetteHeight) * 180.0 / M_PI;
    std::vector<std::string> args = {"render",
                                     item.at("fgr_scene").get<std::string>(),
                                     "--width",
                                     std::to_string(kSilhouetteWidth),
                                     "--height",
                                     std::to_string(kSilhouetteHeight),
                                     "--effects",
                                     "none",
                                     "--alpha",
                                     "--eye",
                                     text(eye),
                                     "--target",
                                     text(target),
                                     "--up",
                                     text(up),
                                     "--fov",
                                     fmt::format("{:.12g}", fov),
                                     "--set",
                                     fmt::format("max_distance={:.9g}", 10.0 * distance),
                                     "-o",
                                     output.string()};
    for (const json& setting : item.at("fgr_set")) {
        args.push_back("--set");
        args.push_back(setting.get<std::string>());
    }
    return args;
}

// Covered pixels (alpha over half).
std::vector<bool> silhouette(const fs::path& png) {
    const PngSamples image = read_png_samples(png);
    EXPECT_EQ(image.channels, 4) << png;
    EXPECT_EQ(image.width, kSilhouetteWidth) << png;
    EXPECT_EQ(image.height, kSilhouetteHeight) << png;
    const int half = image.bit_depth == 16 ? 32768 : 128;
    std::vector<bool> mask(static_cast<size_t>(kSilhouetteWidth) * kSilhouetteHeight);
    if (image.channels != 4 || image.width != kSilhouetteWidth || image.height != kSilhouetteHeight)
        return mask;
    for (int y = 0; y < kSilhouetteHeight; ++y) {
        for (int x = 0; x < kSilhouetteWidth; ++x) {
            const size_t at = (static_cast<size_t>(y) * kSilhouetteWidth + x) * 4 + 3;
            mask[static_cast<size_t>(y) * kSilhouetteWidth + x] = image.samples[at] >= half;
        }
    }
    return mask;
}

double intersection_over_union(const std::vector<bool>& a, const std::vector<bool>& b) {
    size_t both = 0, either = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        both += a[i] && b[i];
        either += a[i] || b[i];
    }
    return either == 0 ? 1.0 : static_cast<double>(both) / static_cast<double>(either);
}

class MandelbulberAgreement : public ::testing::TestWithParam<ComparisonCase> {};

TEST_P(MandelbulberAgreement, HitSilhouetteMatchesMandelbulbers) {
    const json& item = GetParam().item;
    const std::string id = GetParam().id();
    test::TempDir dir("fgr_mandelbulber");
    const fs::path output = dir.path() / (id + ".png");
    const test::RunResult result = test::run_fgr(render_arguments(item, output), dir.path());
    ASSERT_TRUE(result.exited && result.exit_code == 0) << result;
    const std::vector<bool> theirs = silhouette(kMaskDir / (id + ".png"));
    const std::vector<bool> ours = silhouette(output);
    const double iou = intersection_over_union(theirs, ours);
    RecordProperty("iou", fmt::format("{:.4f}", iou));
    fmt::print("{}: IoU {:.4f} with Mandelbulber 2\n", id, iou);
    EXPECT_GE(iou, kMinimumIou) << id << ": fgr's silhouette against Mandelbulber 2's";
}

TEST(MandelbulberCases, AtLeastEightFormulasAgree) {
    const std::vector<ComparisonCase> cases = comparison_cases();
    std::vector<std::string> scenes;
    for (const ComparisonCase& comparison : cases) {
        EXPECT_TRUE(fs::exists(kMaskDir / (comparison.id() + ".png"))) << comparison.id();
        const std::string scene = comparison.item.at("fgr_scene").get<std::string>();
        if (std::find(scenes.begin(), scenes.end(), scene) == scenes.end()) scenes.push_back(scene);
    }
    EXPECT_GE(scenes.size(), 8u) << "formula scenes compared with Mandelbulber 2";
}

INSTANTIATE_TEST_SUITE_P(Cases, MandelbulberAgreement, ::testing::ValuesIn(comparison_cases()),
                         [](const ::testing::TestParamInfo<ComparisonCase>& param_info) {
                             return param_info.param.id();
                         });

}  // namespace
}  // namespace fgr
