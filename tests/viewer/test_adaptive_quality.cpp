// SPDX-License-Identifier: Apache-2.0
// Adaptive quality: the preview scale that holds the target frame time, the pass sequence from
// preview to refinement to idle, the cost average, and scaled image sizes.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

#include "viewer/adaptive_quality.hpp"

namespace fgr::viewer {
namespace {

constexpr float kScaleStep = 1.0f / 64.0f;
constexpr int64_t kFullHd = 1920 * 1080;

QualitySettings settings_with(double target_ms, int sample_cap = 16, float min_scale = 0.1f) {
    QualitySettings settings;
    settings.target_ms = target_ms;
    settings.sample_cap = sample_cap;
    settings.min_scale = min_scale;
    return settings;
}

// Time a frame at `scale` would take at the controller's current cost estimate.
double predicted_ms(const QualityController& controller, int64_t full_pixels, float scale) {
    return controller.ms_per_pixel() * static_cast<double>(full_pixels) * scale * scale;
}

TEST(QualityController, ScaleIsOneBeforeAnyMeasurement) {
    const QualityController controller(settings_with(1.0));
    EXPECT_EQ(controller.ms_per_pixel(), 0.0);
    EXPECT_EQ(controller.preview_scale(kFullHd), 1.0f);
    const RenderPass pass = controller.next_pass(true, 0, kFullHd);
    EXPECT_EQ(pass.kind, RenderPass::Kind::Preview);
    EXPECT_EQ(pass.scale, 1.0f);
}

TEST(QualityController, FirstMeasurementIsTakenAsIs) {
    QualityController controller(settings_with(33.0));
    controller.record_frame(1000, 5.0);
    EXPECT_DOUBLE_EQ(controller.ms_per_pixel(), 0.005);
}

TEST(QualityController, ScaleHitsTheTargetExactlyWhenItIsAStep) {
    // 10 ms at full size; 2.5 ms needs a quarter of the pixels: scale 0.5.
    QualityController controller(settings_with(2.5));
    controller.record_frame(kFullHd, 10.0);
    EXPECT_FLOAT_EQ(controller.preview_scale(kFullHd), 0.5f);
    EXPECT_NEAR(predicted_ms(controller, kFullHd, 0.5f), 2.5, 1e-9);
}

TEST(QualityController, ScaleRoundsDownToASixtyFourth) {
    // Frames measured at a quarter size cost the same per pixel as full ones would.
    for (const double target_ms : {3.0, 7.0, 12.5, 20.0, 29.0}) {
        QualityController controller(settings_with(target_ms));
        controller.record_frame(kFullHd / 4, 8.0);  // 32 ms at full size
        const float scale = controller.preview_scale(kFullHd);
        const double exact = std::sqrt(target_ms / 32.0);

        EXPECT_FLOAT_EQ(scale * 64.0f, std::floor(scale * 64.0f)) << target_ms;
        EXPECT_LE(scale, exact + 1e-6) << target_ms;
        EXPECT_GT(scale, exact - kScaleStep) << target_ms;
        // So the predicted frame time is at most the target, and not far below it.
        EXPECT_LE(predicted_ms(controller, kFullHd, scale), target_ms + 1e-6);
        const float next_step = scale + kScaleStep;
        EXPECT_GT(predicted_ms(controller, kFullHd, next_step), target_ms);
    }
}

TEST(QualityController, ScaleIsClampedToMinScaleAndOne) {
    QualityController slow(settings_with(1.0, 16, 0.25f));
    slow.record_frame(kFullHd, 1000.0);  // needs scale 0.03 for 1 ms
    EXPECT_FLOAT_EQ(slow.preview_scale(kFullHd), 0.25f);

    QualityController fast(settings_with(33.0));
    fast.record_frame(kFullHd, 1.0);  // full size is far under the target
    EXPECT_FLOAT_EQ(fast.preview_scale(kFullHd), 1.0f);
}

TEST(QualityController, MinScaleNeedNotBeAStep) {
    // 0.1 is not a multiple of 1/64; rounding down must not take the scale below it.
    QualityController controller(settings_with(1.0, 16, 0.1f));
    controller.record_frame(kFullHd, 1000.0);
    EXPECT_FLOAT_EQ(controller.preview_scale(kFullHd), 0.1f);
}

TEST(QualityController, UnusableMinScaleStillGivesAPositiveScale) {
    QualityController controller(settings_with(1.0, 16, 0.0f));
    controller.record_frame(kFullHd, 1e9);
    const float scale = controller.preview_scale(kFullHd);
    EXPECT_GT(scale, 0.0f);
    EXPECT_LE(scale, 1.0f);
}

TEST(QualityController, ScaleFollowsThePixelCount) {
    QualityController controller(settings_with(2.5));
    controller.record_frame(kFullHd, 10.0);
    // Four times the pixels at the same cost: half the scale again.
    EXPECT_FLOAT_EQ(controller.preview_scale(4 * kFullHd), 0.25f);
    EXPECT_EQ(controller.preview_scale(0), 1.0f);
}

TEST(QualityController, InteractivePassIsAPreviewAtThePreviewScale) {
    QualityController controller(settings_with(2.5));
    controller.record_frame(kFullHd, 10.0);
    const RenderPass pass = controller.next_pass(true, 5, kFullHd);
    EXPECT_EQ(pass.kind, RenderPass::Kind::Preview);
    EXPECT_FLOAT_EQ(pass.scale, 0.5f);
    EXPECT_EQ(pass.sample, 0);
}

TEST(QualityController, StillViewRefinesSampleBySampleThenIdles) {
    QualityController controller(settings_with(2.5, 4));
    controller.record_frame(kFullHd, 10.0);  // a reduced preview scale must not leak into refines
    for (int done = 0; done < 4; ++done) {
        const RenderPass pass = controller.next_pass(false, done, kFullHd);
        EXPECT_EQ(pass.kind, RenderPass::Kind::Refine) << done;
        EXPECT_EQ(pass.sample, done);
        EXPECT_EQ(pass.scale, 1.0f);
    }
    EXPECT_EQ(controller.next_pass(false, 4, kFullHd).kind, RenderPass::Kind::Idle);
    EXPECT_EQ(controller.next_pass(false, 9, kFullHd).kind, RenderPass::Kind::Idle);
}

TEST(QualityController, CapOfZeroStillRendersTheCentreSample) {
    const QualityController controller(settings_with(33.0, 0));
    const RenderPass first = controller.next_pass(false, 0, kFullHd);
    EXPECT_EQ(first.kind, RenderPass::Kind::Refine);
    EXPECT_EQ(first.sample, 0);
    EXPECT_EQ(controller.next_pass(false, 1, kFullHd).kind, RenderPass::Kind::Idle);
}

TEST(QualityController, CostIsAnExponentialMovingAverage) {
    QualityController controller(settings_with(33.0));
    controller.record_frame(1000, 10.0);  // 0.01 ms per pixel
    controller.record_frame(1000, 20.0);  // 0.02
    const double after_one = controller.ms_per_pixel();
    ASSERT_GT(after_one, 0.01);
    ASSERT_LT(after_one, 0.02);
    const double weight = (after_one - 0.01) / (0.02 - 0.01);

    // Each further measurement closes the same fraction of the remaining gap.
    controller.record_frame(1000, 20.0);
    const double after_two = controller.ms_per_pixel();
    EXPECT_NEAR(0.02 - after_two, (0.02 - after_one) * (1.0 - weight), 1e-12);

    for (int i = 0; i < 100; ++i) {
        controller.record_frame(500, 10.0);  // the same 0.02 per pixel at another size
    }
    EXPECT_NEAR(controller.ms_per_pixel(), 0.02, 1e-9);
}

TEST(QualityController, BadMeasurementsAreIgnored) {
    QualityController controller(settings_with(33.0));
    controller.record_frame(0, 10.0);
    controller.record_frame(-5, 10.0);
    controller.record_frame(1000, 0.0);
    controller.record_frame(1000, -1.0);
    controller.record_frame(1000, std::numeric_limits<double>::quiet_NaN());
    controller.record_frame(1000, std::numeric_limits<double>::infinity());
    EXPECT_EQ(controller.ms_per_pixel(), 0.0);

    controller.record_frame(1000, 10.0);
    controller.record_frame(1000, std::numeric_limits<double>::quiet_NaN());
    controller.record_frame(0, 1e6);
    EXPECT_DOUBLE_EQ(controller.ms_per_pixel(), 0.01);
}

TEST(QualityController, SettingsCanBeReplaced) {
    QualityController controller(settings_with(2.5));
    controller.record_frame(kFullHd, 10.0);
    controller.set_settings(settings_with(10.0, 8));
    EXPECT_EQ(controller.settings().sample_cap, 8);
    EXPECT_FLOAT_EQ(controller.preview_scale(kFullHd), 1.0f);
    EXPECT_EQ(controller.next_pass(false, 8, kFullHd).kind, RenderPass::Kind::Idle);
}

TEST(AdaptiveQuality, ScaledSizeRounds) {
    EXPECT_EQ(scaled_size(1920, 0.5f), 960);
    EXPECT_EQ(scaled_size(1080, 0.25f), 270);
    EXPECT_EQ(scaled_size(101, 0.5f), 51);  // 50.5 rounds up
    EXPECT_EQ(scaled_size(99, 0.5f), 50);   // 49.5 rounds up
    EXPECT_EQ(scaled_size(100, 0.333f), 33);
    EXPECT_EQ(scaled_size(100, 0.336f), 34);
}

TEST(AdaptiveQuality, ScaledSizeStaysWithinOneAndFull) {
    EXPECT_EQ(scaled_size(1920, 1.0f), 1920);
    EXPECT_EQ(scaled_size(1920, 2.0f), 1920);
    EXPECT_EQ(scaled_size(10, 0.01f), 1);
    EXPECT_EQ(scaled_size(10, 0.0f), 1);
    EXPECT_EQ(scaled_size(10, -1.0f), 1);
    EXPECT_EQ(scaled_size(1, 0.5f), 1);
    EXPECT_EQ(scaled_size(640, std::numeric_limits<float>::quiet_NaN()), 640);
}

}  // namespace
}  // namespace fgr::viewer
