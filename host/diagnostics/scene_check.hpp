// SPDX-License-Identifier: Apache-2.0
#pragma once
// Checking any scene's numerics, as `fgr check` does and tests/diagnostics/test_scene_stability.cpp
// does for every built scene: the DE stays finite at hard points and at every parameter's extremes,
// it is 1-Lipschitz, the march's steps never reach the surface (measured by bisection), one ray per
// work-item renders what the packets render, and every camera and camera path sees something.
// Each check reports what it measured and, when it fails, what the scene's author can change.
// Checks that need a distance estimator are skipped, with the reason, for inside-only and IFS
// scenes.
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace fgr {

enum class CheckStatus { Passed, Failed, Skipped };

struct CheckResult {
    std::string name;   // e.g. "march-safety": stable, for selecting and for tests
    std::string title;  // what holds when it passes, e.g. "march steps never reach the surface"
    CheckStatus status = CheckStatus::Passed;
    std::string detail;  // what was measured; for a skipped check, why
    std::string advice;  // a failed check: what to change, e.g. "set step_factor <= 0.76"
};

struct SceneCheckReport {
    std::string scene_id;
    // The parameters checked at other values than their defaults, as "id=value" (--set's form);
    // empty when every parameter was at its default.
    std::vector<std::string> settings;
    std::vector<CheckResult> results;
    bool passed() const;  // no check failed (skipped ones do not count)
};

// The names of the checks, in the order SceneChecker::run_all runs them.
const std::vector<std::string>& scene_check_names();

class SceneChecker {
public:
    // Builds the scene's program (shaded, or brute force for an inside-only scene) at
    // `packet_width` (0: the device's preference). The checks run at the parameter values
    // `params` (laid out as default_param_values gives them; empty: the scene's defaults), as a
    // scene's author renders it with `--set`; "the extremes" move one parameter at a time from
    // there. Throws KernelBuildError when the scene's source does not compile,
    // std::invalid_argument when `params` is not the scene's layout.
    SceneChecker(const ComputeDevice& device, ProgramCache& cache, const Scene& scene,
                 int packet_width = 0, std::vector<float> params = {});
    ~SceneChecker();

    // The DE and the shading normal are finite at the origin, the axes, huge and tiny points and
    // the default camera's eye and target. (Every check runs at the checked parameters.)
    CheckResult finite_at_hard_points();
    // Renders with the camera at the origin, through the origin, grazing and far away are finite.
    CheckResult finite_for_hard_cameras();
    // Every parameter at its minimum and maximum renders finite pixels (and a finite DE).
    CheckResult finite_at_parameter_extremes();
    // step_factor * |DE(p) - DE(q)| <= |p - q| (2% and float rounding allowed) over pairs around
    // the default view.
    CheckResult lipschitz();
    // step_factor * DE <= the distance to the surface, measured by bisection along rays (1%).
    CheckResult march_safety();
    // One ray per work-item renders the packets' image within one 8-bit level, the same hits.
    CheckResult packet_agreement();
    // The scene's own scene_de_pair gives each point what scene_de gives it (skipped without one).
    CheckResult de_pair();
    // The shading normal at every hit of the default view is finite and of unit length.
    CheckResult normals_at_hits();
    // Over-relaxed steps agree with a cautious march (no holes, no hits behind thin parts).
    CheckResult relaxed_steps();
    // Every camera and every camera path (at four times) renders finite pixels and some surface.
    CheckResult cameras_and_paths();
    // The default view hits 5-97% of pixels and is neither nearly uniform nor nearly black.
    CheckResult default_view();

    // Every check above, in scene_check_names() order; `only`, when given, runs that one check.
    SceneCheckReport run_all(const std::optional<std::string>& only = std::nullopt);

    Renderer& renderer() { return *renderer_; }

private:
    // What the Lipschitz check measured over its pairs of points (scene_check.cpp says how jumps
    // are told from steep slopes); measured once, and read again by the checks whose advice
    // depends on it.
    struct LipschitzSample {
        std::string non_finite;  // "DE is NaN at (...)" when a pair's DE is not finite
        float step_factor = 1.0f;
        size_t pairs = 0;
        float worst = 0.0f;  // the largest step_factor * |dDE| / |dp|
        glm::vec3 worst_near{0.0f};
        long violations = 0;        // pairs over the bound
        long examined = 0;          // of those, the worst, halved towards the change
        long jumps = 0;             // examined pairs that kept their difference: the DE jumps
        float largest_jump = 0.0f;  // the largest difference kept
        glm::vec3 jump_near{0.0f};
        float worst_steep = 0.0f;  // the largest ratio over the bound that is not a jump
    };
    const LipschitzSample& lipschitz_sample();
    std::string jump_text();
    // `step_advice` (lower the step factor) as it stands for a DE that is only steep; where the DE
    // jumps, the advice names the likely cause, a bailout, first.
    std::string step_factor_advice(const std::string& step_advice);

    Frame render(const CameraView& view, const std::vector<float>& params, int width = 48,
                 int height = 32);
    std::vector<glm::vec3> region_points(int count, unsigned seed) const;
    std::optional<CheckResult> skip_without_de(const std::string& name, const std::string& title);

    const ComputeDevice& device_;
    ProgramCache& cache_;
    const Scene& scene_;
    std::vector<float> params_;  // the values every check runs at
    std::unique_ptr<Renderer> renderer_;
    std::optional<LipschitzSample> lipschitz_sample_;
};

// The report as a beginner reads it: which parameter values it checked, one line per check (ok /
// FAILED / skipped), what was measured, and under each failure what to do; ends with a one-line
// verdict.
std::string format_check_report(const SceneCheckReport& report);

}  // namespace fgr
