// SPDX-License-Identifier: Apache-2.0
// Adaptive sampling (render/adaptive_sampling.hpp) and the per-pixel variance it runs on, at
// 24x24 on the CPU device with one kernel for every case: its mean against the closed form and
// against fixed sampling, a scene where stopping on what a pixel has seen IS biased (and the
// default rule is not), where it spends its samples, and the variance estimate against the
// spread it estimates. Means are compared within 4 standard errors computed from the pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"
#include "output/denoised_frame.hpp"
#include "pixel_estimate.hpp"
#include "render/adaptive_sampling.hpp"
#include "render/environment.hpp"
#include "render/path_settings.hpp"
#include "render/renderer.hpp"
#include "scene/parameters.hpp"
#include "test_scenes.hpp"

namespace fgr {
// Named, so that the unity build's other path tests' helpers of the same names stay apart.
namespace adaptive_sampling_test {
namespace {

constexpr int kSphere = 0;        // a unit sphere seen from outside
constexpr int kInsideSphere = 1;  // the camera at the centre of a hollow sphere of radius 3
constexpr int kSize = 24;

Scene adaptive_scene() {
    Scene scene = test::inline_scene(R"CL(
#define FGR_SCENE_HAS_MATERIAL
real scene_de(vec3 p, PARAMS) {
    if (param_shape == 1) return 3.0f - v3_length(p);
    return v3_length(p) - 1.0f;
}
material scene_material(vec3 p, PARAMS) {
    (void)p;
    material m;
    m.albedo = param_albedo;
    m.specular = v3_splat(0.0f, 0.0f, 0.0f);
    m.roughness = fgr_real(1.0f);
    m.emission = param_emission;
    return m;
}
)CL");
    scene.id = "adaptive-test";
    const auto add = [&scene](const char* id, ParamType type, float high, float value) {
        ParamInfo param;
        param.id = id;
        param.type = type;
        param.min_value = 0.0f;
        param.max_value = high;
        param.default_value = {value, value, value};
        scene.params.insert(scene.params.end() - 5, param);  // before the built-in knobs
    };
    add("shape", ParamType::Int, 1.0f, 0.0f);
    add("albedo", ParamType::Colour, 1.0f, 0.5f);
    add("emission", ParamType::Colour, 100.0f, 0.0f);
    // A small bright sun: found by BSDF sampling alone (light sampling off), a diffuse pixel
    // sees it in about 1 sample of 100, and reads 0 otherwise.
    Light sun;
    sun.vector = {0.3f, -0.8f, 0.5f};
    sun.intensity = 1.0f;
    sun.angular_radius = 0.1f;
    scene.lights = {sun};
    return scene;
}

using Estimate = test::PixelEstimate;

bool agree(const Estimate& a, const Estimate& b, const char* what, double sigmas = 4.0) {
    const double tolerance = sigmas * std::hypot(a.standard_error, b.standard_error);
    std::printf("%s: %.5f +- %.5f against %.5f +- %.5f (%ld pixels)\n", what, a.mean,
                a.standard_error, b.mean, b.standard_error, a.pixels);
    return std::abs(a.mean - b.mean) <= tolerance;
}

class AdaptiveSampling : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        scene_ = std::make_unique<Scene>(adaptive_scene());
        device_ = std::make_unique<ComputeDevice>(open_device(-1));
        KernelSwitches switches;
        switches.packet_width = 16;
        switches.mode = RenderMode::Path;
        renderer_ = std::make_unique<Renderer>(*device_, cache_, *scene_, switches);
    }
    static void TearDownTestSuite() {
        renderer_.reset();
        device_.reset();
        scene_.reset();
    }

    // A uniform environment of `radiance`; the scene's sun too when `sun`.
    static PathSettings lit_by(float radiance, bool sun) {
        PathSettings settings;
        settings.scene_lights = sun;
        EnvironmentChoice choice;
        choice.kind = EnvironmentKind::Uniform;
        choice.radiance = glm::vec3(radiance);
        settings.environment = prepare_environment(choice, *scene_);
        return settings;
    }

    static FrameRequest request(int shape, const std::string& material, const PathSettings& path,
                                int samples) {
        std::vector<float> params = default_param_values(*scene_);
        set_param_from_text(*scene_, params, "shape=" + std::to_string(shape));
        if (!material.empty()) set_param_from_text(*scene_, params, material);
        FrameRequest request;
        request.width = kSize;
        request.height = kSize;
        request.view = scene_->cameras.front().view;
        if (shape == kInsideSphere) {
            request.view.position = {0.0, 0.0, 0.0};
            request.view.target = {0.0, 1.0, 0.0};
        }
        request.params = params;
        request.samples = samples;
        request.path = path;
        return request;
    }

    // The sun scene: a white diffuse sphere under a dim uniform sky, lit by a small sun found by
    // BSDF sampling alone, so that a pixel's samples are mostly 0 and rarely bright.
    static PathSettings rare_sun(uint32_t seed) {
        PathSettings settings = lit_by(0.05f, true);
        settings.light_sampling = false;
        settings.mis = false;
        settings.stratified = false;  // independent samples: the rule's argument holds exactly
        settings.seed = seed;
        settings.max_bounces = 1;
        return settings;
    }

    static Renderer& renderer() { return *renderer_; }

    static inline std::unique_ptr<Scene> scene_;
    static inline std::unique_ptr<ComputeDevice> device_;
    static inline ProgramCache cache_{std::filesystem::path()};
    static inline std::unique_ptr<Renderer> renderer_;
};

const auto kEveryPixel = [](size_t) { return true; };

// The closed form: inside a sphere of albedo 0.5 and emission 0.5 every pixel reads 1. Adaptive
// sampling's mean matches it and fixed sampling's, and it took fewer samples than the cap.
TEST_F(AdaptiveSampling, MeanMatchesTheClosedFormAndFixedSampling) {
    PathSettings path = lit_by(0.0f, false);
    path.seed = 7;
    const Frame fixed = renderer().render(request(kInsideSphere, "emission=0.5,0.5,0.5", path, 16));
    path.noise_threshold = 0.05f;
    path.min_samples = 4;
    const Frame adaptive =
        renderer().render(request(kInsideSphere, "emission=0.5,0.5,0.5", path, 64));
    ASSERT_TRUE(adaptive.adaptive.has_value());
    if (getenv("DEBUG_SEEDS")) {
        for (int stratified = 0; stratified < 2; ++stratified) {
            double total = 0.0, total_fixed = 0.0;
            for (uint32_t seed = 100; seed < 120; ++seed) {
                PathSettings p = path;
                p.seed = seed;
                p.stratified = stratified;
                total +=
                    test::red_channel_estimate(
                        renderer().render(request(kInsideSphere, "emission=0.5,0.5,0.5", p, 64)),
                        kEveryPixel)
                        .mean;
                p.noise_threshold = 0.0f;
                total_fixed +=
                    test::red_channel_estimate(
                        renderer().render(request(kInsideSphere, "emission=0.5,0.5,0.5", p, 16)),
                        kEveryPixel)
                        .mean;
            }
            std::printf("stratified %d: adaptive mean over 20 seeds %.5f fixed %.5f\n", stratified,
                        total / 20, total_fixed / 20);
        }
    }
    std::printf("%s\n", adaptive_summary(*adaptive.adaptive).c_str());
    const Estimate exact{1.0, 0.0, 1};
    EXPECT_TRUE(
        agree(test::red_channel_estimate(adaptive, kEveryPixel), exact, "adaptive against 1"));
    EXPECT_TRUE(agree(test::red_channel_estimate(fixed, kEveryPixel), exact, "fixed against 1"));
    EXPECT_TRUE(agree(test::red_channel_estimate(adaptive, kEveryPixel),
                      test::red_channel_estimate(fixed, kEveryPixel), "adaptive against fixed"));
    EXPECT_LT(adaptive.adaptive->mean_spp, 64.0);
    EXPECT_EQ(adaptive.samples_per_pixel.size(), size_t(kSize * kSize));
}

// A small bright sun seen rarely: a pixel whose first samples all missed it reads zero variance.
// Stopping there and averaging what it saw leaves it dark (the naive rule: measurably biased
// low); the default rule's mean matches a light-sampled render of the same light, whose
// estimator has a tiny variance.
TEST_F(AdaptiveSampling, RareBrightLightBiasesTheNaiveRuleOnly) {
    PathSettings reference_path = lit_by(0.05f, true);
    reference_path.max_bounces = 1;
    reference_path.seed = 3;
    const Frame reference = renderer().render(request(kSphere, "", reference_path, 64));
    const auto on_sphere = [&reference](size_t i) { return reference.alpha[i] == 1.0f; };
    const Estimate truth = test::red_channel_estimate(reference, on_sphere);

    PathSettings path = rare_sun(11);
    path.noise_threshold = 0.1f;
    path.min_samples = 4;
    FrameRequest adaptive_request = request(kSphere, "", path, 128);
    const Frame naive = render_adaptive(renderer(), adaptive_request, AdaptiveRule::Naive);
    // The default rule's estimates are noisy where a pixel's last round rests on a few samples
    // that found the sun: the mean of 6 seeds' images (independent) makes the test sharp.
    Estimate unbiased;
    double spp = 0.0;
    constexpr int kSeeds = 6;
    for (int seed = 0; seed < kSeeds; ++seed) {
        adaptive_request.path.seed = 11 + 101 * static_cast<uint32_t>(seed);
        const Frame frame = render_adaptive(renderer(), adaptive_request, AdaptiveRule::Unbiased);
        if (seed == 0) std::printf("default rule: %s\n", adaptive_summary(*frame.adaptive).c_str());
        const Estimate one = test::red_channel_estimate(frame, on_sphere);
        unbiased.mean += one.mean / kSeeds;
        unbiased.standard_error += one.standard_error * one.standard_error / (kSeeds * kSeeds);
        unbiased.pixels += one.pixels;
        spp += frame.adaptive->mean_spp / kSeeds;
    }
    unbiased.standard_error = std::sqrt(unbiased.standard_error);
    std::printf("naive rule: %s\n", adaptive_summary(*naive.adaptive).c_str());
    EXPECT_TRUE(agree(unbiased, truth, "default rule against the truth"));
    // Fewer samples than fixed sampling's cap, or the test shows nothing.
    EXPECT_LT(spp, 128.0 * 0.8);
    EXPECT_FALSE(
        agree(test::red_channel_estimate(naive, on_sphere), truth, "naive rule against the truth"));
    EXPECT_LT(test::red_channel_estimate(naive, on_sphere).mean, truth.mean);
}

// Flat regions (the uniform sky around the sphere: every sample reads the same) stop at the
// first rounds; the lit sphere, whose samples vary, takes more.
TEST_F(AdaptiveSampling, FlatSkyTakesFewerSamplesThanTheNoisySurface) {
    PathSettings path = lit_by(0.3f, true);
    path.seed = 5;
    path.noise_threshold = 0.02f;
    path.min_samples = 4;
    const Frame frame = renderer().render(request(kSphere, "", path, 64));
    double sky = 0.0, surface = 0.0;
    long sky_pixels = 0, surface_pixels = 0;
    for (size_t i = 0; i < frame.alpha.size(); ++i) {
        if (frame.alpha[i] == 0.0f) {
            sky += frame.samples_per_pixel[i];
            ++sky_pixels;
        } else if (frame.alpha[i] == 1.0f) {
            surface += frame.samples_per_pixel[i];
            ++surface_pixels;
        }
    }
    ASSERT_GT(sky_pixels, 50);
    ASSERT_GT(surface_pixels, 50);
    sky /= double(sky_pixels);
    surface /= double(surface_pixels);
    std::printf("samples per pixel: sky %.1f, surface %.1f\n", sky, surface);
    EXPECT_LT(sky, 0.5 * surface);
}

// --denoise with --noise-threshold: the adaptive render (one, its rounds inside) carries each
// pixel's variance, which the denoiser takes as it is.
TEST_F(AdaptiveSampling, DenoisingTakesTheAdaptiveRendersVariance) {
    PathSettings path = lit_by(0.3f, true);
    path.seed = 6;
    path.noise_threshold = 0.05f;
    path.min_samples = 4;
    int renders = 0;
    Frame frame = render_with_variance(request(kSphere, "", path, 32), [&](const FrameRequest& r) {
        ++renders;
        return renderer().render(r);
    });
    EXPECT_EQ(renders, 1);
    ASSERT_TRUE(frame.adaptive);
    ASSERT_EQ(frame.variance.size(), frame.linear.size());
    for (float v : frame.variance) ASSERT_GE(v, 0.0f);
    const std::vector<float> raw = frame.linear;
    denoise_frame(frame, DisplayTransform{}, DenoiseSettings{});
    EXPECT_EQ(frame.raw_linear, raw);
    EXPECT_NE(frame.linear, raw);
}

// Frame::variance against the variance it estimates. Inside the emitting sphere every pixel's
// estimate has the same distribution, so the spread of the pixels' values is the variance each
// pixel's estimate has; the mean of the per-pixel estimates must agree with it within their
// standard errors. Fixed sampling (two half-buffers) and adaptive sampling (its weights) alike.
TEST_F(AdaptiveSampling, VarianceEstimateMatchesTheSpread) {
    const auto check = [](const Frame& frame, const char* what) {
        const size_t n = frame.alpha.size();
        double mean = 0.0, estimated = 0.0;
        for (size_t i = 0; i < n; ++i) {
            mean += frame.linear[i * 3];
            estimated += frame.variance[i * 3];
        }
        mean /= double(n);
        estimated /= double(n);
        double m2 = 0.0, m4 = 0.0, spread_of_estimates = 0.0;
        for (size_t i = 0; i < n; ++i) {
            const double d = frame.linear[i * 3] - mean;
            m2 += d * d;
            m4 += d * d * d * d;
            const double e = frame.variance[i * 3] - estimated;
            spread_of_estimates += e * e;
        }
        if (getenv("DEBUG_ADAPTIVE")) {
            for (size_t i = 0; i < n; ++i) {
                const double d = frame.linear[i * 3] - mean;
                if (d * d > 0.1 || frame.samples_per_pixel[i] < 10)
                    std::printf("pixel %zu value %.3f spp %.0f var %.4g\n", i, frame.linear[i * 3],
                                frame.samples_per_pixel[i], frame.variance[i * 3]);
            }
        }
        const double empirical = m2 / double(n - 1);
        m4 /= double(n);
        // Standard errors: of a sample variance, sqrt((m4 - s^4) / n); of a mean, s / sqrt(n).
        const double empirical_error =
            std::sqrt(std::max(m4 - empirical * empirical, 0.0) / double(n));
        const double estimated_error = std::sqrt(spread_of_estimates / double(n - 1) / double(n));
        std::printf("%s: estimated variance %.3g +- %.2g, spread %.3g +- %.2g\n", what, estimated,
                    estimated_error, empirical, empirical_error);
        EXPECT_GT(empirical, 0.0) << what;
        EXPECT_NEAR(estimated, empirical, 4.0 * std::hypot(empirical_error, estimated_error))
            << what;
    };
    PathSettings path = lit_by(0.0f, false);
    path.seed = 9;
    path.stratified = false;
    check(renderer().render(request(kInsideSphere, "emission=0.5,0.5,0.5", path, 8)), "fixed 8");
    path.noise_threshold = 0.05f;
    path.min_samples = 4;
    check(renderer().render(request(kInsideSphere, "emission=0.5,0.5,0.5", path, 64)), "adaptive");
}

// A pixel whose second round was planned from a variance estimate that came out low (few samples
// given much weight) cannot reach the threshold once later rounds show the real variance: more
// samples only bring it nearer the floor that round's weight sets. It stops near that floor
// instead of taking every sample the cap allows, and its weights still sum to 1. The rounds are
// fed frames made up here (every pixel alike), so the rule is tested without the renderer's noise.
TEST_F(AdaptiveSampling, PixelThatCannotReachTheThresholdStopsNearItsFloor) {
    constexpr int kSide = 4;
    constexpr size_t kPixels = kSide * kSide;
    PathSettings path = lit_by(0.3f, false);
    path.noise_threshold = 0.1f;
    path.min_samples = 4;
    FrameRequest adaptive = request(kSphere, "", path, 4096);
    adaptive.width = kSide;
    adaptive.height = kSide;
    AdaptiveSampler sampler(adaptive);
    // A frame of `samples` samples of value 1 whose per-sample relative variance reads `relative`.
    const auto round_frame = [&](double relative, int samples) {
        Frame frame;
        frame.samples = samples;
        frame.linear.assign(kPixels * 3, 1.0f);
        frame.variance.assign(kPixels * 3, static_cast<float>(relative / samples));
        frame.albedo.assign(kPixels * 3, 0.5f);
        frame.normal.assign(kPixels * 3, 0.0f);
        frame.alpha.assign(kPixels, 1.0f);
        frame.depth.assign(kPixels, 1.0f);
        return frame;
    };
    // The first round reads a relative variance of 0.08, so the second is planned as a pixel
    // needing 8 samples (0.08 / 0.1^2) and its 4 get half the weight; from then on every round
    // reads 10, the pixel's real variance.
    int rounds = 0;
    while (const FrameRequest* round = sampler.next_round()) {
        ASSERT_LT(rounds, 20);
        sampler.add_round(round_frame(rounds == 0 ? 0.08 : 10.0, round->samples));
        ++rounds;
    }
    // With half its weight on 4 samples, the pixel's relative variance is at least
    // 10 * 0.5^2 / 4 = 0.625, far above 0.1^2: the rule takes what brings the rest of the weight
    // within a quarter of that floor (16 samples more) and stops there.
    const Frame frame = sampler.frame(*scene_);
    for (size_t i = 0; i < kPixels; ++i) {
        EXPECT_LE(frame.samples_per_pixel[i], 64.0f) << i;
        EXPECT_NEAR(frame.linear[i * 3], 1.0f, 1e-6f) << i;
    }
    ASSERT_TRUE(frame.adaptive);
    EXPECT_EQ(frame.adaptive->share_converged, 0.0);
}

// Fixed sampling fills the sample counts and variance too (the denoiser reads them), and a pixel
// whose limit stops it after its first samples reads what a render of only those samples reads.
TEST_F(AdaptiveSampling, SampleLimitsGiveEachPixelItsOwnSamples) {
    PathSettings path = lit_by(0.5f, true);
    path.seed = 4;
    const Frame two = renderer().render(request(kSphere, "", path, 2));
    const Frame eight = renderer().render(request(kSphere, "", path, 8));
    FrameRequest limited = request(kSphere, "", path, 8);
    limited.sample_limits.assign(kSize * kSize, 8.0f);
    for (int i = 0; i < kSize * kSize; i += 3) limited.sample_limits[i] = 2.0f;
    const Frame frame = renderer().render(limited);
    ASSERT_EQ(frame.samples_per_pixel.size(), size_t(kSize * kSize));
    ASSERT_EQ(frame.variance.size(), size_t(kSize * kSize * 3));
    ASSERT_EQ(eight.variance.size(), size_t(kSize * kSize * 3));
    for (int i = 0; i < kSize * kSize; ++i) {
        const Frame& same = i % 3 == 0 ? two : eight;
        EXPECT_EQ(frame.samples_per_pixel[i], i % 3 == 0 ? 2.0f : 8.0f) << i;
        EXPECT_EQ(eight.samples_per_pixel[i], 8.0f) << i;
        for (int c = 0; c < 3; ++c) {
            const float tolerance = 1e-5f * std::max(1.0f, same.linear[i * 3 + c]);
            EXPECT_NEAR(frame.linear[i * 3 + c], same.linear[i * 3 + c], tolerance) << i;
            EXPECT_NEAR(frame.variance[i * 3 + c], same.variance[i * 3 + c],
                        1e-4f * std::max(1e-3f, same.variance[i * 3 + c]))
                << i;
            EXPECT_GE(eight.variance[i * 3 + c], 0.0f) << i;
        }
    }
}

}  // namespace
}  // namespace adaptive_sampling_test
}  // namespace fgr
