/* @SCENE_NAME@ (@SCENE_ID@): the scene's description. Its distance estimator and colour are in
 * @SCENE_SYMBOL@.cl. Every field is explained in fgr's SDK guide (share/fgr/sdk/README.md). */
#include "fgr/scene_helpers.h"
#include "@SCENE_SYMBOL@_cl.h" /* @SCENE_SYMBOL@_cl: the OpenCL source, embedded at build time */

/* Each parameter is readable in the .cl file as param_<id>; users change them with
 * `fgr render --set id=value` or in the viewer's panel, without recompiling. */
static const fgr_param_desc params[] = {
    FGR_FLOAT_PARAM("radius", "Radius", "Shape", 0.25f, 1.5f, 1.0f, "radius of the ball"),
    FGR_FLOAT_PARAM("bumps", "Bump height", "Shape", 0.0f, 0.25f, 0.08f,
                    "height of the sine bumps on the ball"),
    FGR_FLOAT_PARAM("frequency", "Bump frequency", "Shape", 1.0f, 24.0f, 9.0f,
                    "bumps per radian along each axis"),
    FGR_COLOUR_PARAM("tint", "Tint", "Colour", 0.95f, 0.55f, 0.25f, "colour of the bumps' tops"),
};

/* The first camera is the default view. Z is up; the field of view is horizontal, in degrees. */
static const fgr_camera cameras[] = {
    FGR_CAMERA_Z_UP("front", 0.0f, -3.6f, 1.4f, 0.0f, 0.0f, 0.0f, 50.0f),
    FGR_CAMERA_Z_UP("close", 0.6f, -1.5f, 0.9f, 0.0f, 0.0f, 0.2f, 50.0f),
};

/* A camera path: keyframe times in seconds, interpolated with Catmull-Rom. */
static const fgr_keyframe orbit_keys[] = {
    FGR_KEYFRAME_Z_UP(0.0f, 0.0f, -3.6f, 1.4f, 0.0f, 0.0f, 0.0f, 50.0f),
    FGR_KEYFRAME_Z_UP(2.0f, 3.6f, 0.0f, 1.4f, 0.0f, 0.0f, 0.0f, 50.0f),
    FGR_KEYFRAME_Z_UP(4.0f, 0.0f, 3.6f, 1.4f, 0.0f, 0.0f, 0.0f, 50.0f),
    FGR_KEYFRAME_Z_UP(6.0f, -3.6f, 0.0f, 1.4f, 0.0f, 0.0f, 0.0f, 50.0f),
    FGR_KEYFRAME_Z_UP(8.0f, 0.0f, -3.6f, 1.4f, 0.0f, 0.0f, 0.0f, 50.0f),
};

static const fgr_camera_path paths[] = {
    FGR_CAMERA_PATH("orbit", orbit_keys),
};

/* Directional lights point towards the light; colour, then intensity. For a light with a disc
 * (soft shadows in the path mode; the shaded mode treats it as point-like), use
 * FGR_DIRECTIONAL_DISC_LIGHT(..., angular_radius_degrees): the sun's is about 0.27. */
static const fgr_light lights[] = {
    FGR_DIRECTIONAL_LIGHT(0.6f, -0.5f, 0.8f, 1.0f, 0.95f, 0.85f, 1.1f),
    FGR_DIRECTIONAL_LIGHT(-0.7f, 0.4f, 0.2f, 0.4f, 0.5f, 0.8f, 0.35f),
};

/* FGR_SCENE asks for no render mode (default_mode NULL): fgr renders shaded unless the user
 * names a mode. FGR_SCENE_WITH_MODE(..., "path") makes the path tracer the scene's default. */
static const fgr_scene_desc scene = FGR_SCENE(
    "@SCENE_ID@", "@SCENE_NAME@", "a bumpy ball: the scene fgr new-scene starts from",
    @SCENE_SYMBOL@_cl, @SCENE_SYMBOL@_cl_path, params, cameras, paths, lights,
    FGR_EFFECT_SHADOWS | FGR_EFFECT_AMBIENT_OCCLUSION,
    /* max steps, max distance, hit threshold (pixels), DE iterations, step factor */
    FGR_MARCH(160u, 12.0f, 1.0f, 8u, 1.0f));

FGR_PLUGIN_EXPORT const fgr_scene_desc* fgr_scene_entry(void) { return &scene; }
