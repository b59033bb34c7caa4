// SPDX-License-Identifier: Apache-2.0
/* Benchmark scene: fractal and primitive geometry together on a reflective floor, lit by a sun and
 * a point light, with ambient occlusion, soft shadows and reflections. It exercises every part of
 * the renderer at once, so `fgr bench` figures on it say how a realistic scene performs.
 *
 * Objects (z up, the floor is z = 0):
 *   a power-8 Mandelbulb, a Menger sponge, a smooth blend of a sphere and a torus, a twisted
 *   column, and the floor. The fractals' distances are clamped by their bounding sphere and box,
 *   so packets of rays far from them skip their iterations (max(DE, bound) is still a bound), and
 *   the scene unions its objects with op_union_culled, which skips an object wherever something
 *   else is nearer than its bound for every lane of the packet: a shadow ray or reflection
 *   crossing the floor pays for the floor alone. */

#define FGR_KERNEL_API 3

#define BENCH_BULB_CENTRE v3_splat(-1.7f, 0.5f, 0.72f)
#define BENCH_BULB_SCALE 0.6f
#define BENCH_SPONGE_CENTRE v3_splat(1.5f, 0.7f, 0.62f)
#define BENCH_SPONGE_HALF 0.6f
#define BENCH_BLOB_CENTRE v3_splat(0.1f, -1.5f, 0.55f)
#define BENCH_COLUMN_CENTRE v3_splat(0.2f, 1.9f, 0.0f)

/* Distance to the sphere bounding an object, or the object's own DE once inside it. */
inline real bounded(real bound, real object) { return fmax(bound, object); }

/* A lane farther than 0.1 from an object's bound gets the bound alone, whether its packet took
 * the early exit (every lane that far) or computed the object for its other lanes: a lane's
 * distance never depends on which packet it marches in, so every packet width renders the same
 * image. */
inline real far_lanes_get_bound(real bound, real near_value) {
    return select(near_value, bound, bound > 0.1f);
}

inline real bench_bulb(vec3 p, PARAMS, int record, orbit_trap* trap) {
    vec3 in_object = op_scale_point(op_translate(p, BENCH_BULB_CENTRE), BENCH_BULB_SCALE);
    real bound = sd_sphere(in_object, 1.25f);
    if (!record && fgr_all(bound > 0.1f)) return op_scale_distance(bound, BENCH_BULB_SCALE);
    real de = mandelbulb_de(in_object, 8.0f, 2.0f, param_iterations, 0, record, trap);
    real distance = bounded(bound, de);
    if (!record) distance = far_lanes_get_bound(bound, distance);
    return op_scale_distance(distance, BENCH_BULB_SCALE);
}

/* Menger sponge filling the cube [-1, 1]^3: the cube minus, at every level, the cross of square
 * holes through the middle third of each sub-cube (Inigo Quilez's construction). Exact. */
inline real menger_sponge(vec3 p, int levels) {
    real d = sd_box(p, v3_splat(1.0f, 1.0f, 1.0f));
    float cell_scale = 1.0f;
    for (int level = 0; level < levels; ++level) {
        /* position in the current sub-cube, in [-1, 1) */
        vec3 cell = v3_sub(v3_scale(p, fgr_real(cell_scale)), v3_splat(-1.0f, -1.0f, -1.0f));
        cell = v3(cell.x - 2.0f * floor(cell.x * 0.5f), cell.y - 2.0f * floor(cell.y * 0.5f),
                  cell.z - 2.0f * floor(cell.z * 0.5f));
        cell = v3_sub(cell, v3_splat(1.0f, 1.0f, 1.0f));
        cell_scale *= 3.0f;
        vec3 r = v3(fabs(1.0f - 3.0f * fabs(cell.x)), fabs(1.0f - 3.0f * fabs(cell.y)),
                    fabs(1.0f - 3.0f * fabs(cell.z)));
        real cross = fmin(fmax(r.x, r.y), fmin(fmax(r.y, r.z), fmax(r.z, r.x)));
        d = fmax(d, (cross - 1.0f) / cell_scale);
    }
    return d;
}

inline real bench_sponge(vec3 p) {
    vec3 in_object =
        op_scale_point(op_rotate_z(op_translate(p, BENCH_SPONGE_CENTRE), 0.5f), BENCH_SPONGE_HALF);
    real bound = sd_box(in_object, v3_splat(1.0f, 1.0f, 1.0f));
    if (fgr_all(bound > 0.1f)) return op_scale_distance(bound, BENCH_SPONGE_HALF);
    return op_scale_distance(far_lanes_get_bound(bound, menger_sponge(in_object, 4)),
                             BENCH_SPONGE_HALF);
}

inline real bench_blob(vec3 p) {
    vec3 in_object = op_translate(p, BENCH_BLOB_CENTRE);
    real sphere = sd_sphere(in_object, 0.38f);
    real ring = sd_torus(op_rotate_x(in_object, 0.6f), 0.55f, 0.12f);
    return op_smooth_union(sphere, ring, 0.2f);
}

inline real bench_column(vec3 p) {
    vec3 in_object = op_translate(p, BENCH_COLUMN_CENTRE);
    real excess;
    vec3 inside = op_clamp_to_cylinder(in_object, 0.6f, 1.6f, &excess);
    real twisted = sd_round_box(op_twist(op_translate(inside, v3_splat(0.0f, 0.0f, 0.8f)), 1.4f),
                                v3_splat(0.28f, 0.28f, 0.75f), 0.05f);
    return op_extend_from_clamp(twisted / op_twist_lipschitz(1.4f, 0.5f), excess);
}

inline real bench_floor(vec3 p) { return sd_plane(p, v3_splat(0.0f, 0.0f, 1.0f), 0.0f); }

/* Lower bounds of the objects' DE values, for op_union_culled: a ray near the floor or one object
 * evaluates that object alone, and the scene's DE is the same to the last bit. Each is 1e-5 under
 * the bound it stands for, so rounding cannot lift it above the object's DE. */
inline real bulb_lower(vec3 p) {
    vec3 in_object = op_scale_point(op_translate(p, BENCH_BULB_CENTRE), BENCH_BULB_SCALE);
    return op_scale_distance(sd_sphere(in_object, 1.25f), BENCH_BULB_SCALE) - 1e-5f;
}
inline real sponge_lower(vec3 p) {
    vec3 in_object =
        op_scale_point(op_rotate_z(op_translate(p, BENCH_SPONGE_CENTRE), 0.5f), BENCH_SPONGE_HALF);
    return op_scale_distance(sd_box(in_object, v3_splat(1.0f, 1.0f, 1.0f)), BENCH_SPONGE_HALF) -
           1e-5f;
}
inline real blob_lower(vec3 p) {
    /* sphere >= |q| - 0.38, ring >= |q| - (0.55 + 0.12), their smooth union >= min - 0.2 / 4 */
    return v3_length(op_translate(p, BENCH_BLOB_CENTRE)) - 0.72f - 1e-5f;
}
inline real column_lower(vec3 p) {
    /* Outside its clamping cylinder the column's DE is at least the way back to it. */
    real excess;
    op_clamp_to_cylinder(op_translate(p, BENCH_COLUMN_CENTRE), 0.6f, 1.6f, &excess);
    return select(fgr_real(-INFINITY), excess - 1e-5f, excess > 0.0f);
}

real scene_de(vec3 p, PARAMS) {
    orbit_trap unused;
    real d = bench_floor(p);
    d = op_union_culled(d, blob_lower(p), bench_blob(p));
    d = op_union_culled(d, column_lower(p), bench_column(p));
    d = op_union_culled(d, sponge_lower(p), bench_sponge(p));
    return op_union_culled(d, bulb_lower(p), bench_bulb(p, PARAMS_PASS, 0, &unused));
}

/* Which object is nearest, per lane: 0 floor, 1 bulb, 2 sponge, 3 blob, 4 column. */
inline real nearest_object(vec3 p, PARAMS) {
    orbit_trap unused;
    real best = bench_floor(p), id = fgr_real(0.0f);
    real candidates[4] = {bench_bulb(p, PARAMS_PASS, 0, &unused), bench_sponge(p), bench_blob(p),
                          bench_column(p)};
    for (int i = 0; i < 4; ++i) {
        mask closer = candidates[i] < best;
        best = select(best, candidates[i], closer);
        id = select(id, fgr_real((float)(i + 1)), closer);
    }
    return id;
}

#define FGR_SCENE_HAS_COLOUR
vec3 scene_colour(vec3 p, PARAMS) {
    real id = nearest_object(p, PARAMS_PASS);
    real checker = fgr_parity(floor(p.x) + floor(p.y) + 1000.0f);
    vec3 colour = v3(mix(fgr_real(0.22f), fgr_real(0.45f), checker),
                     mix(fgr_real(0.22f), fgr_real(0.45f), checker),
                     mix(fgr_real(0.24f), fgr_real(0.48f), checker));
    if (fgr_any(id == 1.0f)) {
        orbit_trap trap = trap_init();
        bench_bulb(p, PARAMS_PASS, 1, &trap);
        colour =
            v3_select(colour, trap_colour(trap, FGR_TRAP_POINT, param_palette, param_base_colour),
                      id == 1.0f);
    }
    colour = v3_select(colour, v3_splat(0.55f, 0.62f, 0.75f), id == 2.0f);
    colour = v3_select(colour, v3_splat(0.80f, 0.25f, 0.18f), id == 3.0f);
    colour = v3_select(colour, v3_splat(0.85f, 0.75f, 0.45f), id == 4.0f);
    return colour;
}

#define FGR_SCENE_HAS_REFLECTIVITY
real scene_reflectivity(vec3 p, PARAMS) {
    /* The floor is polished; everything else reflects only at grazing angles. (Which surface by
     * the nearest object, not by height: hit points sit up to a pixel footprint off the floor.) */
    return select(fgr_real(0.03f), fgr_real(param_floor_reflectivity),
                  nearest_object(p, PARAMS_PASS) == 0.0f);
}
