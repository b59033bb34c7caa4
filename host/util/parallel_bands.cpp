// SPDX-License-Identifier: Apache-2.0
#include "util/parallel_bands.hpp"

#include <algorithm>
#include <system_error>
#include <thread>
#include <vector>

namespace fgr {

namespace {
constexpr std::size_t kMaxBands = 8;
}

void in_parallel_bands(std::size_t count, std::size_t min_band,
                       const std::function<void(std::size_t, std::size_t)>& work) {
    const std::size_t threads = std::max<std::size_t>(1, std::thread::hardware_concurrency());
    const std::size_t bands = std::clamp<std::size_t>(count / std::max<std::size_t>(min_band, 1), 1,
                                                      std::min(threads, kMaxBands));
    std::vector<std::jthread> helpers;
    helpers.reserve(bands - 1);
    for (std::size_t band = 0; band + 1 < bands; ++band) {
        const std::size_t first = count * band / bands, last = count * (band + 1) / bands;
        try {
            helpers.emplace_back(work, first, last);
        } catch (const std::system_error&) {
            work(first, last);  // no thread to be had: the band is done here instead
        }
    }
    work(count * (bands - 1) / bands, count);
}  // the jthreads join here

}  // namespace fgr
