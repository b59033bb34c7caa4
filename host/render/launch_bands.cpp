// SPDX-License-Identifier: Apache-2.0
#include "render/launch_bands.hpp"

#include <algorithm>
#include <cmath>

namespace fgr {

bool bands_follow_work(const BandNeeds& needs) {
    const bool interactive = needs.cancellable && needs.response == CancelResponse::Interactive;
    return !interactive && (needs.progress || needs.cancellable);
}

int launch_bands(double launch_work, const BandNeeds& needs) {
    if (!bands_follow_work(needs)) return needs.cancellable ? kInteractiveBands : 1;
    const double bands = std::ceil(std::max(launch_work, 0.0) / kBandPixelSamples);
    return static_cast<int>(std::clamp(bands, 1.0, double(kInteractiveBands)));
}

int band_tiles(int tiles, int group, int bands) {
    const int groups = (tiles + group - 1) / group;
    return std::max(1, (groups + bands - 1) / bands) * group;
}

}  // namespace fgr
