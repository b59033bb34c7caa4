// SPDX-License-Identifier: Apache-2.0
/* SDF gallery: every primitive, combinator and transform of kernels/sdf/fgr_sdf.cl, one per plinth
 * slot on a 6 x 4 grid standing on a platform.
 *
 *   row 0 (front)  sphere, box, round box, torus, cylinder, capsule
 *   row 1          cone, octahedron, tetrahedron, elongated sphere, onion shells, rounded cross
 *   row 2          union, subtraction, intersection, smooth union / subtraction / intersection
 *   row 3 (back)   twist, bend, sine displacement, limited repetition, infinite repetition,
 *                  rotated and scaled copies
 *
 * Every object lies within GALLERY_OBJECT_RADIUS of its slot centre for every parameter value.
 * Its DE is max(object DE, distance to that bounding ball): still a bound, 1-Lipschitz, and never
 * below the ball's distance, so an object whose ball is no nearer than the nearest thing so far
 * can be skipped for a whole packet without changing any lane's result. */

#define GALLERY_COLUMNS 6
#define GALLERY_ROWS 4
#define GALLERY_SPACING 2.5f
#define GALLERY_OBJECT_HEIGHT 1.05f /* slot centres above the platform top (z = 0) */
#define GALLERY_OBJECT_RADIUS 1.0f
#define GALLERY_OBJECT_COUNT (GALLERY_COLUMNS * GALLERY_ROWS)

inline vec3 slot_centre(int index) {
    const int column = index % GALLERY_COLUMNS, row = index / GALLERY_COLUMNS;
    return v3_splat((column - 0.5f * (GALLERY_COLUMNS - 1)) * GALLERY_SPACING,
                    (row - 0.5f * (GALLERY_ROWS - 1)) * GALLERY_SPACING, GALLERY_OBJECT_HEIGHT);
}

/* The platform: a slab under the grid with rounded edges, its top at z = 0. */
inline real platform_de(vec3 p) {
    const float half_x = 0.5f * GALLERY_COLUMNS * GALLERY_SPACING + 0.4f;
    const float half_y = 0.5f * GALLERY_ROWS * GALLERY_SPACING + 0.4f;
    return sd_round_box(op_translate(p, v3_splat(0.0f, 0.0f, -0.3f)),
                        v3_splat(half_x, half_y, 0.3f), 0.12f);
}

/* --- row 0: primitives --------------------------------------------------------------------- */

inline real object_round_box(vec3 p, PARAMS) {
    return sd_round_box(op_rotate_z(p, 0.5f), v3_splat(0.6f, 0.5f, 0.55f), param_rounding);
}

inline real object_torus(vec3 p) {
    /* Stood up on its edge, turned towards the camera so the hole shows. */
    return sd_torus(op_rotate_z(op_rotate_x(p, 1.3f), 0.35f), 0.62f, 0.22f);
}

/* --- row 1: more primitives, elongate, onion, round ---------------------------------------- */

inline real object_onion(vec3 p) {
    /* Two nested shells of a sphere, their front quarter cut away by a plane to show them. */
    real shells = op_onion(op_onion(sd_sphere(p, 0.62f), 0.16f), 0.05f);
    real back_half = sd_plane(p, v3_splat(0.0f, -1.0f, 0.0f), 0.0f);
    real below = sd_plane(p, v3_splat(0.0f, 0.0f, 1.0f), 0.05f);
    return op_intersection(shells, op_union(back_half, below));
}

inline real object_rounded_cross(vec3 p, PARAMS) {
    /* Three bars, unioned (exact outside), then grown by the rounding radius. */
    const float bar = 0.6f - param_rounding, thin = 0.1f;
    vec3 q = op_rotate_z(op_rotate_x(p, 0.4f), 0.6f);
    real d = op_union(
        sd_box(q, v3_splat(bar, thin, thin)),
        op_union(sd_box(q, v3_splat(thin, bar, thin)), sd_box(q, v3_splat(thin, thin, bar))));
    return op_round(d, 0.1f + param_rounding);
}

/* --- row 2: combinators -------------------------------------------------------------------- */

inline real object_union(vec3 p) {
    real ball = sd_sphere(op_translate(p, v3_splat(-0.25f, 0.0f, 0.25f)), 0.5f);
    real block =
        sd_box(op_translate(p, v3_splat(0.22f, 0.0f, -0.22f)), v3_splat(0.38f, 0.38f, 0.38f));
    return op_union(ball, block);
}

inline real object_subtraction(vec3 p) {
    real block = sd_box(op_rotate_z(p, 0.4f), v3_splat(0.55f, 0.55f, 0.55f));
    return op_subtraction(block, sd_sphere(p, 0.72f));
}

inline real object_intersection(vec3 p) {
    return op_intersection(sd_box(op_rotate_z(p, 0.4f), v3_splat(0.55f, 0.55f, 0.55f)),
                           sd_sphere(p, 0.72f));
}

inline real object_smooth_union(vec3 p, PARAMS) {
    /* Three balls on a capsule, melted together. */
    const float k = param_smooth_k;
    real d = sd_capsule(p, v3_splat(-0.45f, 0.0f, -0.4f), v3_splat(0.45f, 0.0f, -0.4f), 0.18f);
    d = op_smooth_union(d, sd_sphere(op_translate(p, v3_splat(-0.4f, 0.0f, -0.2f)), 0.32f), k);
    d = op_smooth_union(d, sd_sphere(op_translate(p, v3_splat(0.4f, 0.0f, -0.2f)), 0.32f), k);
    return op_smooth_union(d, sd_sphere(op_translate(p, v3_splat(0.0f, 0.0f, 0.3f)), 0.4f), k);
}

inline real object_smooth_subtraction(vec3 p, PARAMS) {
    /* A cylinder drilled by a smaller one, the hole's rim rounded over. */
    real drum = sd_cylinder(p, 0.7f, 0.35f);
    real hole = sd_cylinder(p, 0.35f, 0.7f);
    real groove = sd_torus(op_translate(p, v3_splat(0.0f, 0.0f, 0.35f)), 0.7f, 0.12f);
    return op_smooth_subtraction(op_smooth_subtraction(drum, hole, param_smooth_k), groove,
                                 0.5f * param_smooth_k);
}

inline real object_smooth_intersection(vec3 p, PARAMS) {
    return op_smooth_intersection(sd_octahedron(op_rotate_z(p, 0.3f), 1.05f), sd_sphere(p, 0.72f),
                                  param_smooth_k);
}

/* --- row 3: transforms --------------------------------------------------------------------- */

inline real object_twist(vec3 p, PARAMS) {
    /* A square column twisted about its axis. The column's corners are 0.453 from the axis, so
     * the twist is evaluated inside a cylinder of that reach and extended outside it. */
    const float reach = 0.46f;
    real excess;
    vec3 q = op_clamp_to_cylinder(p, reach, 0.85f, &excess);
    real d = sd_round_box(op_twist(q, param_twist), v3_splat(0.32f, 0.32f, 0.8f), 0.04f);
    return op_extend_from_clamp(d / op_twist_lipschitz(param_twist, reach), excess);
}

inline real object_bend(vec3 p, PARAMS) {
    /* A bar bent into an arc; its centre sits below the slot centre so the raised ends stay in
     * the slot. Only points within `reach` above the bar's centre line are evaluated directly. */
    const float reach = 0.6f;
    vec3 lowered = op_translate(p, v3_splat(0.0f, 0.0f, -0.3f));
    real excess;
    vec3 q = op_clamp_to_box(lowered, v3_splat(0.95f, 0.3f, reach), &excess);
    real d = sd_round_box(op_bend(q, param_bend), v3_splat(0.88f, 0.25f, 0.1f), 0.05f);
    return op_extend_from_clamp(d / op_bend_lipschitz(param_bend, reach), excess);
}

inline real object_displaced(vec3 p, PARAMS) {
    return op_displace_sine(sd_sphere(p, 0.72f), p, param_displacement, param_frequency);
}

inline real object_repeat_limited(vec3 p, PARAMS) {
    /* A 3 x 3 x 3 block of balls, one per cell of the spacing. */
    const float spacing = param_spacing;
    vec3 q = op_repeat_limited(p, v3_splat(spacing, spacing, spacing), v3_splat(1.0f, 1.0f, 1.0f));
    return sd_sphere(q, 0.32f * spacing);
}

inline real object_repeat(vec3 p, PARAMS) {
    /* An endless lattice of small cubes, seen through a ball. */
    const float spacing = 0.5f * param_spacing;
    vec3 q = op_repeat(op_rotate_z(p, 0.5f), v3_splat(spacing, spacing, spacing));
    real cubes =
        sd_round_box(q, v3_splat(0.3f * spacing, 0.3f * spacing, 0.3f * spacing), 0.05f * spacing);
    return op_intersection(cubes, sd_sphere(p, 0.8f));
}

inline real object_rotate_scale(vec3 p) {
    /* One tetrahedron at three scales, each turned further: sd(p / s) * s per copy. */
    real d = fgr_real(1e20f);
    for (int i = 0; i < 3; ++i) {
        const float scale = 0.6f - 0.17f * i;
        const float height = -0.38f + 0.5f * i;
        vec3 q = op_rotate_z(op_translate(p, v3_splat(0.0f, 0.0f, height)), 0.45f * i);
        q = op_rotate_x(q, 0.2f * i);
        d = op_union(d, op_scale_distance(sd_tetrahedron(op_scale_point(q, scale), 0.55f), scale));
    }
    return d;
}

/* Object `index`'s DE in its slot's coordinates (a uniform switch: the same object in every
 * lane). */
inline real object_de(int index, vec3 p, PARAMS) {
    switch (index) {
        case 0:
            return sd_sphere(p, 0.8f);
        case 1:
            return sd_box(op_rotate_z(p, 0.5f), v3_splat(0.55f, 0.55f, 0.55f));
        case 2:
            return object_round_box(p, PARAMS_PASS);
        case 3:
            return object_torus(p);
        case 4:
            return sd_cylinder(p, 0.55f, 0.75f);
        case 5:
            return sd_capsule(p, v3_splat(-0.35f, 0.15f, -0.55f), v3_splat(0.35f, -0.15f, 0.55f),
                              0.3f);
        case 6:
            return sd_cone(p, 0.75f, 0.65f, 0.12f);
        case 7:
            return sd_octahedron(op_rotate_z(p, 0.3f), 0.9f);
        case 8:
            return sd_tetrahedron(op_rotate_z(p, 0.785398f), 0.5f);
        case 9:
            return sd_sphere(op_elongate(op_rotate_z(p, 0.5f), v3_splat(0.35f, 0.0f, 0.3f)), 0.4f);
        case 10:
            return object_onion(p);
        case 11:
            return object_rounded_cross(p, PARAMS_PASS);
        case 12:
            return object_union(p);
        case 13:
            return object_subtraction(p);
        case 14:
            return object_intersection(p);
        case 15:
            return object_smooth_union(p, PARAMS_PASS);
        case 16:
            return object_smooth_subtraction(p, PARAMS_PASS);
        case 17:
            return object_smooth_intersection(p, PARAMS_PASS);
        case 18:
            return object_twist(p, PARAMS_PASS);
        case 19:
            return object_bend(p, PARAMS_PASS);
        case 20:
            return object_displaced(p, PARAMS_PASS);
        case 21:
            return object_repeat_limited(p, PARAMS_PASS);
        case 22:
            return object_repeat(p, PARAMS_PASS);
        default:
            return object_rotate_scale(p);
    }
}

/* The nearest of platform and objects; *nearest gets its index (-1 for the platform). */
inline real gallery_de(vec3 p, PARAMS, real* nearest) {
    real best = platform_de(p);
    *nearest = fgr_real(-1.0f);
    for (int i = 0; i < GALLERY_OBJECT_COUNT; ++i) {
        vec3 in_slot = op_translate(p, slot_centre(i));
        real ball = v3_length(in_slot) - GALLERY_OBJECT_RADIUS;
        if (!fgr_any(ball < best)) continue; /* cannot be nearer in any lane: result unchanged */
        real d = op_intersection(object_de(i, in_slot, PARAMS_PASS), ball);
        mask nearer = d < best;
        *nearest = select(*nearest, fgr_real((float)i), nearer);
        best = fmin(best, d);
    }
    return best;
}

real scene_de(vec3 p, PARAMS) {
    real nearest;
    return gallery_de(p, PARAMS_PASS, &nearest);
}

#define FGR_SCENE_HAS_COLOUR
/* Objects: a pastel colour each, walking the hue circle by the golden ratio so neighbours
 * differ. Platform: a two-grey checker with one square per slot. */
vec3 scene_colour(vec3 p, PARAMS) {
    real nearest;
    gallery_de(p, PARAMS_PASS, &nearest);
    vec3 object = palette(nearest * 0.618034f + 0.1f, 3);
    real checker = fgr_parity(floor(p.x / GALLERY_SPACING + 0.5f * GALLERY_COLUMNS) +
                              floor(p.y / GALLERY_SPACING + 0.5f * GALLERY_ROWS));
    real grey = select(fgr_real(0.55f), fgr_real(0.38f), fabs(checker) > 0.5f);
    return v3_select(object, v3(grey, grey, grey * 1.04f), nearest < 0.0f);
}
