// SPDX-License-Identifier: Apache-2.0
#include "denoise/denoise.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <thread>

#include "util/parallel_bands.hpp"

namespace fgr {
namespace {

// Colour: Rousselle, Knaus and Zwicker's variance-cancelled distance ("Adaptive rendering with
// non-local means filtering", SIGGRAPH Asia 2012, eq. 4): the squared difference less what the
// two variances explain (alpha), over the variances scaled by k^2. kEpsilon only keeps 0/0 away:
// with no variance any difference at all is an edge.
// Rousselle et al. use k = 0.45 with variances from many samples; the variance here comes from
// few (two halves, or the viewer's samples) and is noisier, so both filters take a wider k,
// measured on path-traced fractals against 2048-sample references (docs/user-guide/denoising.md).
constexpr float kColourAlpha = 1.0f;
constexpr float kColourK = 2.0f;
constexpr float kAtrousColourK = 4.0f;
constexpr float kEpsilon = 1e-12f;
// Features (squared differences over these squared): albedo and coverage in [0, 1], unit
// normals, and depth relative to the nearer pixel's, per pixel of distance between the two.
// Joint NL-means takes the smaller of its colour and feature weights where a-trous multiplies
// them, so it measured best with albedo and normal weights half as wide (kNlMeansFeatureScale).
constexpr float kSigmaAlbedo = 0.1f;
constexpr float kSigmaNormal = 0.3f;
constexpr float kSigmaAlpha = 0.1f;
constexpr float kSigmaDepthPerPixel = 0.02f;
constexpr float kNlMeansFeatureScale = 0.5f;
// The regression fits how colour follows albedo, normal and depth, so it needs its neighbours
// less alike in those: it measured best with feature weights twice as wide as the others'.
constexpr float kRegressionFeatureScale = 2.0f;
// Joint NL-means: 15x15 window, 3x3 patches (Rousselle et al. 2013 use 21x21 and 7x7 for
// offline renders; these keep a 640x480 still under a second on two cores).
constexpr int kWindowRadius = 7;
constexpr int kPatchRadius = 1;
// A-trous: five passes of a 3x3 binomial kernel ([1 2 1] / 4 each way), taps 1, 2, 4, 8, 16
// pixels apart. Dammertz et al. use the 5x5 B3 spline; the 3x3 kernel costs 9 taps a pass
// instead of 25 and measured as well on our renders (the weights, not the kernel, shape the
// result).
constexpr int kAtrousPasses = 5;
constexpr int kAtrousRadius = 1;
constexpr std::array<float, 3> kKernel = {0.25f, 0.5f, 0.25f};

// A pixel's features, each scaled by the inverse of its width so that the feature distance is a
// plain sum of squares; absent features are 0 everywhere and so never differ.
struct Guide {
    std::array<float, 3> albedo{};
    std::array<float, 3> normal{};
    float alpha = 0.0f;
    float depth = 0.0f;  // as given: < 0 where the camera ray missed
};

struct Planes {
    int width = 0;
    int height = 0;
    std::vector<float> colour;    // 3 a pixel; 0 where invalid
    std::vector<float> variance;  // 3 a pixel, >= 0; 0 where invalid
    std::vector<unsigned char> valid;
    std::vector<Guide> guides;
    size_t index(int x, int y) const { return size_t(y) * size_t(width) + size_t(x); }
};

void check_plane(std::span<const float> plane, size_t pixels, int channels, const char* name,
                 bool required) {
    if (plane.empty() && !required) return;
    if (plane.size() != pixels * size_t(channels)) {
        throw std::invalid_argument(
            fmt::format("denoise: the {} plane holds {} floats, not the {} of {} pixels x {}", name,
                        plane.size(), pixels * size_t(channels), pixels, channels));
    }
}

bool finite_at(std::span<const float> plane, size_t pixel, int channels) {
    if (plane.empty()) return true;
    for (int c = 0; c < channels; ++c) {
        if (!std::isfinite(plane[pixel * size_t(channels) + size_t(c)])) return false;
    }
    return true;
}

Planes prepare(const DenoiseInput& input) {
    if (input.width <= 0 || input.height <= 0) {
        throw std::invalid_argument(
            fmt::format("denoise: a {}x{} image has no pixels", input.width, input.height));
    }
    const size_t pixels = size_t(input.width) * size_t(input.height);
    check_plane(input.colour, pixels, 3, "colour", true);
    check_plane(input.variance, pixels, 3, "variance", true);
    check_plane(input.albedo, pixels, 3, "albedo", false);
    check_plane(input.normal, pixels, 3, "normal", false);
    check_plane(input.depth, pixels, 1, "depth", false);
    check_plane(input.alpha, pixels, 1, "alpha", false);
    Planes planes{input.width,
                  input.height,
                  std::vector<float>(pixels * 3, 0.0f),
                  std::vector<float>(pixels * 3, 0.0f),
                  std::vector<unsigned char>(pixels, 0),
                  std::vector<Guide>(pixels)};
    for (size_t p = 0; p < pixels; ++p) {
        const bool valid = finite_at(input.colour, p, 3) && finite_at(input.variance, p, 3) &&
                           finite_at(input.albedo, p, 3) && finite_at(input.normal, p, 3) &&
                           finite_at(input.depth, p, 1) && finite_at(input.alpha, p, 1);
        planes.valid[p] = valid ? 1 : 0;
        if (!valid) continue;
        Guide& guide = planes.guides[p];
        for (size_t c = 0; c < 3; ++c) {
            planes.colour[3 * p + c] = input.colour[3 * p + c];
            planes.variance[3 * p + c] = std::max(input.variance[3 * p + c], 0.0f);
            if (!input.albedo.empty()) guide.albedo[c] = input.albedo[3 * p + c] / kSigmaAlbedo;
            if (!input.normal.empty()) guide.normal[c] = input.normal[3 * p + c] / kSigmaNormal;
        }
        if (!input.alpha.empty()) guide.alpha = input.alpha[p] / kSigmaAlpha;
        if (!input.depth.empty()) guide.depth = input.depth[p];
    }
    return planes;
}

// The variance of a few samples is itself noisy: averaged over the 3x3 pixels around (among the
// valid ones whose camera rays met the surface, or missed it, alike), as SVGF prefilters it.
std::vector<float> smoothed_variance(const Planes& planes) {
    std::vector<float> out(planes.variance.size(), 0.0f);
    const auto missed = [&](size_t p) { return planes.guides[p].depth < 0.0f; };
    in_parallel_bands(size_t(planes.height), 16, [&](size_t first, size_t last) {
        for (int y = int(first); y < int(last); ++y) {
            for (int x = 0; x < planes.width; ++x) {
                const size_t p = planes.index(x, y);
                if (!planes.valid[p]) continue;
                std::array<float, 3> sum{};
                int count = 0;
                for (int dy = -1; dy <= 1; ++dy) {
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int qx = x + dx, qy = y + dy;
                        if (qx < 0 || qy < 0 || qx >= planes.width || qy >= planes.height) continue;
                        const size_t q = planes.index(qx, qy);
                        if (!planes.valid[q] || missed(q) != missed(p)) continue;
                        for (size_t c = 0; c < 3; ++c) sum[c] += planes.variance[3 * q + c];
                        ++count;
                    }
                }
                for (size_t c = 0; c < 3; ++c) out[3 * p + c] = sum[c] / float(count);
            }
        }
    });
    return out;
}

// Weights below exp(-kNegligible) are left out (under 1e-9 of the pixel's own).
constexpr float kNegligible = 20.0f;

// How unlike two pixels' features are, as an exponent (0 for equal ones, the weight is
// exp(-exponent)); past kNegligible when one camera ray hit the surface and the other missed.
// `distance` in pixels between them; `surface_factor` multiplies the albedo and normal terms.
float feature_exponent(const Guide& p, const Guide& q, float distance, float surface_factor) {
    if ((p.depth < 0.0f) != (q.depth < 0.0f)) return 2.0f * kNegligible;
    float surface = 0.0f;
    for (size_t c = 0; c < 3; ++c) {
        const float da = p.albedo[c] - q.albedo[c], dn = p.normal[c] - q.normal[c];
        surface += da * da + dn * dn;
    }
    const float dalpha = p.alpha - q.alpha;
    float exponent = surface * surface_factor + dalpha * dalpha;
    if (p.depth > 0.0f) {
        const float relative = std::fabs(p.depth - q.depth) /
                               (std::min(p.depth, q.depth) * kSigmaDepthPerPixel * distance);
        exponent += relative * relative;
    }
    return exponent;
}

// Rousselle et al.'s per-pixel colour distance of p and q, summed over the channels (not yet
// divided by them).
float colour_distance(const float* cp, const float* vp, const float* cq, const float* vq, float k) {
    float sum = 0.0f;
    for (int c = 0; c < 3; ++c) {
        const float d = cp[c] - cq[c];
        const float noise = kColourAlpha * (vp[c] + std::min(vp[c], vq[c]));
        sum += (d * d - noise) / (kEpsilon + k * k * (vp[c] + vq[c]));
    }
    return sum;
}

// A neighbour noisier than the pixel counts in proportion to how much less it knows (the ratio of
// their variances, as an inverse-variance mean weighs estimates of one value): a converged pixel
// takes nothing from noisy neighbours, however alike their colours.
float precision_weight(const float* vp, const float* vq) {
    const float p = vp[0] + vp[1] + vp[2], q = vq[0] + vq[1] + vq[2];
    return q <= p ? 1.0f : (p + kEpsilon) / (q + kEpsilon);
}

// Rows a thread takes at least: enough pixels to be worth a thread, and small images still
// split (so that the tests see the bands join up).
size_t band_length(const Planes& planes) { return size_t(std::max(4, 512 / planes.width)); }

void run_bands(const Planes& planes, int threads, const std::function<void(size_t, size_t)>& work) {
    if (threads == 1) {
        work(0, size_t(planes.height));
    } else {
        in_parallel_bands(size_t(planes.height), band_length(planes), work);
    }
}

std::vector<float> atrous(const Planes& planes, const DenoiseSettings& settings) {
    std::vector<float> colour = planes.colour, variance = smoothed_variance(planes);
    std::vector<float> next_colour(colour.size()), next_variance(variance.size());
    for (int pass = 0; pass < kAtrousPasses; ++pass) {
        const int step = 1 << pass;
        run_bands(planes, settings.threads, [&](size_t first, size_t last) {
            for (int y = int(first); y < int(last); ++y) {
                for (int x = 0; x < planes.width; ++x) {
                    const size_t p = planes.index(x, y);
                    const float* cp = &colour[3 * p];
                    const float* vp = &variance[3 * p];
                    if (!planes.valid[p]) {
                        std::copy(cp, cp + 3, &next_colour[3 * p]);
                        std::copy(vp, vp + 3, &next_variance[3 * p]);
                        continue;
                    }
                    const Guide& gp = planes.guides[p];
                    std::array<float, 3> sum{}, sum_variance{};
                    float weights = 0.0f;
                    for (int j = -kAtrousRadius; j <= kAtrousRadius; ++j) {
                        const int qy = y + j * step;
                        if (qy < 0 || qy >= planes.height) continue;
                        for (int i = -kAtrousRadius; i <= kAtrousRadius; ++i) {
                            const int qx = x + i * step;
                            if (qx < 0 || qx >= planes.width) continue;
                            const size_t q = planes.index(qx, qy);
                            if (!planes.valid[q]) continue;
                            const float* cq = &colour[3 * q];
                            const float* vq = &variance[3 * q];
                            float w = kKernel[size_t(i + kAtrousRadius)] *
                                      kKernel[size_t(j + kAtrousRadius)];
                            if (q != p) {
                                const float distance =
                                    float(step * std::max(std::abs(i), std::abs(j)));
                                const float exponent =
                                    std::max(colour_distance(cp, vp, cq, vq, kAtrousColourK) / 3.0f,
                                             0.0f) +
                                    feature_exponent(gp, planes.guides[q], distance, 1.0f);
                                if (exponent > kNegligible) continue;
                                w *= std::exp(-exponent) * precision_weight(vp, vq);
                            }
                            weights += w;
                            for (size_t c = 0; c < 3; ++c) {
                                sum[c] += w * cq[c];
                                sum_variance[c] += w * w * vq[c];
                            }
                        }
                    }
                    for (size_t c = 0; c < 3; ++c) {
                        next_colour[3 * p + c] = sum[c] / weights;
                        next_variance[3 * p + c] = sum_variance[c] / (weights * weights);
                    }
                }
            }
        });
        colour.swap(next_colour);
        variance.swap(next_variance);
    }
    return colour;
}

// A local fit of colour over a window: the weighted mean (NlMeans), or a weighted least-squares
// fit of colour as an affine function of the features around the pixel, evaluated at the pixel
// (Regression). The regressors are 1 and the feature differences q - p: normal (3), albedo (3)
// and depth (relative to the pixel's, over the window's reach); misses have none but the 1.
constexpr int kRegressors = 8;
// The upper triangle of the normal equations' matrix for `regressors` regressors.
constexpr int gram_terms(int regressors) { return regressors * (regressors + 1) / 2; }
// Ridge on the feature coefficients, relative to the sum of the weights: enough to keep a window
// whose features do not vary (the sky, a flat wall) solvable, too little to bias a fit that has
// the data (measured: 1e-2 changes nothing, 1e-1 blurs).
constexpr double kRidge = 1e-3;
// The rows whose sums the window's offsets fill together are as many as keep those sums within
// kSumsInCache floats (a core's cache), at least kLeastRowsAtOnce: each offset's colour distances
// are computed for those rows and the patch's margin, so fewer rows cost more of them. The
// regression's sums are 60 floats a pixel, 4 rows of a 640-pixel image; the mean's 4 floats.
// Measured from 160x120 to 1920x1080: the regression 1.5x faster than a pixel's sums at a time
// over a band; at 640x480, 2 rows or 8 at once slower than 4.
constexpr size_t kSumsInCache = size_t{1} << 16;
constexpr size_t kLeastRowsAtOnce = 4;
// An 11x11 window: as good as 15x15 for the fit (within 2% either way on three scenes) at half the
// cost, which at 8 regressors a neighbour is most of the filter's time.
constexpr int kRegressionWindowRadius = 5;

struct LocalFit {
    int regressors = 1;  // 1: the weighted mean; kRegressors: the first-order regression
    float surface_factor = 1.0f;
    int window_radius = kWindowRadius;
};

LocalFit local_fit(DenoiseMethod method) {
    if (method == DenoiseMethod::Regression) {
        return {kRegressors, 1.0f / (kRegressionFeatureScale * kRegressionFeatureScale),
                kRegressionWindowRadius};
    }
    return {1, 1.0f / (kNlMeansFeatureScale * kNlMeansFeatureScale), kWindowRadius};
}

// The regressors of neighbour q for pixel p (the first is 1): features already divided by their
// widths, depth relative to p's over the window's reach.
std::array<float, kRegressors> regressors(const Guide& p, const Guide& q, float reach) {
    std::array<float, kRegressors> x{};
    x[0] = 1.0f;
    for (size_t c = 0; c < 3; ++c) {
        x[1 + c] = q.normal[c] - p.normal[c];
        x[4 + c] = q.albedo[c] - p.albedo[c];
    }
    if (p.depth > 0.0f && q.depth > 0.0f) {
        x[7] = (q.depth - p.depth) / (p.depth * kSigmaDepthPerPixel * reach);
    }
    return x;
}

// Solves the ridge-regularised normal equations for the fit's value at the pixel (the first
// coefficient) by Cholesky factorisation; false when they are singular all the same.
bool solve_fit(const float* gram, const float* moments, float* rgb) {
    double a[kRegressors][kRegressors];
    double b[kRegressors][3];
    const double weights = gram[0];
    for (int i = 0, t = 0; i < kRegressors; ++i) {
        for (int j = i; j < kRegressors; ++j, ++t) a[i][j] = a[j][i] = gram[t];
        if (i > 0) a[i][i] += kRidge * weights;
        for (int c = 0; c < 3; ++c) b[i][c] = moments[3 * i + c];
    }
    for (int j = 0; j < kRegressors; ++j) {  // a = L L^T, L in the lower triangle
        double d = a[j][j];
        for (int k = 0; k < j; ++k) d -= a[j][k] * a[j][k];
        if (!(d > 1e-12 * weights)) return false;
        a[j][j] = std::sqrt(d);
        for (int i = j + 1; i < kRegressors; ++i) {
            double v = a[i][j];
            for (int k = 0; k < j; ++k) v -= a[i][k] * a[j][k];
            a[i][j] = v / a[j][j];
        }
    }
    for (int c = 0; c < 3; ++c) {
        double y[kRegressors];
        for (int i = 0; i < kRegressors; ++i) {  // L y = b
            double v = b[i][c];
            for (int k = 0; k < i; ++k) v -= a[i][k] * y[k];
            y[i] = v / a[i][i];
        }
        for (int i = kRegressors - 1; i >= 0; --i) {  // L^T beta = y
            double v = y[i];
            for (int k = i + 1; k < kRegressors; ++k) v -= a[k][i] * y[k];
            y[i] = v / a[i][i];
        }
        rgb[c] = float(y[0]);
    }
    return std::isfinite(rgb[0]) && std::isfinite(rgb[1]) && std::isfinite(rgb[2]);
}

// Adds one offset's neighbours to a row's sums, term by term across the row's `width` pixels:
// gram term (i, j) += weight x_i x_j and moment (i, c) += weight x_i colour_c, with `weights`,
// `xs` (regressor i of pixel x at i * width + x) and `colours` (channel c at c * width + x) as
// the row's pixels see their neighbours; `weighted` holds width floats of scratch. Each sum takes
// its terms in the same order as a pixel at a time would, so the result does not depend on this
// layout.
void accumulate_row(const float* weights, const float* xs, const float* colours, int regressors,
                    int width, float* weighted, float* gram, float* moments) {
    const size_t n = size_t(width);
    for (int i = 0, t = 0; i < regressors; ++i) {
        const float* xi = xs + size_t(i) * n;
        for (size_t x = 0; x < n; ++x) weighted[x] = weights[x] * xi[x];
        for (int j = i; j < regressors; ++j, ++t) {
            const float* xj = xs + size_t(j) * n;
            float* g = gram + size_t(t) * n;
            for (size_t x = 0; x < n; ++x) g[x] += weighted[x] * xj[x];
        }
        for (size_t c = 0; c < 3; ++c) {
            const float* colour = colours + c * n;
            float* m = moments + (3 * size_t(i) + c) * n;
            for (size_t x = 0; x < n; ++x) m[x] += weighted[x] * colour[x];
        }
    }
}

// Joint non-local means weights (colour patches and features) over the window, and the local fit
// with them: the weighted mean, or the first-order regression.
std::vector<float> local_regression(const Planes& planes, const DenoiseSettings& settings) {
    const LocalFit fit = local_fit(settings.method);
    const int terms = gram_terms(fit.regressors);
    const std::vector<float> variance = smoothed_variance(planes);
    const int w = planes.width, h = planes.height;
    std::vector<float> out(planes.colour.size());
    // A band's rows are filtered a few at a time, so that their sums stay in the cache while
    // every offset of the window adds to them.
    const auto filter_rows = [&](size_t first, size_t last) {
        const int y0 = int(first), y1 = int(last);
        const int rows = y1 - y0 + 2 * kPatchRadius;
        // Per offset: each pixel pair's colour distance over these rows and the patch's margin
        // (distance), summed along rows over the patch (row_sums), then down columns.
        std::vector<float> distance(size_t(rows) * size_t(w)), row_sums(distance.size());
        // Per row, term by term across the row (so that the loops over a row's pixels
        // vectorise): the weighted sums of the regressors' products (gram, upper
        // triangle; gram term 0 is the sum of the weights) and of the regressors times the
        // colour (moments).
        const size_t row_gram = size_t(terms) * size_t(w);
        const size_t row_moments = size_t(fit.regressors) * 3 * size_t(w);
        std::vector<float> gram(size_t(y1 - y0) * row_gram, 0.0f);
        std::vector<float> moments(size_t(y1 - y0) * row_moments, 0.0f);
        // One row's neighbours at one offset: each pixel's weight (0 for none), the neighbour's
        // regressors and colour, term by term across the row. The mean's one regressor is 1.
        const size_t row_pixels = static_cast<size_t>(w);
        std::vector<float> weights(row_pixels), xs(size_t(fit.regressors) * row_pixels, 1.0f),
            colours(3 * row_pixels), weighted(row_pixels);
        const auto clamp_x = [w](int x) { return std::clamp(x, 0, w - 1); };
        const auto clamp_y = [h](int y) { return std::clamp(y, 0, h - 1); };
        const int radius = fit.window_radius;
        for (int oy = -radius; oy <= radius; ++oy) {
            for (int ox = -radius; ox <= radius; ++ox) {
                const bool self = ox == 0 && oy == 0;
                if (!self) {
                    for (int r = 0; r < rows; ++r) {
                        const int y = clamp_y(y0 - kPatchRadius + r);
                        const int qy = clamp_y(y + oy);
                        for (int x = 0; x < w; ++x) {
                            const size_t p = planes.index(x, y),
                                         q = planes.index(clamp_x(x + ox), qy);
                            distance[size_t(r) * size_t(w) + size_t(x)] =
                                colour_distance(&planes.colour[3 * p], &variance[3 * p],
                                                &planes.colour[3 * q], &variance[3 * q], kColourK);
                        }
                    }
                    for (int r = 0; r < rows; ++r) {
                        const float* in = &distance[size_t(r) * size_t(w)];
                        float* row = &row_sums[size_t(r) * size_t(w)];
                        for (int x = 0; x < w; ++x) {
                            float s = 0.0f;
                            for (int k = -kPatchRadius; k <= kPatchRadius; ++k)
                                s += in[clamp_x(x + k)];
                            row[x] = s;
                        }
                    }
                }
                constexpr float patch_terms =
                    3.0f * float((2 * kPatchRadius + 1) * (2 * kPatchRadius + 1));
                const float distance_pixels = float(std::max(std::abs(ox), std::abs(oy)));
                for (int y = y0; y < y1; ++y) {
                    const int qy = y + oy;
                    if (qy < 0 || qy >= h) continue;
                    const int r = y - y0 + kPatchRadius;
                    // Pixels without a neighbour here get weight 0 and add nothing: their
                    // regressors and colour keep an earlier pixel's values, all finite.
                    std::fill(weights.begin(), weights.end(), 0.0f);
                    for (int x = 0; x < w; ++x) {
                        const int qx = x + ox;
                        if (qx < 0 || qx >= w) continue;
                        const size_t p = planes.index(x, y), q = planes.index(qx, qy);
                        if (!planes.valid[p] || !planes.valid[q]) continue;
                        const Guide& gp = planes.guides[p];
                        const Guide& gq = planes.guides[q];
                        float weight = 1.0f;
                        if (!self) {
                            float patch = 0.0f;
                            for (int k = -kPatchRadius; k <= kPatchRadius; ++k) {
                                patch += row_sums[size_t(r + k) * size_t(w) + size_t(x)];
                            }
                            const float colour = patch / patch_terms;
                            if (colour > kNegligible) continue;
                            // The smaller of the two weights (Rousselle et al. 2013).
                            const float exponent = std::max(
                                colour,
                                feature_exponent(gp, gq, distance_pixels, fit.surface_factor));
                            if (exponent > kNegligible) continue;
                            weight = std::exp(-exponent) *
                                     precision_weight(&variance[3 * p], &variance[3 * q]);
                        }
                        weights[size_t(x)] = weight;
                        for (size_t c = 0; c < 3; ++c) {
                            colours[c * size_t(w) + size_t(x)] = planes.colour[3 * q + c];
                        }
                        if (fit.regressors == 1) continue;
                        const std::array<float, kRegressors> xq = regressors(gp, gq, float(radius));
                        for (int i = 0; i < kRegressors; ++i) {
                            xs[size_t(i) * size_t(w) + size_t(x)] = xq[size_t(i)];
                        }
                    }
                    float* g = &gram[size_t(y - y0) * row_gram];
                    float* m = &moments[size_t(y - y0) * row_moments];
                    accumulate_row(weights.data(), xs.data(), colours.data(), fit.regressors, w,
                                   weighted.data(), g, m);
                }
            }
        }
        std::array<float, gram_terms(kRegressors)> pixel_gram{};
        std::array<float, kRegressors * 3> pixel_moments{};
        for (int y = y0; y < y1; ++y) {
            const float* g_row = &gram[size_t(y - y0) * row_gram];
            const float* m_row = &moments[size_t(y - y0) * row_moments];
            for (int x = 0; x < w; ++x) {
                const size_t p = planes.index(x, y);
                float* rgb = &out[3 * p];
                if (!planes.valid[p]) {
                    std::fill(rgb, rgb + 3, 0.0f);
                    continue;
                }
                for (int t = 0; t < terms; ++t) {
                    pixel_gram[size_t(t)] = g_row[size_t(t) * size_t(w) + size_t(x)];
                }
                for (int k = 0; k < fit.regressors * 3; ++k) {
                    pixel_moments[size_t(k)] = m_row[size_t(k) * size_t(w) + size_t(x)];
                }
                // A fit the features cannot pin down falls back to the weighted mean.
                if (fit.regressors > 1 && solve_fit(pixel_gram.data(), pixel_moments.data(), rgb)) {
                    continue;
                }
                for (size_t c = 0; c < 3; ++c) rgb[c] = pixel_moments[c] / pixel_gram[0];
            }
        }
    };
    const size_t sums_per_row = size_t(terms + 3 * fit.regressors) * size_t(w);
    const size_t rows_at_once = std::max(kLeastRowsAtOnce, kSumsInCache / sums_per_row);
    run_bands(planes, settings.threads, [&](size_t first, size_t last) {
        for (size_t y = first; y < last; y += rows_at_once) {
            filter_rows(y, std::min(y + rows_at_once, last));
        }
    });
    return out;
}

}  // namespace

std::vector<float> denoise(const DenoiseInput& input, const DenoiseSettings& settings) {
    const Planes planes = prepare(input);
    std::vector<float> out = settings.method == DenoiseMethod::Atrous
                                 ? atrous(planes, settings)
                                 : local_regression(planes, settings);
    // Pixels the filter could not trust keep what they had, NaN included.
    for (size_t p = 0; p < planes.valid.size(); ++p) {
        if (planes.valid[p]) continue;
        for (size_t c = 0; c < 3; ++c) out[3 * p + c] = input.colour[3 * p + c];
    }
    return out;
}

const char* denoise_method_name(DenoiseMethod method) {
    switch (method) {
        case DenoiseMethod::Atrous:
            return "a-trous";
        case DenoiseMethod::NlMeans:
            return "nl-means";
        case DenoiseMethod::Regression:
            return "regression";
    }
    return "unknown";
}

}  // namespace fgr
