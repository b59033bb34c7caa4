// SPDX-License-Identifier: Apache-2.0
#include "diagnostics/time_to_quality.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace fgr {
namespace {

constexpr double kSmallestError = 1e-12;  // an exact image's error, in the logarithms
constexpr std::size_t kMaxCsvBytes = std::size_t{16} << 20;
constexpr std::size_t kMaxCsvRows = 100000;

void check_point(const QualityPoint& point) {
    if (!(point.render_ms > 0.0) || !std::isfinite(point.render_ms)) {
        throw std::invalid_argument(fmt::format("render_ms {} of {} / {} / {} is not positive",
                                                point.render_ms, point.scene, point.configuration,
                                                point.budget));
    }
    if (!(point.error >= 0.0) || !std::isfinite(point.error)) {
        throw std::invalid_argument(
            fmt::format("error {} of {} / {} / {} is not a finite value >= 0", point.error,
                        point.scene, point.configuration, point.budget));
    }
}

// (scene, configuration) pairs in order of first appearance, each with its points in order.
std::vector<std::pair<std::pair<std::string, std::string>, std::vector<QualityPoint>>> ladders_of(
    const std::vector<QualityPoint>& points) {
    std::vector<std::pair<std::pair<std::string, std::string>, std::vector<QualityPoint>>> ladders;
    for (const QualityPoint& point : points) {
        const std::pair<std::string, std::string> key{point.scene, point.configuration};
        auto found = std::find_if(ladders.begin(), ladders.end(),
                                  [&](const auto& ladder) { return ladder.first == key; });
        if (found == ladders.end()) {
            ladders.push_back({key, {}});
            found = std::prev(ladders.end());
        }
        found->second.push_back(point);
    }
    return ladders;
}

std::string format_ms(double ms) {
    return ms >= 100.0 ? fmt::format("{:.0f}", ms) : fmt::format("{:.3g}", ms);
}

// gnuplot's single-quoted strings: a quote is doubled.
std::string quoted(const std::string& text) {
    std::string out = "'";
    for (char c : text) {
        if (c == '\'') out += '\'';
        out += c;
    }
    return out + "'";
}

std::vector<std::string> split_csv_line(const std::string& line) {
    std::vector<std::string> fields;
    std::string field;
    std::istringstream in(line);
    while (std::getline(in, field, ',')) fields.push_back(field);
    if (!line.empty() && line.back() == ',') fields.emplace_back();
    return fields;
}

double parse_number(const std::string& text, const std::string& where) {
    double value = 0.0;
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, value);
    if (error != std::errc() || stop != end || text.empty()) {
        throw std::runtime_error(fmt::format("{}: '{}' is not a number", where, text));
    }
    return value;
}

}  // namespace

QualityCrossing crossing_time(const std::vector<QualityPoint>& ladder, double threshold) {
    if (!(threshold > 0.0) || !std::isfinite(threshold)) {
        throw std::invalid_argument(fmt::format("threshold {} is not positive", threshold));
    }
    QualityCrossing crossing;
    for (const QualityPoint& point : ladder) {
        check_point(point);
        crossing.longest_ms = std::max(crossing.longest_ms, point.render_ms);
    }
    for (std::size_t i = 0; i < ladder.size(); ++i) {
        if (ladder[i].error > threshold) continue;
        if (i == 0) {
            crossing.ms = ladder[0].render_ms;
            crossing.at_first_point = true;
            return crossing;
        }
        const double t0 = std::log(ladder[i - 1].render_ms), t1 = std::log(ladder[i].render_ms);
        const double e0 = std::log(std::max(ladder[i - 1].error, kSmallestError));
        const double e1 = std::log(std::max(ladder[i].error, kSmallestError));
        // e0 > log(threshold) >= e1, so e0 > e1 and the fraction lies in (0, 1].
        const double fraction = (e0 - std::log(threshold)) / (e0 - e1);
        crossing.ms = std::exp(t0 + fraction * (t1 - t0));
        return crossing;
    }
    return crossing;
}

std::vector<QualitySummaryRow> summarise_quality(const std::vector<QualityPoint>& points,
                                                 double threshold, std::string baseline) {
    const auto ladders = ladders_of(points);
    if (baseline.empty() && !ladders.empty()) baseline = ladders.front().first.second;
    std::vector<QualitySummaryRow> rows;
    std::map<std::string, QualityCrossing> baselines;  // by scene
    for (const auto& [key, ladder] : ladders) {
        QualitySummaryRow row{key.first, key.second, crossing_time(ladder, threshold), std::nullopt,
                              SpeedupBound::Exact};
        if (key.second == baseline) baselines[key.first] = row.crossing;
        rows.push_back(std::move(row));
    }
    for (QualitySummaryRow& row : rows) {
        const auto found = baselines.find(row.scene);
        if (found == baselines.end() || !row.crossing.ms) continue;
        const QualityCrossing& base = found->second;
        row.speedup = (base.ms ? *base.ms : base.longest_ms) / *row.crossing.ms;
        const bool base_upper = base.ms && base.at_first_point;
        if (!base.ms || (row.crossing.at_first_point && !base_upper)) {
            row.bound = SpeedupBound::AtLeast;
        } else if (base_upper) {
            row.bound = row.crossing.at_first_point ? SpeedupBound::Unknown : SpeedupBound::AtMost;
        }
    }
    return rows;
}

std::string quality_table_markdown(const std::vector<QualitySummaryRow>& rows, double threshold) {
    std::string table = fmt::format(
        "| scene | configuration | time to 1 - SSIM <= {:g} (ms) | speed-up |\n"
        "| --- | --- | --- | --- |\n",
        threshold);
    for (const QualitySummaryRow& row : rows) {
        std::string time;
        if (!row.crossing.ms) {
            time = "> " + format_ms(row.crossing.longest_ms) + " (not reached)";
        } else {
            time = (row.crossing.at_first_point ? "<= " : "") + format_ms(*row.crossing.ms);
        }
        std::string speedup = "-";
        if (row.speedup) {
            const char* prefix = row.bound == SpeedupBound::AtLeast   ? ">= "
                                 : row.bound == SpeedupBound::AtMost  ? "<= "
                                 : row.bound == SpeedupBound::Unknown ? "~"
                                                                      : "";
            speedup = fmt::format("{}{:.2f}x", prefix, *row.speedup);
        }
        table +=
            fmt::format("| {} | {} | {} | {} |\n", row.scene, row.configuration, time, speedup);
    }
    return table;
}

std::string quality_gnuplot(const std::vector<QualityPoint>& points, double threshold,
                            const std::string& png) {
    const auto ladders = ladders_of(points);
    std::vector<std::string> scenes;
    for (const auto& [key, ladder] : ladders) {
        if (std::find(scenes.begin(), scenes.end(), key.first) == scenes.end()) {
            scenes.push_back(key.first);
        }
    }
    std::string script = fmt::format(
        "# SPDX-License-Identifier: Apache-2.0\n"
        "# Time to quality: 1 - SSIM against a long reference render over render time, one line\n"
        "# per configuration (written by fgr bench quality).\n"
        "set terminal pngcairo size {},520 font 'sans,10'\n"
        "set output {}\n"
        "set datafile separator ','\n",
        std::max<std::size_t>(1, scenes.size()) * 560, quoted(png));
    for (std::size_t i = 0; i < ladders.size(); ++i) {
        script += fmt::format("$ladder{} << EOD\n", i);
        for (const QualityPoint& point : ladders[i].second) {
            script += fmt::format("{:.6g},{:.6g},{}\n", point.render_ms, point.error, point.budget);
        }
        script += "EOD\n";
    }
    script += fmt::format(
        "set multiplot layout 1,{}\n"
        "set logscale xy\n"
        "set grid\n"
        "set key top right font 'sans,9'\n"
        "set xlabel 'render time (ms)'\n"
        "set ylabel '1 - SSIM against the reference'\n",
        std::max<std::size_t>(1, scenes.size()));
    for (const std::string& scene : scenes) {
        script += fmt::format("set title {} noenhanced\n", quoted(scene));
        script +=
            fmt::format("plot {:g} with lines lw 2 dt 2 lc rgb '#666666' title '1 - SSIM = {:g}'",
                        threshold, threshold);
        int style = 1;
        for (std::size_t i = 0; i < ladders.size(); ++i) {
            if (ladders[i].first.first != scene) continue;
            script += fmt::format(
                ", \\\n     $ladder{0} using 1:2 with linespoints lw 2 pt {1} lc {1} title {2} "
                "noenhanced, \\\n     $ladder{0} using 1:2:3 with labels offset 0.6,0.6 font "
                "'sans,7' tc lt {1} notitle",
                i, style, quoted(ladders[i].first.second));
            ++style;
        }
        script += "\n";
    }
    return script + "unset multiplot\n";
}

std::vector<QualityPoint> parse_quality_csv(const std::string& text, const std::string& source) {
    if (text.size() > kMaxCsvBytes) {
        throw std::runtime_error(fmt::format("{}: over {} MiB: not a time-to-quality table", source,
                                             kMaxCsvBytes >> 20));
    }
    std::istringstream in(text);
    std::string line;
    std::map<std::string, std::size_t> column;
    std::vector<QualityPoint> points;
    const std::vector<std::string> needed = {"scene", "configuration", "budget", "render_ms",
                                             "one_minus_ssim"};
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty() || line[0] == '#') continue;
        const std::vector<std::string> fields = split_csv_line(line);
        const std::string where = fmt::format("{} line {}", source, number);
        if (column.empty()) {
            for (std::size_t i = 0; i < fields.size(); ++i) column.emplace(fields[i], i);
            for (const std::string& name : needed) {
                if (!column.contains(name)) {
                    throw std::runtime_error(
                        fmt::format("{}: the header has no column '{}'", where, name));
                }
            }
            continue;
        }
        if (points.size() >= kMaxCsvRows) {
            throw std::runtime_error(fmt::format("{}: over {} rows", source, kMaxCsvRows));
        }
        const auto field = [&](const std::string& name) -> const std::string& {
            const std::size_t index = column.at(name);
            if (index >= fields.size()) {
                throw std::runtime_error(fmt::format("{}: no '{}' value", where, name));
            }
            return fields[index];
        };
        QualityPoint point{field("scene"), field("configuration"), field("budget"),
                           parse_number(field("render_ms"), where),
                           parse_number(field("one_minus_ssim"), where)};
        if (point.scene.empty() || point.configuration.empty()) {
            throw std::runtime_error(fmt::format("{}: empty scene or configuration", where));
        }
        try {
            check_point(point);
        } catch (const std::invalid_argument& error) {
            throw std::runtime_error(fmt::format("{}: {}", where, error.what()));
        }
        points.push_back(std::move(point));
    }
    if (column.empty()) throw std::runtime_error(fmt::format("{}: no header line", source));
    return points;
}

}  // namespace fgr
