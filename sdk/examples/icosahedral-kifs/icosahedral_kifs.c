// SPDX-License-Identifier: Apache-2.0
/* The SDK guide's iterate-function example: an icosahedral kaleidoscopic IFS with a rotation in
 * the loop. The DE is in icosahedral_kifs.cl; this file describes parameters, cameras, a path,
 * lights and effects. */
#include "fgr/scene_helpers.h"
#include "icosahedral_kifs_cl.h" /* icosahedral_kifs_cl and its path, embedded at build time */

static const fgr_param_desc params[] = {
    FGR_FLOAT_PARAM("scale", "Scale", "Fractal", 1.5f, 4.0f, 3.0f,
                    "size ratio between levels: from about 2.9 the twelve copies stop overlapping"),
    FGR_VEC3_PARAM("axis", "Rotation axis", "Fractal", -1.0f, 1.0f, 0.2f, 0.5f, 1.0f,
                   "what each level turns about (any length)"),
    FGR_FLOAT_PARAM("angle", "Rotation angle", "Fractal", -60.0f, 60.0f, 8.0f,
                    "degrees each level turns: 0 gives the symmetric IFS, more a twisted one"),
    FGR_COLOUR_PARAMS(0, 1, 1.0f, 0.96f, 0.9f),
};

static const fgr_camera cameras[] = {
    FGR_CAMERA_Z_UP("front", 1.2f, -3.3f, 1.2f, 0.0f, 0.0f, 0.0f, 45.0f),
    FGR_CAMERA_Z_UP("close", 0.4f, -1.5f, 0.9f, 0.2f, 0.0f, 0.5f, 50.0f),
};

static const fgr_keyframe orbit_keys[] = {
    FGR_KEYFRAME_Z_UP(0.0f, 1.2f, -3.3f, 1.2f, 0.0f, 0.0f, 0.0f, 45.0f),
    FGR_KEYFRAME_Z_UP(4.0f, 3.3f, 1.2f, 0.8f, 0.0f, 0.0f, 0.0f, 45.0f),
    FGR_KEYFRAME_Z_UP(8.0f, -1.2f, 3.3f, 1.2f, 0.0f, 0.0f, 0.0f, 45.0f),
    FGR_KEYFRAME_Z_UP(12.0f, 1.2f, -3.3f, 1.2f, 0.0f, 0.0f, 0.0f, 45.0f),
};

static const fgr_camera_path paths[] = {
    FGR_CAMERA_PATH("orbit", orbit_keys),
};

static const fgr_light lights[] = {
    FGR_DIRECTIONAL_LIGHT(0.4f, -0.7f, 0.8f, 1.0f, 0.93f, 0.82f, 1.15f),
    FGR_DIRECTIONAL_LIGHT(-0.7f, 0.5f, -0.2f, 0.35f, 0.5f, 0.9f, 0.4f),
};

static const fgr_scene_desc scene = FGR_SCENE_TUNED(
    "icosahedral-kifs", "Icosahedral KIFS",
    "icosahedra of icosahedra, turned per level: the SDK guide's iterate-function example",
    icosahedral_kifs_cl, icosahedral_kifs_cl_path, params, cameras, paths, lights,
    FGR_EFFECT_SOFT_SHADOWS | FGR_EFFECT_AMBIENT_OCCLUSION,
    /* A strict bound: full steps. */
    FGR_MARCH(200u, 12.0f, 1.0f, 9u, 1.0f),
    /* No bailout: every point runs every iteration, so "iterations" would be one flat colour. */
    NULL, NULL, 0, FGR_COLOUR_MODES_NO_ITERATIONS, 0.0f);

FGR_PLUGIN_EXPORT const fgr_scene_desc* fgr_scene_entry(void) { return &scene; }
