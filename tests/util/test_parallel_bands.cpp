// SPDX-License-Identifier: Apache-2.0
// in_parallel_bands (util/parallel_bands.hpp): every index of the range done exactly once.

#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>
#include <vector>

#include "util/parallel_bands.hpp"

namespace fgr {
namespace {

TEST(ParallelBands, EveryIndexIsDoneOnceInBandsOfAtLeastTheMinimum) {
    for (const std::size_t count : {std::size_t{0}, std::size_t{1}, std::size_t{7},
                                    std::size_t{65536}, std::size_t{3 * 65536 + 5}}) {
        for (const std::size_t min_band : {std::size_t{1}, std::size_t{1000}, std::size_t{65536}}) {
            std::vector<std::atomic<int>> done(count);
            std::atomic<int> bands = 0;
            std::atomic<bool> short_band = false;
            in_parallel_bands(count, min_band, [&](std::size_t first, std::size_t last) {
                ++bands;
                if (count >= min_band && last - first < min_band) short_band = true;
                for (std::size_t i = first; i < last; ++i) ++done[i];
            });
            int wrong = 0;
            for (const std::atomic<int>& times : done) wrong += times != 1;
            EXPECT_EQ(wrong, 0) << count << " values, bands of at least " << min_band;
            EXPECT_GE(bands, 1);
            EXPECT_FALSE(short_band) << count << " values, bands of at least " << min_band;
        }
    }
}

}  // namespace
}  // namespace fgr
