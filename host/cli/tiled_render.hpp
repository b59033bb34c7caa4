// SPDX-License-Identifier: Apache-2.0
#pragma once
// fgr render in tiles: what makes a render tiled, and the tiled render itself (the progress
// line, Ctrl-C, --resume), on top of output/tiled/tiled_still.hpp. Under mpirun the tiles are
// shared out over the ranks (distributed/task_farm.hpp) and rank 0 writes the file.

#include "commands.hpp"
#include "device/program_cache.hpp"
#include "output/still_image.hpp"
#include "render/renderer.hpp"

namespace fgr {

// Whether the command renders in tiles: as the still needs (renders_in_tiles), or when given
// --tile-size or --resume.
bool tiled_render_wanted(const RenderOptions& options);

// Options a tiled render cannot honour: UsageError naming them.
void check_tiled_options(const RenderOptions& options);

// Renders in tiles to options.output; returns the exit code (130 when Ctrl-C stopped it).
int render_tiled(const Scene& scene, const FrameRequest& request, const ComputeDevice& device,
                 ProgramCache& cache, const RenderOptions& options);

// A part for `fgr merge` (--part, --tile I/N): whether one was asked for, the options it cannot
// honour (UsageError naming them), and the render (rows of tile I of N, or the whole image, in
// bands streamed to the .exr part); returns the exit code (130 when Ctrl-C stopped it).
bool part_render_wanted(const RenderOptions& options);
void check_part_options(const RenderOptions& options);
int render_part_file(const Scene& scene, const FrameRequest& request, const ComputeDevice& device,
                     ProgramCache& cache, const RenderOptions& options);

}  // namespace fgr
