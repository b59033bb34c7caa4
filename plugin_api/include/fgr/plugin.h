// SPDX-License-Identifier: Apache-2.0
/*
 * fgr scene plugin ABI, version 1 (minor 5: see FGR_ABI_VERSION_MINOR and plugin_api/ABI.md).
 *
 * A scene plugin is a shared library that exports exactly one symbol, FGR_SCENE_ENTRY_SYMBOL
 * ("fgr_scene_entry"), a function returning a pointer to a constant fgr_scene_desc. Everything the
 * host learns about the scene (its OpenCL C source, parameters, cameras, camera paths, lights,
 * effects and march settings) is reached through that one description.
 *
 * Versioning rules (see plugin_api/ABI.md for the full text):
 *   - Every struct starts with fgr_struct_header: its size as compiled into the plugin and the ABI
 *     version the plugin was built against. Use FGR_HEADER(type) to fill it in.
 *   - Fields are only ever appended. The host reads a field only when struct_size covers it, so a
 *     plugin built against an older minor version keeps working.
 *   - The major version changes only when compatibility breaks; the host refuses a plugin whose
 *     major version differs from its own.
 *
 * Arrays of structs (params, cameras, ...) are read with the first element's struct_size as the
 * stride; every element of one array carries the same header.
 *
 * A scene is either given by its OpenCL `source` (which defines scene_de, or only an inside test,
 * scene_inside: see fgr_scene_desc) or, from ABI 1.3, an iterated function system: a list of
 * contractive affine maps (fgr_ifs_map) that the host ray traces exactly, as it does IFS scene
 * files (*.ifs.json). See fgr_scene_desc::ifs_maps.
 *
 * Ownership: every pointer in these structs is owned by the plugin and must stay valid and
 * unchanged from the moment fgr_scene_entry returns until the host unloads the library. The host
 * copies everything it keeps while validating the description, so it never writes through these
 * pointers and never frees them. All strings are NUL-terminated UTF-8, except that the scene's
 * `source` may instead be given a length (fgr_scene_desc::source_length, ABI 1.1).
 *
 * This header is C11 and compiles unchanged as C++.
 */
#ifndef FGR_PLUGIN_H
#define FGR_PLUGIN_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define FGR_ABI_VERSION_MAJOR 1u
#define FGR_ABI_VERSION_MINOR 5u
/* Packed as (major << 16) | minor. */
#define FGR_ABI_VERSION ((FGR_ABI_VERSION_MAJOR << 16) | FGR_ABI_VERSION_MINOR)
#define FGR_ABI_MAJOR(version) ((uint32_t)(version) >> 16)
#define FGR_ABI_MINOR(version) ((uint32_t)(version)&0xffffu)

/* The one symbol a plugin exports. */
#define FGR_SCENE_ENTRY_SYMBOL "fgr_scene_entry"

#if defined(_WIN32)
#define FGR_PLUGIN_EXPORT __declspec(dllexport)
#else
#define FGR_PLUGIN_EXPORT __attribute__((visibility("default")))
#endif

/* Leads every struct that crosses the boundary. */
typedef struct fgr_struct_header {
    uint32_t struct_size; /* sizeof the struct as the plugin compiled it */
    uint32_t abi_version; /* FGR_ABI_VERSION the plugin was compiled against */
} fgr_struct_header;

#define FGR_HEADER(type) \
    { (uint32_t)sizeof(type), FGR_ABI_VERSION }

/* ---------------------------------------------------------------------------------------------
 * Parameters. Each becomes a value in the parameter buffer the kernel reads, so changing a value
 * never recompiles the kernel. In the scene's OpenCL source a parameter with id "power" is read
 * as param_power (float, int, bool, or vec3 for vec3 and colour).
 */
typedef enum fgr_param_type {
    FGR_PARAM_FLOAT = 0,
    FGR_PARAM_INT = 1,  /* integral values; with `choices` an enumeration */
    FGR_PARAM_BOOL = 2, /* min 0, max 1 */
    FGR_PARAM_VEC3 = 3,
    FGR_PARAM_COLOUR = 4 /* linear RGB, components in [min, max] */
} fgr_param_type;

typedef struct fgr_param_desc {
    fgr_struct_header header;
    const char* id;          /* stable, [a-z][a-z0-9_]*, at most 63 chars; unique in the scene */
    const char* label;       /* shown in UIs; NULL means "same as id" */
    const char* group;       /* UI grouping, e.g. "Fractal"; NULL means "Scene" */
    uint32_t type;           /* an fgr_param_type */
    float min_value;         /* inclusive; applies to every component of vec3 and colour */
    float max_value;         /* inclusive; min_value <= max_value */
    float default_value[3];  /* [0] for scalars; all three for vec3 and colour */
    const char* choices;     /* FGR_PARAM_INT only, may be NULL: names of the values min..max
                                separated by '|', e.g. "colatitude|latitude" for 0..1 */
    const char* description; /* one line, may be NULL */
} fgr_param_desc;

/* ---------------------------------------------------------------------------------------------
 * Cameras. The first camera in fgr_scene_desc::cameras is the scene's default view.
 * Field of view is horizontal, in degrees, in (0, 180).
 */
typedef struct fgr_camera {
    fgr_struct_header header;
    const char* name; /* unique among the scene's cameras, [a-z0-9_-]+ */
    float position[3];
    float target[3];
    float up[3];
    float fov_degrees;
} fgr_camera;

typedef struct fgr_keyframe {
    fgr_struct_header header;
    float time; /* seconds from the start of the path; strictly increasing along a path */
    float position[3];
    float target[3];
    float up[3];
    float fov_degrees;
} fgr_keyframe;

typedef struct fgr_camera_path {
    fgr_struct_header header;
    const char* name;              /* unique among the scene's paths, [a-z0-9_-]+ */
    const fgr_keyframe* keyframes; /* at least two */
    uint32_t keyframe_count;
} fgr_camera_path;

/* ---------------------------------------------------------------------------------------------
 * Lights.
 */
typedef enum fgr_light_type {
    FGR_LIGHT_DIRECTIONAL = 0, /* `vector` points from the scene towards the light */
    FGR_LIGHT_POINT = 1        /* `vector` is the light's position; falls off with 1/d^2 */
} fgr_light_type;

typedef struct fgr_light {
    fgr_struct_header header;
    uint32_t type; /* an fgr_light_type */
    float vector[3];
    float colour[3]; /* linear RGB, non-negative */
    float intensity; /* non-negative */

    /* ABI 1.2. Directional lights: the angular radius of the light's disc as seen from the scene,
     * in degrees (the sun's is about 0.27). 0, and every light of a plugin built against 1.0 or
     * 1.1, means a point-like (delta) light. Finite, in [0, 45]. Point lights ignore it (it must
     * still be in range). The path mode samples the disc; the shaded mode ignores it (its soft
     * shadows, FGR_EFFECT_SOFT_SHADOWS, keep their own parameter, shadow_sharpness). */
    float angular_radius_degrees;
} fgr_light;

/* ---------------------------------------------------------------------------------------------
 * Effects a scene calls for. The host compiles a kernel containing exactly the requested effects;
 * an effect not asked for leaves no code behind. Bits not listed here are reserved and rejected.
 */
typedef enum fgr_effect_flag {
    FGR_EFFECT_SHADOWS = 1u << 0,           /* hard shadows towards every light */
    FGR_EFFECT_AMBIENT_OCCLUSION = 1u << 1, /* darkening from the march's step count */
    FGR_EFFECT_SOFT_SHADOWS = 1u << 2,      /* penumbrae from near misses (replaces hard ones) */
    FGR_EFFECT_REFLECTIONS = 1u << 3,       /* mirror bounces, Fresnel-weighted */
    FGR_EFFECT_SAMPLED_OCCLUSION = 1u << 4, /* ambient occlusion from DE probes along the normal */
    FGR_EFFECT_GLOW = 1u << 5,              /* rays that miss glow by how near they passed */
    FGR_EFFECT_FOG = 1u << 6,               /* exponential distance fog */
    FGR_EFFECT_DEPTH_OF_FIELD = 1u << 7,    /* thin lens; converges over samples (--spp) */
    FGR_EFFECT_REFRACTION = 1u << 8 /* transparency: refraction through solids, absorption */
} fgr_effect_flag;
#define FGR_EFFECT_ALL_V1                                                                       \
    (FGR_EFFECT_SHADOWS | FGR_EFFECT_AMBIENT_OCCLUSION | FGR_EFFECT_SOFT_SHADOWS |              \
     FGR_EFFECT_REFLECTIONS | FGR_EFFECT_SAMPLED_OCCLUSION | FGR_EFFECT_GLOW | FGR_EFFECT_FOG | \
     FGR_EFFECT_DEPTH_OF_FIELD | FGR_EFFECT_REFRACTION)

/* How rays are marched. These are quality knobs: they reach the kernel as built-in parameters
 * (max_steps, max_distance, hit_threshold, iterations, step_factor), so changing them never
 * recompiles. */
typedef struct fgr_march_settings {
    fgr_struct_header header;
    uint32_t max_steps;     /* DE evaluations per ray at most, >= 1 */
    float max_distance;     /* rays stop beyond this distance from the camera, > 0 */
    float hit_threshold;    /* a ray hits when DE < hit_threshold * t * pixel_angle; > 0 */
    uint32_t de_iterations; /* default of the built-in `iterations` parameter, >= 1 */
    float step_factor;      /* rays advance step_factor * DE, in (0, 1] (0 means 1): below 1 for
                               DEs that are estimates rather than strict bounds (escape-time
                               fractals), so the march never steps past the surface */
} fgr_march_settings;

/* ---------------------------------------------------------------------------------------------
 * IFS maps (ABI 1.3). One contractive affine map w(x) = A x + t of an iterated function system; the
 * scene's surface is the attractor, the set the maps reproduce. The host checks each map as it
 * checks an IFS file's (sdk/README.md, "IFS scenes"): every number finite, at most 1e6 in size;
 * A contractive (largest singular value < 1) and invertible (smallest singular value above 1e-9
 * times the largest).
 */
typedef struct fgr_ifs_map {
    fgr_struct_header header;
    float matrix[12]; /* three rows [a b c t]: row r of A, then component r of t; so
                         w(x)_r = matrix[4r] x + matrix[4r+1] y + matrix[4r+2] z + matrix[4r+3] */
    float colour[3];  /* linear RGB albedo of the points this map makes, components in [0, 1] */
} fgr_ifs_map;

/* ---------------------------------------------------------------------------------------------
 * Defaults for built-in parameters (ABI 1.4). The host gives every scene the same built-in
 * parameters (the effect knobs such as ao_radius, glow_radius, fog_colour, fog_density, exposure:
 * `fgr list` shows them all); a scene may give some of them its own default. The value is in the
 * parameter's own units, as `--set` takes it, and must lie in its range. The march settings'
 * knobs (max_steps, max_distance, hit_threshold, iterations, step_factor) keep their defaults in
 * fgr_scene_desc::march and may not be given here.
 */
typedef struct fgr_builtin_default {
    fgr_struct_header header;
    const char* id; /* a built-in parameter's id, e.g. "ao_radius"; at most once per scene */
    float value[3]; /* [0] for scalars; all three for colours */
} fgr_builtin_default;

/* The orbit-trap colour modes of kernels/shading/fgr_colour.cl, as values of a scene's
 * `colour_mode` parameter (FGR_COLOUR_PARAMS in fgr/scene_helpers.h): bit i stands for value i
 * (ABI 1.4). */
typedef enum fgr_colour_mode_flag {
    FGR_COLOUR_MODE_POINT = 1u << 0,     /* distance of the orbit to the origin */
    FGR_COLOUR_MODE_PLANES = 1u << 1,    /* ... to the coordinate planes */
    FGR_COLOUR_MODE_AXES = 1u << 2,      /* ... to the coordinate axes */
    FGR_COLOUR_MODE_ITERATIONS = 1u << 3 /* iterations before escape (flat for KIFS scenes) */
} fgr_colour_mode_flag;
#define FGR_COLOUR_MODES_ALL_V1_4                                            \
    (FGR_COLOUR_MODE_POINT | FGR_COLOUR_MODE_PLANES | FGR_COLOUR_MODE_AXES | \
     FGR_COLOUR_MODE_ITERATIONS)

/* ---------------------------------------------------------------------------------------------
 * The scene. Fields after `march` were appended in later minor versions (see each one's comment):
 * the source's length (1.1), the render mode the scene asks for by default (`default_mode`, 1.2)
 * IFS maps instead of a distance estimator (`ifs_maps`, 1.3), and the scene's own defaults for
 * built-in parameters, its length scale and the colour modes it offers (1.4).
 * fgr_march_settings can therefore no longer grow: new march settings go into the scene itself.
 *
 * OpenCL source contract (see sdk/README.md): the source defines
 *     real scene_de(vec3 p, PARAMS)
 * returning a distance bound to the surface for every lane of p, or instead, for a set with no
 * known distance estimator, after `#define FGR_SCENE_INSIDE_ONLY` on a line of its own,
 *     mask scene_inside(vec3 p, PARAMS)
 * true in the lanes where p is in the set (with `#define FGR_SCENE_HAS_INSIDE`, a scene may define
 * both). This is no ABI change: the description is the same, and the host reads the directive
 * from the source. Such a scene renders only in the "brute" mode. Optionally, after
 * `#define FGR_SCENE_HAS_COLOUR`,
 *     vec3 scene_colour(vec3 p, PARAMS)
 * returning the linear albedo. `real` and `vec3` are the packet types of the kernel library.
 */
typedef struct fgr_scene_desc {
    fgr_struct_header header;
    const char* id;          /* [a-z][a-z0-9_-]*, at most 63 chars; what users type */
    const char* name;        /* display name */
    const char* description; /* one line */
    const char* source;      /* OpenCL C source of the scene, at most 4 MiB; NUL-terminated
                                unless source_length gives its length */
    const char* source_name; /* file name used in compiler messages, e.g. "mandelbulb.cl" */

    const fgr_param_desc* params; /* params[0 .. param_count), may be NULL when the count is 0 */
    uint32_t param_count;         /* at most 1024 */

    const fgr_camera* cameras; /* at least one; cameras[0] is the default view */
    uint32_t camera_count;

    const fgr_camera_path* camera_paths; /* may be NULL when the count is 0 */
    uint32_t camera_path_count;

    /* At least one light (the shaded mode is lit by them alone): a count of 0, or a count over a
     * NULL array, is refused naming the scene; scene_helpers.h's FGR_SCENE refuses an empty list,
     * NULL or a pointer at compile time ("a scene needs at least one light"). */
    const fgr_light* lights; /* at least one */
    uint32_t light_count;    /* at most 16 */

    uint64_t effects; /* OR of fgr_effect_flag */
    fgr_march_settings march;

    /* ABI 1.1. How many bytes `source` points to: the host reads no further, and the source ends
     * at the first NUL among them or after them, so it need not be NUL-terminated. At most
     * 4 MiB + 1 (a NUL-terminated 4 MiB source). 0, or a plugin built against 1.0, means that
     * `source` is NUL-terminated. FGR_SCENE (fgr/scene_helpers.h) fills it for a source array. */
    uint64_t source_length;

    /* ABI 1.2. The render mode the scene asks for when the user names none, by name: "shaded",
     * "path" or "brute" (fgr's `--mode`: every mode the host has; a host refuses a name it does not
     * know, with the choices). NULL or "", and every plugin built against 1.0 or 1.1, mean
     * "shaded". A source with FGR_SCENE_INSIDE_ONLY renders "brute" whatever this says, and
     * "path" is refused for it. */
    const char* default_mode;

    /* ABI 1.3. An IFS scene: when ifs_map_count is not 0 the scene is the attractor of these
     * maps, ray traced exactly like an IFS scene file, and has no distance estimator. Then
     * `source` must be NULL or "" (source_name and march are ignored, though march must still be
     * valid), `params` must be empty (the scene gets the depth slider `ifs_depth` and the
     * built-in parameters), `effects` may hold only FGR_EFFECT_SHADOWS, FGR_EFFECT_REFLECTIONS,
     * FGR_EFFECT_FOG and FGR_EFFECT_DEPTH_OF_FIELD (exact tracing has no distance estimate), and
     * cameras, camera paths, lights and default_mode are as for any scene. ifs_map_count 0, and
     * every plugin built against 1.0 to 1.2, mean a distance-estimated scene; the other three
     * fields are then ignored. */
    const fgr_ifs_map* ifs_maps; /* ifs_maps[0 .. ifs_map_count), at most 64 */
    uint32_t ifs_map_count;
    /* The depth slider's default and maximum: levels of maps applied at most before a node's
     * bounding ellipsoid counts as the surface. Each in [0, 24], default <= max; 0 means "not
     * given", as in an IFS file that leaves it out: the maximum is then 24, the default the
     * maximum, lowered where the maps would make it costly (docs/sdk/ifs.md). */
    uint32_t ifs_default_depth;
    uint32_t ifs_max_depth;

    /* ABI 1.4. The scene's own defaults for built-in parameters (see fgr_builtin_default), each
     * checked against the parameter's range: a bad one refuses the plugin, naming the parameter.
     * builtin_default_count 0, and every plugin built against 1.0 to 1.3, mean none. */
    const fgr_builtin_default* builtin_defaults; /* [0 .. builtin_default_count), at most 64 */
    uint32_t builtin_default_count;
    /* ABI 1.4. The values of the scene's `colour_mode` parameter it offers, an OR of
     * fgr_colour_mode_flag (bit i: value i); the others are refused (`--set colour_mode=...`) and
     * not listed. Non-zero only with a `colour_mode` enum parameter whose default it offers.
     * 0, and every older plugin, mean every value. A KIFS scene, whose points all reach the
     * last iteration, leaves out FGR_COLOUR_MODE_ITERATIONS. */
    uint32_t colour_modes;
    /* ABI 1.4. The scene's length scale: about the radius of what the default camera frames. The
     * defaults of the distance-like built-in parameters are fractions (or, for rates per unit
     * length, multiples) of it: ao_radius 0.1 scale, glow_radius 0.05 scale, aperture 0.05 scale,
     * fog_density 0.15 / scale, absorption 1 / scale (each clamped to its range). Values are
     * still in scene units. Finite, in [1e-6, 1e6]; 0, and every older plugin, mean 1, the scale
     * the built-in defaults were tuned for. A builtin_defaults entry overrides the scaled value. */
    float scale;

    /* ABI 1.5. The environment the path mode lights the scene with when the user names none (no
     * --environment): one fgr generates, named as --environment names it: "sky", "studio",
     * "uniform" (radiance 1), "uniform:V" or "uniform:R,G,B" (finite, non-negative radiances). At
     * most 63 bytes; a map file is refused (that stays the user's --environment FILE). NULL or "",
     * and every plugin built against 1.0 to 1.4, mean "sky". In the path mode the scene's lights
     * shine besides it, under whichever environment, except that the sky's sun takes the place of
     * the first directional light; the user's --no-scene-lights leaves the environment alone.
     * The shaded mode ignores it. A 1.4 host ignores it and lights the path mode with the sky. */
    const char* environment;
} fgr_scene_desc;

/* The entry point. Must return the same pointer every call, or NULL on failure. */
typedef const fgr_scene_desc* (*fgr_scene_entry_fn)(void);

#ifdef __cplusplus
}
#endif

#endif /* FGR_PLUGIN_H */
