// SPDX-License-Identifier: Apache-2.0
/* fgr kernel library: colouring by orbit traps.
 *
 * While a fractal iterates z, an orbit trap keeps the closest the orbit came to some shape. The
 * trap value, mapped through a palette, colours the surface: fractal detail gets colour that
 * follows its structure. A scene's scene_colour re-runs its iteration with a trap and ends with
 *
 *     return trap_colour(trap, param_colour_mode, param_palette, param_base_colour);
 *
 * (from kernel API 4, where a colour parameter is a float3: v3_uniform(param_base_colour)),
 * or, for a fractal whose `iterate(vec3 p, PARAMS, int record, orbit_trap* trap)` returns the DE
 * and records the orbit when asked, both scene functions at once:
 *
 *     #define FGR_SCENE_HAS_COLOUR
 *     FGR_TRAP_COLOURED_SCENE(iterate)
 *
 * declaring the parameters with FGR_COLOUR_PARAMS (see docs/sdk/describing.md):
 *   colour_mode  point|planes|axes|iterations  which trap drives the palette
 *   palette      one of FGR_PALETTE_NAMES        the colour ramp
 *   base_colour  colour                          multiplies the palette (the scene's own tint)
 */

#define FGR_TRAP_POINT 0
#define FGR_TRAP_PLANES 1
#define FGR_TRAP_AXES 2
#define FGR_TRAP_ITERATIONS 3

typedef struct orbit_trap {
    real point;  /* min |z|: distance to the origin */
    real planes; /* min over the orbit of min(|x|, |y|, |z|): distance to the coordinate planes */
    real axes;   /* min distance to the x, y and z axes */
    real iterations; /* iterations the lane took (the escape-time colouring) */
} orbit_trap;

inline orbit_trap trap_init(void) {
    orbit_trap trap;
    trap.point = fgr_real(1e20f);
    trap.planes = fgr_real(1e20f);
    trap.axes = fgr_real(1e20f);
    trap.iterations = fgr_real(0.0f);
    return trap;
}

/* Records orbit point z for the lanes in `active`. */
inline orbit_trap trap_update(orbit_trap trap, vec3 z, mask active) {
    vec3 a = v3_abs(z);
    real to_point = v3_length(z);
    real to_planes = fmin(a.x, fmin(a.y, a.z));
    real to_axes =
        sqrt(fmin(z.y * z.y + z.z * z.z, fmin(z.x * z.x + z.z * z.z, z.x * z.x + z.y * z.y)));
    trap.point = select(trap.point, fmin(trap.point, to_point), active);
    trap.planes = select(trap.planes, fmin(trap.planes, to_planes), active);
    trap.axes = select(trap.axes, fmin(trap.axes, to_axes), active);
    trap.iterations = select(trap.iterations, trap.iterations + 1.0f, active);
    return trap;
}

/* Cosine palettes (Inigo Quilez): colour(t) = a + b cos(2 pi (c t + d)), smooth and periodic. */
#define FGR_PALETTE_COUNT 5
/* For plugin authors: the names of the palettes in order, for an enum parameter's choices. */
#define FGR_PALETTE_NAMES "ember|ocean|forest|pastel|mono"

inline vec3 palette(real t, int index) {
    float3 a = (float3)(0.5f, 0.5f, 0.5f), b = (float3)(0.5f, 0.5f, 0.5f);
    float3 c = (float3)(1.0f, 1.0f, 1.0f), d = (float3)(0.0f, 0.10f, 0.20f);
    switch (index) {
        case 0: /* ember: deep reds to gold */
            a = (float3)(0.55f, 0.35f, 0.25f);
            b = (float3)(0.45f, 0.35f, 0.25f);
            c = (float3)(1.0f, 1.0f, 1.0f);
            d = (float3)(0.0f, 0.08f, 0.18f);
            break;
        case 1: /* ocean: teal to ivory */
            a = (float3)(0.35f, 0.50f, 0.60f);
            b = (float3)(0.30f, 0.30f, 0.30f);
            c = (float3)(1.0f, 1.0f, 1.0f);
            d = (float3)(0.55f, 0.45f, 0.35f);
            break;
        case 2: /* forest: moss to sand */
            a = (float3)(0.45f, 0.50f, 0.35f);
            b = (float3)(0.30f, 0.30f, 0.25f);
            c = (float3)(1.0f, 1.0f, 1.0f);
            d = (float3)(0.10f, 0.20f, 0.30f);
            break;
        case 3: /* pastel: the full hue circle, soft */
            a = (float3)(0.65f, 0.65f, 0.65f);
            b = (float3)(0.30f, 0.30f, 0.30f);
            c = (float3)(1.0f, 1.0f, 1.0f);
            d = (float3)(0.0f, 0.33f, 0.67f);
            break;
        default: /* mono: greys */
            a = (float3)(0.6f, 0.6f, 0.6f);
            b = (float3)(0.3f, 0.3f, 0.3f);
            c = (float3)(1.0f, 1.0f, 1.0f);
            d = (float3)(0.0f, 0.0f, 0.0f);
            break;
    }
    const float two_pi = 6.28318531f;
    return v3(a.x + b.x * fgr_cos(two_pi * (c.x * t + d.x)),
              a.y + b.y * fgr_cos(two_pi * (c.y * t + d.y)),
              a.z + b.z * fgr_cos(two_pi * (c.z * t + d.z)));
}

/* The trap chosen by `mode`, squashed to a palette coordinate, times the base colour. */
inline vec3 trap_colour(orbit_trap trap, int mode, int palette_index, vec3 base) {
    real t;
    switch (mode) {
        case FGR_TRAP_POINT:
            t = 1.6f * trap.point;
            break;
        case FGR_TRAP_PLANES:
            t = 3.0f * sqrt(fmax(trap.planes, 0.0f));
            break;
        case FGR_TRAP_AXES:
            t = 2.5f * sqrt(fmax(trap.axes, 0.0f));
            break;
        default:
            t = 0.08f * trap.iterations;
            break;
    }
    vec3 ramp = palette(t, palette_index);
    return v3_mul(v3_max(ramp, v3_splat(0.0f, 0.0f, 0.0f)), base);
}

/* scene_colour from the orbit trap `iterate` records, for the (few) points being shaded. */
#define FGR_TRAP_COLOUR_FUNCTION(iterate)                          \
    vec3 scene_colour(vec3 p, PARAMS) {                            \
        orbit_trap trap = trap_init();                             \
        iterate(p, PARAMS_PASS, 1, &trap);                         \
        return trap_colour(trap, param_colour_mode, param_palette, \
                           fgr_param_lanes(param_base_colour));    \
    }

/* scene_de and scene_colour of a fractal coloured by its orbit: `iterate` runs the iteration once
 * for the distance, and again recording the orbit trap at the (few) points being shaded. */
#define FGR_TRAP_COLOURED_SCENE(iterate)            \
    real scene_de(vec3 p, PARAMS) {                 \
        orbit_trap unused;                          \
        return iterate(p, PARAMS_PASS, 0, &unused); \
    }                                               \
    FGR_TRAP_COLOUR_FUNCTION(iterate)

/* The same for an inside-only scene (fgr_geometry.cl): `iterate` returns the lanes whose orbit
 * stayed bounded, and defines scene_inside and scene_colour. Put `#define FGR_SCENE_INSIDE_ONLY`
 * on a line of its own above it: the host reads that line to know the scene has no DE. */
#define FGR_TRAP_COLOURED_INSIDE_SCENE(iterate)     \
    mask scene_inside(vec3 p, PARAMS) {             \
        orbit_trap unused;                          \
        return iterate(p, PARAMS_PASS, 0, &unused); \
    }                                               \
    FGR_TRAP_COLOUR_FUNCTION(iterate)
