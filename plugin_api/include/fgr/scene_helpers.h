// SPDX-License-Identifier: Apache-2.0
/*
 * Conveniences for writing scene descriptions in C: initialisers for the common structs. Not part
 * of the ABI contract itself (they only expand to fgr/plugin.h initialisers); C11 and C++.
 */
#ifndef FGR_SCENE_HELPERS_H
#define FGR_SCENE_HELPERS_H

#include <stddef.h>

#include "fgr/plugin.h"

/* A float parameter. */
#define FGR_FLOAT_PARAM(id, label, group, min, max, value, description)          \
    {                                                                            \
        FGR_HEADER(fgr_param_desc), id, label, group, FGR_PARAM_FLOAT, min, max, \
            {value, 0.0f, 0.0f}, NULL, description                               \
    }

/* An integer parameter. */
#define FGR_INT_PARAM(id, label, group, min, max, value, description)                            \
    {                                                                                            \
        FGR_HEADER(fgr_param_desc), id, label, group, FGR_PARAM_INT, (float)(min), (float)(max), \
            {(float)(value), 0.0f, 0.0f}, NULL, description                                      \
    }

/* An enumeration: an int parameter 0 .. n-1 whose values are named by "a|b|c". */
#define FGR_ENUM_PARAM(id, label, group, count, value, choices, description)                   \
    {                                                                                          \
        FGR_HEADER(fgr_param_desc), id, label, group, FGR_PARAM_INT, 0.0f, (float)((count)-1), \
            {(float)(value), 0.0f, 0.0f}, choices, description                                 \
    }

/* A vec3 parameter, every component in [min, max]. */
#define FGR_VEC3_PARAM(id, label, group, min, max, x, y, z, description)                         \
    {                                                                                            \
        FGR_HEADER(fgr_param_desc), id, label, group, FGR_PARAM_VEC3, min, max, {x, y, z}, NULL, \
            description                                                                          \
    }

/* A linear RGB colour with components in [0, 1]. */
#define FGR_COLOUR_PARAM(id, label, group, r, g, b, description)                               \
    {                                                                                          \
        FGR_HEADER(fgr_param_desc), id, label, group, FGR_PARAM_COLOUR, 0.0f, 1.0f, {r, g, b}, \
            NULL, description                                                                  \
    }

/* The three colouring parameters kernels/shading/fgr_colour.cl's trap_colour() reads:
 * colour_mode (which orbit trap), palette (which ramp) and base_colour (the scene's tint). */
#define FGR_COLOUR_PARAMS(mode, palette, r, g, b)                                                 \
    FGR_ENUM_PARAM("colour_mode", "Colour by", "Colour", 4, mode, "point|planes|axes|iterations", \
                   "orbit trap that drives the palette"),                                         \
        FGR_ENUM_PARAM("palette", "Palette", "Colour", 5, palette,                                \
                       "ember|ocean|forest|pastel|mono", "colour ramp"),                          \
    {                                                                                             \
        FGR_HEADER(fgr_param_desc), "base_colour", "Base colour", "Colour", FGR_PARAM_COLOUR,     \
            0.0f, 1.0f, {r, g, b}, NULL, "tint multiplying the palette"                           \
    }

/* The colour modes of a KIFS scene (ABI 1.4 colour_modes): all but "iterations", which is one
 * flat colour when every point reaches the last iteration. */
#define FGR_COLOUR_MODES_NO_ITERATIONS \
    (FGR_COLOUR_MODE_POINT | FGR_COLOUR_MODE_PLANES | FGR_COLOUR_MODE_AXES)

/* A camera looking from (px, py, pz) at (tx, ty, tz) with +z up; fov is horizontal, degrees. */
#define FGR_CAMERA_Z_UP(name, px, py, pz, tx, ty, tz, fov) \
    { FGR_HEADER(fgr_camera), name, {px, py, pz}, {tx, ty, tz}, {0.0f, 0.0f, 1.0f}, fov }

/* A keyframe at `time` seconds, +z up. */
#define FGR_KEYFRAME_Z_UP(time, px, py, pz, tx, ty, tz, fov) \
    { FGR_HEADER(fgr_keyframe), time, {px, py, pz}, {tx, ty, tz}, {0.0f, 0.0f, 1.0f}, fov }

/* A camera path over a static array of keyframes. */
#define FGR_CAMERA_PATH(name, keys) \
    { FGR_HEADER(fgr_camera_path), name, keys, (uint32_t)(sizeof(keys) / sizeof((keys)[0])) }

/* A directional light from (x, y, z), point-like (angular radius 0). */
#define FGR_DIRECTIONAL_LIGHT(x, y, z, r, g, b, intensity) \
    { FGR_HEADER(fgr_light), FGR_LIGHT_DIRECTIONAL, {x, y, z}, {r, g, b}, intensity, 0.0f }

/* A directional light whose disc has the given angular radius in degrees, in [0, 45] (the sun's
 * is about 0.27): the path mode samples the disc, the shaded mode treats it as point-like. */
#define FGR_DIRECTIONAL_DISC_LIGHT(x, y, z, r, g, b, intensity, angular_radius_degrees) \
    {                                                                                   \
        FGR_HEADER(fgr_light), FGR_LIGHT_DIRECTIONAL, {x, y, z}, {r, g, b}, intensity,  \
            angular_radius_degrees                                                      \
    }

#define FGR_POINT_LIGHT(x, y, z, r, g, b, intensity) \
    { FGR_HEADER(fgr_light), FGR_LIGHT_POINT, {x, y, z}, {r, g, b}, intensity, 0.0f }

#define FGR_COUNT(array) ((uint32_t)(sizeof(array) / sizeof((array)[0])))

/* The light count of FGR_SCENE, FGR_SCENE_WITH_MODE and FGR_IFS_SCENE: a scene needs at least one
 * light, so an empty list, NULL or a pointer (whose size says nothing of a count) fails to compile
 * with that message instead of a puzzling count (GNU C counts NULL as 8 "lights" of sizeof(void)).
 * Dividing by sizeof(fgr_light), not by the first element's size, is what makes NULL and pointers
 * count 0 here. */
#ifdef __cplusplus
template <size_t Bytes>
constexpr uint32_t fgr_light_count_of_size() {
    static_assert(Bytes / sizeof(fgr_light) > 0,
                  "a scene needs at least one light: pass a non-empty static array of fgr_light "
                  "(not NULL, not a pointer) as FGR_SCENE's lights");
    return (uint32_t)(Bytes / sizeof(fgr_light));
}
#define FGR_LIGHT_COUNT(lights) fgr_light_count_of_size<sizeof(lights)>()
#else
#define FGR_LIGHT_COUNT(lights)                                                               \
    ((uint32_t)(sizeof(lights) / sizeof(fgr_light)) +                                         \
     0u * (uint32_t)sizeof(struct {                                                           \
         _Static_assert(sizeof(lights) / sizeof(fgr_light) > 0,                               \
                        "a scene needs at least one light: pass a non-empty static array of " \
                        "fgr_light (not NULL, not a pointer) as FGR_SCENE's lights");         \
         int fgr_unused;                                                                      \
     }))
#endif

/* March settings: at most `steps` DE evaluations per ray, rays stop beyond `distance`, hit when
 * DE < threshold * pixel footprint, `iterations` DE iterations by default, rays advance
 * step_factor * DE (1 for strict bounds, below 1 for estimated DEs). */
#define FGR_MARCH(steps, distance, threshold, iterations, step_factor) \
    { FGR_HEADER(fgr_march_settings), steps, distance, threshold, iterations, step_factor }

/* fgr_scene_desc::source_length for `source`: the size of a char array (its NUL included: the
 * source ends there), 0 ("NUL-terminated") for a pointer, whose size says nothing. */
#ifdef __cplusplus
template <typename T>
constexpr uint64_t fgr_source_length(const T&) {
    return 0;
}
template <size_t N>
constexpr uint64_t fgr_source_length(const char (&)[N]) {
    return N;
}
#define FGR_SOURCE_LENGTH(source) fgr_source_length(source)
#else
#define FGR_SOURCE_LENGTH(source)                                \
    _Generic(&(source), const char(*)[sizeof(source)]            \
             : (uint64_t)sizeof(source), char(*)[sizeof(source)] \
             : (uint64_t)sizeof(source), default                 \
             : (uint64_t)0)
#endif

/* A whole scene description from static arrays of params, cameras, camera paths and lights. It
 * asks for no render mode (default_mode NULL: fgr renders it shaded unless told otherwise, or in
 * the brute mode if its source is inside-only, see FGR_SCENE_INSIDE_ONLY in fgr's SDK guide). */
#define FGR_SCENE(id, name, description, source, source_name, params, cameras, paths, lights,     \
                  effects, march)                                                                 \
    {                                                                                             \
        FGR_HEADER(fgr_scene_desc), id, name, description, source, source_name, params,           \
            FGR_COUNT(params), cameras, FGR_COUNT(cameras), paths, FGR_COUNT(paths), lights,      \
            FGR_LIGHT_COUNT(lights), effects, march, FGR_SOURCE_LENGTH(source), NULL, NULL, 0, 0, \
            0, NULL, 0, 0, 0.0f, NULL                                                             \
    }

/* The same, asking for a render mode by default: "shaded", "path" or "brute" (ABI 1.2: any mode
 * the host has; an inside-only source renders brute whatever it asks, "path" is refused). (Not
 * written with FGR_SCENE's help: `march` is usually FGR_MARCH(...), whose commas would split the
 * arguments of a macro it is passed on to.) */
#define FGR_SCENE_WITH_MODE(id, name, description, source, source_name, params, cameras, paths, \
                            lights, effects, march, default_mode)                               \
    {                                                                                           \
        FGR_HEADER(fgr_scene_desc), id, name, description, source, source_name, params,         \
            FGR_COUNT(params), cameras, FGR_COUNT(cameras), paths, FGR_COUNT(paths), lights,    \
            FGR_LIGHT_COUNT(lights), effects, march, FGR_SOURCE_LENGTH(source), default_mode,   \
            NULL, 0, 0, 0, NULL, 0, 0, 0.0f, NULL                                               \
    }

/* A built-in parameter's own default in this scene (ABI 1.4), e.g.
 * FGR_BUILTIN_DEFAULT("ao_radius", 0.002f): in the parameter's units and range. */
#define FGR_BUILTIN_DEFAULT(id, value)                             \
    {                                                              \
        FGR_HEADER(fgr_builtin_default), id, { value, 0.0f, 0.0f } \
    }

/* The same for a colour built-in, e.g.
 * FGR_BUILTIN_COLOUR_DEFAULT("fog_colour", 0.8f, 0.8f, 0.9f). */
#define FGR_BUILTIN_COLOUR_DEFAULT(id, r, g, b)          \
    {                                                    \
        FGR_HEADER(fgr_builtin_default), id, { r, g, b } \
    }

/* A scene tuned beyond fgr's defaults (ABI 1.4): FGR_SCENE_WITH_MODE's fields (default_mode may
 * be NULL), then the scene's defaults for built-in parameters as a pointer and a count (an array
 * of FGR_BUILTIN_DEFAULT and FGR_COUNT(array), or NULL and 0), the colour modes it offers (an OR
 * of FGR_COLOUR_MODE_*, 0 for all) and its length scale (0 for 1; see fgr_scene_desc::scale). */
#define FGR_SCENE_TUNED(id, name, description, source, source_name, params, cameras, paths,   \
                        lights, effects, march, default_mode, builtin_defaults,               \
                        builtin_default_count, colour_modes, scale)                           \
    {                                                                                         \
        FGR_HEADER(fgr_scene_desc), id, name, description, source, source_name, params,       \
            FGR_COUNT(params), cameras, FGR_COUNT(cameras), paths, FGR_COUNT(paths), lights,  \
            FGR_LIGHT_COUNT(lights), effects, march, FGR_SOURCE_LENGTH(source), default_mode, \
            NULL, 0, 0, 0, builtin_defaults, builtin_default_count, colour_modes, scale, NULL \
    }

/* An IFS map x -> scale x + (tx, ty, tz): a uniform scaling towards a point (ABI 1.3). */
#define FGR_IFS_SCALE_MAP(scale, tx, ty, tz, r, g, b)                                \
    {                                                                                \
        FGR_HEADER(fgr_ifs_map),                                                     \
            {scale, 0.0f, 0.0f, tx, 0.0f, scale, 0.0f, ty, 0.0f, 0.0f, scale, tz}, { \
            r, g, b                                                                  \
        }                                                                            \
    }

/* A whole IFS scene description (ABI 1.3): no source and no parameters of its own, the maps of a
 * static array, the depth slider's default and maximum (0: fgr's defaults, as in an IFS file). */
#define FGR_IFS_SCENE(id, name, description, maps, default_depth, max_depth, cameras, paths,       \
                      lights, effects)                                                             \
    {                                                                                              \
        FGR_HEADER(fgr_scene_desc), id, name, description, NULL, NULL, NULL, 0, cameras,           \
            FGR_COUNT(cameras), paths, FGR_COUNT(paths), lights, FGR_LIGHT_COUNT(lights), effects, \
            FGR_MARCH(1u, 100.0f, 1.0f, 1u, 1.0f), 0, NULL, maps, FGR_COUNT(maps), default_depth,  \
            max_depth, NULL, 0, 0, 0.0f, NULL                                                      \
    }

/* A scene with an environment of its own for the path mode (ABI 1.5): FGR_SCENE_TUNED's fields
 * (NULL, 0, 0 and 0.0f for fgr's defaults), then the environment as --environment names a
 * generated one: "sky", "studio", "uniform", "uniform:V" or "uniform:R,G,B" (NULL for the sky). Its
 * lights still shine besides it; see fgr_scene_desc::environment. */
#define FGR_SCENE_WITH_ENVIRONMENT(id, name, description, source, source_name, params, cameras,   \
                                   paths, lights, effects, march, default_mode, builtin_defaults, \
                                   builtin_default_count, colour_modes, scale, environment)       \
    {                                                                                             \
        FGR_HEADER(fgr_scene_desc), id, name, description, source, source_name, params,           \
            FGR_COUNT(params), cameras, FGR_COUNT(cameras), paths, FGR_COUNT(paths), lights,      \
            FGR_LIGHT_COUNT(lights), effects, march, FGR_SOURCE_LENGTH(source), default_mode,     \
            NULL, 0, 0, 0, builtin_defaults, builtin_default_count, colour_modes, scale,          \
            environment                                                                           \
    }

#endif /* FGR_SCENE_HELPERS_H */
