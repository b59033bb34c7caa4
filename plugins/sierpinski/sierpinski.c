// SPDX-License-Identifier: Apache-2.0
/* The Sierpinski tetrahedron scene plugin: a kaleidoscopic IFS of tetrahedral folds, standing on
 * a face with its apex up the z axis. The DE is in sierpinski.cl. */
#include <stddef.h>

#include "fgr/scene_helpers.h"
#include "sierpinski_cl.h" /* sierpinski_cl: the OpenCL source, embedded at build time */

#define FOV 50.0f

static const fgr_param_desc params[] = {
    FGR_FLOAT_PARAM("scale", "Scale", "Fractal", 1.5f, 3.0f, 2.0f,
                    "size ratio between levels: 2 gives touching copies, less overlaps them"),
    FGR_VEC3_PARAM("offset", "Offset", "Fractal", 0.0f, 2.0f, 1.0f, 1.0f, 1.0f,
                   "corner each copy is scaled towards, in the tetrahedron's own frame"),
    FGR_FLOAT_PARAM("twist", "Twist", "Fractal", -180.0f, 180.0f, 0.0f,
                    "degrees each level turns about the vertical axis"),
    FGR_COLOUR_PARAMS(0, 3, 1.0f, 0.97f, 0.95f),
};

/* The tetrahedron spans z in [-0.58, 1.73] and a circumradius of 1.73: the views aim a little
 * above its centroid so apex and base both sit inside the frame. */
static const fgr_camera cameras[] = {
    FGR_CAMERA_Z_UP("front", 3.636f, 4.038f, 1.805f, 0.0f, 0.0f, 0.45f, FOV),
    FGR_CAMERA_Z_UP("below", 2.2f, 3.0f, -2.4f, 0.0f, 0.0f, 0.2f, FOV),
    FGR_CAMERA_Z_UP("window", 0.12f, 0.9f, 0.1f, 0.0f, 0.0f, 0.05f, 70.0f),
};

/* One turn about the vertical axis at 14 degrees elevation, distance 5.6, in 12 seconds. */
static const fgr_keyframe orbit_keys[] = {
    FGR_KEYFRAME_Z_UP(0.0f, 3.636f, 4.038f, 1.805f, 0.0f, 0.0f, 0.45f, FOV),
    FGR_KEYFRAME_Z_UP(1.5f, -0.284f, 5.426f, 1.805f, 0.0f, 0.0f, 0.45f, FOV),
    FGR_KEYFRAME_Z_UP(3.0f, -4.038f, 3.636f, 1.805f, 0.0f, 0.0f, 0.45f, FOV),
    FGR_KEYFRAME_Z_UP(4.5f, -5.426f, -0.284f, 1.805f, 0.0f, 0.0f, 0.45f, FOV),
    FGR_KEYFRAME_Z_UP(6.0f, -3.636f, -4.038f, 1.805f, 0.0f, 0.0f, 0.45f, FOV),
    FGR_KEYFRAME_Z_UP(7.5f, 0.284f, -5.426f, 1.805f, 0.0f, 0.0f, 0.45f, FOV),
    FGR_KEYFRAME_Z_UP(9.0f, 4.038f, -3.636f, 1.805f, 0.0f, 0.0f, 0.45f, FOV),
    FGR_KEYFRAME_Z_UP(10.5f, 5.426f, 0.284f, 1.805f, 0.0f, 0.0f, 0.45f, FOV),
    FGR_KEYFRAME_Z_UP(12.0f, 3.636f, 4.038f, 1.805f, 0.0f, 0.0f, 0.45f, FOV),
};

/* From the front view up to the hole in the middle of the front face, looking through it into
 * the central void. */
static const fgr_keyframe fly_in_keys[] = {
    FGR_KEYFRAME_Z_UP(0.0f, 3.636f, 4.038f, 1.805f, 0.0f, 0.0f, 0.45f, FOV),
    FGR_KEYFRAME_Z_UP(3.0f, 0.6f, 2.2f, 0.6f, 0.0f, 0.0f, 0.2f, 55.0f),
    FGR_KEYFRAME_Z_UP(6.0f, 0.12f, 0.9f, 0.1f, 0.0f, 0.0f, 0.05f, 70.0f),
};

static const fgr_camera_path paths[] = {
    FGR_CAMERA_PATH("orbit", orbit_keys),
    FGR_CAMERA_PATH("fly-in", fly_in_keys),
};

/* A warm key from above the front view's left, grazing both faces it shows, and a cool fill from
 * low on the right. */
static const fgr_light lights[] = {
    FGR_DIRECTIONAL_LIGHT(0.69f, 0.12f, 0.7f, 1.0f, 0.92f, 0.8f, 1.1f),
    FGR_DIRECTIONAL_LIGHT(-0.5f, 0.85f, -0.1f, 0.45f, 0.55f, 0.85f, 0.4f),
};

static const fgr_scene_desc scene = FGR_SCENE_TUNED(
    "sierpinski", "Sierpinski tetrahedron",
    "kaleidoscopic IFS of tetrahedral folds, with scale, offset and twist", sierpinski_cl,
    "sierpinski.cl", params, cameras, paths, lights,
    FGR_EFFECT_AMBIENT_OCCLUSION | FGR_EFFECT_SHADOWS,
    /* 2^-10 tetrahedra are about a pixel wide at 640 pixels from the front view. The DE is a
     * strict bound, so rays take full steps (step factor 1). */
    FGR_MARCH(192u, 16.0f, 1.0f, 10u, 1.0f),
    /* A KIFS: every point reaches the last iteration, so "iterations" would be one flat colour. */
    NULL, NULL, 0, FGR_COLOUR_MODES_NO_ITERATIONS, 0.0f);

FGR_PLUGIN_EXPORT const fgr_scene_desc* fgr_scene_entry(void) { return &scene; }
