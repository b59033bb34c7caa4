/* The Mandelbox scene plugin: box fold, sphere fold and scale, with the running-derivative DE. */
#include <stddef.h>

#include "fgr/scene_helpers.h"
#include "mandelbox_cl.h" /* mandelbox_cl: the OpenCL source, embedded at build time */

static const fgr_param_desc params[] = {
    FGR_FLOAT_PARAM("scale", "Scale", "Fractal", -3.0f, 3.0f, -1.5f,
                    "z -> scale * folds(z) + p; |scale| below 1.2 is raised to 1.2"),
    FGR_FLOAT_PARAM("folding_limit", "Folding limit", "Fractal", 0.5f, 1.5f, 1.0f,
                    "box fold reflects coordinates beyond +-limit"),
    FGR_FLOAT_PARAM("min_radius", "Min radius", "Fractal", 0.1f, 1.5f, 0.5f,
                    "sphere fold's inner radius; clamped to at most fixed_radius"),
    FGR_FLOAT_PARAM("fixed_radius", "Fixed radius", "Fractal", 0.5f, 1.5f, 1.0f,
                    "sphere fold inverts in the sphere of this radius"),
    FGR_FLOAT_PARAM("bailout", "Bailout", "Fractal", 10.0f, 1000.0f, 100.0f, "escape radius"),
    FGR_COLOUR_PARAMS(1, 0, 1.0f, 0.97f, 0.92f),
};

static const fgr_camera cameras[] = {
    FGR_CAMERA_Z_UP("front", 7.0f, -8.0f, 5.0f, 0.0f, 0.0f, 0.0f, 50.0f),
};

static const fgr_keyframe orbit_keys[] = {
    FGR_KEYFRAME_Z_UP(0.0f, 7.0f, -8.0f, 5.0f, 0.0f, 0.0f, 0.0f, 50.0f),
    FGR_KEYFRAME_Z_UP(2.5f, 8.0f, 7.0f, 3.0f, 0.0f, 0.0f, 0.0f, 50.0f),
    FGR_KEYFRAME_Z_UP(5.0f, -7.0f, 8.0f, 1.0f, 0.0f, 0.0f, 0.0f, 50.0f),
    FGR_KEYFRAME_Z_UP(7.5f, -8.0f, -7.0f, 3.0f, 0.0f, 0.0f, 0.0f, 50.0f),
    FGR_KEYFRAME_Z_UP(10.0f, 7.0f, -8.0f, 5.0f, 0.0f, 0.0f, 0.0f, 50.0f),
};

static const fgr_camera_path paths[] = {
    FGR_CAMERA_PATH("orbit", orbit_keys),
};

static const fgr_light lights[] = {
    FGR_DIRECTIONAL_LIGHT(-0.3f, -0.7f, 0.8f, 1.0f, 0.94f, 0.84f, 1.1f),
    FGR_DIRECTIONAL_LIGHT(0.6f, 0.6f, -0.2f, 0.45f, 0.6f, 0.9f, 0.4f),
};

static const fgr_scene_desc scene = {
    FGR_HEADER(fgr_scene_desc),
    "mandelbox",
    "Mandelbox",
    "Mandelbox: box fold, sphere fold and scale, running-derivative DE",
    mandelbox_cl,
    "mandelbox.cl",
    params,
    FGR_COUNT(params),
    cameras,
    FGR_COUNT(cameras),
    paths,
    FGR_COUNT(paths),
    lights,
    FGR_COUNT(lights),
    FGR_EFFECT_AMBIENT_OCCLUSION,
    {FGR_HEADER(fgr_march_settings), 256u, 40.0f, 1.0f, 14u},
};

FGR_PLUGIN_EXPORT const fgr_scene_desc* fgr_scene_entry(void) { return &scene; }
