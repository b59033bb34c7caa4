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
    fgr_layout_int marginal_offset;    /* into env_data: height + 1 floats */
    fgr_layout_int conditional_offset; /* into env_data: height rows of width + 1 floats */
} environment_info;

#ifdef __cplusplus
}  // namespace fgr::layout
#endif

#endif /* FGR_LAYOUT_ENVIRONMENT_H */
