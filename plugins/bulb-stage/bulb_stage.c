// SPDX-License-Identifier: Apache-2.0
/* The bulb-stage scene plugin: a metal Mandelbulb on a tiled floor, path traced by default
 * (ABI 1.2's default_mode), lit by the sky's sun (its key light, a disc of the sun's size). */
#include <stddef.h>

#include "bulb_stage_cl.h" /* bulb_stage_cl: the OpenCL source, embedded at build time */
#include "fgr/scene_helpers.h"

static const fgr_param_desc params[] = {
    {FGR_HEADER(fgr_param_desc),
     "power",
     "Power",
     "Fractal",
     FGR_PARAM_FLOAT,
     2.0f,
     16.0f,
     {8.0f, 0.0f, 0.0f},
     NULL,
     "exponent n of z -> z^n + c"},
    {FGR_HEADER(fgr_param_desc),
     "bulb_colour",
     "Metal colour",
     "Materials",
     FGR_PARAM_COLOUR,
     0.0f,
     1.0f,
     {1.0f, 0.78f, 0.34f},
     NULL,
     "the metal's reflectance at normal incidence (gold)"},
    {FGR_HEADER(fgr_param_desc),
     "bulb_roughness",
     "Metal roughness",
     "Materials",
     FGR_PARAM_FLOAT,
     0.0f,
     1.0f,
     {0.3f, 0.0f, 0.0f},
     NULL,
     "0: a mirror; 1: matte metal"},
    {FGR_HEADER(fgr_param_desc),
     "floor_colour",
     "Floor colour",
     "Materials",
     FGR_PARAM_COLOUR,
     0.0f,
     1.0f,
     {0.62f, 0.6f, 0.56f},
     NULL,
     "the tiles' diffuse albedo"},
    {FGR_HEADER(fgr_param_desc),
     "tile",
     "Tile size",
     "Floor",
     FGR_PARAM_FLOAT,
     0.05f,
     4.0f,
     {0.5f, 0.0f, 0.0f},
     NULL,
     "side of a floor tile"},
    {FGR_HEADER(fgr_param_desc),
     "floor_height",
     "Floor height",
     "Floor",
     FGR_PARAM_FLOAT,
     -2.0f,
     0.0f,
     {-0.95f, 0.0f, 0.0f},
     NULL,
     "where the floor is (the bulb reaches down to about -1.1)"},
};

static const fgr_camera cameras[] = {
    FGR_CAMERA_Z_UP("front", 3.5f, -3.1f, 0.9f, 0.0f, 0.0f, -0.15f, 45.0f),
    FGR_CAMERA_Z_UP("low", 1.9f, -1.4f, -0.75f, 0.0f, 0.0f, -0.1f, 55.0f),
};

static const fgr_keyframe orbit_keys[] = {
    FGR_KEYFRAME_Z_UP(0.0f, 3.5f, -3.1f, 0.9f, 0.0f, 0.0f, -0.15f, 45.0f),
    FGR_KEYFRAME_Z_UP(4.0f, 3.5f, 3.1f, 0.6f, 0.0f, 0.0f, -0.15f, 45.0f),
    FGR_KEYFRAME_Z_UP(8.0f, -3.5f, 3.1f, 0.9f, 0.0f, 0.0f, -0.15f, 45.0f),
};

static const fgr_camera_path paths[] = {
    {FGR_HEADER(fgr_camera_path), "orbit", orbit_keys, sizeof orbit_keys / sizeof orbit_keys[0]},
};

/* The sun, up left behind the camera: a disc of the real sun's angular radius (0.27 degrees). */
static const fgr_light lights[] = {
    {FGR_HEADER(fgr_light),
     FGR_LIGHT_DIRECTIONAL,
     {-0.45f, -0.7f, 0.75f},
     {1.0f, 0.95f, 0.88f},
     1.2f,
     0.27f},
};

static const fgr_scene_desc scene = {
    .header = FGR_HEADER(fgr_scene_desc),
    .id = "bulb-stage",
    .name = "Bulb stage",
    .description = "a gold Mandelbulb on a tiled floor, path traced under the sky",
    .source = bulb_stage_cl,
    .source_name = "bulb_stage.cl",
    .params = params,
    .param_count = FGR_COUNT(params),
    .cameras = cameras,
    .camera_count = FGR_COUNT(cameras),
    .camera_paths = paths,
    .camera_path_count = FGR_COUNT(paths),
    .lights = lights,
    .light_count = FGR_COUNT(lights),
    .effects = FGR_EFFECT_SOFT_SHADOWS | FGR_EFFECT_AMBIENT_OCCLUSION,
    /* The bulb's DE is an estimate: rays advance 0.75 of it, so the march never steps into
     * the set (`fgr check bulb-stage` samples the bound). */
    .march = FGR_MARCH(384u, 40.0f, 1.0f, 10u, 0.75f),
    .source_length = FGR_SOURCE_LENGTH(bulb_stage_cl),
    .default_mode = "path",
};

FGR_PLUGIN_EXPORT const fgr_scene_desc* fgr_scene_entry(void) { return &scene; }
