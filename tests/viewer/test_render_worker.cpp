// SPDX-License-Identifier: Apache-2.0
// The viewer's render thread without a window: a still view is refined sample by sample to the
// cap and then left alone, a moving view gets reduced-resolution previews, a newer view abandons
// refinement of an older one, a kernel that fails to build is reported while the worker keeps
// serving other scenes, screenshots are written at full size even when stop() follows at once,
// the distance estimate at the camera is reported for the fly speed, and deep views (a deep zoom,
// or the camera flown up to the surface) render in double under auto.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <functional>
#include <future>
#include <glm/geometric.hpp>
#include <thread>

#include "child_process.hpp"
#include "deep_zoom.hpp"
#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"
#include "fgr/plugin.h"
#include "image/embedded_view.hpp"
#include "image/image_io.hpp"
#include "image_compare.hpp"
#include "mandelbulb_reference.hpp"
#include "render/precision.hpp"
#include "render/renderer.hpp"
#include "render/sample_budget.hpp"
#include "scene/ifs/ifs.hpp"
#include "scene/parameters.hpp"
#include "test_scenes.hpp"
#include "viewer/render_worker.hpp"
#include "viewer/view_still.hpp"

namespace fgr::viewer {
namespace {

using namespace std::chrono_literals;

constexpr int kSphere = 0;
constexpr int kBroken = 1;

std::vector<std::shared_ptr<const Scene>> worker_scenes() {
    Scene broken =
        test::inline_scene("real scene_de(vec3 p, PARAMS) { return undeclared_radius; }");
    broken.id = "broken";
    return {std::make_shared<const Scene>(test::sphere_scene()),
            std::make_shared<const Scene>(broken)};
}

using test::pixels_over_one_level;

class RenderWorkerTest : public ::testing::Test {
protected:
    ViewState state(int scene, int width, int height, uint64_t generation,
                    bool interactive = false) const {
        ViewState view;
        view.scene = scenes_[static_cast<size_t>(scene)];
        view.effects = view.scene->effects;
        view.view = view.scene->cameras.front().view;
        view.params = default_param_values(*view.scene);
        view.width = width;
        view.height = height;
        view.generation = generation;
        view.interactive = interactive;
        return view;
    }

    // Polls until `done` holds (collecting frames on the way) or two minutes pass.
    bool wait_for(const std::function<bool()>& done) {
        const auto deadline = std::chrono::steady_clock::now() + 120s;
        while (std::chrono::steady_clock::now() < deadline) {
            if (auto frame = worker_->take_frame()) frames_.push_back(std::move(*frame));
            if (done()) return true;
            std::this_thread::sleep_for(2ms);
        }
        return false;
    }

    bool wait_idle(uint64_t generation) {
        return wait_for([&] {
            const WorkerStatus status = worker_->status();
            return status.idle && status.idle_generation == generation;
        });
    }

    // The last frame taken of `generation`, or null when none arrived.
    const DisplayFrame* last_frame_of(uint64_t generation) const {
        for (auto frame = frames_.rbegin(); frame != frames_.rend(); ++frame) {
            if (frame->generation == generation) return &*frame;
        }
        return nullptr;
    }

    // `scene` rendered here, not by the worker: its default view at the sample cap (3).
    Frame render_directly(const Scene& scene, int width, int height) {
        FrameRequest request{width, height, scene.cameras.front().view,
                             default_param_values(scene)};
        request.samples = 3;
        ProgramCache cache{std::filesystem::path()};
        return Renderer(device(), cache, scene,
                        {preferred_packet_width(device().info), scene.effects})
            .render(request);
    }

    static ComputeDevice& device() {
        static ComputeDevice opened = open_device(-1);
        return opened;
    }

    std::vector<std::shared_ptr<const Scene>> scenes_ = worker_scenes();
    std::unique_ptr<RenderWorker> worker_ =
        std::make_unique<RenderWorker>(-1, 0, QualitySettings{33.0, 3, 0.1f});
    std::vector<DisplayFrame> frames_;
};

TEST_F(RenderWorkerTest, StillViewIsRefinedToTheSampleCapThenLeftAlone) {
    worker_->submit(state(kSphere, 64, 48, 1));
    ASSERT_TRUE(wait_idle(1));
    // Frames are handed over latest-wins, so a quick one may be superseded before it is taken.
    ASSERT_FALSE(frames_.empty());
    EXPECT_EQ(frames_.back().samples, 3);
    for (size_t i = 0; i < frames_.size(); ++i) {
        if (i > 0) {
            EXPECT_GT(frames_[i].samples, frames_[i - 1].samples);
        }
        EXPECT_EQ(frames_[i].scale, 1.0f);
        EXPECT_EQ(frames_[i].image.width, 64);
        EXPECT_EQ(frames_[i].generation, 1u);
    }
    // The accumulated image is the one a 3-sample render gives.
    ComputeDevice device = open_device(-1);
    ProgramCache cache{std::filesystem::path()};
    Renderer renderer(device, cache, *scenes_[kSphere],
                      {preferred_packet_width(device.info), scenes_[kSphere]->effects});
    FrameRequest request;
    request.width = 64;
    request.height = 48;
    request.view = scenes_[kSphere]->cameras.front().view;
    request.params = default_param_values(*scenes_[kSphere]);
    request.samples = 3;
    const Image8 expected = renderer.render(request).image;
    int largest = 0;
    for (size_t i = 0; i < expected.rgb.size(); ++i) {
        largest =
            std::max(largest, std::abs(int(expected.rgb[i]) - int(frames_.back().image.rgb[i])));
    }
    EXPECT_LE(largest, 1);
    // Idle means idle: nothing more arrives for the same view.
    std::this_thread::sleep_for(200ms);
    EXPECT_FALSE(worker_->take_frame().has_value());
}

// Under a noise threshold a standing path-traced view refines a round of adaptive sampling a
// pass, until every pixel is done, and ends on the image fgr render gives the same request.
TEST_F(RenderWorkerTest, AdaptiveSamplingRefinesInRoundsToTheStillsImage) {
    ViewState view = state(kSphere, 32, 24, 1);
    view.mode = RenderMode::Path;
    view.path.noise_threshold = 0.2f;
    view.path.min_samples = 4;
    worker_->submit(view);
    ASSERT_TRUE(wait_idle(1));
    ASSERT_FALSE(frames_.empty());
    const DisplayFrame& last = frames_.back();
    ProgramCache cache{std::filesystem::path()};
    KernelSwitches switches{preferred_packet_width(device().info), scenes_[kSphere]->effects};
    switches.mode = RenderMode::Path;
    Renderer renderer(device(), cache, *scenes_[kSphere], switches);
    FrameRequest request{32, 24, view.view, view.params};
    request.samples = kMaxSamples;  // the standing view's cap in path mode
    request.path = view.path;
    const Frame still = renderer.render(request);
    ASSERT_TRUE(still.adaptive.has_value());
    EXPECT_LT(still.adaptive->mean_spp, double(kMaxSamples));
    EXPECT_GT(still.adaptive->rounds, 1);
    int largest = 0;
    for (size_t i = 0; i < still.image.rgb.size(); ++i) {
        largest = std::max(largest, std::abs(int(still.image.rgb[i]) - int(last.image.rgb[i])));
    }
    EXPECT_LE(largest, 1);
}

// A scene whose parameter may be compiled in is shown by the generic kernel while the specialised
// one builds on its own thread (held at the gate here, so the order is certain), then by the
// specialised one, which draws the same image.
TEST_F(RenderWorkerTest, TheGenericKernelShowsUntilTheSpecialisedOneIsBuilt) {
    auto specialisable = std::make_shared<const Scene>(
        test::inline_scene("#define FGR_SPECIALISABLE iterations\n"
                           "real scene_de(vec3 p, PARAMS) {\n"
                           "    return v3_length(p) - 0.05f * (float)param_iterations;\n"
                           "}\n"));
    std::promise<void> release;
    std::shared_future<void> released = release.get_future().share();
    std::atomic<bool> at_gate{false};
    worker_->set_specialise_gate([&at_gate, released] {
        at_gate = true;
        released.wait();
    });
    ViewState view = state(kSphere, 32, 24, 1);
    view.scene = specialisable;
    view.effects = specialisable->effects;
    view.params = default_param_values(*specialisable);
    worker_->submit(view);
    // Refined to the sample cap while the specialised build waits at the gate.
    ASSERT_TRUE(wait_idle(1));
    ASSERT_TRUE(wait_for([&] { return at_gate.load(); }));
    EXPECT_TRUE(worker_->status().specialising);
    ASSERT_FALSE(frames_.empty());
    for (const DisplayFrame& frame : frames_) EXPECT_FALSE(frame.specialised);
    const DisplayFrame generic = frames_.back();
    EXPECT_EQ(generic.samples, 3);
    frames_.clear();
    release.set_value();
    ASSERT_TRUE(wait_for([&] {
        return !frames_.empty() && frames_.back().specialised && frames_.back().samples == 3;
    }));
    EXPECT_FALSE(worker_->status().specialising);
    EXPECT_EQ(frames_.back().image.rgb, generic.image.rgb);
}

// An IFS scene's frames say how deep the image went, for the viewer's status line: the depth
// slider's value where the footprint does not stop it sooner, and every refined sample keeps
// the level sample 0 reported. A DE scene reports none.
TEST_F(RenderWorkerTest, IfsFramesReportTheDepthReached) {
    const auto sponge = std::make_shared<const Scene>(ifs_scene_to_scene(
        read_ifs_file(std::filesystem::path(FGR_TEST_PLUGIN_DIR) / "menger.ifs.json"),
        "menger.ifs.json"));
    for (const int depth : {1, 3}) {
        ViewState view = state(kSphere, 64, 48, uint64_t(depth));
        view.scene = sponge;
        view.effects = sponge->effects;
        view.view = sponge->cameras.front().view;
        view.params = default_param_values(*sponge);
        set_param_from_text(*sponge, view.params, "ifs_depth=" + std::to_string(depth));
        worker_->submit(view);
        ASSERT_TRUE(wait_idle(uint64_t(depth)));
        const DisplayFrame* last = last_frame_of(uint64_t(depth));
        ASSERT_NE(last, nullptr);
        EXPECT_EQ(last->samples, 3);
        EXPECT_EQ(last->ifs_depth_reached, depth);
    }
    worker_->submit(state(kSphere, 64, 48, 10));
    ASSERT_TRUE(wait_idle(10));
    ASSERT_NE(last_frame_of(10), nullptr);
    EXPECT_EQ(last_frame_of(10)->ifs_depth_reached, -1);
}

TEST_F(RenderWorkerTest, MovingViewGetsPreviewsAtTheResolutionThatHoldsTheTarget) {
    worker_->set_quality({0.5, 3, 0.1f});  // a target no full frame can meet
    worker_->submit(state(kSphere, 256, 192, 1));
    ASSERT_TRUE(wait_idle(1));  // measures the cost per pixel
    frames_.clear();
    for (uint64_t generation = 2; generation < 6; ++generation) {
        ViewState moving = state(kSphere, 256, 192, generation, true);
        moving.view.position.x += 0.01f * static_cast<float>(generation);
        worker_->submit(moving);
        ASSERT_TRUE(
            wait_for([&] { return !frames_.empty() && frames_.back().generation == generation; }));
    }
    for (const DisplayFrame& frame : frames_) {
        EXPECT_LT(frame.scale, 1.0f);
        EXPECT_GE(frame.scale, 0.1f);
        EXPECT_EQ(frame.samples, 1);
        EXPECT_EQ(frame.image.width, scaled_size(256, frame.scale));
        EXPECT_EQ(frame.image.height, scaled_size(192, frame.scale));
    }
    // An interactive view already previewed is not rendered again until it changes.
    frames_.clear();
    std::this_thread::sleep_for(200ms);
    EXPECT_FALSE(worker_->take_frame().has_value());
}

TEST_F(RenderWorkerTest, ANewerViewAbandonsRefiningTheOlderOne) {
    worker_->set_quality({33.0, 1000, 0.1f});
    worker_->submit(state(kSphere, 320, 240, 1));
    ASSERT_TRUE(wait_for([&] { return !frames_.empty(); }));
    ViewState moved = state(kSphere, 320, 240, 2);
    moved.view.position.z += 0.5f;
    worker_->submit(moved);
    ASSERT_TRUE(
        wait_for([&] { return frames_.back().generation == 2 && frames_.back().samples >= 2; }));
    // Once the newer view shows, no frame of the older one follows; its refinement (1000
    // samples) was abandoned, or the test would have timed out waiting.
    bool seen_new = false;
    for (const DisplayFrame& frame : frames_) {
        seen_new |= frame.generation == 2;
        if (seen_new) {
            EXPECT_EQ(frame.generation, 2u);
        }
    }
}

TEST_F(RenderWorkerTest, ABrokenKernelIsReportedAndOtherScenesStillRender) {
    worker_->submit(state(kBroken, 32, 24, 1));
    ASSERT_TRUE(wait_idle(1));
    WorkerStatus status = worker_->status();
    EXPECT_NE(status.error.find("broken"), std::string::npos) << status.error;
    EXPECT_NE(status.error_log.find("undeclared_radius"), std::string::npos) << status.error_log;
    EXPECT_TRUE(frames_.empty());
    const std::vector<std::string> messages = worker_->take_messages();
    ASSERT_EQ(messages.size(), 1u);

    worker_->submit(state(kSphere, 32, 24, 2));
    ASSERT_TRUE(wait_idle(2));
    EXPECT_FALSE(frames_.empty());
    EXPECT_TRUE(worker_->status().error.empty());
    // Going back does not rebuild: the failure is remembered, not retried on every change.
    worker_->submit(state(kBroken, 32, 24, 3));
    ASSERT_TRUE(wait_idle(3));
    EXPECT_FALSE(worker_->status().error.empty());
    EXPECT_TRUE(worker_->take_messages().empty());
}

TEST_F(RenderWorkerTest, ChangingTheEffectsBuildsTheirKernelAndChangesTheImage) {
    worker_->submit(state(kSphere, 48, 36, 1));
    ASSERT_TRUE(wait_idle(1));
    ASSERT_NE(last_frame_of(1), nullptr) << "no frame of the plain view";
    const Image8 plain = last_frame_of(1)->image;
    ViewState glowing = state(kSphere, 48, 36, 2);
    glowing.effects = FGR_EFFECT_GLOW;  // near misses around the sphere light up
    worker_->submit(glowing);
    ASSERT_TRUE(wait_idle(2));
    EXPECT_TRUE(worker_->status().error.empty()) << worker_->status().error;
    ASSERT_NE(last_frame_of(2), nullptr) << "no frame with glow";
    EXPECT_EQ(frames_.back().generation, 2u);
    EXPECT_GT(pixels_over_one_level(last_frame_of(2)->image, plain), 20);
}

TEST_F(RenderWorkerTest, AReloadIsBuiltBeforeItIsAcceptedAndABrokenOneIsRefused) {
    Scene bigger = *scenes_[kSphere];
    bigger.source = "real scene_de(vec3 p, PARAMS) { return v3_length(p) - 2.0f * param_radius; }";
    Scene broken = *scenes_[kSphere];
    broken.source = "real scene_de(vec3 p, PARAMS) { return v3_length(p) - missing_name; }";
    worker_->request_reload({std::make_shared<const Scene>(bigger), scenes_[kSphere], 0});
    worker_->request_reload({std::make_shared<const Scene>(broken), scenes_[kSphere], 0});
    std::vector<ReloadResult> results;
    ASSERT_TRUE(wait_for([&] {
        for (ReloadResult& result : worker_->take_reloads()) results.push_back(std::move(result));
        return results.size() == 2 && worker_->status().pending_reloads == 0;
    }));
    EXPECT_TRUE(results[0].ok) << results[0].error;
    EXPECT_FALSE(results[1].ok);
    EXPECT_NE(results[1].error.find(scenes_[kSphere]->id), std::string::npos);
    EXPECT_NE(results[1].error_log.find("missing_name"), std::string::npos);
    // The accepted version renders what it says: a sphere twice the size fills more pixels.
    ViewState before = state(kSphere, 48, 36, 1);
    worker_->submit(before);
    ASSERT_TRUE(wait_idle(1));
    ASSERT_NE(last_frame_of(1), nullptr);
    const Frame small = render_directly(*scenes_[kSphere], 48, 36);
    EXPECT_EQ(pixels_over_one_level(last_frame_of(1)->image, small.image), 0);
    ViewState after = before;
    after.scene = results[0].request.candidate;
    after.generation = 2;
    worker_->submit(after);
    ASSERT_TRUE(wait_idle(2));
    ASSERT_NE(last_frame_of(2), nullptr) << "the accepted version rendered nothing";
    const Frame big = render_directly(*results[0].request.candidate, 48, 36);
    EXPECT_GT(big.hits, small.hits);
    EXPECT_EQ(pixels_over_one_level(last_frame_of(2)->image, big.image), 0);
}

TEST_F(RenderWorkerTest, ScreenshotsAreFinishedBeforeStopReturns) {
    test::TempDir dir("fgr_worker_test");
    ScreenshotRequest request;
    request.scene = scenes_[kSphere];
    request.view = view_of_state(state(kSphere, 120, 90, 1), EnvironmentChoice{}, 4);
    request.file = dir.path() / "shot.png";
    worker_->request_screenshot(request);
    worker_->stop();
    const Image8 shot = read_png(dir.path() / "shot.png");
    EXPECT_EQ(shot.width, 120);
    EXPECT_EQ(shot.height, 90);
    EXPECT_EQ(read_embedded_view(dir.path() / "shot.png"), view_file_text(request.view))
        << "the screenshot carries its view";
    const std::vector<std::string> messages = worker_->take_messages();
    ASSERT_EQ(messages.size(), 1u);
    EXPECT_NE(messages[0].find("shot.png"), std::string::npos);
}

TEST_F(RenderWorkerTest, ReportsTheDistanceEstimateAtTheCamera) {
    EXPECT_LT(worker_->status().de_at_camera, 0.0f) << "unknown before the first frame";
    worker_->submit(state(kSphere, 16, 12, 1));
    ASSERT_TRUE(wait_idle(1));
    // The camera is 3 from the centre of a sphere of radius 0.4.
    EXPECT_NEAR(worker_->status().de_at_camera, 2.6f, 1e-4f);
}

class RenderWorkerPrecision : public RenderWorkerTest {
protected:
    // The Mandelbulb seen through `view` at 96x72 under `precision`, refined to the sample cap
    // (3), with a fine hit threshold (0.001) so that float and double images differ even in the
    // default view: whether the worker's image is the double renderer's. Its frame's flag is a
    // label; the pixels say which precision was used. The worker's image must match exactly one
    // of the two renderers' (within one level at every pixel), and the label must agree.
    bool renders_in_double(const CameraView& view, Precision precision) {
        constexpr int width = 96, height = 72;
        ViewState bulb;
        bulb.scene = bulb_;
        bulb.effects = bulb_->effects;
        bulb.view = view;
        bulb.params = default_param_values(*bulb_);
        set_param_from_text(*bulb_, bulb.params, "hit_threshold=0.001");
        bulb.width = width;
        bulb.height = height;
        bulb.precision = precision;
        bulb.generation = ++generation_;
        worker_->submit(bulb);
        EXPECT_TRUE(wait_idle(generation_));
        EXPECT_TRUE(worker_->status().error.empty()) << worker_->status().error;
        const DisplayFrame* frame = last_frame_of(generation_);
        if (frame == nullptr) {
            ADD_FAILURE() << "no frame of this view arrived";
            return false;
        }
        EXPECT_EQ(frame->samples, 3);
        FrameRequest request{width, height, view, bulb.params};
        request.samples = 3;
        Image8 images[2];
        for (bool in_double : {false, true}) {
            ProgramCache cache{std::filesystem::path()};
            images[in_double] =
                Renderer(device(), cache, *bulb_,
                         with_precision({preferred_packet_width(device().info), bulb_->effects},
                                        in_double))
                    .render(request)
                    .image;
        }
        const long apart = pixels_over_one_level(images[0], images[1]);
        EXPECT_GT(apart, 10) << "this view cannot tell float from double";
        const bool like_float = pixels_over_one_level(frame->image, images[0]) == 0;
        const bool like_double = pixels_over_one_level(frame->image, images[1]) == 0;
        EXPECT_NE(like_float, like_double)
            << "the image is neither float's nor double's (" << apart << " pixels tell them apart)";
        EXPECT_EQ(frame->double_precision, like_double) << "the frame's label is not what rendered";
        std::printf(
            "float and double differ in %ld pixels; the worker's image is %s's (label %s)\n", apart,
            like_double  ? "double"
            : like_float ? "float"
                         : "neither",
            frame->double_precision ? "double" : "float");
        return like_double;
    }

    std::shared_ptr<const Scene> bulb_ =
        std::make_shared<const Scene>(test::built_scene("mandelbulb.so"));
    uint64_t generation_ = 0;
};

TEST_F(RenderWorkerPrecision, ADeepZoomRendersInDoubleUnderAutoAndInFloatWhenAskedTo) {
    const CameraView deep = test::mandelbulb_deep_zoom(*bulb_, 1e-7);
    const CameraView canonical = bulb_->cameras.front().view;
    EXPECT_TRUE(renders_in_double(deep, Precision::Auto));
    EXPECT_FALSE(renders_in_double(deep, Precision::Float));
    EXPECT_FALSE(renders_in_double(canonical, Precision::Auto));
    EXPECT_TRUE(renders_in_double(canonical, Precision::Double));
}

// Flying in keeps the fly camera's target far ahead; the camera's nearness to the surface (its
// DE) still switches to double, and the DE that sets the fly speed is then probed in double:
// exact to the surface's own rounding, where float's is off by about a percent.
TEST_F(RenderWorkerPrecision, FlyingUpToTheSurfaceSwitchesToDoubleAndProbesInDouble) {
    const CameraView deep = test::mandelbulb_deep_zoom(*bulb_);
    const CameraView canonical = bulb_->cameras.front().view;
    CameraView flown = canonical;
    flown.position = deep.position;
    flown.target = deep.position + glm::normalize(deep.target - deep.position) *
                                       glm::length(canonical.target - canonical.position);
    EXPECT_TRUE(renders_in_double(flown, Precision::Auto));
    const long double reference = test::mandelbulb_de<long double>(
        flown.position.x, flown.position.y, flown.position.z, test::BulbParams{});
    ASSERT_GT(reference, 0.0L);
    ASSERT_LT(reference, test::kDeepZoomStandoff * 1.01);
    EXPECT_NEAR(worker_->status().de_at_camera, double(reference), 1e-3 * double(reference));
}

// A standing path view's refine pass takes as many regrouped samples as fit in the target frame
// time (the cost per pixel sample measured so far), at most a regrouped launch's and what the cap
// leaves; one with the packet kernel, in other modes and before any measurement.
TEST(RenderWorkerPasses, RegroupedPathPassesFitTheTargetFrameTime) {
    ViewState view;
    view.scene = std::make_shared<const Scene>(test::sphere_scene());
    view.width = 100;
    view.height = 100;
    view.mode = RenderMode::Path;
    const double per_sample = 5.0 / 10000.0;  // 5 ms a sample of the 100x100 view
    EXPECT_EQ(refine_pass_samples(view, 0, 4096, per_sample, 33.0), 6);
    EXPECT_EQ(refine_pass_samples(view, 4093, 4096, per_sample, 33.0), 3);
    EXPECT_EQ(refine_pass_samples(view, 8, 4096, per_sample / 100.0, 33.0), kRegroupLaunchSamples);
    EXPECT_EQ(refine_pass_samples(view, 8, 4096, per_sample * 10.0, 33.0), 1);
    EXPECT_EQ(refine_pass_samples(view, 8, 4096, 0.0, 33.0), 1);
    view.path.regroup = false;
    EXPECT_EQ(refine_pass_samples(view, 0, 4096, per_sample, 33.0), 1);
    view.path.regroup = true;
    view.mode = RenderMode::Shaded;
    EXPECT_EQ(refine_pass_samples(view, 0, 4096, per_sample, 33.0), 1);
}

}  // namespace
}  // namespace fgr::viewer
