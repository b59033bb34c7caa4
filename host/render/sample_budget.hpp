// SPDX-License-Identifier: Apache-2.0
#pragma once
// How many samples a render takes in each render mode, what one sample is there, and how many fgr
// accepts: asked here by the command line, the viewer, tiled stills, parts, video frames and the
// MPI ranks, so that none of them keeps a count of its own.
//
// A sample is one launch of the mode's kernel over the image (FrameRequest::samples). In the
// shaded and path modes it is one jittered camera ray a pixel, and the frame averages them; in the
// brute mode it is one pass of stratified inside tests along each pixel's ray, refining the depth
// the mode keeps: more passes find finer detail, and nothing is averaged.

#include <optional>
#include <string_view>

#include "scene/render_mode.hpp"

namespace fgr {

// Samples per pixel one render may take, in every mode.
constexpr int kMinSamples = 1;
constexpr int kMaxSamples = 4096;

struct SampleBudget {
    // What the samples are, in words: "samples", or "passes" in the brute mode.
    std::string_view unit;
    // Samples a still takes unless told: `fgr render` (its tiles and parts too), each frame of
    // `fgr video`, and each rank's share under MPI.
    int still = 1;
    // Samples the viewer accumulates while the view stands still; 0: as many as its quality
    // setting says (`fgr view --samples`), which suits a mode that converges in a few.
    int standing_view = 0;
    // Whether renders with different seeds (FrameRequest::path.seed) take different samples, so
    // that their frames add up to one render of all their samples (MPI ranks, parts merged by
    // seed). Only the path tracer's do: the shaded mode jitters by the sample's index alone, and
    // brute passes refine one depth buffer.
    bool seeded = false;

    bool operator==(const SampleBudget&) const = default;
};

// The budget of `mode`.
SampleBudget sample_budget(RenderMode mode);

// Whether parts rendered in the mode named `mode` (as part files record it) take different samples
// with different seeds (SampleBudget::seeded); false for a name no mode has.
bool seeded_samples(std::string_view mode);

// Throws std::invalid_argument unless kMinSamples <= samples <= kMaxSamples.
void check_samples(int samples);

// The samples a still in `mode` takes: `asked` when given (std::invalid_argument when it is out
// of range, as check_samples), else the mode's default.
int still_samples(RenderMode mode, std::optional<int> asked);

}  // namespace fgr
