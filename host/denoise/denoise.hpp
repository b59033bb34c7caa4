// SPDX-License-Identifier: Apache-2.0
#pragma once
// A feature-guided denoiser for path-traced images, hand-written from published methods because
// no denoising library is packaged for Debian 12. Two filters share one weighting of pixels:
//
//   Atrous   edge-avoiding a-trous wavelet filtering (Dammertz, Sewtz, Hanika and Lensch, "Edge-
//            avoiding a-trous wavelet transform for fast global illumination filtering", HPG
//            2010), with the colour weight driven by the estimate's variance and the variance
//            filtered alongside the colour, as in SVGF (Schied et al., "Spatiotemporal
//            variance-guided filtering", HPG 2017). Five passes of a 5x5 kernel whose taps
//            spread 1, 2, 4, 8, 16 pixels apart: fast, for the viewer's progressive preview.
//   NlMeans  joint non-local means (Rousselle, Manzi and Zwicker, "Robust denoising using
//            feature and color information", Pacific Graphics 2013): each pixel the weighted
//            mean of a 15x15 window, weighted by how alike 3x3 patches of colour are (their
//            difference measured against the variance) and how alike the features are.
//   Regression  the same weights, and instead of their mean a weighted least-squares fit of the
//            colour as an affine function of the features (albedo, normal, depth) around the
//            pixel, read at the pixel: a first-order regression on features as in NFOR (Bitterli
//            et al., "Nonlinearly weighted first-order regression for denoising Monte Carlo
//            renderings", EGSR 2016) and Moon, Carr and Yoon's weighted local regression (2014).
//            Shading on a fractal changes from pixel to pixel with the normal; the fit follows
//            that change, so neighbours whose normals differ still lend their samples, where the
//            mean has to leave them out. About 1.6 times the error reduction of the mean on the
//            Mandelbulb; the default for stills and videos.
//
// In all three a neighbour's weight falls to zero when its colour differs from the pixel's by more
// than the two pixels' variances explain, so a converged image (variance 0) comes back as it was,
// and when its albedo, normal, depth or coverage differs, so edges of the surface and of its
// texture stay sharp.

#include <span>
#include <vector>

namespace fgr {

// One image's planes, row-major from the top row, each `width * height` pixels.
struct DenoiseInput {
    int width = 0;
    int height = 0;
    std::span<const float> colour;    // linear RGB, 3 floats a pixel
    std::span<const float> variance;  // of each channel's estimate (of the mean), 3 floats a pixel
    // Features, each optional (empty: not used): the first hit's albedo (RGB) and normal (XYZ),
    // averaged over the samples, the pixel centre's depth (-1 where it missed) and coverage.
    std::span<const float> albedo{};
    std::span<const float> normal{};
    std::span<const float> depth{};
    std::span<const float> alpha{};
};

enum class DenoiseMethod { Atrous, NlMeans, Regression };

struct DenoiseSettings {
    DenoiseMethod method = DenoiseMethod::Regression;
    // Threads: 0, one a hardware thread; 1, the calling thread alone.
    int threads = 0;
};

// The denoised linear RGB, 3 floats a pixel. A pixel with a non-finite value in any plane comes
// back unchanged and is nobody's neighbour; a negative variance counts as 0. Throws
// std::invalid_argument naming the plane whose size does not match width x height (colour and
// variance are required), or a size that is not positive.
std::vector<float> denoise(const DenoiseInput& input, const DenoiseSettings& settings = {});

// The method's name as users see it ("a-trous", "nl-means", "regression").
const char* denoise_method_name(DenoiseMethod method);

}  // namespace fgr
