// SPDX-License-Identifier: Apache-2.0
#pragma once
// How far one image is from another: RMSE on linear values, and SSIM (the structural similarity
// index of Wang, Bovik, Sheikh and Simoncelli, "Image quality assessment: from error visibility to
// structural similarity", IEEE TIP 13(4), 2004), a perceptual measure that weighs local means,
// contrasts and structure the way a viewer notices them rather than summing squared differences.
// The accuracy sweeps compare a setting's image with a reference render through these.

#include <vector>

#include "image/hdr_image.hpp"
#include "image/image_io.hpp"

namespace fgr {

// One channel of values, row-major from the top row.
struct GreyImage {
    int width = 0;
    int height = 0;
    std::vector<float> values;
};

// SSIM's window and constants, as Wang et al. 2004 define them: an 11x11 circular-symmetric
// Gaussian window of standard deviation 1.5 pixels, normalised to sum 1, and stabilising constants
// C1 = (K1 L)^2, C2 = (K2 L)^2 for values spanning L.
inline constexpr int kSsimWindow = 11;
inline constexpr double kSsimSigma = 1.5;
inline constexpr double kSsimK1 = 0.01;
inline constexpr double kSsimK2 = 0.03;

// Mean SSIM of two single-channel images of the same size whose values span `dynamic_range` (L;
// 1 for values in [0, 1], 255 for 8-bit levels). In each window the means, variances and the
// covariance are weighted by the Gaussian (population statistics, not sample ones), and
//   SSIM = (2 mu_x mu_y + C1)(2 sigma_xy + C2) / ((mu_x^2 + mu_y^2 + C1)(sigma_x^2 + sigma_y^2 +
//   C2)).
// Borders: only windows that lie wholly inside the image count, (width - 10) x (height - 10) of
// them, averaged with equal weight (no padding; what Wang's ssim_index.m does with filter2
// 'valid' and scikit-image's structural_similarity does by cropping its map). So a pixel near
// an edge weighs in fewer windows than one in the middle; a corner pixel lies in one.
// 1 means identical (exactly, for identical inputs); it is symmetric in its two images and can
// fall below 0 for inverted structure. Throws std::invalid_argument when the sizes differ, a side
// is under 11 pixels, a value is not finite or `dynamic_range` is not positive.
double ssim(const GreyImage& image, const GreyImage& reference, double dynamic_range);

// What a screen shows of linear RGB, as one luma channel in [0, 1]: each channel times
// `exposure`, clamped to [0, 1] (NaN to 0), sRGB-encoded, then weighted with the Rec. 709
// coefficients 0.2126, 0.7152, 0.0722 (luma Y' from gamma-encoded R'G'B', as video and
// scikit-image's rgb2gray form it).
GreyImage display_luma(const HdrImage& linear, float exposure = 1.0f);

// SSIM of two linear-RGB images of the same size as they are displayed: on display_luma (both
// times `exposure`, then clamped; HDR images can pick what range of light to judge), L = 1.
// Colour enters through luma only. The perceptual metric of the accuracy sweeps; 1 - ssim is
// their error (0 for identical images, lower is better).
double ssim(const HdrImage& image, const HdrImage& reference, float exposure = 1.0f);

// Root-mean-square difference over every channel of every pixel, in linear units. Throws
// std::invalid_argument when the sizes differ.
double rmse(const HdrImage& image, const HdrImage& reference);

// An 8-bit sRGB image decoded to linear RGB (the exact inverse of the sRGB curve, so
// display_luma gives back the levels / 255 to float rounding).
HdrImage linear_rgb(const Image8& image);

}  // namespace fgr
