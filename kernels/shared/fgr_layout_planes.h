// SPDX-License-Identifier: Apache-2.0
/* fgr: how the kernels' outputs are laid out in memory, and which plane holds what (see
 * fgr_layout_types.h for how this header is shared).
 *
 * Work-item g renders tile g, FGR_TILE_WIDTH(w) x FGR_TILE_HEIGHT(w) pixels in the w lanes of one
 * packet (w = FGR_WIDTH, the packet width). A plane is one float per pixel, tile-major: each lane
 * at tile * w + lane, lane = row in the tile * FGR_TILE_WIDTH(w) + column. A kernel writes plane p
 * at planes + p * plane_size; the host reads plane p of pixel (x, y) at
 * planes[p * plane_size + TileLayout::index(x, y)].
 *
 * Which planes a render has depends on the program's switches: FGR_STATS (`stats`, the work
 * behind each pixel), FGR_AOVS (`aovs`, what a still's alpha and layers need) and the scene's
 * geometry (`ifs`, FGR_GEOMETRY_IFS). The macros taking them want 0 or 1. */
#ifndef FGR_LAYOUT_PLANES_H
#define FGR_LAYOUT_PLANES_H

/* A tile's shape for packet width w (1, 4, 8 or 16): 1x1, 2x2, 4x2, 4x4. */
#define FGR_TILE_WIDTH(w) ((w) == 1 ? 1 : (w) == 4 ? 2 : 4)
#define FGR_TILE_HEIGHT(w) ((w) / FGR_TILE_WIDTH(w))

/* --- Every render mode ---------------------------------------------------------------------- */

#define FGR_COLOUR_PLANE 0 /* r, g, b: summed over samples, or the finished colour (brute) */
#define FGR_COLOUR_PLANES 3
#define FGR_DEPTH_PLANE 3   /* distance to the first hit (sample 0); -1: none */
#define FGR_COMMON_PLANES 4 /* a mode's own planes follow */

/* --- Shaded (fgr_mode_shaded.cl) ------------------------------------------------------------ */

/* With stats, written by sample 0: the work behind each pixel. The primary march's DE
 * evaluations (IFS scenes: nodes visited), 1 where the ray ran out of steps (else 0), and the DE
 * evaluations of the secondary rays its lane took part in. */
#define FGR_SHADED_STEPS_PLANE 4
#define FGR_SHADED_OUT_OF_STEPS_PLANE 5
#define FGR_SHADED_SECONDARY_STEPS_PLANE 6
/* DE scenes: the secondary rays' DE evaluations of the pixel's packet, in every lane. IFS scenes:
 * the most nodes the ray's heap held (-1: it overflowed). Each scene writes only its own one. */
#define FGR_SHADED_SECONDARY_PACKET_STEPS_PLANE 7
#define FGR_SHADED_HEAP_PEAK_PLANE 8
#define FGR_SHADED_STATS_PLANES 5

/* IFS scenes, written by sample 0 after the stats planes: the level of the node each pixel hit
 * (-1: missed), how deep the footprint and the depth slider let the image go. */
#define FGR_SHADED_LEVEL_PLANE(stats) (FGR_COMMON_PLANES + ((stats) ? FGR_SHADED_STATS_PLANES : 0))

/* With aovs, after those: the layers, summed over samples (zero for a sample that missed). Their
 * order from FGR_SHADED_AOV_PLANE: */
#define FGR_SHADED_AOV_PLANE(stats, ifs) (FGR_SHADED_LEVEL_PLANE(stats) + ((ifs) ? 1 : 0))
#define FGR_SHADED_AOV_ALBEDO 0     /* 3: the first hit's albedo */
#define FGR_SHADED_AOV_NORMAL 3     /* 3: its shading normal */
#define FGR_SHADED_AOV_COVERAGE 6   /* 1 for a sample whose camera ray met the surface */
#define FGR_SHADED_AOV_FOREGROUND 7 /* 3: the colour of those samples alone */
#define FGR_SHADED_AOV_PLANES 10

/* --- Path (fgr_mode_path.cl) ---------------------------------------------------------------- */

/* Always, summed over samples: the first hit's albedo, normal and coverage; then the radiance of
 * the odd-numbered samples alone (the two halves of the samples give each pixel's variance); then
 * one the host writes: each pixel takes the samples whose index is below its value there (adaptive
 * sampling; the host writes a huge value when every pixel takes every sample). */
#define FGR_PATH_ALBEDO_PLANE 4        /* 3 */
#define FGR_PATH_NORMAL_PLANE 7        /* 3 */
#define FGR_PATH_ALPHA_PLANE 10        /* 1 where the camera ray met the surface */
#define FGR_PATH_ODD_RADIANCE_PLANE 11 /* 3 */
#define FGR_PATH_SAMPLE_LIMIT_PLANE 14 /* read, not written, by the kernel */
#define FGR_PATH_AUXILIARY_PLANES 11

/* With stats, summed over samples: the DE evaluations each lane took part in, and those its
 * packet made (for lane utilisation). */
#define FGR_PATH_LANE_STEPS_PLANE 15
#define FGR_PATH_PACKET_STEPS_PLANE 16
#define FGR_PATH_STATS_PLANES 2

/* With aovs, after those: the radiance of the samples whose camera ray met the surface (3
 * planes), the foreground without the environment seen past it. */
#define FGR_PATH_FOREGROUND_PLANE(stats) \
    (FGR_PATH_SAMPLE_LIMIT_PLANE + 1 + ((stats) ? FGR_PATH_STATS_PLANES : 0))
#define FGR_PATH_FOREGROUND_PLANES 3

/* --- Brute (fgr_mode_brute.cl) -------------------------------------------------------------- */

/* Written by fgr_brute_shade: the albedo and normal the shading used. */
#define FGR_BRUTE_ALBEDO_PLANE 4 /* 3 */
#define FGR_BRUTE_NORMAL_PLANE 7 /* 3 */
#define FGR_BRUTE_SURFACE_PLANES 6
/* With stats: each pixel's inside tests, summed over passes. */
#define FGR_BRUTE_STATS_PLANE 10
#define FGR_BRUTE_STATS_PLANES 1

/* The farthest any pixel's screen-space shading reads from it, in pixels: the occlusion disc's
 * and the glow's radius are capped here (only images over 1024 pixels wide reach the occlusion
 * cap, over 12288 the glow's), so a tile of a gigapixel still is rendered with this much padding
 * (host/output/tiled/tiled_still.cpp) and no more. */
#define FGR_BRUTE_MAX_REACH 256

/* --- The cone prepass (fgr_prepass.cl) ------------------------------------------------------ */

/* Pixels per block side: one cone per block. */
#define FGR_PREPASS_BLOCK 8
/* Its buffer: planes of one float per block (the kernel's block_plane floats each). */
#define FGR_PREPASS_STARTS_PLANE 0      /* where the block's camera rays start */
#define FGR_PREPASS_EVALUATIONS_PLANE 1 /* the DE evaluations its cone took */
#define FGR_PREPASS_PLANES 2

/* --- The probes (fgr_probe.cl) -------------------------------------------------------------- */

/* Their points: planes of one float per point (plane_size floats each, whole packets). */
#define FGR_PROBE_POINT_PLANE 0      /* 3: x, y, z as floats */
#define FGR_PROBE_POINT_REST_PLANE 3 /* 3: x, y, z of what those miss of the host's doubles */
#define FGR_PROBE_POINT_PLANES 6
/* Their outputs: fgr_probe_de's distance, fgr_probe_normal's x, y, z from plane 0. */
#define FGR_PROBE_DE_PLANES 1
#define FGR_PROBE_NORMAL_PLANES 3
/* fgr_probe_de_pair: each point's DE as the first point of a pair, then as the second */
#define FGR_PROBE_DE_PAIR_PLANES 2

#endif /* FGR_LAYOUT_PLANES_H */
