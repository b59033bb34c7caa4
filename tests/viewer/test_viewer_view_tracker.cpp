// SPDX-License-Identifier: Apache-2.0
// The viewer's view tracker without a window: a view whose image inputs are unchanged keeps its
// generation (the render thread goes on refining it), a change of any one of them starts a new
// generation and counts as interactive until the view settles, and the view is refined only when
// the render thread reports that generation idle with nothing pending.
#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "render/environment.hpp"
#include "scene/scene.hpp"
#include "viewer/render_worker.hpp"
#include "viewer/view_tracker.hpp"

namespace fgr::viewer {
namespace {

// The same scene and environment each time: they compare by identity.
ViewState base_state() {
    static const auto scene = std::make_shared<const Scene>();
    static const auto environment = std::make_shared<const PreparedEnvironment>();
    ViewState state;
    state.scene = scene;
    state.effects = 3;
    state.view.position = {0.0, -3.0, 0.0};
    state.params = {1.0f, 2.0f};
    state.width = 64;
    state.height = 48;
    state.mode = RenderMode::Path;
    state.path.environment = environment;
    return state;
}

// A view the settle time has passed over: not interactive, its generation being refined.
constexpr double kLater = 10.0;

TEST(ViewerViewTracker, AnUnchangedViewKeepsItsGenerationAndSettles) {
    ViewTracker tracker;
    const ViewState first = tracker.track(base_state(), 0.0, false);
    EXPECT_TRUE(first.interactive);
    const ViewState again = tracker.track(base_state(), kSettleSeconds / 2, false);
    EXPECT_EQ(again.generation, first.generation);
    EXPECT_TRUE(again.interactive);
    const ViewState settled = tracker.track(base_state(), kLater, false);
    EXPECT_EQ(settled.generation, first.generation);
    EXPECT_FALSE(settled.interactive);
}

TEST(ViewerViewTracker, EveryImageInputStartsANewGeneration) {
    const std::vector<std::pair<std::string, std::function<void(ViewState&)>>> changes = {
        {"scene", [](ViewState& s) { s.scene = std::make_shared<const Scene>(); }},
        {"effects", [](ViewState& s) { s.effects ^= 1; }},
        {"view.position", [](ViewState& s) { s.view.position.z += 1e-9; }},
        {"view.target", [](ViewState& s) { s.view.target.x += 1.0; }},
        {"view.up",
         [](ViewState& s) {
             s.view.up = {0.0f, 1.0f, 0.0f};
         }},
        {"view.fov_degrees", [](ViewState& s) { s.view.fov_degrees += 1.0f; }},
        {"projection.kind", [](ViewState& s) { s.projection.kind = ProjectionKind::Fisheye; }},
        {"projection.convergence", [](ViewState& s) { s.projection.convergence = 2.0; }},
        {"params", [](ViewState& s) { s.params[1] = 2.5f; }},
        {"width", [](ViewState& s) { s.width += 1; }},
        {"height", [](ViewState& s) { s.height += 1; }},
        {"precision", [](ViewState& s) { s.precision = Precision::Double; }},
        {"mode", [](ViewState& s) { s.mode = RenderMode::Shaded; }},
        {"path.max_bounces", [](ViewState& s) { s.path.max_bounces += 1; }},
        {"path.roulette_depth", [](ViewState& s) { s.path.roulette_depth += 1; }},
        {"path.radiance_clamp", [](ViewState& s) { s.path.radiance_clamp = 4.0f; }},
        {"path.light_sampling", [](ViewState& s) { s.path.light_sampling = false; }},
        {"path.mis", [](ViewState& s) { s.path.mis = false; }},
        {"path.environment_importance",
         [](ViewState& s) { s.path.environment_importance = false; }},
        {"path.scene_lights", [](ViewState& s) { s.path.scene_lights = false; }},
        {"path.stratified", [](ViewState& s) { s.path.stratified = false; }},
        {"path.seed", [](ViewState& s) { s.path.seed += 1; }},
        {"path.environment",
         [](ViewState& s) { s.path.environment = std::make_shared<const PreparedEnvironment>(); }},
    };
    for (const auto& [field, change] : changes) {
        ViewTracker tracker;
        const ViewState base = base_state();
        const uint64_t settled = tracker.track(base, 0.0, false).generation;
        ViewState changed = base;
        change(changed);
        const ViewState next = tracker.track(changed, kLater, false);
        EXPECT_EQ(next.generation, settled + 1) << field;
        EXPECT_TRUE(next.interactive) << field;
    }
}

TEST(ViewerViewTracker, GenerationAndInteractivityAreAnswersNotInputs) {
    ViewTracker tracker;
    const ViewState first = tracker.track(base_state(), 0.0, false);
    ViewState stamped = base_state();
    stamped.generation = first.generation + 41;
    stamped.interactive = true;
    const ViewState next = tracker.track(stamped, kLater, false);
    EXPECT_EQ(next.generation, first.generation);
    EXPECT_FALSE(next.interactive);
}

TEST(ViewerViewTracker, APlayingPathKeepsTheViewInteractive) {
    ViewTracker tracker;
    tracker.track(base_state(), 0.0, false);
    EXPECT_TRUE(tracker.track(base_state(), kLater, true).interactive);
    EXPECT_FALSE(tracker.track(base_state(), kLater, false).interactive);
}

TEST(ViewerViewTracker, RefinedOnlyWhenItsGenerationIsIdleWithNothingPending) {
    ViewTracker tracker;
    const uint64_t generation = tracker.track(base_state(), 0.0, false).generation;
    tracker.track(base_state(), kLater, false);
    WorkerStatus idle;
    idle.idle = true;
    idle.idle_generation = generation;
    EXPECT_TRUE(tracker.refined(idle));

    WorkerStatus older = idle;
    older.idle_generation = generation - 1;
    EXPECT_FALSE(tracker.refined(older));
    WorkerStatus compiling = idle;
    compiling.compiling = true;
    EXPECT_FALSE(tracker.refined(compiling));
    WorkerStatus screenshot = idle;
    screenshot.pending_screenshots = 1;
    EXPECT_FALSE(tracker.refined(screenshot));
    WorkerStatus reload = idle;
    reload.pending_reloads = 1;
    EXPECT_FALSE(tracker.refined(reload));

    tracker.scene_replaced();
    EXPECT_FALSE(tracker.refined(idle));
    tracker.track(base_state(), kLater, false);
    EXPECT_TRUE(tracker.refined(idle));

    tracker.track(base_state(), kLater + kSettleSeconds / 2, true);  // a path is playing
    EXPECT_FALSE(tracker.refined(idle));
}

}  // namespace
}  // namespace fgr::viewer
