// SPDX-License-Identifier: Apache-2.0
#pragma once
// Comparing two 8-bit images of the same size, sample by sample.

#include <cstddef>
#include <cstdlib>

#include "image/image_io.hpp"

namespace fgr::test {

// The mean of |a - b| over every sample, in levels.
inline double mean_abs_difference(const Image8& a, const Image8& b) {
    double sum = 0.0;
    for (size_t i = 0; i < a.rgb.size(); ++i) sum += std::abs(int(a.rgb[i]) - int(b.rgb[i]));
    return sum / static_cast<double>(a.rgb.size());
}

// How many pixels have a channel more than one level apart.
inline long pixels_over_one_level(const Image8& a, const Image8& b) {
    long over = 0;
    for (size_t pixel = 0; pixel * 3 < a.rgb.size(); ++pixel) {
        bool differs = false;
        for (size_t c = 0; c < 3; ++c) {
            differs |= std::abs(int(a.rgb[3 * pixel + c]) - int(b.rgb[3 * pixel + c])) > 1;
        }
        over += differs;
    }
    return over;
}

}  // namespace fgr::test
