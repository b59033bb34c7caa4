// SPDX-License-Identifier: Apache-2.0
/* The Bristorbrot scene plugin: Doug Bristor's non-conformal quadratic map of R^3 as a Julia set
 * (default) or a Mandelbrot set. Inside-only (no distance estimate, see bristorbrot.cl): rendered
 * by the brute-force mode. */
#include <stddef.h>

#include "bristorbrot_cl.h" /* bristorbrot_cl: the OpenCL source, embedded at build time */
#include "fgr/scene_helpers.h"

/* The default Julia constant lies inside the Mandelbrot form's set (its orbit stays bounded), so
 * the Julia set has an interior and stays solid as iterations grow (a c just outside, such as
 * (-0.2, 0.6, 0.3), looks alike at 12 iterations but thins to dust by 30). It is a knot of swirled
 * sheets within about (-1.3, -1.1, -1.1) .. (1.3, 1.1, 1.1); the Mandelbrot form spans
 * (-1.8, -1.1, -1.1) .. (0.7, 1.1, 1.1). */
static const fgr_param_desc params[] = {
    FGR_ENUM_PARAM("form", "Form", "Fractal", 2, 1, "mandelbrot|julia",
                   "mandelbrot: z0 = c = p; julia: z0 = p, c = julia_c"),
    FGR_VEC3_PARAM("julia_c", "Julia c", "Fractal", -1.5f, 1.5f, -0.15f, 0.55f, 0.35f,
                   "the constant c of the Julia form"),
    FGR_FLOAT_PARAM("twist", "Twist", "Fractal", 0.0f, 2.0f, 1.0f,
                    "k in y (2x - k z), z (2x + k y): 1 is Bristor's map, 0 the (symmetric, "
                    "distance-estimable) quaternion square"),
    FGR_FLOAT_PARAM("bailout", "Bailout", "Fractal", 2.0f, 64.0f, 4.0f,
                    "escape radius: from 4 (twist 1) or 9 (twist 2) up, no orbit that passed it "
                    "stays bounded; larger keeps more slow escapers at a given iteration count"),
    FGR_COLOUR_PARAMS(0, 0, 1.0f, 0.95f, 0.9f),
};

static const fgr_camera cameras[] = {
    FGR_CAMERA_Z_UP("front", 2.4f, -2.4f, 1.35f, 0.0f, 0.0f, -0.1f, 50.0f),
    FGR_CAMERA_Z_UP("side", -2.4f, -2.4f, 1.35f, 0.0f, 0.0f, -0.1f, 50.0f),
    FGR_CAMERA_Z_UP("whorl", 2.8f, 0.13f, 0.19f, 0.1f, -0.2f, -0.3f, 45.0f),
};

/* Once round the knot at a gently rising and falling height. */
static const fgr_keyframe orbit_keys[] = {
    FGR_KEYFRAME_Z_UP(0.0f, 2.4f, -2.4f, 1.35f, 0.0f, 0.0f, -0.1f, 50.0f),
    FGR_KEYFRAME_Z_UP(2.5f, 2.4f, 2.4f, 0.7f, 0.0f, 0.0f, 0.0f, 50.0f),
    FGR_KEYFRAME_Z_UP(5.0f, -2.4f, 2.4f, -0.4f, 0.0f, 0.0f, 0.0f, 50.0f),
    FGR_KEYFRAME_Z_UP(7.5f, -2.4f, -2.4f, 1.35f, 0.0f, 0.0f, -0.1f, 50.0f),
    FGR_KEYFRAME_Z_UP(10.0f, 2.4f, -2.4f, 1.35f, 0.0f, 0.0f, -0.1f, 50.0f),
};

/* From the front view in to the whorl on the +x side. */
static const fgr_keyframe approach_keys[] = {
    FGR_KEYFRAME_Z_UP(0.0f, 2.4f, -2.4f, 1.35f, 0.0f, 0.0f, -0.1f, 50.0f),
    FGR_KEYFRAME_Z_UP(4.0f, 2.7f, -1.2f, 0.7f, 0.05f, -0.1f, -0.15f, 48.0f),
    FGR_KEYFRAME_Z_UP(8.0f, 2.8f, 0.13f, 0.19f, 0.1f, -0.2f, -0.3f, 45.0f),
};

static const fgr_camera_path paths[] = {
    FGR_CAMERA_PATH("orbit", orbit_keys),
    FGR_CAMERA_PATH("approach", approach_keys),
};

/* A warm key light from above the front view's left and a cool rim from behind. */
static const fgr_light lights[] = {
    FGR_DIRECTIONAL_LIGHT(-0.3f, -0.7f, 0.8f, 1.0f, 0.94f, 0.84f, 1.1f),
    FGR_DIRECTIONAL_LIGHT(0.6f, 0.6f, -0.2f, 0.45f, 0.6f, 0.9f, 0.4f),
};

/* No distance estimate: max_steps, hit_threshold and step_factor are the march's and unused
 * here; max_distance is where the brute-force sampling along each ray ends, just past the set
 * from every camera and keyframe above. Shadows (inside tests towards each light) set the sheets
 * apart; they cost little next to the primary sampling. */
static const fgr_scene_desc scene = FGR_SCENE_WITH_MODE(
    "bristorbrot", "Bristorbrot",
    "Doug Bristor's non-conformal quadratic map of R^3, Julia or Mandelbrot form (inside-only)",
    bristorbrot_cl, "bristorbrot.cl", params, cameras, paths, lights,
    FGR_EFFECT_AMBIENT_OCCLUSION | FGR_EFFECT_GLOW | FGR_EFFECT_SHADOWS,
    FGR_MARCH(256u, 5.5f, 1.0f, 12u, 1.0f), "brute");

FGR_PLUGIN_EXPORT const fgr_scene_desc* fgr_scene_entry(void) { return &scene; }
