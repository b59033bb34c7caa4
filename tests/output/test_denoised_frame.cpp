// SPDX-License-Identifier: Apache-2.0
// A frame rendered for the denoiser and denoised (output/denoised_frame.hpp), with a stand-in
// renderer whose samples are known: two halves that together are the whole render, the variance
// from their difference (or from the renderer's own estimates), and the raw colour kept beside
// the denoised one.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "output/denoised_frame.hpp"

namespace fgr {
namespace {

constexpr int kFrameWidth = 16;
constexpr int kFrameHeight = 12;
constexpr size_t kFramePixels = size_t(kFrameWidth) * kFrameHeight;

// Uniform noise in [-0.5, 0.5) for sample `s` of value `i` (an integer hash, the same everywhere).
double sample_noise(int s, size_t i) {
    uint32_t h = uint32_t(s) * 0x9E3779B1u ^ uint32_t(i) * 0x85EBCA77u;
    h ^= h >> 15;
    h *= 0x2C1B3C6Du;
    h ^= h >> 12;
    h *= 0x297A2D39u;
    h ^= h >> 15;
    return double(h) / 4294967296.0 - 0.5;
}

// A stand-in for a path-traced render: a sample's colour in each channel is 0.5 plus noise of
// its index and pixel, so the mean of samples first .. first + n - 1 is known; every pixel sees
// the same flat surface.
Frame fake_render(const FrameRequest& request, bool with_variance) {
    Frame frame;
    frame.image.width = kFrameWidth;
    frame.image.height = kFrameHeight;
    frame.image.rgb.assign(kFramePixels * 3, 0);
    frame.samples = request.samples;
    frame.render_ms = 1.0;
    frame.linear.assign(kFramePixels * 3, 0.0f);
    for (size_t i = 0; i < frame.linear.size(); ++i) {
        double sum = 0.0;
        for (int s = request.first_sample; s < request.first_sample + request.samples; ++s) {
            sum += 0.5 + 0.2 * sample_noise(s, i);
        }
        frame.linear[i] = float(sum / request.samples);
    }
    frame.albedo.assign(kFramePixels * 3, 0.6f);
    frame.normal.assign(kFramePixels * 3, 0.0f);
    for (size_t p = 0; p < kFramePixels; ++p) frame.normal[3 * p + 2] = 1.0f;
    frame.alpha.assign(kFramePixels, 1.0f);
    frame.depth.assign(kFramePixels, 2.0f);
    if (with_variance) frame.variance.assign(kFramePixels * 3, 0.001f * float(request.samples));
    return frame;
}

TEST(DenoisedFrame, HalvesMakeTheWholeRenderAndTheirDifferenceItsVariance) {
    FrameRequest request;
    request.samples = 7;  // halves of 3 and 4
    request.first_sample = 5;
    std::vector<std::pair<int, int>> asked;
    const Frame frame = render_with_variance(request, [&](const FrameRequest& half) {
        asked.emplace_back(half.first_sample, half.samples);
        return fake_render(half, false);
    });
    // The whole render first, which has no variance of its own here; then the halves.
    ASSERT_EQ(asked, (std::vector<std::pair<int, int>>{{5, 7}, {5, 3}, {8, 4}}));
    EXPECT_EQ(frame.samples, 7);
    FrameRequest second = request;
    second.first_sample = 8;
    second.samples = 4;
    FrameRequest first = request;
    first.samples = 3;
    const Frame whole = fake_render(request, false), a = fake_render(first, false),
                b = fake_render(second, false);
    ASSERT_EQ(frame.variance.size(), kFramePixels * 3);
    for (size_t i = 0; i < frame.linear.size(); ++i) {
        EXPECT_NEAR(frame.linear[i], whole.linear[i], 1e-6f) << i;
        const double d = double(a.linear[i]) - b.linear[i];
        EXPECT_NEAR(frame.variance[i], d * d * 3.0 * 4.0 / 49.0, 1e-7) << i;
    }
}

// A renderer that estimates the variance itself (the path tracer) renders once.
TEST(DenoisedFrame, TheRenderersOwnVarianceTakesOneRender) {
    FrameRequest request;
    request.samples = 4;
    request.first_sample = 3;
    std::vector<std::pair<int, int>> asked;
    const Frame frame = render_with_variance(request, [&](const FrameRequest& whole) {
        asked.emplace_back(whole.first_sample, whole.samples);
        return fake_render(whole, true);
    });
    ASSERT_EQ(asked, (std::vector<std::pair<int, int>>{{3, 4}}));
    EXPECT_EQ(frame.samples, 4);
    for (float v : frame.variance) EXPECT_EQ(v, 0.001f * 4.0f);
}

TEST(DenoisedFrame, RefusesOneSample) {
    FrameRequest request;
    request.samples = 1;
    EXPECT_THROW(render_with_variance(
                     request, [](const FrameRequest& half) { return fake_render(half, false); }),
                 std::invalid_argument);
}

TEST(DenoisedFrame, KeepsTheRawColourAndShowsTheDenoisedOne) {
    FrameRequest request;
    request.samples = 8;
    Frame frame = render_with_variance(
        request, [](const FrameRequest& half) { return fake_render(half, false); });
    const std::vector<float> raw = frame.linear;
    frame.foreground = raw;  // every sample hit: the foreground is the colour
    denoise_frame(frame, DisplayTransform{}, DenoiseSettings{});
    EXPECT_EQ(frame.raw_linear, raw);
    ASSERT_EQ(frame.linear.size(), raw.size());
    // A flat surface under noise: the denoised image is flatter than the raw one.
    const auto spread = [](const std::vector<float>& values) {
        double mean = 0.0, squares = 0.0;
        for (float v : values) mean += v;
        mean /= double(values.size());
        for (float v : values) squares += (v - mean) * (v - mean);
        return squares / double(values.size());
    };
    EXPECT_LT(spread(frame.linear), 0.5 * spread(raw));
    for (size_t i = 0; i < frame.linear.size(); ++i) {
        EXPECT_NEAR(frame.foreground[i], frame.linear[i], 1e-6f) << i;
    }
    EXPECT_EQ(frame.image.rgb,
              display_image(frame.linear, DisplayTransform{}, kFrameWidth, kFrameHeight).rgb);
    Frame without;
    without.image.width = kFrameWidth;
    without.image.height = kFrameHeight;
    without.linear = raw;
    EXPECT_THROW(denoise_frame(without, DisplayTransform{}, DenoiseSettings{}),
                 std::invalid_argument);
}

}  // namespace
}  // namespace fgr
