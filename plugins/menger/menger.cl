/* Menger sponge as a kaleidoscopic IFS (Knighty's KIFS, as in Syntopia's Fragmentarium).
 *
 * Each iteration folds space into the cube's fundamental region x >= y >= z >= 0 (fold_menger),
 * optionally twists it, and blows the sub-cube there up to full size:
 *
 *     z <- R fold_menger(z) * scale - offset * (scale - 1)
 *
 * In that region two of the 20 sub-cubes remain: the corner cube at (1, 1, 1) and the edge cube
 * at (1, 1, 0) in the middle layer. The classic code picks the middle layer with
 * `if (z.z < -offset.z * (scale - 1) / 2) z.z += offset.z * (scale - 1)`; here it is written as
 * z.z <- min(|z.z|, |z.z + offset.z * (scale - 1)|), the same up to a sign the next fold (and the
 * symmetric box at the end) ignores, but continuous.
 *
 * After n iterations the point is measured against the cube [-1, 1]^3 and the distance scaled
 * back by scale^-n. Reflections, rotations, uniform scaling and the min above are all 1-Lipschitz,
 * so the estimate is a true lower bound on the distance to the surface it draws, for every
 * parameter value. With scale 3, offset (1, 1, 1) and no twist it is the level-n Menger sponge,
 * 20^n cubes of size 3^-n, and the estimate matches the exact distance to them outside.
 *
 * The loop keeps w = z * scale^-i instead of z: the same map (folds and rotations commute with
 * scaling), but w stays in p's units while z would overflow float for far points or high
 * iteration counts. */

/* Orbit traps see the first few levels only: deeper ones vary faster than a pixel and would turn
 * the colour into speckle. */
#define MENGER_TRAP_LEVELS 4

/* Runs the KIFS for p; returns the DE and, when `record` is set, fills *trap with the orbit. */
inline real menger_iterate(vec3 p, PARAMS, int record, orbit_trap* trap) {
    const float scale = param_scale;
    const vec3 offset = param_offset;
    /* The twist turns about the cube's diagonal, through the corner cube being blown up. */
    const rotation3 twist = rotation_about_axis((float3)(0.57735027f), param_twist);
    const int twisted = param_twist != 0.0f;
    vec3 w = p;        /* the orbit point z_i times scale^-i */
    float size = 1.0f; /* scale^-i: the half-size of one level-i cube */
    for (int i = 0; i < param_iterations; ++i) {
        w = fold_menger(w);
        if (twisted) w = op_rotate(w, twist);
        size /= scale;
        const float shift = (scale - 1.0f) * size;
        w = v3_sub(w, v3_scale(offset, shift));
        /* The nearer of the corner layer and the middle layer (see above). */
        w.z = fmin(fabs(w.z), fabs(w.z + offset.z * shift));
        if (record && i < MENGER_TRAP_LEVELS) {
            *trap = trap_update(*trap, v3_scale(w, 1.0f / size), FGR_TRUE);
        }
    }
    return sd_box(w, v3_splat(size, size, size));
}

#define FGR_SCENE_HAS_COLOUR
FGR_TRAP_COLOURED_SCENE(menger_iterate)
