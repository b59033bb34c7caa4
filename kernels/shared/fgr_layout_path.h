// SPDX-License-Identifier: Apache-2.0
/* fgr: the path tracer's settings as fgr_mode_path.cl receives them, by value (see
 * fgr_layout_types.h for how this header is shared); host/render/modes/path_mode.cpp fills them
 * from PathSettings. */
#ifndef FGR_LAYOUT_PATH_H
#define FGR_LAYOUT_PATH_H

#ifndef __OPENCL_C_VERSION__
#include "fgr_layout_types.h"
#endif

/* Set bits of path_settings.flags. */
#define FGR_PATH_LIGHT_SAMPLING 1 /* next-event estimation */
#define FGR_PATH_MIS 2            /* weigh light and BSDF sampling by the power heuristic */
#define FGR_PATH_ENVIRONMENT_IS 4 /* sample the environment by importance, not uniformly */
#define FGR_PATH_INDEPENDENT 8    /* independent random samples instead of stratified ones */
#define FGR_PATH_REGROUP 16       /* regrouped packets: a lane whose path ends starts another */

#ifdef __cplusplus
namespace fgr::layout {
#endif

typedef struct path_settings {
    fgr_layout_int max_bounces;          /* scattering events after the camera ray at most */
    fgr_layout_int roulette_depth;       /* Russian roulette from this bounce on */
    fgr_layout_float radiance_clamp;     /* > 0: each sample's radiance is clamped to it (biased);
                                          * 0: off */
    fgr_layout_int flags;                /* FGR_PATH_* */
    fgr_layout_uint seed;                /* the render's seed: another seed, another noise */
    fgr_layout_int light_count;          /* lights in the light list */
    fgr_layout_float environment_weight; /* the environment's mean luminance: what light
                                          * sampling weighs it by, times the reflectance */
    fgr_layout_int launch_samples;       /* with FGR_PATH_REGROUP: samples of every pixel this
                                          * launch traces, from `sample` on */
} path_settings;

#ifdef __cplusplus
}  // namespace fgr::layout
#endif

#endif /* FGR_LAYOUT_PATH_H */
