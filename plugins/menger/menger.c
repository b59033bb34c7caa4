// SPDX-License-Identifier: Apache-2.0
/* The Menger sponge scene plugin: a kaleidoscopic IFS of cube folds with the middle-layer
 * correction, centred at the origin in the cube [-1, 1]^3. The DE is in menger.cl. */
#include <stddef.h>

#include "fgr/scene_helpers.h"
#include "menger_cl.h" /* menger_cl: the OpenCL source, embedded at build time */

#define FOV 50.0f

static const fgr_param_desc params[] = {
    FGR_FLOAT_PARAM("scale", "Scale", "Fractal", 2.0f, 4.0f, 3.0f,
                    "size ratio between levels: 3 is the true sponge"),
    FGR_VEC3_PARAM("offset", "Offset", "Fractal", 0.0f, 2.0f, 1.0f, 1.0f, 1.0f,
                   "corner each sub-cube is scaled towards; (1, 1, 1) is the true sponge"),
    FGR_FLOAT_PARAM("twist", "Twist", "Fractal", -180.0f, 180.0f, 0.0f,
                    "degrees each level turns about the cube's diagonal"),
    FGR_COLOUR_PARAMS(0, 0, 1.0f, 1.0f, 1.0f),
};

static const fgr_camera cameras[] = {
    FGR_CAMERA_Z_UP("corner", 4.191f, 2.934f, 2.278f, 0.0f, 0.0f, 0.0f, FOV),
    FGR_CAMERA_Z_UP("face", 0.0f, 5.0f, 0.35f, 0.0f, 0.0f, 0.0f, FOV),
    FGR_CAMERA_Z_UP("tunnel", 0.0f, 0.9f, 0.0f, 0.35f, 0.0f, 0.1f, 75.0f),
};

/* One turn about the vertical axis at 24 degrees elevation, distance 5.6, in 12 seconds. */
static const fgr_keyframe orbit_keys[] = {
    FGR_KEYFRAME_Z_UP(0.0f, 4.191f, 2.934f, 2.278f, 0.0f, 0.0f, 0.0f, FOV),
    FGR_KEYFRAME_Z_UP(1.5f, 0.888f, 5.038f, 2.278f, 0.0f, 0.0f, 0.0f, FOV),
    FGR_KEYFRAME_Z_UP(3.0f, -2.934f, 4.191f, 2.278f, 0.0f, 0.0f, 0.0f, FOV),
    FGR_KEYFRAME_Z_UP(4.5f, -5.038f, 0.888f, 2.278f, 0.0f, 0.0f, 0.0f, FOV),
    FGR_KEYFRAME_Z_UP(6.0f, -4.191f, -2.934f, 2.278f, 0.0f, 0.0f, 0.0f, FOV),
    FGR_KEYFRAME_Z_UP(7.5f, -0.888f, -5.038f, 2.278f, 0.0f, 0.0f, 0.0f, FOV),
    FGR_KEYFRAME_Z_UP(9.0f, 2.934f, -4.191f, 2.278f, 0.0f, 0.0f, 0.0f, FOV),
    FGR_KEYFRAME_Z_UP(10.5f, 5.038f, -0.888f, 2.278f, 0.0f, 0.0f, 0.0f, FOV),
    FGR_KEYFRAME_Z_UP(12.0f, 4.191f, 2.934f, 2.278f, 0.0f, 0.0f, 0.0f, FOV),
};

/* From the corner view round to the front face and down its central tunnel (the square hole
 * through the middle of every face), ending in the hollow at the sponge's centre. */
static const fgr_keyframe fly_in_keys[] = {
    FGR_KEYFRAME_Z_UP(0.0f, 4.191f, 2.934f, 2.278f, 0.0f, 0.0f, 0.0f, FOV),
    FGR_KEYFRAME_Z_UP(3.0f, 0.6f, 3.2f, 0.5f, 0.0f, 0.0f, 0.0f, FOV),
    FGR_KEYFRAME_Z_UP(5.0f, 0.0f, 1.6f, 0.0f, 0.0f, 0.0f, 0.0f, 60.0f),
    FGR_KEYFRAME_Z_UP(7.0f, 0.0f, 0.9f, 0.0f, 0.35f, 0.0f, 0.1f, 75.0f),
};

static const fgr_camera_path paths[] = {
    FGR_CAMERA_PATH("orbit", orbit_keys),
    FGR_CAMERA_PATH("fly-in", fly_in_keys),
};

/* A warm key from above the corner view's left, a cool fill from low on the right. */
static const fgr_light lights[] = {
    FGR_DIRECTIONAL_LIGHT(0.75f, -0.2f, 0.65f, 1.0f, 0.93f, 0.82f, 1.1f),
    FGR_DIRECTIONAL_LIGHT(-0.3f, 0.9f, -0.2f, 0.45f, 0.55f, 0.85f, 0.4f),
};

static const fgr_scene_desc scene = FGR_SCENE_TUNED(
    "menger", "Menger sponge", "kaleidoscopic IFS of cube folds, with scale, offset and twist",
    menger_cl, "menger.cl", params, cameras, paths, lights,
    FGR_EFFECT_AMBIENT_OCCLUSION | FGR_EFFECT_SHADOWS,
    /* Level-6 cubes (3^-6 of the sponge) are about a pixel wide at 640 pixels from the corner
     * view; flat faces need few steps, tunnels seen edge-on need more. The DE is a strict bound,
     * so rays take full steps (step factor 1). */
    FGR_MARCH(192u, 16.0f, 1.0f, 6u, 1.0f),
    /* A KIFS: every point reaches the last iteration, so "iterations" would be one flat colour. */
    NULL, NULL, 0, FGR_COLOUR_MODES_NO_ITERATIONS, 0.0f);

FGR_PLUGIN_EXPORT const fgr_scene_desc* fgr_scene_entry(void) { return &scene; }
