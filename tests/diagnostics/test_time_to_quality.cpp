// SPDX-License-Identifier: Apache-2.0
// Time to quality's arithmetic (diagnostics/time_to_quality.hpp): the crossing interpolated in
// log-log, the speed-ups and their bounds, the table and the CSV it is read from.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "diagnostics/time_to_quality.hpp"

namespace fgr {
namespace {

// A ladder whose error falls as a power of the time, error = e10 (ms / 10)^-slope, at 10, 20,
// 40, ... ms: a line in log-log, so the interpolated crossing is exact.
std::vector<QualityPoint> power_ladder(const std::string& configuration, double e10, double slope,
                                       int points, const std::string& scene = "room") {
    std::vector<QualityPoint> ladder;
    double ms = 10.0;
    for (int i = 0; i < points; ++i, ms *= 2.0) {
        ladder.push_back(
            {scene, configuration, std::to_string(1 << i), ms, e10 * std::pow(ms / 10.0, -slope)});
    }
    return ladder;
}

TEST(TimeToQuality, CrossingOfAPowerLawIsExact) {
    // 0.1 (t / 10)^-0.5 = 0.005 at t = 10 * 20^2 = 4000 ms, between the ladder's 2560 and 5120.
    const QualityCrossing crossing = crossing_time(power_ladder("path", 0.1, 0.5, 12), 0.005);
    ASSERT_TRUE(crossing.ms.has_value());
    EXPECT_NEAR(*crossing.ms, 4000.0, 1e-6);
    EXPECT_FALSE(crossing.at_first_point);
    EXPECT_DOUBLE_EQ(crossing.longest_ms, 10.0 * 2048.0);
}

TEST(TimeToQuality, InterpolatesBetweenTheTwoPointsAroundTheThreshold) {
    // log-log halfway: errors 0.02 and 0.005 at 100 and 400 ms put 0.01 at 200 ms.
    const std::vector<QualityPoint> ladder = {
        {"s", "c", "1", 50.0, 0.08}, {"s", "c", "2", 100.0, 0.02}, {"s", "c", "4", 400.0, 0.005}};
    EXPECT_NEAR(*crossing_time(ladder, 0.01).ms, 200.0, 1e-9);
    // Exactly at a point's error: that point's time.
    EXPECT_NEAR(*crossing_time(ladder, 0.005).ms, 400.0, 1e-9);
}

TEST(TimeToQuality, TheFirstCrossingCountsWhenNoiseMakesTheErrorRiseAgain) {
    const std::vector<QualityPoint> ladder = {{"s", "c", "1", 100.0, 0.02},
                                              {"s", "c", "2", 200.0, 0.004},
                                              {"s", "c", "4", 400.0, 0.006},
                                              {"s", "c", "8", 800.0, 0.001}};
    const QualityCrossing crossing = crossing_time(ladder, 0.005);
    ASSERT_TRUE(crossing.ms.has_value());
    EXPECT_GT(*crossing.ms, 100.0);
    EXPECT_LT(*crossing.ms, 200.0);
}

TEST(TimeToQuality, AFirstPointAlreadyGoodEnoughIsAnUpperBound) {
    const QualityCrossing crossing = crossing_time({{"s", "c", "1", 30.0, 0.001}}, 0.005);
    ASSERT_TRUE(crossing.ms.has_value());
    EXPECT_DOUBLE_EQ(*crossing.ms, 30.0);
    EXPECT_TRUE(crossing.at_first_point);
}

TEST(TimeToQuality, ALadderThatNeverGetsThereHasNoCrossing) {
    const QualityCrossing crossing = crossing_time(power_ladder("path", 0.1, 0.5, 4), 0.005);
    EXPECT_FALSE(crossing.ms.has_value());
    EXPECT_DOUBLE_EQ(crossing.longest_ms, 80.0);
}

TEST(TimeToQuality, RefusesBadValues) {
    EXPECT_THROW(crossing_time({{"s", "c", "1", 0.0, 0.1}}, 0.005), std::invalid_argument);
    EXPECT_THROW(crossing_time({{"s", "c", "1", 10.0, -0.1}}, 0.005), std::invalid_argument);
    EXPECT_THROW(crossing_time({{"s", "c", "1", 10.0, NAN}}, 0.005), std::invalid_argument);
    EXPECT_THROW(crossing_time({{"s", "c", "1", 10.0, 0.1}}, 0.0), std::invalid_argument);
}

TEST(TimeToQuality, SpeedUpsAreAgainstTheBaselineOfTheSameScene) {
    // "fast" makes the same error in a quarter of the time: its crossing is 1000 ms, 4x sooner.
    std::vector<QualityPoint> points = power_ladder("path", 0.1, 0.5, 12);
    for (QualityPoint point : power_ladder("path", 0.1, 0.5, 12)) {
        point.configuration = "fast";
        point.render_ms /= 4.0;
        points.push_back(point);
    }
    // Another scene where the baseline never gets there: a lower bound.
    for (QualityPoint point : power_ladder("path", 0.1, 0.5, 3, "sky")) points.push_back(point);
    points.push_back({"sky", "fast", "1", 20.0, 0.004});
    const std::vector<QualitySummaryRow> rows = summarise_quality(points, 0.005);
    ASSERT_EQ(rows.size(), 4u);
    EXPECT_EQ(rows[0].configuration, "path");
    EXPECT_NEAR(*rows[0].speedup, 1.0, 1e-9);
    EXPECT_EQ(rows[1].configuration, "fast");
    EXPECT_NEAR(*rows[1].crossing.ms, 1000.0, 1e-6);
    EXPECT_NEAR(*rows[1].speedup, 4.0, 1e-9);
    EXPECT_EQ(rows[1].bound, SpeedupBound::Exact);
    EXPECT_EQ(rows[2].scene, "sky");
    EXPECT_FALSE(rows[2].speedup.has_value());
    EXPECT_NEAR(*rows[3].speedup, 40.0 / 20.0, 1e-9);
    EXPECT_EQ(rows[3].bound, SpeedupBound::AtLeast);

    const std::string table = quality_table_markdown(rows, 0.005);
    EXPECT_NE(table.find("| room | fast | 1000 | 4.00x |"), std::string::npos) << table;
    EXPECT_NE(table.find("| sky | path | > 40 (not reached) | - |"), std::string::npos) << table;
    EXPECT_NE(table.find("| sky | fast | <= 20 | >= 2.00x |"), std::string::npos) << table;

    // A named baseline.
    const std::vector<QualitySummaryRow> against_fast = summarise_quality(points, 0.005, "fast");
    EXPECT_NEAR(*against_fast[0].speedup, 0.25, 1e-9);
}

TEST(TimeToQuality, GnuplotScriptHoldsEveryLadderAndTheThreshold) {
    std::vector<QualityPoint> points = power_ladder("path", 0.1, 0.5, 3);
    points.push_back({"sky", "it's", "1", 20.0, 0.004});
    const std::string script = quality_gnuplot(points, 0.005, "quality.png");
    EXPECT_EQ(script.rfind("# SPDX-License-Identifier: Apache-2.0\n", 0), 0u) << script;
    EXPECT_NE(script.find("set output 'quality.png'"), std::string::npos);
    EXPECT_NE(script.find("set multiplot layout 1,2"), std::string::npos);
    EXPECT_NE(script.find("$ladder1 << EOD\n20,0.004,1\nEOD"), std::string::npos) << script;
    EXPECT_NE(script.find("title 'it''s'"), std::string::npos) << script;
    EXPECT_NE(script.find("plot 0.005 with lines"), std::string::npos) << script;
}

TEST(TimeToQuality, ReadsTheCsvByColumnName) {
    const std::vector<QualityPoint> points = parse_quality_csv(
        "# made by a test\n"
        "configuration,scene,budget,repeat,one_minus_ssim,render_ms\n"
        "path,room,1,3,0.5,12.5\n"
        "\n"
        "path,room,2,3,0.25,25\r\n",
        "m.csv");
    ASSERT_EQ(points.size(), 2u);
    EXPECT_EQ(points[0], (QualityPoint{"room", "path", "1", 12.5, 0.5}));
    EXPECT_EQ(points[1], (QualityPoint{"room", "path", "2", 25.0, 0.25}));
}

TEST(TimeToQuality, RefusesABadCsvInOneLineNamingIt) {
    const auto error_of = [](const std::string& text) {
        try {
            parse_quality_csv(text, "m.csv");
        } catch (const std::runtime_error& error) {
            return std::string(error.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(error_of("scene,configuration,budget,render_ms\n"),
              "m.csv line 1: the header has no column 'one_minus_ssim'");
    EXPECT_EQ(error_of("scene,configuration,budget,render_ms,one_minus_ssim\nr,c,1,fast,0.1\n"),
              "m.csv line 2: 'fast' is not a number");
    EXPECT_EQ(error_of("scene,configuration,budget,render_ms,one_minus_ssim\nr,c,1,10\n"),
              "m.csv line 2: no 'one_minus_ssim' value");
    EXPECT_EQ(error_of("scene,configuration,budget,render_ms,one_minus_ssim\nr,c,1,-1,0.1\n"),
              "m.csv line 2: render_ms -1 of r / c / 1 is not positive");
    EXPECT_EQ(error_of(""), "m.csv: no header line");
}

}  // namespace
}  // namespace fgr
