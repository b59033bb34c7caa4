// SPDX-License-Identifier: Apache-2.0
#include "viewer/frame_stats.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>

namespace fgr::viewer {
namespace {

// Nearest-rank percentile of sorted, non-empty data: the value at rank ceil(percent / 100 * n),
// computed in integers so that e.g. 95% of 20 is rank 19 and not 20 through rounding.
double nearest_rank(const std::vector<double>& sorted, std::size_t percent) {
    const std::size_t rank = (percent * sorted.size() + 99) / 100;
    return sorted[std::max<std::size_t>(rank, 1) - 1];
}

// The middle value, or the mean of the two middle values for an even count.
double median(const std::vector<double>& sorted) {
    const std::size_t half = sorted.size() / 2;
    if (sorted.size() % 2 == 1) {
        return sorted[half];
    }
    return 0.5 * (sorted[half - 1] + sorted[half]);
}

}  // namespace

void FrameStats::add(double ms) {
    if (std::isfinite(ms) && ms >= 0.0) {
        times_.push_back(ms);
    }
}

FrameSummary FrameStats::summary() const {
    FrameSummary summary;
    if (times_.empty()) {
        return summary;
    }
    std::vector<double> sorted = times_;
    std::sort(sorted.begin(), sorted.end());
    summary.count = count();
    summary.mean_ms =
        std::accumulate(sorted.begin(), sorted.end(), 0.0) / static_cast<double>(sorted.size());
    summary.min_ms = sorted.front();
    summary.median_ms = median(sorted);
    summary.p95_ms = nearest_rank(sorted, 95);
    summary.max_ms = sorted.back();
    return summary;
}

std::string format_summary(const std::string& name, const FrameSummary& summary) {
    return fmt::format("{} count {} mean {:.1f} min {:.1f} median {:.1f} p95 {:.1f} max {:.1f}",
                       name, summary.count, summary.mean_ms, summary.min_ms, summary.median_ms,
                       summary.p95_ms, summary.max_ms);
}

}  // namespace fgr::viewer
