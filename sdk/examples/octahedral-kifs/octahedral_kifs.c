// SPDX-License-Identifier: Apache-2.0
/* The SDK guide's worked example: an octahedral kaleidoscopic IFS. The DE is in
 * octahedral_kifs.cl; this file describes parameters, cameras, a path, lights and effects. */
#include "fgr/scene_helpers.h"
#include "octahedral_kifs_cl.h" /* octahedral_kifs_cl and its path, embedded at build time */

static const fgr_param_desc params[] = {
    FGR_FLOAT_PARAM("scale", "Scale", "Fractal", 1.8f, 3.0f, 2.0f,
                    "size ratio between levels: 2 makes the sub-octahedra touch"),
    FGR_VEC3_PARAM("offset", "Offset", "Fractal", 0.0f, 1.5f, 1.0f, 0.0f, 0.0f,
                   "the vertex each level is scaled towards"),
    FGR_FLOAT_PARAM("twist", "Twist", "Fractal", -45.0f, 45.0f, 0.0f,
                    "degrees each level turns about the z axis: small values give a coral"),
    FGR_COLOUR_PARAMS(0, 0, 1.0f, 0.97f, 0.92f),
};

static const fgr_camera cameras[] = {
    FGR_CAMERA_Z_UP("three-quarter", 2.4f, -2.9f, 1.5f, 0.0f, 0.0f, 0.0f, 50.0f),
    FGR_CAMERA_Z_UP("vertex", 0.0f, -0.2f, 2.4f, 0.0f, 0.0f, 0.4f, 60.0f),
};

static const fgr_keyframe orbit_keys[] = {
    FGR_KEYFRAME_Z_UP(0.0f, 2.4f, -2.9f, 1.5f, 0.0f, 0.0f, 0.0f, 50.0f),
    FGR_KEYFRAME_Z_UP(3.0f, 2.9f, 2.4f, 1.0f, 0.0f, 0.0f, 0.0f, 50.0f),
    FGR_KEYFRAME_Z_UP(6.0f, -2.4f, 2.9f, 1.5f, 0.0f, 0.0f, 0.0f, 50.0f),
    FGR_KEYFRAME_Z_UP(9.0f, -2.9f, -2.4f, 1.0f, 0.0f, 0.0f, 0.0f, 50.0f),
    FGR_KEYFRAME_Z_UP(12.0f, 2.4f, -2.9f, 1.5f, 0.0f, 0.0f, 0.0f, 50.0f),
};

static const fgr_camera_path paths[] = {
    FGR_CAMERA_PATH("orbit", orbit_keys),
};

static const fgr_light lights[] = {
    FGR_DIRECTIONAL_LIGHT(0.5f, -0.6f, 0.9f, 1.0f, 0.92f, 0.8f, 1.15f),
    FGR_DIRECTIONAL_LIGHT(-0.6f, 0.7f, -0.1f, 0.35f, 0.5f, 0.9f, 0.4f),
};

static const fgr_scene_desc scene = FGR_SCENE_TUNED(
    "octahedral-kifs", "Octahedral KIFS",
    "octahedra of octahedra, twisted per level: the SDK guide's worked example", octahedral_kifs_cl,
    octahedral_kifs_cl_path, params, cameras, paths, lights,
    FGR_EFFECT_SOFT_SHADOWS | FGR_EFFECT_AMBIENT_OCCLUSION,
    /* A strict bound: full steps. Level 9 octahedra (2^-9) are about a pixel at 640 wide. */
    FGR_MARCH(200u, 12.0f, 1.0f, 9u, 1.0f),
    /* A KIFS: every point reaches the last iteration, so "iterations" would be one flat colour. */
    NULL, NULL, 0, FGR_COLOUR_MODES_NO_ITERATIONS, 0.0f);

FGR_PLUGIN_EXPORT const fgr_scene_desc* fgr_scene_entry(void) { return &scene; }
