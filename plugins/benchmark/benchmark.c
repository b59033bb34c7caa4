// SPDX-License-Identifier: Apache-2.0
/* The benchmark scene: several fractal and primitive geometries, two lights, ambient occlusion,
 * soft shadows and reflections, and a fixed 12-second camera path ("benchmark") for timing. */
#include "benchmark_cl.h" /* benchmark_cl: the OpenCL source, embedded at build time */
#include "fgr/scene_helpers.h"

static const fgr_param_desc params[] = {
    FGR_FLOAT_PARAM("floor_reflectivity", "Floor reflectivity", "Materials", 0.0f, 1.0f, 0.25f,
                    "mirror reflectivity of the floor at normal incidence"),
    FGR_ENUM_PARAM("palette", "Bulb palette", "Materials", 5, 0, "ember|ocean|forest|pastel|mono",
                   "colour ramp of the Mandelbulb"),
    {FGR_HEADER(fgr_param_desc),
     "base_colour",
     "Bulb tint",
     "Materials",
     FGR_PARAM_COLOUR,
     0.0f,
     1.0f,
     {1.0f, 0.95f, 0.9f},
     NULL,
     "tint multiplying the bulb's palette"},
};

static const fgr_camera cameras[] = {
    FGR_CAMERA_Z_UP("overview", 4.6f, -4.4f, 2.9f, 0.0f, 0.2f, 0.5f, 55.0f),
    FGR_CAMERA_Z_UP("low", 3.2f, -2.6f, 0.45f, -0.6f, 0.6f, 0.6f, 60.0f),
};

/* A full orbit around the group, rising and falling: 12 s, the same every run. */
static const fgr_keyframe benchmark_keys[] = {
    FGR_KEYFRAME_Z_UP(0.0f, 4.6f, -4.4f, 2.9f, 0.0f, 0.2f, 0.5f, 55.0f),
    FGR_KEYFRAME_Z_UP(3.0f, 5.2f, 3.2f, 1.6f, 0.0f, 0.2f, 0.5f, 55.0f),
    FGR_KEYFRAME_Z_UP(6.0f, -3.8f, 4.6f, 2.4f, 0.0f, 0.2f, 0.6f, 55.0f),
    FGR_KEYFRAME_Z_UP(9.0f, -5.0f, -2.8f, 1.2f, 0.0f, 0.2f, 0.5f, 55.0f),
    FGR_KEYFRAME_Z_UP(12.0f, 4.6f, -4.4f, 2.9f, 0.0f, 0.2f, 0.5f, 55.0f),
};

static const fgr_camera_path paths[] = {
    FGR_CAMERA_PATH("benchmark", benchmark_keys),
};

static const fgr_light lights[] = {
    FGR_DIRECTIONAL_LIGHT(0.45f, -0.35f, 0.82f, 1.0f, 0.93f, 0.82f, 1.0f),
    FGR_POINT_LIGHT(-1.2f, -2.6f, 2.4f, 0.55f, 0.7f, 1.0f, 5.0f),
};

static const fgr_scene_desc scene =
    FGR_SCENE("benchmark", "Benchmark",
              "Mandelbulb, Menger sponge and primitives on a mirror floor: every effect at once",
              benchmark_cl, "benchmark.cl", params, cameras, paths, lights,
              FGR_EFFECT_AMBIENT_OCCLUSION | FGR_EFFECT_SOFT_SHADOWS | FGR_EFFECT_REFLECTIONS,
              /* The bulb's DE is an estimate (see plugins/mandelbulb): advance 0.8 DE. */
              FGR_MARCH(256u, 30.0f, 1.0f, 8u, 0.8f));

FGR_PLUGIN_EXPORT const fgr_scene_desc* fgr_scene_entry(void) { return &scene; }
