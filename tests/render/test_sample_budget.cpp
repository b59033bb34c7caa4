// SPDX-License-Identifier: Apache-2.0
// Each render mode's sample budget (render/sample_budget.hpp): the samples a still takes unless
// told, what a sample is (a pass in the brute mode), what the viewer accumulates, which modes'
// samples differ with the seed, the limits and their errors; and that the command line's stills
// take their samples from it.

#include <gtest/gtest.h>

#include <optional>
#include <stdexcept>
#include <string>

#include "cli/commands.hpp"
#include "render/sample_budget.hpp"
#include "scene/parameters.hpp"
#include "test_scenes.hpp"

namespace fgr {
namespace {

TEST(SampleBudget, EachModeDeclaresItsStillDefaultAndWhatASampleIs) {
    EXPECT_EQ(sample_budget(RenderMode::Shaded).still, 1) << "sample 0 is the sharp image";
    EXPECT_EQ(sample_budget(RenderMode::Path).still, 64);
    EXPECT_EQ(sample_budget(RenderMode::Brute).still, 16);
    EXPECT_EQ(sample_budget(RenderMode::Shaded).unit, "samples");
    EXPECT_EQ(sample_budget(RenderMode::Path).unit, "samples");
    EXPECT_EQ(sample_budget(RenderMode::Brute).unit, "passes");
}

TEST(SampleBudget, TheViewerAccumulatesThePathTracersAndTheBrutePassesToTheirCaps) {
    EXPECT_EQ(sample_budget(RenderMode::Shaded).standing_view, 0) << "the quality setting decides";
    EXPECT_EQ(sample_budget(RenderMode::Path).standing_view, 4096);
    EXPECT_EQ(sample_budget(RenderMode::Brute).standing_view, 256);
    for (const RenderModeInfo& info : render_modes()) {
        const SampleBudget budget = sample_budget(info.mode);
        EXPECT_GE(budget.still, kMinSamples) << info.name;
        EXPECT_LE(budget.still, kMaxSamples) << info.name;
        EXPECT_LE(budget.standing_view, kMaxSamples) << info.name;
    }
}

TEST(SampleBudget, OnlyThePathTracersSamplesDifferWithTheSeed) {
    EXPECT_FALSE(sample_budget(RenderMode::Shaded).seeded);
    EXPECT_TRUE(sample_budget(RenderMode::Path).seeded);
    EXPECT_FALSE(sample_budget(RenderMode::Brute).seeded);
    // By the names part files record.
    EXPECT_TRUE(seeded_samples("path"));
    EXPECT_FALSE(seeded_samples("shaded"));
    EXPECT_FALSE(seeded_samples("brute"));
    EXPECT_FALSE(seeded_samples("no-such-mode"));
    EXPECT_FALSE(seeded_samples(""));
}

TEST(SampleBudget, AStillTakesWhatWasAskedElseTheModesDefault) {
    EXPECT_EQ(still_samples(RenderMode::Shaded, std::nullopt), 1);
    EXPECT_EQ(still_samples(RenderMode::Path, std::nullopt), 64);
    EXPECT_EQ(still_samples(RenderMode::Brute, std::nullopt), 16);
    for (const RenderModeInfo& info : render_modes()) {
        EXPECT_EQ(still_samples(info.mode, 3), 3) << info.name;
        EXPECT_EQ(still_samples(info.mode, kMinSamples), kMinSamples) << info.name;
        EXPECT_EQ(still_samples(info.mode, kMaxSamples), kMaxSamples) << info.name;
    }
}

TEST(SampleBudget, RefusesCountsOutsideOneTo4096InEveryMode) {
    EXPECT_EQ(kMinSamples, 1);
    EXPECT_EQ(kMaxSamples, 4096);
    for (const RenderModeInfo& info : render_modes()) {
        for (int samples : {0, -1, kMaxSamples + 1, 1 << 30}) {
            EXPECT_THROW(still_samples(info.mode, samples), std::invalid_argument)
                << info.name << " " << samples;
        }
    }
    EXPECT_NO_THROW(check_samples(1));
    EXPECT_NO_THROW(check_samples(4096));
    try {
        check_samples(0);
        FAIL() << "0 samples accepted";
    } catch (const std::invalid_argument& error) {
        EXPECT_EQ(std::string(error.what()), "samples per pixel must be between 1 and 4096");
    }
    EXPECT_THROW(check_samples(4097), std::invalid_argument);
}

// The command line's stills (fgr render, its tiles and parts, fgr video's frames, each MPI rank)
// take the budget's count: --spp when given, else the mode's.
TEST(SampleBudget, TheCommandLinesStillsAskIt) {
    const Scene scene = test::built_scene("mandelbulb.so");
    for (const RenderModeInfo& info : render_modes()) {
        RenderOptions options;
        options.mode.mode = std::string(info.name);
        FrameRequest request = scene_request(scene, options);
        EXPECT_EQ(still_job(scene, request, options).request.samples,
                  sample_budget(info.mode).still)
            << info.name;
        options.samples = 5;
        request = scene_request(scene, options);
        EXPECT_EQ(still_job(scene, request, options).request.samples, 5) << info.name;
    }
}

}  // namespace
}  // namespace fgr
