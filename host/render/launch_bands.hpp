// SPDX-License-Identifier: Apache-2.0
#pragma once

// How many launches ("bands" of tiles) one launch of samples is split into. A band is what a
// frame reports its progress by and what a cancel waits for, but bands cost time: the device
// waits for a band's slowest tile before the next band starts, so a launch of few tiles in many
// bands leaves cores idle (the path tracer's regrouped tiles differ most in cost), and PoCL
// compiles the kernel once more for launches at an offset. Work is counted in plain pixel
// samples (a shaded sample's camera and shadow ray at the defaults; render/render_cost.hpp weighs
// a frame's samples against it).

namespace fgr {

// How soon a frame's cancel hook must be obeyed.
enum class CancelResponse {
    // At once (the viewer, which abandons a frame when the view moves): every launch in
    // kInteractiveBands bands.
    Interactive,
    // Within a fraction of a second (a render a signal stops): between launches, and within a
    // launch between bands of about kBandPixelSamples.
    Batch,
};

// Bands each launch of an interactively cancellable frame is split into.
inline constexpr int kInteractiveBands = 32;
// The work of a band where the split is by work (progress reports, batch cancels): about a
// quarter of a second on a 2-core laptop CPU, far less on a GPU. A shorter launch stays whole.
inline constexpr double kBandPixelSamples = 4.0 * (1 << 20);

// What a frame's bands are for.
struct BandNeeds {
    bool progress = false;     // it reports its progress as it renders
    bool cancellable = false;  // it may be cancelled, as `response` says
    CancelResponse response = CancelResponse::Interactive;
};

// Whether launch_bands depends on the launch's work: for progress reports and batch cancels,
// not for an interactive cancel (always kInteractiveBands) or a frame that needs no bands (1), so
// that those need no cost estimate.
bool bands_follow_work(const BandNeeds& needs);

// Bands a launch of `launch_work` plain pixel samples is split into: kInteractiveBands for an
// interactively cancellable frame; for progress reports or a batch cancel, bands of about
// kBandPixelSamples each (1 for a launch of less), at most kInteractiveBands; otherwise 1.
int launch_bands(double launch_work, const BandNeeds& needs);

// Tiles in a band when `tiles` are split into about `bands` bands of whole work-groups of
// `group` tiles.
int band_tiles(int tiles, int group, int bands);

}  // namespace fgr
