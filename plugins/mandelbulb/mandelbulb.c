// SPDX-License-Identifier: Apache-2.0
/* The Mandelbulb scene plugin: power-n Mandelbulb with the analytic running-derivative DE.
 * Its default camera is the canonical view fgr is benchmarked on (see bench/). */
#include <stddef.h>

#include "fgr/scene_helpers.h"
#include "mandelbulb_cl.h" /* mandelbulb_cl: the OpenCL source, embedded at build time */

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
     "bailout",
     "Bailout",
     "Fractal",
     FGR_PARAM_FLOAT,
     1.5f,
     64.0f,
     {2.0f, 0.0f, 0.0f},
     NULL,
     "escape radius"},
    {FGR_HEADER(fgr_param_desc),
     "variant",
     "Angle form",
     "Fractal",
     FGR_PARAM_INT,
     0.0f,
     1.0f,
     {0.0f, 0.0f, 0.0f},
     "colatitude|latitude",
     "colatitude: theta = atan2(sqrt(x^2+y^2), z); latitude: theta = asin(z/r) (Mandelbulber2)"},
    FGR_COLOUR_PARAMS(0, 0, 1.0f, 0.95f, 0.9f),
};

/* Camera (2, -2, 1) looking at the origin, horizontal field of view 2 atan(0.5) = 53.13 degrees. */
static const fgr_camera cameras[] = {
    {FGR_HEADER(fgr_camera),
     "canonical",
     {2.0f, -2.0f, 1.0f},
     {0.0f, 0.0f, 0.0f},
     {0.0f, 0.0f, 1.0f},
     53.130102f},
    {FGR_HEADER(fgr_camera),
     "top",
     {0.0f, -0.3f, 2.6f},
     {0.0f, 0.0f, 0.0f},
     {0.0f, 1.0f, 0.0f},
     53.130102f},
    {FGR_HEADER(fgr_camera),
     "close",
     {0.9f, -0.9f, 0.55f},
     {0.2f, -0.2f, 0.2f},
     {0.0f, 0.0f, 1.0f},
     45.0f},
};

static const fgr_keyframe orbit_keys[] = {
    {FGR_HEADER(fgr_keyframe), 0.0f, {2.0f, -2.0f, 1.0f}, {0, 0, 0}, {0, 0, 1}, 53.130102f},
    {FGR_HEADER(fgr_keyframe), 2.5f, {2.0f, 2.0f, 0.6f}, {0, 0, 0}, {0, 0, 1}, 53.130102f},
    {FGR_HEADER(fgr_keyframe), 5.0f, {-2.0f, 2.0f, 0.2f}, {0, 0, 0}, {0, 0, 1}, 53.130102f},
    {FGR_HEADER(fgr_keyframe), 7.5f, {-2.0f, -2.0f, 0.6f}, {0, 0, 0}, {0, 0, 1}, 53.130102f},
    {FGR_HEADER(fgr_keyframe), 10.0f, {2.0f, -2.0f, 1.0f}, {0, 0, 0}, {0, 0, 1}, 53.130102f},
};

static const fgr_keyframe dive_keys[] = {
    {FGR_HEADER(fgr_keyframe), 0.0f, {2.0f, -2.0f, 1.0f}, {0, 0, 0}, {0, 0, 1}, 53.130102f},
    {FGR_HEADER(fgr_keyframe), 4.0f, {0.9f, -0.9f, 0.55f}, {0.2f, -0.2f, 0.2f}, {0, 0, 1}, 45.0f},
    {FGR_HEADER(fgr_keyframe), 8.0f, {0.6f, -0.55f, 0.45f}, {0.3f, -0.1f, 0.3f}, {0, 0, 1}, 35.0f},
};

static const fgr_camera_path paths[] = {
    {FGR_HEADER(fgr_camera_path), "orbit", orbit_keys, sizeof orbit_keys / sizeof orbit_keys[0]},
    {FGR_HEADER(fgr_camera_path), "dive", dive_keys, sizeof dive_keys / sizeof dive_keys[0]},
};

/* A warm key light from the upper left of the canonical view and a cool fill from the right. */
static const fgr_light lights[] = {
    {FGR_HEADER(fgr_light),
     FGR_LIGHT_DIRECTIONAL,
     {-0.1f, -0.75f, 0.75f},
     {1.0f, 0.93f, 0.82f},
     1.1f,
     0.0f},
    {FGR_HEADER(fgr_light),
     FGR_LIGHT_DIRECTIONAL,
     {0.7f, 0.5f, -0.3f},
     {0.45f, 0.55f, 0.8f},
     0.35f,
     0.0f},
};

/* The analytic DE 0.5 r log(r) / dr is an estimate: sampled, its gradient reaches about 1.24, so
 * rays advance 0.8 DE and never step into the surface (`fgr check mandelbulb`). The
 * reference comparison (bench/compare_reference.sh) sets step_factor=1, the reference's rule. */
#define MANDELBULB_STEP_FACTOR 0.8f

static const fgr_scene_desc scene = FGR_SCENE(
    "mandelbulb", "Mandelbulb", "power-n Mandelbulb, analytic running-derivative DE", mandelbulb_cl,
    "mandelbulb.cl", params, cameras, paths, lights, FGR_EFFECT_AMBIENT_OCCLUSION,
    FGR_MARCH(256u, 10.0f, 1.0f, 12u, MANDELBULB_STEP_FACTOR));

FGR_PLUGIN_EXPORT const fgr_scene_desc* fgr_scene_entry(void) { return &scene; }
