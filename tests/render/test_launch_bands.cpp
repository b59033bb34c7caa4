// SPDX-License-Identifier: Apache-2.0
// How launches are split into bands of tiles (render/launch_bands.hpp): an interactive frame's
// cancel is obeyed within a thirty-second of a launch; progress reports and batch cancels split a
// launch into bands of about kBandPixelSamples, so that a short launch stays whole and keeps
// every core busy to its end; and bands are whole work-groups that cover every tile.

#include <gtest/gtest.h>

#include "render/launch_bands.hpp"

namespace fgr {
namespace {

constexpr BandNeeds kProgress{true, false};
constexpr BandNeeds kBatchCancel{false, true, CancelResponse::Batch};
constexpr BandNeeds kInteractiveCancel{false, true, CancelResponse::Interactive};

TEST(LaunchBands, AnInteractiveCancelSplitsEveryLaunchWhateverItsSize) {
    EXPECT_EQ(launch_bands(1.0, kInteractiveCancel), kInteractiveBands);
    EXPECT_EQ(launch_bands(1e12, kInteractiveCancel), kInteractiveBands);
    EXPECT_EQ(launch_bands(1.0, {true, true, CancelResponse::Interactive}), kInteractiveBands);
    // So the viewer's frames need no cost estimate.
    EXPECT_FALSE(bands_follow_work(kInteractiveCancel));
}

TEST(LaunchBands, ProgressAndBatchCancelsSplitALaunchOnlyAsFarAsItsWorkNeeds) {
    for (const BandNeeds& needs :
         {kProgress, kBatchCancel, BandNeeds{true, true, CancelResponse::Batch}}) {
        EXPECT_TRUE(bands_follow_work(needs));
        // A path-traced part of 160x120 pixels, 16 samples a launch, about 7 plain samples
        // each: 2.2 M plain pixel samples, under a band's worth, so the launch stays whole.
        EXPECT_EQ(launch_bands(160.0 * 120 * 16 * 7, needs), 1);
        EXPECT_EQ(launch_bands(0.0, needs), 1);
        EXPECT_EQ(launch_bands(kBandPixelSamples, needs), 1);
        EXPECT_EQ(launch_bands(kBandPixelSamples * 1.01, needs), 2);
        EXPECT_EQ(launch_bands(kBandPixelSamples * 9.5, needs), 10);
        // A 512x512 tile of 16 path samples a launch: 29.4 M, exactly 7 bands' worth.
        EXPECT_EQ(launch_bands(512.0 * 512 * 16 * 7, needs), 7);
        // However long, never more bands than an interactive frame's.
        EXPECT_EQ(launch_bands(1e12, needs), kInteractiveBands);
    }
}

TEST(LaunchBands, AFrameNobodyWatchesOrCancelsIsNeverSplit) {
    EXPECT_EQ(launch_bands(1e12, BandNeeds{}), 1);
    EXPECT_FALSE(bands_follow_work(BandNeeds{}));
}

TEST(LaunchBands, BandsAreWholeWorkGroupsThatCoverEveryTile) {
    for (int tiles : {1, 7, 8, 9, 150 * 8, 1201}) {
        for (int bands : {1, 2, 5, 32}) {
            const int band = band_tiles(tiles, 8, bands);
            EXPECT_EQ(band % 8, 0) << tiles << " tiles, " << bands << " bands";
            const int launches = (tiles + band - 1) / band;
            EXPECT_LE(launches, bands) << tiles << " tiles, " << bands << " bands";
            EXPECT_GE(launches * band, tiles);
        }
    }
    EXPECT_EQ(band_tiles(1200, 8, 1), 1200);
    EXPECT_EQ(band_tiles(1200, 8, 32), 40);  // 150 groups: 5 a band
}

}  // namespace
}  // namespace fgr
