// SPDX-License-Identifier: Apache-2.0
/* The menger-room scene plugin: a Menger sponge in a closed room lit by a lamp under the ceiling,
 * path traced by default (most of its light arrives after several bounces). The DE and the
 * materials are in menger_room.cl. */
#include <stddef.h>

#include "fgr/scene_helpers.h"
#include "menger_room_cl.h" /* menger_room_cl: the OpenCL source, embedded at build time */

static const fgr_param_desc params[] = {
    FGR_FLOAT_PARAM("sponge_size", "Sponge size", "Sponge", 0.3f, 1.5f, 0.75f,
                    "half the side of the sponge, which stands on the floor (the room is 5 wide)"),
    FGR_COLOUR_PARAM("sponge_colour", "Sponge colour", "Materials", 0.8f, 0.8f, 0.78f,
                     "the sponge's diffuse albedo"),
    FGR_COLOUR_PARAM("wall_colour", "Wall colour", "Materials", 0.75f, 0.75f, 0.73f,
                     "diffuse albedo of the floor, the ceiling and the front and back walls"),
    FGR_COLOUR_PARAM("left_colour", "Left wall colour", "Materials", 0.7f, 0.18f, 0.14f,
                     "diffuse albedo of the wall at -x"),
    FGR_COLOUR_PARAM("right_colour", "Right wall colour", "Materials", 0.16f, 0.55f, 0.2f,
                     "diffuse albedo of the wall at +x"),
    FGR_FLOAT_PARAM("lamp", "Lamp panel radiance", "Light", 0.0f, 50.0f, 0.0f,
                    "radiance of the square panel in the ceiling (0: dark; the point light "
                    "below it lights the room)"),
};

/* Inside the room, from near the front wall, looking at the sponge slightly from above. */
static const fgr_camera cameras[] = {
    FGR_CAMERA_Z_UP("inside", 1.0f, -2.4f, 1.1f, 0.0f, 0.0f, -0.3f, 70.0f),
    FGR_CAMERA_Z_UP("corner", -2.2f, -2.2f, 1.8f, 0.0f, 0.0f, -0.2f, 60.0f),
};

static const fgr_keyframe orbit_keys[] = {
    FGR_KEYFRAME_Z_UP(0.0f, 0.9f, -2.35f, 0.9f, 0.0f, 0.0f, -0.15f, 62.0f),
    FGR_KEYFRAME_Z_UP(4.0f, 2.2f, 0.9f, 0.9f, 0.0f, 0.0f, -0.15f, 62.0f),
    FGR_KEYFRAME_Z_UP(8.0f, -0.9f, 2.2f, 0.9f, 0.0f, 0.0f, -0.15f, 62.0f),
};

static const fgr_camera_path paths[] = {
    FGR_CAMERA_PATH("orbit", orbit_keys),
};

/* The lamp: a point light hanging 0.8 below the ceiling panel (nearer, the ceiling above it would
 * take a bright spot that every path bouncing off it carries as a firefly). */
static const fgr_light lights[] = {
    FGR_POINT_LIGHT(0.0f, 0.0f, 1.4f, 1.0f, 0.93f, 0.8f, 1.2f),
};

static const fgr_scene_desc scene = FGR_SCENE_WITH_ENVIRONMENT(
    "menger-room", "Menger room",
    "a Menger sponge in a closed room lit by a lamp: light that bounces, path traced",
    menger_room_cl, "menger_room.cl", params, cameras, paths, lights,
    FGR_EFFECT_AMBIENT_OCCLUSION | FGR_EFFECT_SHADOWS,
    /* Level-4 cubes are a few pixels wide at 640 pixels; the room is at most 7.6 across, and
     * both DEs are strict bounds (full steps). */
    FGR_MARCH(256u, 12.0f, 1.0f, 4u, 1.0f), "path", NULL, 0, 0, 0.0f,
    /* Nothing outside the room reaches in: a black environment, so the light sampler spends
     * every sample on the lamp. */
    "uniform:0");

FGR_PLUGIN_EXPORT const fgr_scene_desc* fgr_scene_entry(void) { return &scene; }
