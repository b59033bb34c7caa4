// SPDX-License-Identifier: Apache-2.0
// Frame-time statistics: the summary of known data (nearest-rank p95), rejected samples, and the
// exact text of the summary line.

#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "viewer/frame_stats.hpp"

namespace fgr::viewer {
namespace {

TEST(FrameStats, EmptySummaryIsAllZeros) {
    const FrameStats stats;
    const FrameSummary summary = stats.summary();
    EXPECT_EQ(summary.count, 0);
    EXPECT_EQ(summary.mean_ms, 0.0);
    EXPECT_EQ(summary.min_ms, 0.0);
    EXPECT_EQ(summary.median_ms, 0.0);
    EXPECT_EQ(summary.p95_ms, 0.0);
    EXPECT_EQ(summary.max_ms, 0.0);
}

TEST(FrameStats, SummaryOfOneToTwenty) {
    FrameStats stats;
    // Added out of order: the summary must not depend on insertion order.
    for (int i = 20; i >= 1; i -= 2) {
        stats.add(i);
    }
    for (int i = 1; i <= 19; i += 2) {
        stats.add(i);
    }
    const FrameSummary summary = stats.summary();
    EXPECT_EQ(summary.count, 20);
    EXPECT_DOUBLE_EQ(summary.mean_ms, 10.5);
    EXPECT_DOUBLE_EQ(summary.min_ms, 1.0);
    EXPECT_DOUBLE_EQ(summary.median_ms, 10.5);  // mean of the two middle values
    EXPECT_DOUBLE_EQ(summary.p95_ms, 19.0);     // rank ceil(0.95 * 20) = 19
    EXPECT_DOUBLE_EQ(summary.max_ms, 20.0);
}

TEST(FrameStats, NearestRankPercentileAndOddMedian) {
    FrameStats stats;
    for (int i = 1; i <= 101; ++i) {
        stats.add(i * 0.5);  // 0.5 .. 50.5
    }
    const FrameSummary summary = stats.summary();
    EXPECT_EQ(summary.count, 101);
    EXPECT_DOUBLE_EQ(summary.mean_ms, 25.5);
    EXPECT_DOUBLE_EQ(summary.median_ms, 25.5);  // the 51st value
    EXPECT_DOUBLE_EQ(summary.p95_ms, 48.0);     // rank ceil(95.95) = 96
    EXPECT_DOUBLE_EQ(summary.max_ms, 50.5);
}

TEST(FrameStats, SmallSamples) {
    FrameStats one;
    one.add(7.0);
    const FrameSummary single = one.summary();
    EXPECT_EQ(single.count, 1);
    EXPECT_DOUBLE_EQ(single.mean_ms, 7.0);
    EXPECT_DOUBLE_EQ(single.min_ms, 7.0);
    EXPECT_DOUBLE_EQ(single.median_ms, 7.0);
    EXPECT_DOUBLE_EQ(single.p95_ms, 7.0);
    EXPECT_DOUBLE_EQ(single.max_ms, 7.0);

    FrameStats three;
    for (const double ms : {30.0, 10.0, 20.0}) {
        three.add(ms);
    }
    const FrameSummary summary = three.summary();
    EXPECT_DOUBLE_EQ(summary.mean_ms, 20.0);
    EXPECT_DOUBLE_EQ(summary.median_ms, 20.0);
    EXPECT_DOUBLE_EQ(summary.p95_ms, 30.0);  // rank ceil(2.85) = 3
}

TEST(FrameStats, OneSlowFrameShowsInMaxButNotP95) {
    FrameStats stats;
    for (int i = 0; i < 99; ++i) {
        stats.add(16.0);
    }
    stats.add(500.0);
    const FrameSummary summary = stats.summary();
    EXPECT_DOUBLE_EQ(summary.p95_ms, 16.0);
    EXPECT_DOUBLE_EQ(summary.max_ms, 500.0);
    EXPECT_DOUBLE_EQ(summary.mean_ms, (99 * 16.0 + 500.0) / 100.0);
}

TEST(FrameStats, IgnoresNonFiniteAndNegativeTimes) {
    FrameStats stats;
    stats.add(std::numeric_limits<double>::quiet_NaN());
    stats.add(std::numeric_limits<double>::infinity());
    stats.add(-std::numeric_limits<double>::infinity());
    stats.add(-1.0);
    EXPECT_EQ(stats.count(), 0);

    stats.add(0.0);  // a zero time is a real (if suspicious) measurement
    stats.add(4.0);
    stats.add(-3.0);
    EXPECT_EQ(stats.count(), 2);
    const FrameSummary summary = stats.summary();
    EXPECT_DOUBLE_EQ(summary.min_ms, 0.0);
    EXPECT_DOUBLE_EQ(summary.mean_ms, 2.0);
    EXPECT_DOUBLE_EQ(summary.max_ms, 4.0);
}

TEST(FrameStats, FormatSummaryText) {
    FrameSummary summary;
    summary.count = 120;
    summary.mean_ms = 16.6666;
    summary.min_ms = 12.04;
    summary.median_ms = 16.24;
    summary.p95_ms = 21.96;
    summary.max_ms = 250.0;
    EXPECT_EQ(format_summary("frame", summary),
              "frame count 120 mean 16.7 min 12.0 median 16.2 p95 22.0 max 250.0");
}

TEST(FrameStats, FormatEmptySummary) {
    EXPECT_EQ(format_summary("preview", FrameStats().summary()),
              "preview count 0 mean 0.0 min 0.0 median 0.0 p95 0.0 max 0.0");
}

}  // namespace
}  // namespace fgr::viewer
