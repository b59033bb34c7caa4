// SPDX-License-Identifier: Apache-2.0
/*
 * A scene description written with fgr/scene_helpers.h, compiled as C11 and as C++ by the
 * SceneHelpers* ctest tests (tests/CMakeLists.txt, compile_check.cmake). As written it compiles;
 * each switch gives FGR_SCENE a light list a scene cannot have, which must fail to compile with
 * "a scene needs at least one light":
 *   LIGHTS_EMPTY    an empty array (GNU C accepts it and would count 0)
 *   LIGHTS_NULL     NULL (GNU C would count sizeof(NULL) / sizeof(void), 8 lights at NULL)
 *   LIGHTS_POINTER  a pointer to a light array (its size says nothing of a count)
 */
#include "fgr/scene_helpers.h"

static const fgr_param_desc params[] = {
    FGR_FLOAT_PARAM("radius", "Radius", "Shape", 0.25f, 1.5f, 1.0f, "sphere radius"),
};
static const fgr_camera cameras[] = {
    FGR_CAMERA_Z_UP("front", 0.0f, -4.0f, 0.0f, 0.0f, 0.0f, 0.0f, 60.0f),
};
static const fgr_keyframe keys[] = {
    FGR_KEYFRAME_Z_UP(0.0f, 0.0f, -4.0f, 0.0f, 0.0f, 0.0f, 0.0f, 60.0f),
    FGR_KEYFRAME_Z_UP(1.0f, 4.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 60.0f),
};
static const fgr_camera_path paths[] = {FGR_CAMERA_PATH("orbit", keys)};
static const fgr_light one_light[] = {
    FGR_DIRECTIONAL_LIGHT(1.0f, -1.0f, 1.0f, 1.0f, 1.0f, 1.0f, 1.0f),
};

#if defined(LIGHTS_EMPTY)
static const fgr_light no_lights[] = {};
#define SCENE_LIGHTS no_lights
#elif defined(LIGHTS_NULL)
#define SCENE_LIGHTS NULL
#elif defined(LIGHTS_POINTER)
static const fgr_light* const light_pointer = one_light;
#define SCENE_LIGHTS light_pointer
#else
#define SCENE_LIGHTS one_light
#endif

static const char source[] =
    "real scene_de(vec3 p, PARAMS) { return v3_length(p) - param_radius; }\n";

static const fgr_scene_desc scene =
    FGR_SCENE("lights-check", "Lights check", "one light or a compile error", source, "lights.cl",
              params, cameras, paths, SCENE_LIGHTS, 0, FGR_MARCH(64u, 10.0f, 1.0f, 8u, 1.0f));

const fgr_scene_desc* lights_check_scene(void);
const fgr_scene_desc* lights_check_scene(void) { return &scene; }
