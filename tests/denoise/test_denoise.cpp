// SPDX-License-Identifier: Apache-2.0
// The denoiser (denoise/denoise.hpp) on synthetic images whose right answer is known: a converged
// image comes back unchanged, noise goes down, edges of albedo stay where they were, a converged
// region beside a noisy one keeps its pixels, and bad planes are refused or passed through.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "denoise/denoise.hpp"

namespace fgr {
namespace {

constexpr int kWidth = 48;
constexpr int kHeight = 32;
constexpr size_t kPixels = size_t(kWidth) * kHeight;
const DenoiseMethod kMethods[] = {DenoiseMethod::Atrous, DenoiseMethod::NlMeans,
                                  DenoiseMethod::Regression};

// A synthetic render: colour, the variance of its estimate, and first-hit features.
struct Planes {
    std::vector<float> colour = std::vector<float>(3 * kPixels);
    std::vector<float> variance = std::vector<float>(3 * kPixels, 0.0f);
    std::vector<float> albedo = std::vector<float>(3 * kPixels);
    std::vector<float> normal = std::vector<float>(3 * kPixels);
    std::vector<float> depth = std::vector<float>(kPixels);
    std::vector<float> alpha = std::vector<float>(kPixels, 1.0f);
    DenoiseInput input() const {
        return {kWidth, kHeight, colour, variance, albedo, normal, depth, alpha};
    }
};

// Gaussian noise from mt19937 (whose sequence the standard fixes) by Box-Muller, so that the
// images are the same with every standard library.
class Noise {
public:
    explicit Noise(uint32_t seed) : engine_(seed) {}
    float next() {
        const double u1 = (double(engine_()) + 1.0) / 4294967297.0;
        const double u2 = double(engine_()) / 4294967296.0;
        return float(std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2));
    }

private:
    std::mt19937 engine_;
};

// A lit surface with detail in every feature: albedo that changes in stripes, a normal that turns
// across the image, depth that grows down it, and the sky (a miss) in the top rows.
Planes detailed_scene() {
    Planes planes;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const size_t p = size_t(y) * kWidth + size_t(x);
            const bool sky = y < 4;
            const float albedo = sky ? 0.0f : ((x / 3 + y / 5) % 3 == 0 ? 0.8f : 0.3f);
            const float angle = 0.05f * float(x) + 0.3f * std::sin(0.7f * float(y));
            const float shade = sky ? 1.0f : 0.2f + 0.8f * std::max(std::cos(angle), 0.0f);
            for (size_t c = 0; c < 3; ++c) {
                planes.albedo[3 * p + c] = albedo * (c == 2 ? 0.7f : 1.0f);
                planes.colour[3 * p + c] = sky ? 0.6f + 0.1f * float(c) : albedo * shade;
            }
            planes.normal[3 * p] = sky ? 0.0f : std::sin(angle);
            planes.normal[3 * p + 1] = 0.0f;
            planes.normal[3 * p + 2] = sky ? 0.0f : std::cos(angle);
            planes.depth[p] = sky ? -1.0f : 2.0f + 0.01f * float(y);
            planes.alpha[p] = sky ? 0.0f : 1.0f;
        }
    }
    return planes;
}

// `reference` with Gaussian noise of standard deviation `sigma` added to every channel, and the
// variance estimated as a renderer estimates it, from two halves of the samples: each half's mean
// has variance 2 sigma^2, so (a - b)^2 / 4 estimates sigma^2 (with one degree of freedom).
Planes noisy(const Planes& reference, float sigma, uint32_t seed) {
    Planes planes = reference;
    Noise noise(seed);
    for (size_t i = 0; i < planes.colour.size(); ++i) {
        const float half_a = noise.next() * sigma * std::sqrt(2.0f);
        const float half_b = noise.next() * sigma * std::sqrt(2.0f);
        planes.colour[i] = reference.colour[i] + 0.5f * (half_a + half_b);
        planes.variance[i] = 0.25f * (half_a - half_b) * (half_a - half_b);
    }
    return planes;
}

double mean_squared_error(const std::vector<float>& image, const std::vector<float>& reference) {
    double sum = 0.0;
    for (size_t i = 0; i < image.size(); ++i) {
        sum += (double(image[i]) - reference[i]) * (double(image[i]) - reference[i]);
    }
    return sum / double(image.size());
}

// The 8-bit sRGB level a linear value is written as.
int srgb_level(float linear) {
    const float v = std::clamp(linear, 0.0f, 1.0f);
    const float encoded = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
    return int(std::lround(encoded * 255.0f));
}

TEST(Denoise, ConvergedImageComesBackWithinOneLevel) {
    const Planes planes = detailed_scene();
    for (const DenoiseMethod method : kMethods) {
        const std::vector<float> out = denoise(planes.input(), {method, 0});
        int worst = 0;
        for (size_t i = 0; i < out.size(); ++i) {
            worst = std::max(worst, std::abs(srgb_level(out[i]) - srgb_level(planes.colour[i])));
        }
        EXPECT_LE(worst, 1) << denoise_method_name(method);
    }
}

TEST(Denoise, LowersTheErrorOfANoisyImage) {
    const Planes reference = detailed_scene();
    const Planes input = noisy(reference, 0.08f, 7);
    const double before = mean_squared_error(input.colour, reference.colour);
    for (const DenoiseMethod method : kMethods) {
        const double after =
            mean_squared_error(denoise(input.input(), {method, 0}), reference.colour);
        EXPECT_LT(after, 0.4 * before) << denoise_method_name(method);
    }
}

// A fractal's surface seen at a fold a pixel: the normal tilts from each pixel to the next by
// random angles about two axes, so that few pixels of a window face alike, and the shading
// follows it (Lambert, linear in the normal). The mean can only mix pixels that face alike; the
// regression fits the shading as it changes with the normal and takes the noise out of all.
TEST(Denoise, RegressionFollowsShadingThatTurnsWithTheNormal) {
    Planes reference;
    Noise angles(11);
    const float light[3] = {0.48f, 0.36f, 0.8f};
    for (size_t p = 0; p < kPixels; ++p) {
        const float a = 0.6f * angles.next(), b = 0.6f * angles.next();
        const float normal[3] = {std::sin(a) * std::cos(b), std::sin(b), std::cos(a) * std::cos(b)};
        const float lambert = normal[0] * light[0] + normal[1] * light[1] + normal[2] * light[2];
        for (size_t c = 0; c < 3; ++c) {
            reference.albedo[3 * p + c] = 0.6f;
            reference.colour[3 * p + c] = 0.6f * (0.2f + 0.6f * lambert);
            reference.normal[3 * p + c] = normal[c];
        }
        reference.depth[p] = 2.0f;
    }
    const Planes input = noisy(reference, 0.05f, 5);
    const double before = mean_squared_error(input.colour, reference.colour);
    const double mean =
        mean_squared_error(denoise(input.input(), {DenoiseMethod::NlMeans, 0}), reference.colour);
    const double fit = mean_squared_error(denoise(input.input(), {DenoiseMethod::Regression, 0}),
                                          reference.colour);
    EXPECT_LT(fit, 0.25 * before);
    EXPECT_LT(fit, 0.5 * mean);
}

TEST(Denoise, KeepsAnAlbedoEdgeWithinAPixel) {
    // Left of column 24 a dark albedo, right of it a bright one, the same flat lighting; noise
    // strong enough that a filter blind to albedo would blur the step over several pixels.
    Planes reference;
    for (size_t p = 0; p < kPixels; ++p) {
        const bool bright = p % kWidth >= kWidth / 2;
        for (size_t c = 0; c < 3; ++c) {
            reference.albedo[3 * p + c] = bright ? 0.8f : 0.2f;
            reference.colour[3 * p + c] = bright ? 0.8f : 0.2f;
        }
        reference.normal[3 * p + 2] = 1.0f;
        reference.depth[p] = 3.0f;
    }
    const float sigma = 0.15f;
    const Planes input = noisy(reference, sigma, 11);
    for (const DenoiseMethod method : kMethods) {
        const std::vector<float> out = denoise(input.input(), {method, 0});
        // The profile: each column's mean over the rows and channels. Every column but the two
        // at the step keeps its side's level, to a few standard errors of the input's noise.
        for (int x = 0; x < kWidth; ++x) {
            double sum = 0.0;
            for (int y = 0; y < kHeight; ++y) {
                for (size_t c = 0; c < 3; ++c) sum += out[3 * (size_t(y) * kWidth + size_t(x)) + c];
            }
            const double level = sum / (3.0 * kHeight);
            const double expected = x >= kWidth / 2 ? 0.8 : 0.2;
            const double tolerance = 4.0 * sigma / std::sqrt(3.0 * kHeight);
            EXPECT_NEAR(level, expected, tolerance)
                << denoise_method_name(method) << ", column " << x;
        }
    }
}

TEST(Denoise, ConvergedRegionStaysBesideANoisyOne) {
    // The left half converged (variance 0, detailed), the right half noisy: the left keeps its
    // pixels away from the border, the right loses most of its noise.
    const Planes reference = detailed_scene();
    const Planes noise = noisy(reference, 0.08f, 5);
    Planes input = reference;
    for (size_t p = 0; p < kPixels; ++p) {
        if (p % kWidth < kWidth / 2) continue;
        for (size_t c = 0; c < 3; ++c) {
            input.colour[3 * p + c] = noise.colour[3 * p + c];
            input.variance[3 * p + c] = noise.variance[3 * p + c];
        }
    }
    for (const DenoiseMethod method : kMethods) {
        const std::vector<float> out = denoise(input.input(), {method, 0});
        int worst = 0;
        double before = 0.0, after = 0.0;
        for (size_t p = 0; p < kPixels; ++p) {
            const size_t x = p % kWidth;
            for (size_t c = 0; c < 3; ++c) {
                const size_t i = 3 * p + c;
                if (x + 2 < kWidth / 2) {
                    worst =
                        std::max(worst, std::abs(srgb_level(out[i]) - srgb_level(input.colour[i])));
                } else if (x >= kWidth / 2) {
                    before += std::pow(input.colour[i] - reference.colour[i], 2.0);
                    after += std::pow(out[i] - reference.colour[i], 2.0);
                }
            }
        }
        EXPECT_LE(worst, 1) << denoise_method_name(method);
        EXPECT_LT(after, 0.5 * before) << denoise_method_name(method);
    }
}

TEST(Denoise, ThreadsChangeNothing) {
    const Planes input = noisy(detailed_scene(), 0.08f, 3);
    for (const DenoiseMethod method : kMethods) {
        EXPECT_EQ(denoise(input.input(), {method, 1}), denoise(input.input(), {method, 0}))
            << denoise_method_name(method);
    }
}

// The filters work through an image a few rows at a time. Rows added above the image move every
// boundary between those groups; they repeat the top row, sky, which no pixel of the surface
// takes as a neighbour, so every surface pixel (from row 8, below the sky and the patches and
// prefilter that reach into it) sees the same neighbours in the same order and must come out bit
// for bit the same.
TEST(Denoise, RowsAddedAboveChangeNothingBeyondTheirReach) {
    constexpr int kReach = 8;
    const Planes input = noisy(detailed_scene(), 0.08f, 5);
    for (const int added : {1, 2, 3, 5}) {
        const int height = kHeight + added;
        const size_t shift = size_t(added) * kWidth;
        // The first row repeated `added` times above the image, every plane alike.
        const auto taller = [&](const std::vector<float>& plane) {
            const auto first_row_end = plane.begin() + std::ptrdiff_t(plane.size() / kHeight);
            std::vector<float> out;
            for (int row = 0; row < added; ++row)
                out.insert(out.end(), plane.begin(), first_row_end);
            out.insert(out.end(), plane.begin(), plane.end());
            return out;
        };
        const std::vector<float> colour = taller(input.colour), variance = taller(input.variance),
                                 albedo = taller(input.albedo), normal = taller(input.normal),
                                 depth = taller(input.depth), alpha = taller(input.alpha);
        const DenoiseInput tall{kWidth, height, colour, variance, albedo, normal, depth, alpha};
        for (const DenoiseMethod method : kMethods) {
            for (const int threads : {1, 0}) {
                const std::vector<float> plain = denoise(input.input(), {method, threads});
                const std::vector<float> shifted = denoise(tall, {method, threads});
                for (size_t i = 3 * size_t(kReach) * kWidth; i < plain.size(); ++i) {
                    ASSERT_EQ(plain[i], shifted[i + 3 * shift])
                        << denoise_method_name(method) << ", " << added << " rows added, "
                        << threads << " threads, pixel " << i / 3;
                }
            }
        }
    }
}

TEST(Denoise, RefusesPlanesOfTheWrongSize) {
    const Planes planes = detailed_scene();
    const auto message = [](const DenoiseInput& input) {
        try {
            denoise(input);
        } catch (const std::invalid_argument& error) {
            return std::string(error.what());
        }
        return std::string("no error");
    };
    DenoiseInput input = planes.input();
    input.variance = input.variance.first(10);
    EXPECT_NE(message(input).find("variance"), std::string::npos) << message(input);
    input = planes.input();
    input.depth = input.depth.first(kPixels - 1);
    EXPECT_NE(message(input).find("depth"), std::string::npos) << message(input);
    input = planes.input();
    input.colour = {};
    EXPECT_NE(message(input).find("colour"), std::string::npos) << message(input);
    input = planes.input();
    input.width = 0;
    EXPECT_NE(message(input).find("no pixels"), std::string::npos) << message(input);
    // Features are optional: without them the colour and variance alone guide the filter.
    input = planes.input();
    input.albedo = input.normal = input.depth = input.alpha = {};
    EXPECT_EQ(denoise(input).size(), 3 * kPixels);
}

TEST(Denoise, PassesNonFinitePixelsThroughWithoutSpreadingThem) {
    Planes input = noisy(detailed_scene(), 0.08f, 9);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const size_t bad_colour = 20 * kWidth + 20, bad_variance = 10 * kWidth + 30,
                 bad_normal = 25 * kWidth + 5;
    input.colour[3 * bad_colour + 1] = nan;
    input.variance[3 * bad_variance] = std::numeric_limits<float>::infinity();
    input.normal[3 * bad_normal + 2] = nan;
    for (const DenoiseMethod method : kMethods) {
        const std::vector<float> out = denoise(input.input(), {method, 0});
        for (size_t i = 0; i < out.size(); ++i) {
            const size_t p = i / 3;
            if (p == bad_colour || p == bad_variance || p == bad_normal) {
                EXPECT_TRUE(std::isnan(out[i]) ? std::isnan(input.colour[i])
                                               : out[i] == input.colour[i])
                    << denoise_method_name(method) << ", pixel " << p;
            } else {
                ASSERT_TRUE(std::isfinite(out[i]))
                    << denoise_method_name(method) << ", pixel " << p;
            }
        }
    }
}

}  // namespace
}  // namespace fgr
