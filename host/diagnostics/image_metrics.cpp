// SPDX-License-Identifier: Apache-2.0
#include "diagnostics/image_metrics.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fgr {
namespace {

constexpr int kRadius = kSsimWindow / 2;

// The 1D Gaussian whose outer product is the 2D window; normalised, so the window sums to 1.
std::array<double, kSsimWindow> gaussian_weights() {
    std::array<double, kSsimWindow> weights{};
    double sum = 0.0;
    for (int i = 0; i < kSsimWindow; ++i) {
        const double d = double(i - kRadius);
        weights[size_t(i)] = std::exp(-d * d / (2.0 * kSsimSigma * kSsimSigma));
        sum += weights[size_t(i)];
    }
    for (double& w : weights) w /= sum;
    return weights;
}

// Gaussian-weighted sums of `plane` over every window that lies wholly inside the image:
// (width - 10) x (height - 10) values, row-major. Separable: along rows, then down columns.
std::vector<double> window_means(const std::vector<double>& plane, int width, int height) {
    static const std::array<double, kSsimWindow> weights = gaussian_weights();
    const int out_w = width - 2 * kRadius, out_h = height - 2 * kRadius;
    std::vector<double> rows(size_t(out_w) * size_t(height));
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < out_w; ++x) {
            double sum = 0.0;
            for (int k = 0; k < kSsimWindow; ++k) {
                sum += weights[size_t(k)] * plane[size_t(y) * size_t(width) + size_t(x + k)];
            }
            rows[size_t(y) * size_t(out_w) + size_t(x)] = sum;
        }
    }
    std::vector<double> out(size_t(out_w) * size_t(out_h));
    for (int y = 0; y < out_h; ++y) {
        for (int x = 0; x < out_w; ++x) {
            double sum = 0.0;
            for (int k = 0; k < kSsimWindow; ++k) {
                sum += weights[size_t(k)] * rows[size_t(y + k) * size_t(out_w) + size_t(x)];
            }
            out[size_t(y) * size_t(out_w) + size_t(x)] = sum;
        }
    }
    return out;
}

void check_grey(const GreyImage& image, const char* which) {
    if (image.width <= 0 || image.height <= 0 ||
        image.values.size() != size_t(image.width) * size_t(image.height)) {
        throw std::invalid_argument(fmt::format("ssim: the {} image's {} values do not fill {}x{}",
                                                which, image.values.size(), image.width,
                                                image.height));
    }
    for (float v : image.values) {
        if (!std::isfinite(v)) {
            throw std::invalid_argument(
                fmt::format("ssim: the {} image has a value that is not "
                            "finite",
                            which));
        }
    }
}

void check_same_size(int w1, int h1, int w2, int h2, const char* what) {
    if (w1 != w2 || h1 != h2) {
        throw std::invalid_argument(
            fmt::format("{}: images of different sizes ({}x{} and {}x{})", what, w1, h1, w2, h2));
    }
}

void check_hdr(const HdrImage& image, const char* what) {
    if (image.width < 0 || image.height < 0 ||
        image.rgb.size() != size_t(image.width) * size_t(image.height) * 3) {
        throw std::invalid_argument(fmt::format("{}: {} floats do not fill a {}x{} RGB image", what,
                                                image.rgb.size(), image.width, image.height));
    }
}

float srgb_encode(float linear) {
    if (!(linear > 0.0f)) return 0.0f;  // also NaN
    if (linear >= 1.0f) return 1.0f;
    return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

float srgb_decode(float encoded) {
    return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

}  // namespace

double ssim(const GreyImage& image, const GreyImage& reference, double dynamic_range) {
    check_grey(image, "first");
    check_grey(reference, "second");
    check_same_size(image.width, image.height, reference.width, reference.height, "ssim");
    if (image.width < kSsimWindow || image.height < kSsimWindow) {
        throw std::invalid_argument(
            fmt::format("ssim: a {}x{} image is smaller than the {}x{} window", image.width,
                        image.height, kSsimWindow, kSsimWindow));
    }
    if (!(dynamic_range > 0.0) || !std::isfinite(dynamic_range)) {
        throw std::invalid_argument(
            fmt::format("ssim: dynamic range {} is not positive", dynamic_range));
    }
    const int w = image.width, h = image.height;
    const size_t n = image.values.size();
    std::vector<double> x(n), y(n), xx(n), yy(n), xy(n);
    for (size_t i = 0; i < n; ++i) {
        x[i] = image.values[i];
        y[i] = reference.values[i];
        xx[i] = x[i] * x[i];
        yy[i] = y[i] * y[i];
        xy[i] = x[i] * y[i];
    }
    const std::vector<double> mx = window_means(x, w, h), my = window_means(y, w, h);
    const std::vector<double> exx = window_means(xx, w, h), eyy = window_means(yy, w, h);
    const std::vector<double> exy = window_means(xy, w, h);
    const double c1 = (kSsimK1 * dynamic_range) * (kSsimK1 * dynamic_range);
    const double c2 = (kSsimK2 * dynamic_range) * (kSsimK2 * dynamic_range);
    double sum = 0.0;
    for (size_t i = 0; i < mx.size(); ++i) {
        // Written so that swapping the images changes no rounding: the result is symmetric, and
        // exactly 1 for identical images (numerator and denominator are then the same numbers).
        const double mean_product = mx[i] * my[i];
        const double var_x = exx[i] - mx[i] * mx[i], var_y = eyy[i] - my[i] * my[i];
        const double covariance = exy[i] - mean_product;
        const double numerator = (2.0 * mean_product + c1) * (2.0 * covariance + c2);
        const double denominator = (mx[i] * mx[i] + my[i] * my[i] + c1) * (var_x + var_y + c2);
        sum += numerator / denominator;
    }
    return sum / double(mx.size());
}

GreyImage display_luma(const HdrImage& linear, float exposure) {
    check_hdr(linear, "display_luma");
    GreyImage luma{linear.width, linear.height,
                   std::vector<float>(size_t(linear.width) * size_t(linear.height))};
    for (size_t i = 0; i < luma.values.size(); ++i) {
        const float r = srgb_encode(linear.rgb[3 * i] * exposure);
        const float g = srgb_encode(linear.rgb[3 * i + 1] * exposure);
        const float b = srgb_encode(linear.rgb[3 * i + 2] * exposure);
        luma.values[i] = 0.2126f * r + 0.7152f * g + 0.0722f * b;
    }
    return luma;
}

double ssim(const HdrImage& image, const HdrImage& reference, float exposure) {
    check_hdr(image, "ssim");
    check_hdr(reference, "ssim");
    check_same_size(image.width, image.height, reference.width, reference.height, "ssim");
    return ssim(display_luma(image, exposure), display_luma(reference, exposure), 1.0);
}

double rmse(const HdrImage& image, const HdrImage& reference) {
    check_hdr(image, "rmse");
    check_hdr(reference, "rmse");
    check_same_size(image.width, image.height, reference.width, reference.height, "rmse");
    double squares = 0.0;
    for (size_t i = 0; i < image.rgb.size(); ++i) {
        const double d = double(image.rgb[i]) - double(reference.rgb[i]);
        squares += d * d;
    }
    return image.rgb.empty() ? 0.0 : std::sqrt(squares / double(image.rgb.size()));
}

HdrImage linear_rgb(const Image8& image) {
    if (image.width < 0 || image.height < 0 ||
        image.rgb.size() != size_t(image.width) * size_t(image.height) * 3) {
        throw std::invalid_argument(fmt::format("linear_rgb: {} bytes do not fill a {}x{} image",
                                                image.rgb.size(), image.width, image.height));
    }
    std::array<float, 256> table{};
    for (int i = 0; i < 256; ++i) table[size_t(i)] = srgb_decode(float(i) / 255.0f);
    HdrImage linear{image.width, image.height, std::vector<float>(image.rgb.size())};
    for (size_t i = 0; i < image.rgb.size(); ++i) linear.rgb[i] = table[image.rgb[i]];
    return linear;
}

}  // namespace fgr
