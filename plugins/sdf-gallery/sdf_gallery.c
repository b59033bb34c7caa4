// SPDX-License-Identifier: Apache-2.0
/* The SDF gallery scene plugin: every primitive, combinator and transform of the kernel library's
 * kernels/sdf/fgr_sdf.cl on a 6 x 4 grid of slots, front row to back: primitives, more primitives
 * with elongate / onion / round, the six combinators, the non-rigid transforms. */
#include <stddef.h>

#include "fgr/scene_helpers.h"
#include "sdf_gallery_cl.h" /* sdf_gallery_cl: the OpenCL source, embedded at build time */

/* Ranges keep every object inside its slot's bounding ball (radius 1) and every DE a bound: the
 * twist and bend stretch factors stay below 2, the displacement's Lipschitz factor below 4.5. */
static const fgr_param_desc params[] = {
    FGR_FLOAT_PARAM("smooth_k", "Blend radius", "Combinators", 0.0f, 0.5f, 0.25f,
                    "fillet width of the smooth union, subtraction and intersection"),
    FGR_FLOAT_PARAM("rounding", "Rounding", "Primitives", 0.0f, 0.25f, 0.12f,
                    "edge radius of the round box and the rounded cross"),
    FGR_FLOAT_PARAM("twist", "Twist", "Transforms", -3.0f, 3.0f, 1.6f,
                    "turn of the twisted column, radians per unit of height"),
    FGR_FLOAT_PARAM("bend", "Bend", "Transforms", 0.0f, 0.8f, 0.6f,
                    "curvature of the bent bar (1 / radius)"),
    FGR_FLOAT_PARAM("displacement", "Displacement", "Transforms", 0.0f, 0.12f, 0.06f,
                    "amplitude of the sine displacement"),
    FGR_FLOAT_PARAM("frequency", "Frequency", "Transforms", 2.0f, 16.0f, 9.0f,
                    "spatial frequency of the sine displacement, radians per unit"),
    FGR_FLOAT_PARAM("spacing", "Repetition spacing", "Transforms", 0.3f, 0.46f, 0.4f,
                    "cell size of the repeated balls (the lattice of cubes uses half of it)"),
};

/* The grid spans x in [-7.9, 7.9], y in [-5.4, 5.4]; the default view looks at it from the front,
 * raised enough that the back rows show over the front ones. */
static const fgr_camera cameras[] = {
    FGR_CAMERA_Z_UP("front", 0.0f, -12.5f, 10.0f, 0.0f, -0.9f, 0.0f, 66.0f),
    FGR_CAMERA_Z_UP("primitives", -4.0f, -9.5f, 3.2f, -2.2f, -3.0f, 0.8f, 50.0f),
    FGR_CAMERA_Z_UP("transforms", -3.75f, -1.5f, 3.6f, -3.75f, 3.75f, 0.9f, 62.0f),
    FGR_CAMERA_Z_UP("top", 0.0f, -1.0f, 18.0f, 0.0f, 0.0f, 0.0f, 60.0f),
};

/* Once around the platform at a constant height, looking at its centre. */
static const fgr_keyframe orbit_keys[] = {
    FGR_KEYFRAME_Z_UP(0.0f, 0.0f, -15.0f, 8.0f, 0.0f, 0.0f, 0.5f, 62.0f),
    FGR_KEYFRAME_Z_UP(3.0f, 15.0f, 0.0f, 8.0f, 0.0f, 0.0f, 0.5f, 62.0f),
    FGR_KEYFRAME_Z_UP(6.0f, 0.0f, 15.0f, 8.0f, 0.0f, 0.0f, 0.5f, 62.0f),
    FGR_KEYFRAME_Z_UP(9.0f, -15.0f, 0.0f, 8.0f, 0.0f, 0.0f, 0.5f, 62.0f),
    FGR_KEYFRAME_Z_UP(12.0f, 0.0f, -15.0f, 8.0f, 0.0f, 0.0f, 0.5f, 62.0f),
};

/* Along the front row at eye level, then up over the platform to the transforms at the back. */
static const fgr_keyframe walk_keys[] = {
    FGR_KEYFRAME_Z_UP(0.0f, -8.0f, -8.0f, 2.5f, -4.0f, -3.0f, 0.8f, 50.0f),
    FGR_KEYFRAME_Z_UP(4.0f, 4.0f, -8.5f, 3.0f, 3.0f, -2.0f, 0.8f, 50.0f),
    FGR_KEYFRAME_Z_UP(8.0f, 6.0f, -2.0f, 6.0f, 1.5f, 3.0f, 0.8f, 55.0f),
};

static const fgr_camera_path paths[] = {
    FGR_CAMERA_PATH("orbit", orbit_keys),
    FGR_CAMERA_PATH("walk", walk_keys),
};

/* A warm key light from the front left, high enough for short shadows, and a cool fill from the
 * back right that keeps shadowed sides readable. */
static const fgr_light lights[] = {
    FGR_DIRECTIONAL_LIGHT(-0.45f, -0.55f, 0.7f, 1.0f, 0.93f, 0.82f, 1.1f),
    FGR_DIRECTIONAL_LIGHT(0.6f, 0.5f, 0.45f, 0.55f, 0.65f, 0.9f, 0.4f),
};

static const fgr_scene_desc scene =
    FGR_SCENE("sdf-gallery", "SDF gallery",
              "the kernel library's distance functions: primitives, combinators and transforms",
              sdf_gallery_cl, "sdf_gallery.cl", params, cameras, paths, lights,
              FGR_EFFECT_AMBIENT_OCCLUSION | FGR_EFFECT_SHADOWS,
              /* 40 units covers the whole platform from any camera above; iterations are unused. */
              FGR_MARCH(256u, 40.0f, 1.0f, 1u, 1.0f));

FGR_PLUGIN_EXPORT const fgr_scene_desc* fgr_scene_entry(void) { return &scene; }
