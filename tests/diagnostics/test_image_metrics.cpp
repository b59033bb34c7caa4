// SPDX-License-Identifier: Apache-2.0
// Image metrics (diagnostics/image_metrics.hpp): SSIM against closed forms of its three terms,
// against scikit-image's implementation on synthetic image pairs, and its properties; display luma,
// the sRGB decoding of 8-bit images, and linear RMSE.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <stdexcept>

#include "diagnostics/image_metrics.hpp"

namespace fgr {
namespace {

constexpr double kC1 = 0.01 * 0.01, kC2 = 0.03 * 0.03;  // (K L)^2 for L = 1

GreyImage grey(int width, int height, const std::function<double(int, int)>& value) {
    GreyImage image{width, height, std::vector<float>(size_t(width) * size_t(height))};
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            image.values[size_t(y) * size_t(width) + size_t(x)] = float(value(x, y));
        }
    }
    return image;
}

// The synthetic pair the scikit-image values below were computed on (16 wide, 13 high):
//   a = ((3x^2 + 7y + xy) mod 17) / 16, b = ((5x + 2y^2 + 3) mod 13) / 12,
//   c = a + (((7x + 3y) mod 5) - 2) / 40, d = a + (((7x + 3y) mod 5) - 2) / 8,
// each formed in float32 as here. scikit-image 0.19.3 (Debian python3-skimage), float64:
//   structural_similarity(a, b, gaussian_weights=True, sigma=1.5,
//                         use_sample_covariance=False, data_range=1.0)
// which is Wang et al.'s setting (11x11 Gaussian of sigma 1.5, population covariances, K1 0.01,
// K2 0.03) and averages the map over the windows wholly inside the image, as ssim does.
float pattern_a(int x, int y) { return float((3 * x * x + 7 * y + x * y) % 17) / 16.0f; }
float pattern_b(int x, int y) { return float((5 * x + 2 * y * y + 3) % 13) / 12.0f; }
float ripple(int x, int y) { return float((7 * x + 3 * y) % 5 - 2); }

TEST(Ssim, MatchesScikitImageOnSyntheticPairs) {
    const GreyImage a = grey(16, 13, pattern_a);
    const GreyImage b = grey(16, 13, pattern_b);
    const GreyImage c =
        grey(16, 13, [](int x, int y) { return pattern_a(x, y) + ripple(x, y) / 40.0f; });
    const GreyImage d =
        grey(16, 13, [](int x, int y) { return pattern_a(x, y) + ripple(x, y) / 8.0f; });
    // Both sides sum in double in different orders: agreement to ~1e-15 is expected; 1e-9 leaves
    // room for that and still pins every digit printed by scikit-image.
    EXPECT_NEAR(ssim(a, b, 1.0), -0.123610502206, 1e-9);
    EXPECT_NEAR(ssim(a, c, 1.0), 0.992740012427, 1e-9);
    EXPECT_NEAR(ssim(a, d, 1.0), 0.836728959400, 1e-9);
    // The same pair in 8-bit levels with L = 255: SSIM does not care about the scale.
    const auto times255 = [](GreyImage image) {
        for (float& v : image.values) v *= 255.0f;
        return image;
    };
    EXPECT_NEAR(ssim(times255(a), times255(c), 255.0), 0.992740012427, 1e-9);
}

TEST(Ssim, IdenticalImagesGiveExactlyOne) {
    for (const GreyImage& image :
         {grey(16, 13, pattern_a), grey(11, 11, [](int, int) { return 0.25; }),
          grey(40, 12, [](int x, int y) { return std::sin(0.3 * x) * std::cos(0.7 * y) * 1e3; })}) {
        EXPECT_EQ(ssim(image, image, 1.0), 1.0);
    }
}

TEST(Ssim, IsSymmetric) {
    const GreyImage a = grey(16, 13, pattern_a), b = grey(16, 13, pattern_b);
    const GreyImage d =
        grey(16, 13, [](int x, int y) { return pattern_a(x, y) + ripple(x, y) / 8.0f; });
    EXPECT_EQ(ssim(a, b, 1.0), ssim(b, a, 1.0));
    EXPECT_EQ(ssim(a, d, 1.0), ssim(d, a, 1.0));
}

// A constant offset leaves variances and covariance as they are, so the contrast-structure factor
// is exactly 1 and SSIM is the luminance term (2 mu (mu + d) + C1) / (mu^2 + (mu + d)^2 + C1).
// On a flat image every window's mean is the value itself; on a checkerboard m +- A every
// window's mean is m to within A g^2, g being the window's alternating sum (about 2e-4 for the
// truncated Gaussian), so the same closed form holds there too, to the float rounding of the
// stored values (1e-6 allowed).
TEST(Ssim, ConstantOffsetGivesTheLuminanceTerm) {
    const auto luminance = [](double mu, double offset) {
        return (2.0 * mu * (mu + offset) + kC1) / (mu * mu + (mu + offset) * (mu + offset) + kC1);
    };
    for (const double offset : {0.01, 0.1, 0.3}) {
        const GreyImage flat = grey(20, 15, [](int, int) { return 0.4; });
        const GreyImage shifted = grey(20, 15, [&](int, int) { return 0.4 + offset; });
        EXPECT_NEAR(ssim(flat, shifted, 1.0),
                    luminance(double(0.4f), double(float(0.4 + offset)) - double(0.4f)), 1e-12)
            << offset;
        const auto board = [](int x, int y) { return (x + y) % 2 ? 0.7 : 0.3; };
        const GreyImage checker = grey(20, 15, board);
        const GreyImage checker_shifted =
            grey(20, 15, [&](int x, int y) { return board(x, y) + offset; });
        EXPECT_NEAR(ssim(checker, checker_shifted, 1.0), luminance(0.5, offset), 1e-6) << offset;
    }
}

// A checkerboard m +- A scaled about its mean by k (b = m + k (a - m)): both means are m (to
// A g^2, see above), sigma_a^2 = A^2, sigma_b^2 = k^2 A^2, sigma_ab = k A^2, so
// SSIM = (2 k A^2 + C2) / ((1 + k^2) A^2 + C2): the contrast term for k > 0, and for k = -1 the
// structure term's inversion, (C2 - 2 A^2) / (2 A^2 + C2) < 0.
TEST(Ssim, ScaledContrastGivesTheContrastAndStructureTerms) {
    const double m = 0.5, amplitude = 0.2;
    const auto board = [&](int x, int y) { return (x + y) % 2 ? m + amplitude : m - amplitude; };
    const GreyImage checker = grey(17, 14, board);
    for (const double k : {0.5, 0.9, 2.0, -1.0}) {
        const GreyImage scaled =
            grey(17, 14, [&](int x, int y) { return m + k * (board(x, y) - m); });
        const double a2 = amplitude * amplitude;
        EXPECT_NEAR(ssim(checker, scaled, 1.0), (2.0 * k * a2 + kC2) / ((1.0 + k * k) * a2 + kC2),
                    1e-6)
            << k;
    }
}

// Noise of growing amplitude (one fixed pseudo-random field, scaled) lowers SSIM step by step.
TEST(Ssim, FallsAsNoiseGrows) {
    const auto base = [](int x, int y) {
        return 0.5 + 0.3 * std::sin(0.4 * x) * std::cos(0.25 * y);
    };
    std::vector<float> noise(48 * 32);
    uint32_t state = 12345u;
    for (float& n : noise) {
        state = state * 1664525u + 1013904223u;  // Numerical Recipes' LCG
        n = float(state >> 8) / float(1u << 24) - 0.5f;
    }
    const GreyImage clean = grey(48, 32, base);
    double previous = 1.0;
    for (const double amplitude : {0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.4}) {
        const GreyImage noisy = grey(48, 32, [&](int x, int y) {
            return base(x, y) + amplitude * noise[size_t(y) * 48 + size_t(x)];
        });
        const double value = ssim(noisy, clean, 1.0);
        EXPECT_LT(value, previous) << amplitude;
        previous = value;
    }
}

// Only windows wholly inside the image count, with equal weight. A corner pixel lies in one
// window only (the one centred 5 pixels in from both edges), where its weight is the Gaussian's
// corner w = (g(5) / sum_k g(k))^2, g(k) = exp(-k^2 / (2 * 1.5^2)). Changing it by d on a flat
// image c leaves every other window at 1 and gives that one mean c + w d, variance w (1 - w) d^2
// and covariance 0 with the flat image, so
//   SSIM = (N - 1 + s) / N, s = (2 c (c + w d) + C1) / (c^2 + (c + w d)^2 + C1) * C2 / (w (1 - w)
//   d^2 + C2),
// with N = (W - 10)(H - 10) windows.
TEST(Ssim, BordersCountOnlyWindowsInsideTheImage) {
    double sum = 0.0;
    for (int k = -5; k <= 5; ++k) sum += std::exp(-k * k / (2.0 * 1.5 * 1.5));
    const double w = std::pow(std::exp(-25.0 / (2.0 * 1.5 * 1.5)) / sum, 2.0);
    const double c = 0.25, d = 0.75;
    for (const auto& [width, height] : {std::pair{11, 11}, std::pair{13, 12}, std::pair{30, 20}}) {
        const GreyImage flat = grey(width, height, [&](int, int) { return c; });
        const GreyImage corner =
            grey(width, height, [&](int x, int y) { return x == 0 && y == 0 ? c + d : c; });
        const double mean = c + w * d;
        const double s = (2.0 * c * mean + kC1) / (c * c + mean * mean + kC1) * kC2 /
                         (w * (1.0 - w) * d * d + kC2);
        const double n = double((width - 10) * (height - 10));
        EXPECT_NEAR(ssim(corner, flat, 1.0), (n - 1.0 + s) / n, 1e-12) << width << "x" << height;
    }
    // A window needs 11x11 pixels.
    EXPECT_THROW(ssim(grey(10, 20, pattern_a), grey(10, 20, pattern_a), 1.0),
                 std::invalid_argument);
    EXPECT_THROW(ssim(grey(20, 10, pattern_a), grey(20, 10, pattern_a), 1.0),
                 std::invalid_argument);
}

TEST(Ssim, RefusesMismatchedOrNonFiniteInput) {
    const GreyImage a = grey(16, 13, pattern_a);
    EXPECT_THROW(ssim(a, grey(16, 14, pattern_a), 1.0), std::invalid_argument);
    EXPECT_THROW(ssim(a, a, 0.0), std::invalid_argument);
    GreyImage bad = a;
    bad.values[7] = std::nanf("");
    EXPECT_THROW(ssim(bad, a, 1.0), std::invalid_argument);
    bad.values[7] = INFINITY;
    EXPECT_THROW(ssim(a, bad, 1.0), std::invalid_argument);
    bad.values.pop_back();
    EXPECT_THROW(ssim(a, bad, 1.0), std::invalid_argument);
}

// The linear-RGB entry point: 8-bit sRGB levels decoded by linear_rgb come back as level / 255
// through display_luma (grey pixels: the luma weights sum to 1), so SSIM on the decoded images
// matches scikit-image on level / 255:
//   A8 = 10 + 15 ((3x^2 + 7y + xy) mod 17), C8 = A8 + 4 (((7x + 3y) mod 5) - 2), 16x13;
//   structural_similarity(A8 / 255, C8 / 255, <as above>) = 0.996777938802.
// The float decode and re-encode round trip moves values by ~1e-7: tolerance 1e-5.
TEST(Ssim, OnLinearRgbComparesWhatTheScreenShows) {
    const auto levels = [](bool noisy) {
        Image8 image{16, 13, std::vector<uint8_t>(16 * 13 * 3)};
        for (int y = 0; y < 13; ++y) {
            for (int x = 0; x < 16; ++x) {
                int level = 10 + 15 * ((3 * x * x + 7 * y + x * y) % 17);
                if (noisy) level += 4 * ((7 * x + 3 * y) % 5 - 2);
                for (int ch = 0; ch < 3; ++ch)
                    image.rgb[size_t(y * 16 + x) * 3 + size_t(ch)] = uint8_t(level);
            }
        }
        return image;
    };
    const HdrImage a = linear_rgb(levels(false)), c = linear_rgb(levels(true));
    EXPECT_NEAR(ssim(a, c), 0.996777938802, 1e-5);
    EXPECT_EQ(ssim(a, a), 1.0);
    EXPECT_THROW(ssim(a, HdrImage{16, 12, std::vector<float>(16 * 12 * 3)}), std::invalid_argument);
    // Exposure scales the light before display: HDR images ten times as bright, judged at
    // exposure 0.1, are the same images (to float rounding of the scaling).
    HdrImage bright_a = a, bright_c = c;
    for (float& v : bright_a.rgb) v *= 10.0f;
    for (float& v : bright_c.rgb) v *= 10.0f;
    EXPECT_NEAR(ssim(bright_a, bright_c, 0.1f), 0.996777938802, 1e-5);
    // At exposure 1 most of both clamp to white: another comparison (0.9946 here).
    EXPECT_GT(std::abs(ssim(bright_a, bright_c) - 0.996777938802), 1e-3);
}

TEST(DisplayLuma, EncodesClampsAndWeighsChannels) {
    // Linear 0.5 is sRGB 0.7354 (level 188 of 255) under IEC 61966-2-1; the Rec. 709 weights are
    // what a pure primary keeps; values beyond [0, 1] and NaN clamp.
    const HdrImage image{6,
                         1,
                         {0.5f, 0.5f, 0.5f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f,
                          4.0f, 2.0f, 2.0f, -1.0f, NAN, 0.0f}};
    const GreyImage luma = display_luma(image);
    ASSERT_EQ(luma.values.size(), 6u);
    EXPECT_NEAR(luma.values[0], 0.735357, 1e-5);
    EXPECT_EQ(std::lround(luma.values[0] * 255.0f), 188);
    EXPECT_NEAR(luma.values[1], 0.2126, 1e-6);
    EXPECT_NEAR(luma.values[2], 0.7152, 1e-6);
    EXPECT_NEAR(luma.values[3], 0.0722, 1e-6);
    EXPECT_NEAR(luma.values[4], 1.0, 1e-6);
    EXPECT_EQ(luma.values[5], 0.0f);
    // Exposure scales before the clamp.
    // (4, 2, 2) at exposure 0.25 is (1, 0.5, 0.5).
    EXPECT_NEAR(display_luma(image, 0.25f).values[4], 0.2126 + (0.7152 + 0.0722) * 0.735357, 1e-5);
}

TEST(LinearRgb, InvertsTheSrgbCurveOfEveryLevel) {
    Image8 ramp{256, 1, std::vector<uint8_t>(256 * 3)};
    for (int i = 0; i < 256 * 3; ++i) ramp.rgb[size_t(i)] = uint8_t(i / 3);
    const HdrImage linear = linear_rgb(ramp);
    EXPECT_EQ(linear.rgb[0], 0.0f);
    EXPECT_NEAR(linear.rgb[3 * 255], 1.0f, 1e-6);
    EXPECT_NEAR(linear.rgb[3 * 188], 0.5029, 1e-4);  // level 188 is linear 0.503
    const GreyImage luma = display_luma(linear);
    for (int level = 0; level < 256; ++level) {
        EXPECT_NEAR(luma.values[size_t(level)] * 255.0f, float(level), 2e-4) << level;
    }
    EXPECT_THROW(linear_rgb(Image8{2, 2, std::vector<uint8_t>(11)}), std::invalid_argument);
}

TEST(Rmse, OverEveryChannelInLinearUnits) {
    const HdrImage a{2, 1, {0.0f, 0.5f, 1.0f, 2.0f, 0.25f, 0.0f}};
    HdrImage b = a;
    EXPECT_EQ(rmse(a, b), 0.0);
    b.rgb[3] += 0.6f;  // one channel of six: sqrt(0.36 / 6)
    EXPECT_NEAR(rmse(a, b), std::sqrt(0.36 / 6.0), 1e-7);
    EXPECT_EQ(rmse(a, b), rmse(b, a));
    EXPECT_THROW(rmse(a, HdrImage{1, 2, a.rgb}), std::invalid_argument);
}

}  // namespace
}  // namespace fgr
