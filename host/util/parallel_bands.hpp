// SPDX-License-Identifier: Apache-2.0
#pragma once
// Host loops over a frame's values spread over the CPU's threads.

#include <cstddef>
#include <functional>

namespace fgr {

// Runs work(first, last) over [0, count) cut into consecutive bands, one a hardware thread (at
// most kMaxBands), each at least min_band long; the last band runs on the calling thread, the
// others on threads of their own, and all have ended when it returns. With one band (a small
// count, or one hardware thread) it is work(0, count) on the calling thread. `work` must not
// throw.
void in_parallel_bands(std::size_t count, std::size_t min_band,
                       const std::function<void(std::size_t, std::size_t)>& work);

// Values a band of a frame's host loops holds at least: under it a thread costs more than it saves.
constexpr std::size_t kMinHostBand = std::size_t{1} << 16;

// in_parallel_bands over the rows of an image `width` values wide, each band kMinHostBand values
// at least.
inline void in_parallel_rows(std::size_t rows, std::size_t width,
                             const std::function<void(std::size_t, std::size_t)>& work) {
    in_parallel_bands(rows, kMinHostBand / (width > 0 ? width : 1), work);
}

}  // namespace fgr
