// SPDX-License-Identifier: Apache-2.0
/* The SDK guide's second iterate-function example: Knighty's pseudo-Kleinian. The DE is in
 * pseudo_kleinian.cl; this file describes parameters, cameras, a path, lights and effects. */
#include "fgr/scene_helpers.h"
#include "pseudo_kleinian_cl.h" /* pseudo_kleinian_cl and its path, embedded at build time */

static const fgr_param_desc params[] = {
    FGR_VEC3_PARAM("box", "Box size", "Fractal", 0.5f, 2.0f, 1.0f, 1.0f, 1.3f,
                   "half sizes of the box fold: the cell the structure repeats in"),
    FGR_FLOAT_PARAM("size", "Inversion size", "Fractal", 0.5f, 1.5f, 1.0f,
                    "squared radius of the sphere the orbit is inverted in"),
    FGR_VEC3_PARAM("offset", "Offset", "Fractal", -0.5f, 0.5f, 0.0f, 0.0f, 0.0f,
                   "added after each inversion: deforms the group"),
    FGR_FLOAT_PARAM("thickness", "Thickness", "Fractal", 0.0f, 0.1f, 0.01f,
                    "radius of the cylinders the set is drawn with"),
    FGR_COLOUR_PARAMS(2, 1, 1.0f, 0.97f, 0.93f),
};

static const fgr_camera cameras[] = {
    FGR_CAMERA_Z_UP("inside", 1.7f, -1.5f, 0.95f, 0.0f, 0.5f, 0.2f, 70.0f),
    FGR_CAMERA_Z_UP("above", 0.2f, -0.9f, 2.6f, 0.0f, 0.0f, 0.0f, 60.0f),
};

static const fgr_keyframe drift_keys[] = {
    FGR_KEYFRAME_Z_UP(0.0f, 1.7f, -1.5f, 0.95f, 0.0f, 0.5f, 0.2f, 70.0f),
    FGR_KEYFRAME_Z_UP(5.0f, 1.0f, -0.2f, 0.45f, -0.6f, 1.0f, 0.1f, 70.0f),
    FGR_KEYFRAME_Z_UP(10.0f, 1.7f, -1.5f, 0.95f, 0.0f, 0.5f, 0.2f, 70.0f),
};

static const fgr_camera_path paths[] = {
    FGR_CAMERA_PATH("drift", drift_keys),
};

static const fgr_light lights[] = {
    FGR_DIRECTIONAL_LIGHT(0.3f, -0.5f, 0.8f, 1.0f, 0.92f, 0.8f, 1.1f),
    FGR_DIRECTIONAL_LIGHT(-0.5f, 0.6f, 0.3f, 0.4f, 0.55f, 0.9f, 0.45f),
};

static const fgr_scene_desc scene = FGR_SCENE_TUNED(
    "pseudo-kleinian", "Pseudo-Kleinian",
    "Knighty's pseudo-Kleinian: box folds and sphere inversions; the SDK guide's second "
    "iterate-function example",
    pseudo_kleinian_cl, pseudo_kleinian_cl_path, params, cameras, paths, lights,
    /* No shadows: inside the structure a ceiling hides every directional light. Fog, and rays
     * that stop at 8 units, let the colonnade fade into the distance instead of filling it. */
    FGR_EFFECT_AMBIENT_OCCLUSION | FGR_EFFECT_FOG,
    /* Full steps: with Knighty's factor 0.5 the distance grows at most 0.57 times as fast as the
     * point moves (fgr check's Lipschitz and march-safety measurements), a bound. */
    FGR_MARCH(300u, 8.0f, 1.0f, 8u, 1.0f),
    /* No bailout: every point runs every iteration, so "iterations" would be one flat colour. */
    NULL, NULL, 0, FGR_COLOUR_MODES_NO_ITERATIONS, 0.0f);

FGR_PLUGIN_EXPORT const fgr_scene_desc* fgr_scene_entry(void) { return &scene; }
