// SPDX-License-Identifier: Apache-2.0
/* The stereographic quaternion Julia scene plugin: R^3 lifted onto the unit 3-sphere by the
 * inverse stereographic projection, inside where q -> q^2 + c stays bounded. Inside-only (no
 * distance estimate, see stereographic_julia.cl): rendered by the brute-force mode. */
#include <stddef.h>

#include "fgr/scene_helpers.h"
#include "stereographic_julia_cl.h" /* stereographic_julia_cl: the OpenCL source, embedded */

/* |c| <= 2 keeps every escaping orbit beyond a bailout of 2 (see stereographic_julia.cl). The
 * default c is a quaternion near Douady's rabbit (-0.123 + 0.745 i) turned partly into j: a
 * bell of nested shells, tilted into a conch. */
static const fgr_param_desc params[] = {
    FGR_FLOAT_PARAM("c_x", "c real", "Fractal", -1.0f, 1.0f, -0.125f,
                    "real part of the constant c"),
    FGR_FLOAT_PARAM("c_y", "c i", "Fractal", -1.0f, 1.0f, 0.6f, "i part of c"),
    FGR_FLOAT_PARAM("c_z", "c j", "Fractal", -1.0f, 1.0f, 0.4f, "j part of c"),
    FGR_FLOAT_PARAM("c_w", "c k", "Fractal", -1.0f, 1.0f, 0.0f, "k part of c"),
    FGR_FLOAT_PARAM("scale", "Scale", "Projection", 0.25f, 10.0f, 2.5f,
                    "p is multiplied by this before the projection: the sphere |p| = 1/scale "
                    "lifts to the imaginary unit quaternions"),
    FGR_FLOAT_PARAM("tilt", "Pole tilt", "Projection", -90.0f, 90.0f, 20.0f,
                    "degrees the projection's pole turns from the real axis towards k: 0 gives "
                    "a solid of revolution about Im(c), more twists it into a spiral"),
    FGR_FLOAT_PARAM("bailout", "Bailout", "Fractal", 2.0f, 64.0f, 4.0f,
                    "escape radius: from 2 up no orbit that passed it stays bounded; larger keeps "
                    "more slow escapers at a given iteration count"),
    FGR_COLOUR_PARAMS(0, 1, 1.0f, 0.96f, 0.9f),
};

/* The set spans about (-0.4, -0.7, -1.0) .. (2.2, 1.8, 1.6) (its big shell) and holds the small
 * inverted twin, a ball of thin shells within |p| < 0.4, in the mouth of the shell, which faces
 * (-x, -y). max_distance below is 7.5: the far side of the set from the farthest camera. */
static const fgr_camera cameras[] = {
    FGR_CAMERA_Z_UP("conch", 4.4f, -2.9f, 2.3f, 0.9f, 0.55f, 0.25f, 50.0f),
    FGR_CAMERA_Z_UP("mouth", -2.35f, -1.63f, 1.89f, 0.88f, 0.52f, 0.28f, 50.0f),
    FGR_CAMERA_Z_UP("pagoda", 2.4f, 1.55f, 5.2f, 0.88f, 0.52f, 0.15f, 50.0f),
    FGR_CAMERA_Z_UP("spiral", -3.5f, 2.8f, 0.6f, 0.9f, 0.5f, 0.3f, 50.0f),
};

/* Once round the shell, past the spiral and mouth views. */
static const fgr_keyframe orbit_keys[] = {
    FGR_KEYFRAME_Z_UP(0.0f, 4.4f, -2.9f, 2.3f, 0.9f, 0.55f, 0.25f, 50.0f),
    FGR_KEYFRAME_Z_UP(3.0f, 4.6f, 3.0f, 1.2f, 0.9f, 0.55f, 0.3f, 50.0f),
    FGR_KEYFRAME_Z_UP(6.0f, -3.5f, 2.8f, 0.6f, 0.9f, 0.5f, 0.3f, 50.0f),
    FGR_KEYFRAME_Z_UP(9.0f, -2.8f, -2.0f, 2.0f, 0.88f, 0.52f, 0.28f, 50.0f),
    FGR_KEYFRAME_Z_UP(12.0f, 4.4f, -2.9f, 2.3f, 0.9f, 0.55f, 0.25f, 50.0f),
};

/* Into the mouth of the shell, towards the twin at its bottom. */
static const fgr_keyframe dive_keys[] = {
    FGR_KEYFRAME_Z_UP(0.0f, -2.35f, -1.63f, 1.89f, 0.88f, 0.52f, 0.28f, 50.0f),
    FGR_KEYFRAME_Z_UP(4.0f, -1.3f, -1.0f, 0.75f, 0.0f, 0.0f, 0.0f, 50.0f),
    FGR_KEYFRAME_Z_UP(8.0f, -0.7f, -0.55f, 0.35f, 0.0f, 0.0f, 0.0f, 45.0f),
};

static const fgr_camera_path paths[] = {
    FGR_CAMERA_PATH("orbit", orbit_keys),
    FGR_CAMERA_PATH("dive", dive_keys),
};

/* A warm key from above the conch view's left, a cool fill from the mouth's side. */
static const fgr_light lights[] = {
    FGR_DIRECTIONAL_LIGHT(-0.2f, -0.8f, 0.8f, 1.0f, 0.93f, 0.82f, 1.1f),
    FGR_DIRECTIONAL_LIGHT(-0.7f, 0.3f, 0.1f, 0.45f, 0.6f, 0.9f, 0.4f),
};

/* No distance estimate: max_steps, hit_threshold and step_factor are the march's and unused
 * here; max_distance is where the brute-force sampling along each ray ends, just past the set
 * from every camera and keyframe above; 12 iterations keep the shells thick enough to sample. */
static const fgr_scene_desc scene = FGR_SCENE_WITH_MODE(
    "stereographic-julia", "Stereographic quaternion Julia",
    "quaternion Julia set q -> q^2 + c on the 3-sphere, stereographically projected to R^3 "
    "(inside-only)",
    stereographic_julia_cl, "stereographic_julia.cl", params, cameras, paths, lights,
    FGR_EFFECT_AMBIENT_OCCLUSION | FGR_EFFECT_GLOW, FGR_MARCH(256u, 7.5f, 1.0f, 12u, 1.0f),
    "brute");

FGR_PLUGIN_EXPORT const fgr_scene_desc* fgr_scene_entry(void) { return &scene; }
