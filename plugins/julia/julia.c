// SPDX-License-Identifier: Apache-2.0
/* The quaternion Julia scene plugin: a 3D slice of the 4D Julia set of q -> q^2 + c, with the
 * analytic running-derivative DE. */
#include <stddef.h>

#include "fgr/scene_helpers.h"
#include "julia_cl.h" /* julia_cl: the OpenCL source, embedded at build time */

/* |c| <= 2 keeps the set inside a ball of radius 2 (see julia.cl), well inside any bailout. */
static const fgr_param_desc params[] = {
    FGR_FLOAT_PARAM("c_x", "c real", "Fractal", -1.0f, 1.0f, -0.2f, "real part of the constant c"),
    FGR_FLOAT_PARAM("c_y", "c i", "Fractal", -1.0f, 1.0f, 0.6f, "i part of c"),
    FGR_FLOAT_PARAM("c_z", "c j", "Fractal", -1.0f, 1.0f, 0.2f, "j part of c"),
    FGR_FLOAT_PARAM("c_w", "c k", "Fractal", -1.0f, 1.0f, 0.2f, "k part of c"),
    FGR_FLOAT_PARAM("slice_w", "Slice w", "Fractal", -1.0f, 1.0f, 0.0f,
                    "k coordinate of the 3D slice through the 4D set"),
    FGR_FLOAT_PARAM("bailout", "Bailout", "Fractal", 4.0f, 256.0f, 64.0f,
                    "escape radius; larger is a more accurate DE"),
    FGR_COLOUR_PARAMS(0, 1, 1.0f, 0.97f, 0.92f),
};

static const fgr_camera cameras[] = {
    FGR_CAMERA_Z_UP("front", 2.6f, -2.6f, 1.45f, 0.0f, 0.0f, 0.0f, 45.0f),
    FGR_CAMERA_Z_UP("top", 0.0f, -0.4f, 3.2f, 0.0f, 0.0f, 0.0f, 45.0f),
    FGR_CAMERA_Z_UP("close", 1.1f, -1.3f, 0.7f, 0.1f, 0.0f, 0.1f, 40.0f),
};

/* Once round the set at a gently rising and falling height. */
static const fgr_keyframe orbit_keys[] = {
    FGR_KEYFRAME_Z_UP(0.0f, 2.6f, -2.6f, 1.45f, 0.0f, 0.0f, 0.0f, 45.0f),
    FGR_KEYFRAME_Z_UP(2.5f, 2.9f, 2.9f, 0.8f, 0.0f, 0.0f, 0.0f, 45.0f),
    FGR_KEYFRAME_Z_UP(5.0f, -2.9f, 2.9f, -0.5f, 0.0f, 0.0f, 0.0f, 45.0f),
    FGR_KEYFRAME_Z_UP(7.5f, -2.9f, -2.9f, 0.8f, 0.0f, 0.0f, 0.0f, 45.0f),
    FGR_KEYFRAME_Z_UP(10.0f, 2.6f, -2.6f, 1.45f, 0.0f, 0.0f, 0.0f, 45.0f),
};

/* From the default view in towards the folds near the set's waist. */
static const fgr_keyframe approach_keys[] = {
    FGR_KEYFRAME_Z_UP(0.0f, 2.6f, -2.6f, 1.45f, 0.0f, 0.0f, 0.0f, 45.0f),
    FGR_KEYFRAME_Z_UP(4.0f, 1.7f, -1.9f, 1.0f, 0.05f, 0.0f, 0.05f, 42.0f),
    FGR_KEYFRAME_Z_UP(8.0f, 1.1f, -1.3f, 0.7f, 0.1f, 0.0f, 0.1f, 40.0f),
};

static const fgr_camera_path paths[] = {
    FGR_CAMERA_PATH("orbit", orbit_keys),
    FGR_CAMERA_PATH("approach", approach_keys),
};

/* A warm key light from above the default view's left and a cool rim from behind. */
static const fgr_light lights[] = {
    FGR_DIRECTIONAL_LIGHT(-0.3f, -0.7f, 0.8f, 1.0f, 0.94f, 0.84f, 1.1f),
    FGR_DIRECTIONAL_LIGHT(0.6f, 0.6f, -0.2f, 0.45f, 0.6f, 0.9f, 0.4f),
};

/* The DE is a Koebe-style bound, sampled Lipschitz constant about 1.0 (see julia.cl); rays advance
 * 0.9 DE for a margin where the 4D potential's slice bends sharply. */
#define JULIA_STEP_FACTOR 0.9f

static const fgr_scene_desc scene = FGR_SCENE(
    "julia", "Quaternion Julia",
    "3D slice of the quaternion Julia set q -> q^2 + c, analytic running-derivative DE", julia_cl,
    "julia.cl", params, cameras, paths, lights, FGR_EFFECT_AMBIENT_OCCLUSION | FGR_EFFECT_SHADOWS,
    FGR_MARCH(256u, 10.0f, 1.0f, 12u, JULIA_STEP_FACTOR));

FGR_PLUGIN_EXPORT const fgr_scene_desc* fgr_scene_entry(void) { return &scene; }
