// SPDX-License-Identifier: Apache-2.0
// Rendering: the canonical view against a scalar C++ march, the same image at every packet width,
// determinism, partial tiles, lighting, and parameters and camera paths reaching the image.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "camera/camera.hpp"
#include "device/kernel_assembly.hpp"
#include "device/program_cache.hpp"
#include "image_compare.hpp"
#include "mandelbulb_reference.hpp"
#include "random_points.hpp"
#include "render/renderer.hpp"
#include "scene/parameters.hpp"
#include "test_scenes.hpp"

namespace fgr {
namespace {

class RenderTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        device_ = new ComputeDevice(open_device(-1));
        mandelbulb_ = new Scene(test::built_scene("mandelbulb.so"));
    }
    static void TearDownTestSuite() {
        delete mandelbulb_;
        delete device_;
    }

    Frame render(const Scene& scene, int width, int height, int packet_width = 0,
                 const std::vector<std::string>& assignments = {}) {
        FrameRequest request{width, height, scene.cameras.front().view,
                             default_param_values(scene)};
        for (const auto& assignment : assignments)
            set_param_from_text(scene, request.params, assignment);
        return render(scene, request, packet_width);
    }

    Frame render(const Scene& scene, const FrameRequest& request, int packet_width = 0) {
        const int width = packet_width ? packet_width : preferred_packet_width(device_->info);
        Renderer renderer(*device_, cache_, scene, {width, scene.effects});
        return renderer.render(request);
    }

    static ComputeDevice* device_;
    static Scene* mandelbulb_;
    ProgramCache cache_{std::filesystem::path()};
};
ComputeDevice* RenderTest::device_ = nullptr;
Scene* RenderTest::mandelbulb_ = nullptr;

using test::mean_abs_difference;

TEST_F(RenderTest, CanonicalViewHitsMatchAScalarReferenceMarch) {
    const long expected = test::canonical_view_hits(160, 120, test::BulbParams{});
    const Frame frame = render(*mandelbulb_, 160, 120);
    ASSERT_GT(expected, 160 * 120 / 10);
    EXPECT_NEAR(static_cast<double>(frame.hits), static_cast<double>(expected),
                static_cast<double>(expected) * 0.005);
}

// Packets only group rays: every pixel must come out as one ray per work-item renders it, within
// one 8-bit level (the same maths rounded in another order), hit or missed alike.
void expect_same_pixels(const Frame& packets, const Frame& scalar, const std::string& what) {
    ASSERT_EQ(packets.image.rgb.size(), scalar.image.rgb.size()) << what;
    ASSERT_EQ(packets.depth.size(), scalar.depth.size()) << what;
    const int width = packets.image.width;
    long over_one = 0, hit_mismatch = 0;
    for (size_t pixel = 0; pixel < scalar.depth.size(); ++pixel) {
        const int x = int(pixel) % width, y = int(pixel) / width;
        const bool hit = packets.depth[pixel] >= 0.0f, scalar_hit = scalar.depth[pixel] >= 0.0f;
        if (hit != scalar_hit && hit_mismatch++ < 5) {
            ADD_FAILURE() << what << ": pixel (" << x << ", " << y << ") "
                          << (hit ? "hit" : "missed") << " with packets only";
        }
        for (size_t c = 0; c < 3; ++c) {
            const int a = packets.image.rgb[3 * pixel + c], b = scalar.image.rgb[3 * pixel + c];
            if (std::abs(a - b) > 1 && over_one++ < 5) {
                ADD_FAILURE() << what << ": pixel (" << x << ", " << y << ") channel " << c
                              << " is " << a << " with packets, " << b << " one ray per item";
            }
        }
    }
    EXPECT_EQ(hit_mismatch, 0) << what;
    EXPECT_EQ(over_one, 0) << what << ": channels more than one level apart";
}

// A scene written with plain literals, as the maths reads (`p * 2.0`), builds in float and in
// double and renders exactly what the same scene with float literals (`2.0f`) renders: float
// builds make the literals single precision, double builds keep them double (their values here
// are exact in both, so the two sources must agree to the bit in each precision).
TEST_F(RenderTest, PlainLiteralsWorkInFloatAndDouble) {
    const auto ball = [](const std::string& two, const std::string& half,
                         const std::string& radius) {
        return test::inline_scene(
            "real scene_de(vec3 p, PARAMS) {\n    (void)fgr_params;\n"
            "    return v3_length(v3_scale(p, " +
            two + ")) * " + half + " - " + radius + ";\n}\n");
    };
    const Scene plain = ball("2.0", "0.5", "0.75");
    const Scene suffixed = ball("2.0f", "0.5f", "0.75f");
    for (const bool in_double : {false, true}) {
        SCOPED_TRACE(in_double ? "double" : "float");
        KernelSwitches switches{16, 0};
        switches.double_precision = in_double;
        const FrameRequest request{48, 36, plain.cameras.front().view, default_param_values(plain)};
        Renderer plain_renderer(*device_, cache_, plain, switches);
        Renderer suffixed_renderer(*device_, cache_, suffixed, switches);
        const Frame a = plain_renderer.render(request);
        const Frame b = suffixed_renderer.render(request);
        EXPECT_GT(a.hits, 48 * 36 / 10);
        EXPECT_EQ(a.depth, b.depth);
        EXPECT_EQ(a.image.rgb, b.image.rgb);
    }
}

TEST_F(RenderTest, EveryPacketWidthRendersTheSameImage) {
    const Frame scalar = render(*mandelbulb_, 64, 48, 1);
    ASSERT_GT(scalar.hits, 64 * 48 / 4);
    for (int width : {4, 8, 16}) {
        expect_same_pixels(render(*mandelbulb_, 64, 48, width), scalar,
                           "width " + std::to_string(width));
    }
}

// 37 x 23 leaves partial tiles on the right and at the bottom for every packet shape (2x2, 4x2,
// 4x4): they must render like the rest, so the view is narrowed until the bulb reaches the last
// column and the last row.
TEST_F(RenderTest, PartialTilesAtOddSizesMatchOneRayPerWorkItem) {
    constexpr int kW = 37, kH = 23;
    FrameRequest request{kW, kH, mandelbulb_->cameras.front().view,
                         default_param_values(*mandelbulb_)};
    request.view.fov_degrees = 30.0f;
    const Frame scalar = render(*mandelbulb_, request, 1);
    int last_column = 0, last_row = 0;
    for (int y = 0; y < kH; ++y) last_column += scalar.depth[size_t(y * kW + kW - 1)] >= 0.0f;
    for (int x = 0; x < kW; ++x) last_row += scalar.depth[size_t((kH - 1) * kW + x)] >= 0.0f;
    ASSERT_GT(last_column, kH / 3) << "the surface must reach the partial tiles on the right";
    ASSERT_GT(last_row, kW / 3) << "the surface must reach the partial tiles at the bottom";
    for (int width : {4, 8, 16}) {
        const Frame packets = render(*mandelbulb_, request, width);
        ASSERT_EQ(packets.image.rgb.size(), size_t(kW * kH * 3));
        expect_same_pixels(packets, scalar, "37x23 at width " + std::to_string(width));
    }
}

// The Mandelbulb gives its DE at two points in one loop (scene_de_pair), so the shaded kernel
// takes two tiles a work-item and marches them together. Without the pair (the same source, its
// pair renamed away) each tile marches alone and every DE is a call of its own: the images,
// depths and step counts must be the same to the bit. Sizes with an odd number of tiles leave a
// last pair without its second tile.
TEST_F(RenderTest, PairedTilesRenderExactlyWhatOneTileAWorkItemRenders) {
    Scene unpaired = *mandelbulb_;
    for (const auto& [from, to] :
         {std::pair<std::string, std::string>{"FGR_SCENE_HAS_DE_PAIR", "FGR_SCENE_PAIR_UNUSED"},
          {"scene_de_pair", "unused_de_pair"}}) {
        for (size_t at = unpaired.source.find(from); at != std::string::npos;
             at = unpaired.source.find(from, at + to.size())) {
            unpaired.source.replace(at, from.size(), to);
        }
    }
    ASSERT_TRUE(mandelbulb_->pairs_distances());
    ASSERT_FALSE(unpaired.pairs_distances());
    // Tiles of 2x2, 4x2 and 4x4 lanes: 36x20 has 45 tiles of 4x4, 37x23 has 12x10 of 2x2 and
    // 10x6 of 4x4 (partial ones at the edges), 44x26 has 11x13 of 4x2.
    for (int width : {4, 8, 16}) {
        KernelSwitches switches{width, mandelbulb_->effects};
        switches.stats = true;
        ASSERT_TRUE(pairs_tiles(*mandelbulb_, switches));
        ASSERT_FALSE(pairs_tiles(unpaired, switches));
        Renderer paired_renderer(*device_, cache_, *mandelbulb_, switches);
        Renderer alone_renderer(*device_, cache_, unpaired, switches);
        for (const auto& [w, h] : {std::pair{36, 20}, {37, 23}, {44, 26}}) {
            FrameRequest request{w, h, mandelbulb_->cameras.front().view,
                                 default_param_values(*mandelbulb_)};
            request.view.fov_degrees = 30.0f;
            request.samples = 2;
            const Frame paired = paired_renderer.render(request);
            const Frame alone = alone_renderer.render(request);
            const std::string what = fmt::format("{}x{} at width {}", w, h, width);
            ASSERT_GT(alone.hits, w * h / 4) << what;
            EXPECT_EQ(paired.linear, alone.linear) << what;
            EXPECT_EQ(paired.depth, alone.depth) << what;
            ASSERT_TRUE(paired.stats && alone.stats) << what;
            EXPECT_EQ(paired.stats->de_evaluations, alone.stats->de_evaluations) << what;
            EXPECT_EQ(paired.stats->lane_steps, alone.stats->lane_steps) << what;
        }
        // Normals anywhere in the bulb's box, coarse and fine: the stencil's taps take their DEs
        // in pairs, one tap's orbit often escaping long before the other's, whose iterations then
        // go on alone.
        const std::vector<float> params = default_param_values(*mandelbulb_);
        const std::vector<glm::vec3> points = test::random_points(2000, 1.2f, 11);
        for (const float eps : {0.03f, 1e-3f}) {
            EXPECT_EQ(paired_renderer.probe_normals(points, params, eps),
                      alone_renderer.probe_normals(points, params, eps))
                << "width " << width << ", eps " << eps;
        }
    }
}

TEST_F(RenderTest, SameSettingsGiveBitIdenticalImages) {
    const Frame first = render(*mandelbulb_, 64, 48);
    const Frame second = render(*mandelbulb_, 64, 48);
    EXPECT_EQ(first.image.rgb, second.image.rgb);
    EXPECT_EQ(first.depth, second.depth);
}

// A renderer keeps its planes' buffer between frames: a frame larger than the last, and one
// smaller, come out as a fresh renderer draws them, in every mode (each writes planes of its own).
TEST_F(RenderTest, OneRendererDrawsFramesOfChangingSizesAsFreshOnesDo) {
    for (const RenderMode mode : {RenderMode::Shaded, RenderMode::Path, RenderMode::Brute}) {
        KernelSwitches switches{preferred_packet_width(device_->info), mandelbulb_->effects};
        switches.mode = mode;
        switches.aovs = true;
        Renderer kept(*device_, cache_, *mandelbulb_, switches);
        for (const auto& [width, height] : {std::pair{32, 24}, {72, 56}, {40, 30}, {72, 56}}) {
            FrameRequest request{width, height, mandelbulb_->cameras.front().view,
                                 default_param_values(*mandelbulb_)};
            request.samples = mode == RenderMode::Shaded ? 1 : 4;
            const Frame again = kept.render(request);
            const Frame fresh = Renderer(*device_, cache_, *mandelbulb_, switches).render(request);
            const std::string what = fmt::format("{} {}x{}", render_mode_name(mode), width, height);
            EXPECT_EQ(again.image.rgb, fresh.image.rgb) << what;
            EXPECT_EQ(again.depth, fresh.depth) << what;
            EXPECT_EQ(again.albedo, fresh.albedo) << what;
            EXPECT_EQ(again.normal, fresh.normal) << what;
        }
    }
}

TEST_F(RenderTest, DefaultViewIsANonTrivialImage) {
    const Frame frame = render(*mandelbulb_, 80, 60);
    const double hit_fraction = double(frame.hits) / (80 * 60);
    EXPECT_GT(hit_fraction, 0.3);
    EXPECT_LT(hit_fraction, 0.8);
    EXPECT_LT(frame.depth[0], 0.0f);             // the corner sees the sky
    EXPECT_GT(frame.depth[30 * 80 + 40], 0.0f);  // the centre sees the bulb
    std::set<uint8_t> greys(frame.image.rgb.begin(), frame.image.rgb.end());
    EXPECT_GT(greys.size(), 100u);  // shaded, not flat
    for (float depth : frame.depth) ASSERT_FALSE(std::isnan(depth));
}

TEST_F(RenderTest, ParametersChangeTheImage) {
    const Frame power8 = render(*mandelbulb_, 64, 48);
    const Frame power4 = render(*mandelbulb_, 64, 48, 0, {"power=4"});
    const Frame latitude = render(*mandelbulb_, 64, 48, 0, {"variant=latitude"});
    EXPECT_NE(power8.hits, power4.hits);
    EXPECT_GT(mean_abs_difference(power8.image, power4.image), 5.0);
    EXPECT_GT(mean_abs_difference(power8.image, latitude.image), 5.0);
}

TEST_F(RenderTest, CameraPathStartRendersItsFirstKeyframe) {
    const CameraPath* orbit = mandelbulb_->find_camera_path("orbit");
    ASSERT_NE(orbit, nullptr);
    FrameRequest request{64, 48, evaluate_camera_path(*orbit, 0.0f),
                         default_param_values(*mandelbulb_)};
    const Frame start = render(*mandelbulb_, request);
    // Same view up to float rounding of the re-orthogonalised basis.
    EXPECT_LT(mean_abs_difference(start.image, render(*mandelbulb_, 64, 48).image), 0.1);
    request.view = evaluate_camera_path(*orbit, 3.0f);
    EXPECT_GT(mean_abs_difference(render(*mandelbulb_, request).image, start.image), 5.0);
}

TEST_F(RenderTest, SurfacesFacingTheLightAreBrighter) {
    Scene sphere = test::sphere_scene();
    sphere.lights = {Light{LightType::Directional, {0.0f, 0.0f, 1.0f}, {1.0f, 1.0f, 1.0f}, 1.0f}};
    const Frame frame = render(sphere, 64, 64);
    auto brightness = [&](int x, int y) {
        const size_t i = (static_cast<size_t>(y) * 64 + x) * 3;
        return frame.image.rgb[i] + frame.image.rgb[i + 1] + frame.image.rgb[i + 2];
    };
    // The sphere (radius 0.4 at distance 3, 60 degree view) covers the middle ~30 pixels.
    ASSERT_GT(frame.depth[26 * 64 + 32], 0.0f);
    ASSERT_GT(frame.depth[38 * 64 + 32], 0.0f);
    EXPECT_GT(brightness(32, 26), brightness(32, 38) + 100);
    // Lit from above: the top of the sphere must be near the surface colour, the bottom ambient.
    EXPECT_LT(brightness(32, 38), 3 * 90);
}

}  // namespace
}  // namespace fgr

namespace fgr {
namespace {

TEST_F(RenderTest, SampleProgressIsReportedInOrderAndChangesNothing) {
    FrameRequest request{32, 24, mandelbulb_->cameras.front().view,
                         default_param_values(*mandelbulb_), 5};
    const Frame quiet = render(*mandelbulb_, request);
    std::vector<std::pair<int, int>> reports;
    request.on_sample = [&](int done, int total) { reports.emplace_back(done, total); };
    const Frame reported = render(*mandelbulb_, request);
    ASSERT_EQ(reports.size(), 5u);
    for (int i = 0; i < 5; ++i) EXPECT_EQ(reports[i], std::make_pair(i + 1, 5));
    EXPECT_EQ(reported.image.rgb, quiet.image.rgb);
}

// The viewer refines one sample at a time: samples rendered singly from first_sample k and averaged
// must give the image one multi-sample render gives.
TEST_F(RenderTest, SamplesRenderedOneAtATimeAverageToTheMultiSampleImage) {
    FrameRequest request{48, 36, mandelbulb_->cameras.front().view,
                         default_param_values(*mandelbulb_), 4};
    const Frame together = render(*mandelbulb_, request);
    std::vector<float> sum(together.linear.size(), 0.0f);
    for (int sample = 0; sample < 4; ++sample) {
        request.samples = 1;
        request.first_sample = sample;
        const Frame single = render(*mandelbulb_, request);
        for (size_t i = 0; i < sum.size(); ++i) sum[i] += single.linear[i];
        if (sample > 0) {
            EXPECT_EQ(single.hits, 0) << "depth comes from sample 0 only";
        }
    }
    double largest = 0.0;
    for (size_t i = 0; i < sum.size(); ++i) {
        largest = std::max(largest, double(std::abs(sum[i] / 4.0f - together.linear[i])));
    }
    EXPECT_LT(largest, 1e-5);
    // A jittered sample on its own differs from the centre sample somewhere.
    request.first_sample = 0;
    const Frame centre = render(*mandelbulb_, request);
    request.first_sample = 1;
    EXPECT_NE(render(*mandelbulb_, request).linear, centre.linear);
}

TEST_F(RenderTest, CancelStopsAFrameAndANeverCancellingHookChangesNothing) {
    FrameRequest request{64, 48, mandelbulb_->cameras.front().view,
                         default_param_values(*mandelbulb_)};
    const Frame plain = render(*mandelbulb_, request);
    int polls = 0;
    request.cancel = [&] { return ++polls > 3; };
    const Frame stopped = render(*mandelbulb_, request);
    EXPECT_TRUE(stopped.cancelled);
    EXPECT_TRUE(stopped.image.rgb.empty());
    EXPECT_EQ(polls, 4) << "polled once per band until it said stop";
    polls = 0;
    request.cancel = [&] {
        ++polls;
        return false;
    };
    const Frame banded = render(*mandelbulb_, request);
    EXPECT_FALSE(banded.cancelled);
    EXPECT_GT(polls, 4);
    EXPECT_EQ(banded.image.rgb, plain.image.rgb);
    EXPECT_EQ(banded.hits, plain.hits);
}

// A batch frame (a part, a tile, a video frame, which a signal may stop) is polled between its
// launches, and a launch as short as these stays whole instead of waiting on its slowest tile
// in each of many bands.
TEST_F(RenderTest, ABatchCancelIsPolledBetweenWholeLaunches) {
    FrameRequest request{64, 48, mandelbulb_->cameras.front().view,
                         default_param_values(*mandelbulb_)};
    request.samples = 6;  // a launch each
    const Frame plain = render(*mandelbulb_, request);
    request.cancel_response = CancelResponse::Batch;
    int polls = 0;
    request.cancel = [&] { return ++polls > 3; };
    const Frame stopped = render(*mandelbulb_, request);
    EXPECT_TRUE(stopped.cancelled);
    EXPECT_EQ(polls, 4) << "polled once per launch until it said stop";
    polls = 0;
    request.cancel = [&] {
        ++polls;
        return false;
    };
    const Frame whole = render(*mandelbulb_, request);
    EXPECT_FALSE(whole.cancelled);
    // Before each sample's launch, and before the mode's resolve launch if it has one.
    EXPECT_GE(polls, request.samples);
    EXPECT_LE(polls, request.samples + 1);
    EXPECT_EQ(whole.image.rgb, plain.image.rgb);
}

// `fgr render --stats`: counting the work changes no pixel, and the counts add up.
TEST_F(RenderTest, MarchStatsCountStepsAndRaysThatRanOutOfSteps) {
    FrameRequest request{96, 72, mandelbulb_->cameras.front().view,
                         default_param_values(*mandelbulb_)};
    const int width = preferred_packet_width(device_->info);
    const Frame plain = render(*mandelbulb_, request);
    Renderer counting(*device_, cache_, *mandelbulb_, {width, mandelbulb_->effects, true});
    const Frame counted = counting.render(request);
    ASSERT_TRUE(counted.stats.has_value());
    EXPECT_FALSE(plain.stats.has_value());
    EXPECT_EQ(counted.image.rgb, plain.image.rgb);
    const MarchStats& stats = *counted.stats;
    EXPECT_EQ(stats.pixels, 96 * 72);
    EXPECT_GT(stats.mean_steps, 2.0);
    EXPECT_LE(stats.max_steps, int(param_value(*mandelbulb_, request.params, "max_steps")));
    EXPECT_NEAR(double(stats.de_evaluations),
                stats.mean_steps * double(stats.pixels) + 4.0 * double(counted.hits) +
                    double(stats.prepass_de_evaluations),
                0.5);
    EXPECT_GT(stats.prepass_de_evaluations, 0);
    EXPECT_EQ(stats.out_of_steps, 0) << "the default view resolves every ray";

    // From the eye (without the cone prepass, which would carry rays most of the way there).
    request.prepass.enabled = false;
    set_param_from_text(*mandelbulb_, request.params, "max_steps=12");
    const Frame starved = counting.render(request);
    ASSERT_TRUE(starved.stats.has_value());
    EXPECT_LE(starved.stats->max_steps, 12);
    EXPECT_GT(starved.stats->out_of_steps, stats.pixels / 10) << "12 steps cannot reach the bulb";
    EXPECT_LT(starved.stats->out_of_steps + starved.hits, long(stats.pixels))
        << "rays that miss the bulb still leave the scene";
    EXPECT_NEAR(starved.stats->out_of_steps_percent(),
                100.0 * double(starved.stats->out_of_steps) / double(stats.pixels), 1e-9);
}

// Shadow and reflection rays start only where the camera ray hit: a missed lane of a packet
// marches nothing (its shadow ray would start far out along its miss and cost a packet steps
// after every hit lane has finished). The stats count the DE evaluations each lane's secondary
// rays took part in, per pixel; before shade_surface took the hit mask, missed pixels facing the
// light marched shadow rays too.
TEST_F(RenderTest, SecondaryRaysStartOnlyFromHits) {
    FrameRequest request{96, 72, mandelbulb_->cameras.front().view,
                         default_param_values(*mandelbulb_)};
    const int width = preferred_packet_width(device_->info);
    for (const uint64_t effects : {uint64_t{FGR_EFFECT_SHADOWS}, uint64_t{FGR_EFFECT_SOFT_SHADOWS},
                                   uint64_t{FGR_EFFECT_SHADOWS | FGR_EFFECT_REFLECTIONS}}) {
        SCOPED_TRACE(effects);
        Renderer counting(*device_, cache_, *mandelbulb_, {width, effects, true});
        const Frame counted = counting.render(request);
        ASSERT_TRUE(counted.stats.has_value());
        const MarchStats& stats = *counted.stats;
        ASSERT_GT(counted.hits, stats.pixels / 10);
        ASSERT_LT(counted.hits, stats.pixels * 9 / 10) << "the view must show misses too";
        EXPECT_GT(stats.secondary_de_evaluations, 2 * counted.hits)
            << "every lit hit marches a shadow ray of a few steps at least";
        EXPECT_EQ(stats.secondary_de_evaluations_missed, 0);
        Renderer plain(*device_, cache_, *mandelbulb_, {width, effects, false});
        EXPECT_EQ(plain.render(request).image.rgb, counted.image.rgb)
            << "counting changes no pixel";
    }
}

// Over-relaxation stretches steps where that is safe: the default (1.6) takes at least 10% fewer
// march steps than plain sphere tracing (over_relaxation 1) in the same view (15.6 against 18.3
// here, 19.2 against 23.7 at 640x480) and hits the same pixels within 0.1%.
TEST_F(RenderTest, OverRelaxationTakesFewerStepsForTheSameHits) {
    FrameRequest request{192, 144, mandelbulb_->cameras.front().view,
                         default_param_values(*mandelbulb_)};
    EXPECT_FLOAT_EQ(param_value(*mandelbulb_, request.params, "over_relaxation"), 1.6f);
    Renderer counting(*device_, cache_, *mandelbulb_,
                      {preferred_packet_width(device_->info), mandelbulb_->effects, true});
    const Frame relaxed = counting.render(request);
    set_param_from_text(*mandelbulb_, request.params, "over_relaxation=1");
    const Frame plain = counting.render(request);
    std::printf("mean steps: plain %.2f, over-relaxed %.2f\n", plain.stats->mean_steps,
                relaxed.stats->mean_steps);
    EXPECT_LT(relaxed.stats->mean_steps, 0.9 * plain.stats->mean_steps);
    EXPECT_NEAR(double(relaxed.hits), double(plain.hits), 0.001 * double(plain.hits));
}

// The Mandelbulb's power compiled in (as `fgr render` and the viewer build it) renders exactly the
// generic kernel's image: the same operations in the same order, unrolled. A frame asking for
// another power is refused by the specialised kernel rather than drawn with the wrong one.
TEST_F(RenderTest, SpecialisedKernelRendersTheGenericImage) {
    const Scene& scene = *mandelbulb_;
    FrameRequest request{32, 24, scene.cameras.front().view, default_param_values(scene)};
    // Not the default power: the kernel's own warm-up frame must use the compiled-in value too.
    set_param_from_text(scene, request.params, "power=7");
    ProgramCache cache{std::filesystem::path()};
    KernelSwitches switches{16, scene.effects};
    const Frame generic = Renderer(*device_, cache, scene, switches).render(request);
    switches.specialised = specialisation_for(scene, request.params);
    ASSERT_EQ(switches.specialised, (std::vector<SpecialisedParam>{{"power", 7.0f}}));
    Renderer specialised(*device_, cache, scene, switches);
    const Frame frame = specialised.render(request);
    EXPECT_EQ(frame.linear, generic.linear);
    EXPECT_EQ(frame.depth, generic.depth);
    set_param_from_text(scene, request.params, "power=8");
    EXPECT_THROW(specialised.render(request), std::invalid_argument);
}

}  // namespace
}  // namespace fgr
