// SPDX-License-Identifier: Apache-2.0
/* fgr: the path tracer's environment as the kernels receive it, by value beside the tables'
 * flat buffer env_data (see fgr_layout_types.h for how this header is shared).
 * host/render/environment.hpp builds the tables and fills it; fgr_environment.cl looks the map
 * up and samples it. */
#ifndef FGR_LAYOUT_ENVIRONMENT_H
#define FGR_LAYOUT_ENVIRONMENT_H

#ifndef __OPENCL_C_VERSION__
#include "fgr_layout_types.h"
#endif

#ifdef __cplusplus
namespace fgr::layout {
#endif

typedef struct environment_info {
    fgr_layout_float4 transform; /* x: rotation in turns, y: intensity, z, w: 0 */
    fgr_layout_int width;        /* of the map, in texels */
    fgr_layout_int height;
    fgr_layout_int rows_offset;    /* into env_data: the rows' alias table, height entries */
    fgr_layout_int columns_offset; /* into env_data: each row's columns' alias table, width
                                      entries a row */
} environment_info;

/* env_data, one flat float buffer:
 *   [0, FGR_ENV_TEXEL_FLOATS * width * height)  the texels, row-major from the top row: R, G, B
 *       and the probability that environment_sample picks the texel (FGR_ENV_TEXEL_PROBABILITY)
 *   [rows_offset, + FGR_ENV_ALIAS_FLOATS * height)  the rows' alias table (Walker, Vose)
 *   [columns_offset, + FGR_ENV_ALIAS_FLOATS * width * height)  per row, its columns' alias table
 * An alias table entry is a threshold in [0, 1] (a float) and an alias index (an int's bits): a
 * uniform pick of entry k with a uniform f in [0, 1) gives k when f < threshold, else the alias.
 * The texel's probability is what its two tables realise with the stored thresholds (computed on
 * the host from them), so the pdf and the sampling agree to a float's rounding. */
#define FGR_ENV_TEXEL_FLOATS 4
#define FGR_ENV_TEXEL_PROBABILITY 3
#define FGR_ENV_ALIAS_FLOATS 2
#define FGR_ENV_ALIAS_THRESHOLD 0
#define FGR_ENV_ALIAS_INDEX 1

#ifdef __cplusplus
}  // namespace fgr::layout
#endif

#endif /* FGR_LAYOUT_ENVIRONMENT_H */
