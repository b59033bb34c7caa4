// SPDX-License-Identifier: Apache-2.0
/* fgr: the index of each kernel argument the host sets (see fgr_layout_types.h for how this header
 * is shared). OpenCL C cannot name an argument's position in a signature, so each kernel's
 * parameter list is written in this order beside a reference to these names, and the device
 * layout test reads every kernel's argument names back from the driver at these indices. */
#ifndef FGR_LAYOUT_ARGUMENTS_H
#define FGR_LAYOUT_ARGUMENTS_H

/* Every render mode's fgr_render (and the brute mode's fgr_brute_shade) starts with these
 * (FGR_RENDER_ARGS in fgr_camera.cl). */
#define FGR_RENDER_ARG_PLANES 0       /* __global float*: the output planes */
#define FGR_RENDER_ARG_PLANE_SIZE 1   /* int: floats per plane (whole tiles) */
#define FGR_RENDER_ARG_TILE_COUNT 2   /* int: tiles in the region */
#define FGR_RENDER_ARG_CAMERA 3       /* camera_frame */
#define FGR_RENDER_ARG_SAMPLE 4       /* int: which sample of each pixel this launch renders */
#define FGR_RENDER_ARG_PARAMS 5       /* __constant float*: the scene's parameters */
#define FGR_RENDER_ARG_MARCH_STARTS 6 /* __global const float*: the prepass's starts */
#define FGR_RENDER_ARG_MARCH_HINTS 7  /* __global const float*: reprojected start hints */
#define FGR_RENDER_ARG_HAS_HINTS 8    /* int: whether to read them */
#define FGR_RENDER_ARGS_COUNT 9       /* a mode's own arguments follow */

/* The shaded mode's fgr_render. */
#define FGR_SHADED_ARG_LIGHTS 9       /* __constant float*: FGR_LIGHT_FLOATS each */
#define FGR_SHADED_ARG_LIGHT_COUNT 10 /* int */

/* The path mode's fgr_render. */
#define FGR_PATH_ARG_LIGHTS 9       /* __constant float*: FGR_PATH_LIGHT_FLOATS each */
#define FGR_PATH_ARG_SETTINGS 10    /* path_settings */
#define FGR_PATH_ARG_ENV_DATA 11    /* __global const float*: the environment's tables */
#define FGR_PATH_ARG_ENVIRONMENT 12 /* environment_info */

/* The brute mode's fgr_render and fgr_brute_shade. */
#define FGR_BRUTE_ARG_STATE 9              /* __global float*: each pixel's best depth */
#define FGR_BRUTE_SHADE_ARG_STATE 9        /* __global const float*: the same */
#define FGR_BRUTE_SHADE_ARG_LIGHTS 10      /* __constant float*: FGR_LIGHT_FLOATS each */
#define FGR_BRUTE_SHADE_ARG_LIGHT_COUNT 11 /* int */

/* The cone prepass, fgr_prepass. */
#define FGR_PREPASS_ARG_STARTS 0       /* __global float*: FGR_PREPASS_PLANES planes */
#define FGR_PREPASS_ARG_BLOCK_PLANE 1  /* int: floats per plane (the blocks) */
#define FGR_PREPASS_ARG_PACKET_COUNT 2 /* int */
#define FGR_PREPASS_ARG_CAMERA 3       /* camera_frame */
#define FGR_PREPASS_ARG_PARAMS 4       /* __constant float* */
#define FGR_PREPASS_ARG_CONE_SCALE 5   /* float: 1 for the safe cone */

/* The probes, fgr_probe_de, fgr_probe_normal and fgr_probe_de_pair. */
#define FGR_PROBE_ARG_POINTS 0       /* __global const float*: FGR_PROBE_POINT_PLANES planes */
#define FGR_PROBE_ARG_PLANE_SIZE 1   /* int: floats per plane (whole packets) */
#define FGR_PROBE_ARG_PACKET_COUNT 2 /* int */
#define FGR_PROBE_ARG_OUT 3          /* __global float*: FGR_PROBE_*_PLANES planes */
#define FGR_PROBE_ARG_PARAMS 4       /* __constant float* */
#define FGR_PROBE_ARG_EPS 5          /* fgr_probe_normal: float, the stencil's size */

/* The device math self-test's kernels, fgr_check_<function> (fgr_math_check.cl). */
#define FGR_MATH_CHECK_ARG_A 0          /* __global const lane_scalar*: first operands */
#define FGR_MATH_CHECK_ARG_B 1          /* __global const lane_scalar*: second operands */
#define FGR_MATH_CHECK_ARG_OUT 2        /* __global lane_scalar*: results */
#define FGR_MATH_CHECK_ARG_FIRST_CASE 3 /* int: the first case of this function's run */

#endif /* FGR_LAYOUT_ARGUMENTS_H */
