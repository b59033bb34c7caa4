// SPDX-License-Identifier: Apache-2.0
#pragma once
// Time to quality: how long each configuration of the path tracer takes to make an image whose
// error against a long reference render falls to a threshold (1 - SSIM <= 0.005 by default).
// bench/time_to_quality.sh renders each configuration along a ladder of budgets (samples per
// pixel, or noise thresholds), records each render's time and error as one row of a CSV, and
// `fgr bench quality CSV` turns the rows into the crossing times, the speed-ups over a baseline
// configuration, a markdown table and a gnuplot script (error against time, log-log).

#include <optional>
#include <string>
#include <vector>

namespace fgr {

// One render of the ladder: a scene, a configuration, the budget it was given (as written: "16",
// "0.02"), its render time and its error (1 - SSIM against the scene's reference).
struct QualityPoint {
    std::string scene;
    std::string configuration;
    std::string budget;
    double render_ms = 0.0;
    double error = 0.0;

    bool operator==(const QualityPoint&) const = default;
};

// When one configuration's ladder reaches the threshold.
struct QualityCrossing {
    // Milliseconds at which the error reaches the threshold; none when no point of the ladder does.
    std::optional<double> ms;
    // The ladder's first point is already at or below the threshold: ms is that point's time, an
    // upper bound on the true crossing.
    bool at_first_point = false;
    // The longest render of the ladder: a lower bound on the crossing when ms is empty.
    double longest_ms = 0.0;
};

// The crossing of one configuration's ladder, its points in ladder order (growing budgets): the
// first point whose error is at most `threshold`, interpolated in log-log between it and the point
// before it (the error of a Monte Carlo estimate falls as a power of the time spent, a line in
// log-log). An error of 0 counts as 1e-12 in the logarithms. Throws std::invalid_argument for a
// threshold that is not positive or a point whose time is not positive or error is negative or
// not finite.
QualityCrossing crossing_time(const std::vector<QualityPoint>& ladder, double threshold);

// How a speed-up relates to the true one: where a ladder reached the threshold at its first
// point, that time is an upper bound on its crossing; where the baseline never reached it, its
// longest render is a lower bound.
enum class SpeedupBound {
    Exact,    // both crossings interpolated
    AtLeast,  // this one crossed at its first point, or the baseline never crossed
    AtMost,   // the baseline crossed at its first point
    Unknown,  // both crossed at their first points: no bound either way
};

// One row of the summary: a scene and a configuration, its crossing, and the speed-up over the
// baseline configuration of the same scene (the baseline's crossing time over this one's).
struct QualitySummaryRow {
    std::string scene;
    std::string configuration;
    QualityCrossing crossing;
    std::optional<double> speedup;  // none when this configuration never crossed
    SpeedupBound bound = SpeedupBound::Exact;
};

// The summary of every (scene, configuration) pair in order of first appearance in `points`
// (each pair's points in their order there). `baseline` names the configuration the speed-ups are
// measured against; empty: the first configuration that appears.
std::vector<QualitySummaryRow> summarise_quality(const std::vector<QualityPoint>& points,
                                                 double threshold, std::string baseline = {});

// The summary as a markdown table: scene, configuration, time to the threshold, speed-up.
std::string quality_table_markdown(const std::vector<QualitySummaryRow>& rows, double threshold);

// A gnuplot script that draws `png`: one panel per scene, error against render time on log-log
// axes, one line per configuration with its budgets as labels, and the threshold as a horizontal
// line. The points are written into the script, so it stands alone.
std::string quality_gnuplot(const std::vector<QualityPoint>& points, double threshold,
                            const std::string& png);

// The CSV that bench/time_to_quality.sh writes: a header line naming at least the columns scene,
// configuration, budget, render_ms and one_minus_ssim (in any order, others ignored), then one
// point a line. Blank lines and lines starting with '#' are skipped. `source` names the file in
// errors. Throws std::runtime_error with one line naming the source and line for a missing column,
// a short row, a number that does not parse or a value crossing_time refuses, and for a text over
// 16 MiB or over 100000 rows.
std::vector<QualityPoint> parse_quality_csv(const std::string& text, const std::string& source);

}  // namespace fgr
