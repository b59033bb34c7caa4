// SPDX-License-Identifier: Apache-2.0
#pragma once
// Frame-time statistics the viewer prints on exit (`fgr view --stats`).

#include <string>
#include <vector>

namespace fgr::viewer {

struct FrameSummary {
    int count = 0;
    double mean_ms = 0.0;
    double min_ms = 0.0;
    double median_ms = 0.0;
    double p95_ms = 0.0;  // nearest-rank 95th percentile
    double max_ms = 0.0;
};

class FrameStats {
public:
    // Non-finite or negative times are ignored.
    void add(double ms);
    // All zeros when nothing was added.
    FrameSummary summary() const;
    int count() const { return static_cast<int>(times_.size()); }

private:
    std::vector<double> times_;
};

// "NAME count N mean X min X median X p95 X max X" with times in ms to one decimal.
std::string format_summary(const std::string& name, const FrameSummary& summary);

}  // namespace fgr::viewer
