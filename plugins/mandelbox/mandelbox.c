// SPDX-License-Identifier: Apache-2.0
/* The Mandelbox scene plugin: box fold, sphere fold and scale, with the running-derivative DE. */
#include <stddef.h>

#include "fgr/scene_helpers.h"
#include "mandelbox_cl.h" /* mandelbox_cl: the OpenCL source, embedded at build time */

static const fgr_param_desc params[] = {
    FGR_FLOAT_PARAM("scale", "Scale", "Fractal", -3.0f, 3.0f, 2.0f,
                    "z -> scale * folds(z) + p; |scale| below 1.2 is raised to 1.2"),
    FGR_FLOAT_PARAM("folding_limit", "Folding limit", "Fractal", 0.5f, 1.5f, 1.0f,
                    "box fold reflects coordinates beyond +-limit"),
    FGR_FLOAT_PARAM("min_radius", "Min radius", "Fractal", 0.1f, 1.5f, 0.5f,
                    "sphere fold's inner radius; clamped to at most fixed_radius"),
    FGR_FLOAT_PARAM("fixed_radius", "Fixed radius", "Fractal", 0.5f, 1.5f, 1.0f,
                    "sphere fold inverts in the sphere of this radius"),
    FGR_FLOAT_PARAM("bailout", "Bailout", "Fractal", 10.0f, 100000.0f, 10000.0f,
                    "escape radius; large keeps the DE continuous where the escape count changes"),
    /* Coloured by the steps an orbit took, in ember: the point trap's rings wallpapered the
     * faces and hid their carving. */
    FGR_COLOUR_PARAMS(3, 0, 1.0f, 0.97f, 0.92f),
};

/* At scale 2 the set fills the cube [-6, 6]^3 (corner radius 10.4) and its faces bulge past it:
 * the default view frames the whole cube with a margin, the others look into its carved faces. */
static const fgr_camera cameras[] = {
    FGR_CAMERA_Z_UP("front", 21.0f, -24.9f, 15.1f, 0.0f, 0.0f, 0.0f, 50.0f),
    FGR_CAMERA_Z_UP("face", 2.0f, -13.0f, 2.5f, 0.0f, -6.0f, 0.0f, 60.0f),
    FGR_CAMERA_Z_UP("corner", 9.0f, -9.0f, 9.0f, 5.0f, -5.0f, 5.0f, 55.0f),
};

/* Once round the cube at a height that rises and falls over its top face. */
static const fgr_keyframe orbit_keys[] = {
    FGR_KEYFRAME_Z_UP(0.0f, 16.0f, -19.0f, 11.5f, 0.0f, 0.0f, 0.0f, 50.0f),
    FGR_KEYFRAME_Z_UP(2.5f, 19.0f, 16.0f, 6.0f, 0.0f, 0.0f, 0.0f, 50.0f),
    FGR_KEYFRAME_Z_UP(5.0f, -16.0f, 19.0f, 2.0f, 0.0f, 0.0f, 0.0f, 50.0f),
    FGR_KEYFRAME_Z_UP(7.5f, -19.0f, -16.0f, 6.0f, 0.0f, 0.0f, 0.0f, 50.0f),
    FGR_KEYFRAME_Z_UP(10.0f, 16.0f, -19.0f, 11.5f, 0.0f, 0.0f, 0.0f, 50.0f),
};

/* From the default view down to the carved -y face. */
static const fgr_keyframe approach_keys[] = {
    FGR_KEYFRAME_Z_UP(0.0f, 16.0f, -19.0f, 11.5f, 0.0f, 0.0f, 0.0f, 50.0f),
    FGR_KEYFRAME_Z_UP(4.0f, 6.0f, -15.0f, 5.0f, 0.0f, -6.0f, 0.0f, 55.0f),
    FGR_KEYFRAME_Z_UP(8.0f, 2.0f, -13.0f, 2.5f, 0.0f, -6.0f, 0.0f, 60.0f),
};

static const fgr_camera_path paths[] = {
    FGR_CAMERA_PATH("orbit", orbit_keys),
    FGR_CAMERA_PATH("approach", approach_keys),
};

/* A warm key light from above the default view's left and a cool fill from the far side. */
static const fgr_light lights[] = {
    FGR_DIRECTIONAL_LIGHT(-0.3f, -0.7f, 0.8f, 1.0f, 0.94f, 0.84f, 1.1f),
    FGR_DIRECTIONAL_LIGHT(0.6f, 0.6f, -0.2f, 0.45f, 0.6f, 0.9f, 0.4f),
};

/* r / dr is an estimate: sampled, its Lipschitz constant is about 1.0 with the default bailout;
 * rays advance 0.9 DE for a margin at the fold seams. */
#define MANDELBOX_STEP_FACTOR 0.9f

static const fgr_scene_desc scene = FGR_SCENE(
    "mandelbox", "Mandelbox", "Mandelbox: box fold, sphere fold and scale, running-derivative DE",
    mandelbox_cl, "mandelbox.cl", params, cameras, paths, lights,
    FGR_EFFECT_AMBIENT_OCCLUSION | FGR_EFFECT_SHADOWS,
    FGR_MARCH(256u, 60.0f, 1.0f, 16u, MANDELBOX_STEP_FACTOR));

FGR_PLUGIN_EXPORT const fgr_scene_desc* fgr_scene_entry(void) { return &scene; }
