// SPDX-License-Identifier: Apache-2.0
// The display image's bytes: fill_display_image encodes several values at a time, in bands over
// threads; each byte must be the one the scalar curve gives that value.

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <vector>

#include "image/display.hpp"

namespace fgr {
namespace {

// Values where a lane could go wrong: NaN, infinities, signed zeros, denormals, negatives, the ends
// of [0, 1], the table's steps and half-steps, then random values over the curves' range.
std::vector<float> awkward_values(size_t count) {
    std::vector<float> values = {std::numeric_limits<float>::quiet_NaN(),
                                 std::numeric_limits<float>::infinity(),
                                 -std::numeric_limits<float>::infinity(),
                                 0.0f,
                                 -0.0f,
                                 std::numeric_limits<float>::denorm_min(),
                                 -std::numeric_limits<float>::denorm_min(),
                                 std::numeric_limits<float>::min(),
                                 -1.0f,
                                 1.0f,
                                 std::nextafter(1.0f, 0.0f),
                                 std::nextafter(1.0f, 2.0f),
                                 std::numeric_limits<float>::max(),
                                 0.5f / 4096.0f,
                                 4095.5f / 4096.0f};
    for (int step = 0; step <= 4096; step += 7) values.push_back(float(step) / 4096.0f);
    std::mt19937 random(7);
    std::uniform_real_distribution<float> spread(-0.5f, 8.0f);
    while (values.size() < count) values.push_back(spread(random));
    values.resize(count);
    return values;
}

TEST(DisplayImage, EveryValueEncodesAsTheScalarCurveGivesIt) {
    // 3 x 45,001 values: two bands of 2^16 or more on two threads, neither a multiple of the
    // lanes, so each band ends in the scalar tail.
    const int width = 45001, height = 1;
    const std::vector<float> linear = awkward_values(size_t(width) * height * 3);
    for (const ToneMap curve : {ToneMap::Clamp, ToneMap::Reinhard, ToneMap::Aces}) {
        for (const float exposure : {1.0f, 2.5f}) {
            const DisplayTransform display{exposure, curve};
            const Image8 image = display_image(linear, display, width, height);
            ASSERT_EQ(image.rgb.size(), linear.size());
            size_t differing = 0, first = 0;
            for (size_t i = 0; i < linear.size(); ++i) {
                if (image.rgb[i] != encode_srgb(tone_map(linear[i] * exposure, curve))) {
                    if (differing++ == 0) first = i;
                }
            }
            EXPECT_EQ(differing, 0u)
                << "curve " << int(curve) << ", exposure " << exposure << ": first at value "
                << first << " (" << linear[first] << ")";
        }
    }
}

}  // namespace
}  // namespace fgr
