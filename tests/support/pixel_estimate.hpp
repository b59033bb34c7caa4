// SPDX-License-Identifier: Apache-2.0
#pragma once
// The mean of a frame's pixels with its standard error, for z-tests of Monte Carlo renders: each
// selected pixel's estimate counts as one independent draw.

#include <cmath>
#include <cstddef>
#include <vector>

#include "render/renderer.hpp"

namespace fgr::test {

struct PixelEstimate {
    double mean = 0.0;
    double standard_error = 0.0;  // of the mean, from the spread of the pixels' estimates
    double variance = 0.0;        // of one pixel's estimate
    long pixels = 0;
};

// The mean of per-pixel values, each one independent draw, with its standard error.
inline PixelEstimate estimate_of(const std::vector<double>& values) {
    PixelEstimate result;
    result.pixels = static_cast<long>(values.size());
    if (values.size() < 2) return result;
    for (double v : values) result.mean += v;
    result.mean /= double(values.size());
    double squares = 0.0;
    for (double v : values) squares += (v - result.mean) * (v - result.mean);
    result.variance = squares / double(values.size() - 1);
    result.standard_error = std::sqrt(result.variance / double(values.size()));
    return result;
}

// The red channel's mean over the pixels `keep(i)` selects (i: the pixel's row-major index).
template <typename Keep>
PixelEstimate red_channel_estimate(const Frame& frame, Keep keep) {
    std::vector<double> values;
    for (size_t i = 0; i < frame.alpha.size(); ++i) {
        if (keep(i)) values.push_back(frame.linear[i * 3]);
    }
    return estimate_of(values);
}

}  // namespace fgr::test
