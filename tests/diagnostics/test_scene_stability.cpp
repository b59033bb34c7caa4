// SPDX-License-Identifier: Apache-2.0
// Numerical stability of scenes, through the checks `fgr check` runs (diagnostics/scene_check.hpp):
// the DE never overestimates, nothing produces NaN or Inf in the hard cases (the origin, huge
// points, a camera inside the fractal, every parameter at its extremes, every camera path), and
// each default view is a real image. Every scene this build makes (plugins and IFS files) is
// checked by ctest as `fgr check FILE` (SceneCheck.<file>, tests/CMakeLists.txt), with the
// tolerances argued in host/diagnostics/scene_check.cpp. Here each check is shown to catch the
// fault it is for, on a small scene broken in that one way, and to pass the same scene when it is
// right.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "device/program_cache.hpp"
#include "device_suite.hpp"
#include "diagnostics/scene_check.hpp"
#include "scene/parameters.hpp"
#include "scene/plugin_loader.hpp"
#include "test_scenes.hpp"

namespace fgr {
namespace {

using test::shared_device;

// A ball of radius 1 given by `de`, seen from 4 away by two cameras and along a camera path; its
// march takes steps of `step_factor` times the DE.
Scene ball(const std::string& de, float step_factor = 1.0f) {
    Scene scene =
        test::inline_scene("real scene_de(vec3 p, PARAMS) { (void)fgr_params; " + de + " }");
    scene.params.clear();
    scene.march.step_factor = step_factor;
    add_builtin_params(scene);
    CameraView side = scene.cameras.front().view;
    side.position = {3.0, 2.0, 1.0};
    scene.cameras.push_back({"side", side});
    CameraPath orbit{"orbit", {{0.0f, scene.cameras[0].view}, {2.0f, side}}};
    scene.camera_paths.push_back(orbit);
    return scene;
}

// The same ball with `#define FGR_SCENE_HAS_DE_PAIR` and a scene_de_pair whose body is `pair`
// (points a and b, results *da and *db).
Scene ball_with_pair(const std::string& de, const std::string& pair) {
    Scene scene = ball(de);
    scene.source +=
        "\n#define FGR_SCENE_HAS_DE_PAIR\ninline void scene_de_pair(vec3 a, vec3 b, "
        "real* da, real* db, PARAMS) { " +
        pair + " }\n";
    return scene;
}

const CheckResult& find_check(const SceneCheckReport& report, const std::string& name) {
    for (const CheckResult& check : report.results) {
        if (check.name == name) return check;
    }
    throw std::runtime_error("no check " + name);
}

class SceneCheckTest : public ::testing::Test {
protected:
    SceneCheckReport check(const Scene& scene, int packet_width = 0) {
        SceneChecker checker(shared_device(), cache_, scene, packet_width);
        return checker.run_all();
    }
    ProgramCache cache_{std::filesystem::path()};  // in memory: nothing on disk
};

std::string failures(const SceneCheckReport& report) { return format_check_report(report); }

TEST_F(SceneCheckTest, AnExactBallPassesEveryCheck) {
    const SceneCheckReport report = check(ball_with_pair(
        "return v3_length(p) - 1.0f;", "*da = v3_length(a) - 1.0f; *db = v3_length(b) - 1.0f;"));
    EXPECT_TRUE(report.passed()) << failures(report);
    ASSERT_EQ(report.results.size(), scene_check_names().size());
    for (const CheckResult& result : report.results) {
        EXPECT_NE(result.status, CheckStatus::Skipped) << result.name << ": " << result.detail;
    }
}

// The issue's example: a DE 1.31 times the distance. Both the Lipschitz check and the bisection
// find it and advise the step factor that makes the march safe (1 / 1.31 = 0.763, rounded down),
// and at that step factor both pass.
TEST_F(SceneCheckTest, AnOverestimateIsMeasuredAndTheSafeStepFactorAdvised) {
    const std::string de = "return 1.31f * (v3_length(p) - 1.0f);";
    const SceneCheckReport report = check(ball(de));
    const CheckResult& safety = find_check(report, "march-safety");
    ASSERT_EQ(safety.status, CheckStatus::Failed) << failures(report);
    EXPECT_NE(safety.detail.find("overestimates by up to 1.31x"), std::string::npos)
        << safety.detail;
    EXPECT_NE(safety.advice.find("set step_factor <= 0.76 (now 1)"), std::string::npos)
        << safety.advice;
    const CheckResult& lipschitz = find_check(report, "lipschitz");
    ASSERT_EQ(lipschitz.status, CheckStatus::Failed) << failures(report);
    EXPECT_NE(lipschitz.advice.find("set step_factor <= 0.76"), std::string::npos)
        << lipschitz.advice;
    // A steep DE is not a broken one: nothing about jumps or a bailout.
    EXPECT_EQ(lipschitz.detail.find("jumps"), std::string::npos) << lipschitz.detail;
    EXPECT_EQ(lipschitz.advice.find("bailout"), std::string::npos) << lipschitz.advice;
    EXPECT_EQ(safety.advice.find("bailout"), std::string::npos) << safety.advice;
    EXPECT_FALSE(report.passed());
    EXPECT_NE(format_check_report(report).find("FAILED  march-safety"), std::string::npos);

    const SceneCheckReport advised = check(ball(de, 0.76f));
    EXPECT_EQ(find_check(advised, "march-safety").status, CheckStatus::Passed) << failures(advised);
    EXPECT_EQ(find_check(advised, "lipschitz").status, CheckStatus::Passed) << failures(advised);
}

// A folding KIFS (the Sierpinski tetrahedron) with a bailout: neighbouring points escape at
// different iterations, so their distances are measured at different depths and the DE jumps. The
// checks say so and name the bailout, where a smaller step factor (the Lipschitz ratio asks for
// 0.09) would only crawl; without the bailout the same KIFS passes.
TEST_F(SceneCheckTest, ADistanceThatJumpsAtABailoutNamesTheBailout) {
    const auto kifs = [](const char* bailout) {
        return test::inline_scene(std::string("#define FGR_KERNEL_API 4\n") + "FGR_ORBIT(10, " +
                                  bailout + R"()
FGR_ITERATE
    z = fold_sierpinski(z);
    z = scale_about(z, 2.0f, v3_splat(1.0f, 1.0f, 1.0f));
    dr *= 2.0f;
FGR_DISTANCE((v3_length(z) - 1.7320508f) / dr)
)");
    };
    const Scene broken = kifs("2.0f");
    SceneChecker checker(shared_device(), cache_, broken);
    const CheckResult lipschitz = checker.lipschitz();
    ASSERT_EQ(lipschitz.status, CheckStatus::Failed) << lipschitz.detail;
    EXPECT_NE(lipschitz.detail.find("the DE jumps by up to"), std::string::npos)
        << lipschitz.detail;
    EXPECT_NE(lipschitz.advice.find("remove the bailout"), std::string::npos) << lipschitz.advice;
    EXPECT_EQ(lipschitz.advice.find("set step_factor"), std::string::npos) << lipschitz.advice;
    const CheckResult relaxed = checker.relaxed_steps();
    if (relaxed.status == CheckStatus::Failed) {
        EXPECT_NE(relaxed.advice.find("remove the bailout"), std::string::npos) << relaxed.advice;
    }

    const Scene fixed = kifs("FGR_NO_BAILOUT");
    SceneChecker fixed_checker(shared_device(), cache_, fixed);
    const CheckResult continuous = fixed_checker.lipschitz();
    EXPECT_EQ(continuous.status, CheckStatus::Passed) << continuous.detail << continuous.advice;
}

// The strength the bisection is argued to have (scene_check.cpp): 10% too large fails.
TEST_F(SceneCheckTest, ADistanceTenPercentTooLargeFailsTheMarchSafety) {
    Scene scene = ball("return 1.1f * (v3_length(p) - 1.0f);");
    SceneChecker checker(shared_device(), cache_, scene);
    const CheckResult safety = checker.march_safety();
    EXPECT_EQ(safety.status, CheckStatus::Failed) << safety.detail;
    EXPECT_NE(safety.detail.find("1.10x"), std::string::npos) << safety.detail;
}

// The relaxed-steps check compares the march with a cautious one: steps of half the scene's own
// step factor (at most 0.5). A ball whose DE is 2.5 times the distance is safe at its step factor
// 0.35 (steps of 0.875 of the distance); a "cautious" march at 0.5 would overshoot (1.25) and
// blame the scene for its own holes.
TEST_F(SceneCheckTest, TheCautiousMarchStepsFinerThanASceneWithASmallStepFactor) {
    Scene scene = ball("return 2.5f * (v3_length(p) - 1.0f);", 0.35f);
    SceneChecker checker(shared_device(), cache_, scene);
    const CheckResult relaxed = checker.relaxed_steps();
    EXPECT_EQ(relaxed.status, CheckStatus::Passed) << relaxed.detail;
}

// NaN at one point only: the check names the point and the parameters it used.
TEST_F(SceneCheckTest, ANanAtTheOriginIsNamed) {
    Scene scene = ball("return (v3_length(p) - 1.0f) * (v3_length(p) / v3_length(p));");
    SceneChecker checker(shared_device(), cache_, scene);
    const CheckResult hard = checker.finite_at_hard_points();
    ASSERT_EQ(hard.status, CheckStatus::Failed) << hard.detail;
    EXPECT_NE(hard.detail.find("DE is NaN at (0, 0, 0)"), std::string::npos) << hard.detail;
    EXPECT_NE(hard.advice.find("division by zero"), std::string::npos) << hard.advice;
}

// A plugin whose DE is NaN everywhere loads and compiles, renders nothing and says nothing (hits
// 0, exit 0 from `fgr render`): every check that meets the DE fails.
TEST_F(SceneCheckTest, ADistanceThatIsNanEverywhereFails) {
    LoadResult loaded =
        load_scene_plugin(std::filesystem::path(FGR_TEST_FIXTURE_DIR) / "nan" / "nan_de.so");
    ASSERT_TRUE(loaded.scene) << loaded.error;
    const SceneCheckReport report = check(*loaded.scene);
    EXPECT_FALSE(report.passed());
    for (const char* name : {"hard-points", "parameter-extremes", "lipschitz", "march-safety",
                             "cameras-and-paths", "default-view"}) {
        EXPECT_EQ(find_check(report, name).status, CheckStatus::Failed) << name << "\n"
                                                                        << failures(report);
    }
    EXPECT_NE(find_check(report, "hard-points").detail.find("DE is NaN at (0, 0, 0)"),
              std::string::npos);
    EXPECT_NE(find_check(report, "parameter-extremes").detail.find("with scale = 0.5"),
              std::string::npos)
        << find_check(report, "parameter-extremes").detail;
}

// Code that depends on the packet width: one ray per work-item sees a bigger ball.
TEST_F(SceneCheckTest, LanesThatDisagreeWithSingleRaysFail) {
    Scene scene = ball("return v3_length(p) - (FGR_WIDTH == 1 ? 1.1f : 1.0f);");
    SceneChecker checker(shared_device(), cache_, scene, 4);
    const CheckResult agreement = checker.packet_agreement();
    EXPECT_EQ(agreement.status, CheckStatus::Failed) << agreement.detail;
    EXPECT_NE(agreement.detail.find("width 1 vs 4"), std::string::npos) << agreement.detail;
}

// A pair must give each point what scene_de gives it. One that gives the second point a DE
// nudged by a few ulps (as a pair computed in another order might) fails, naming the points;
// without a pair of its own the check is skipped.
TEST_F(SceneCheckTest, APairThatDisagreesWithTheDeFails) {
    const std::string de = "return v3_length(p) - 1.0f;";
    const Scene nudged = ball_with_pair(de,
                                        "*da = scene_de(a, PARAMS_PASS); "
                                        "*db = scene_de(b, PARAMS_PASS) * 1.0000005f;");
    const CheckResult bad = SceneChecker(shared_device(), cache_, nudged).de_pair();
    ASSERT_EQ(bad.status, CheckStatus::Failed) << bad.detail;
    EXPECT_NE(bad.detail.find("points get another DE from scene_de_pair"), std::string::npos)
        << bad.detail;
    const Scene right = ball_with_pair(de,
                                       "*da = scene_de(a, PARAMS_PASS); "
                                       "*db = scene_de(b, PARAMS_PASS);");
    const CheckResult good = SceneChecker(shared_device(), cache_, right).de_pair();
    EXPECT_EQ(good.status, CheckStatus::Passed) << good.detail;
    const Scene without = ball(de);
    EXPECT_EQ(SceneChecker(shared_device(), cache_, without).de_pair().status,
              CheckStatus::Skipped);
}

TEST_F(SceneCheckTest, ACameraThatSeesNothingFails) {
    Scene scene = ball("return v3_length(p) - 1.0f;");
    scene.cameras[1].view.target = {3.0, 2.0, 10.0};  // looking up, away from the ball
    SceneChecker checker(shared_device(), cache_, scene);
    const CheckResult cameras = checker.cameras_and_paths();
    ASSERT_EQ(cameras.status, CheckStatus::Failed) << cameras.detail;
    EXPECT_NE(cameras.detail.find("camera 'side' sees nothing"), std::string::npos)
        << cameras.detail;
}

// An inside-only scene has no DE: those checks say so and are skipped; the renders are checked.
TEST_F(SceneCheckTest, AnInsideOnlySceneSkipsTheDistanceChecks) {
    Scene scene = test::inside_ball_scene();
    scene.camera_paths.push_back(
        CameraPath{"still", {{0.0f, scene.cameras[0].view}, {1.0f, scene.cameras[0].view}}});
    const SceneCheckReport report = check(scene);
    EXPECT_TRUE(report.passed()) << failures(report);
    for (const char* name : {"hard-points", "lipschitz", "march-safety", "normals-at-hits",
                             "relaxed-steps", "packet-agreement", "de-pair", "default-view"}) {
        EXPECT_EQ(find_check(report, name).status, CheckStatus::Skipped) << name;
    }
    for (const char* name : {"hard-cameras", "parameter-extremes", "cameras-and-paths"}) {
        EXPECT_EQ(find_check(report, name).status, CheckStatus::Passed) << name;
    }
    EXPECT_NE(format_check_report(report).find("skipped"), std::string::npos);
}

}  // namespace
}  // namespace fgr
